#include "casteljau/bezier/split.hpp"

#include <cassert>
#include <cmath>
#include <functional>
#include <vector>

#include "casteljau/bezier/tolerance.hpp"
#include "casteljau/core/parameter_checks.hpp"
#include "de_casteljau.hpp"

namespace casteljau {
namespace {

/// Rows to split: the homogeneous points for a rational curve, else the points.
PointArray working_points(const BezierCurve& curve) {
  return curve.is_rational() ? homogeneous_points(curve) : curve.control_points();
}

BezierCurve curve_from(const BezierCurve& like, std::vector<double> rows, int width) {
  PointArray points = PointArray::from_trusted(width, std::move(rows));
  return like.is_rational() ? from_homogeneous(points) : BezierCurve::from_trusted(std::move(points));
}

/// de Casteljau triangle at t on `rows` (n+1 rows of width): fills left with
/// P^0_0, P^1_0, ..., P^n_0 and right with P^n_0, P^{n-1}_1, ..., P^0_n.
void split_rows(std::vector<double> rows, int n, int width, double t, std::vector<double>& left,
                std::vector<double>& right) {
  left.assign(static_cast<std::size_t>(n + 1) * width, 0.0);
  right.assign(static_cast<std::size_t>(n + 1) * width, 0.0);
  const double s = 1.0 - t;
  for (int j = 0; j < width; ++j) {
    left[j] = rows[j];
    right[n * width + j] = rows[n * width + j];
  }
  double* x = rows.data();
  for (int r = 1; r <= n; ++r) {
    // Row i becomes (1-t) row i + t row i+1: one flat pass over the rows'
    // coordinates (the same lerp_step per coordinate as point_at, so the same
    // bits; flat, the compiler can vectorize it).
    const int count = (n - r + 1) * width;
    for (int m = 0; m < count; ++m) x[m] = detail::lerp_step(x[m], x[m + width], s, t);
    for (int j = 0; j < width; ++j) {
      left[r * width + j] = rows[j];
      right[(n - r) * width + j] = rows[(n - r) * width + j];
    }
  }
}

}  // namespace

Expected<std::pair<BezierCurve, BezierCurve>> split_at(const BezierCurve& curve, double t) {
  if (auto ok = check_split_parameter(t, curve.domain()); !ok) return ok.error();
  const PointArray points = working_points(curve);
  const int width = points.dimension(), n = curve.degree();
  std::vector<double> left, right;
  split_rows({points.coordinates().begin(), points.coordinates().end()}, n, width, t, left, right);
  return std::pair<BezierCurve, BezierCurve>{curve_from(curve, std::move(left), width),
                                             curve_from(curve, std::move(right), width)};
}

Expected<BezierCurve> segment(const BezierCurve& curve, double t0, double t1) {
  if (auto ok = check_segment_parameters(t0, t1, curve.domain()); !ok) return ok.error();
  return extended_segment(curve, t0, t1);
}

BezierCurve extended_segment(const BezierCurve& curve, double t0, double t1) {
  // Two subdivisions (Farin §3.4): C on [0, t1] is the left side of the de
  // Casteljau triangle at t1; that piece on [t0 / t1, 1] (its own parameter)
  // is C on [t0, t1]. Pivoting on the end of larger magnitude keeps the ratio
  // in [-1, 1]; a rational curve stays homogeneous between the two (the
  // intermediate piece may reach weights <= 0 outside [0, 1]). O(n^2 d):
  // each blossom value b(t0^(n-i), t1^i) on its own would cost O(n^3 d).
  if (std::abs(t0) > std::abs(t1)) return reversed(extended_segment(curve, t1, t0));
  const PointArray points = working_points(curve);
  const int width = points.dimension(), n = curve.degree();
  std::vector<double> before, after;
  split_rows({points.coordinates().begin(), points.coordinates().end()}, n, width, t1, before, after);
  if (t1 == 0.0) return curve_from(curve, std::move(before), width);  // t0 = t1 = 0: the point C(0), n + 1 times
  std::vector<double> outside, piece;
  split_rows(std::move(before), n, width, t0 / t1, outside, piece);
  return curve_from(curve, std::move(piece), width);
}

BezierCurve reversed(const BezierCurve& curve) {
  const auto& p = curve.control_points();
  const int d = curve.dimension();
  std::vector<double> rows;
  rows.reserve(p.coordinates().size());
  for (std::size_t i = p.size(); i-- > 0;) rows.insert(rows.end(), p[i].begin(), p[i].end());
  std::vector<double> weights(curve.weights().rbegin(), curve.weights().rend());
  return BezierCurve::from_trusted(PointArray::from_trusted(d, std::move(rows)), std::move(weights));
}

Expected<PointArray> subdivide_recursive(const BezierCurve& curve, int depth, double t) {
  if (depth < 0) return Error{"subdivision depth " + std::to_string(depth) + " is negative"};
  if (depth > tolerances::kMaxSubdivisionDepth) {
    return Error{"subdivision depth " + std::to_string(depth) + " would give 2^" + std::to_string(depth) +
                 " + 1 points, the limit is depth " + std::to_string(tolerances::kMaxSubdivisionDepth), ErrorKind::limit};
  }
  if (!(t > 0.0 && t < 1.0)) return Error{"subdivision parameter must lie strictly between 0 and 1", ErrorKind::out_of_domain};
  const PointArray points = working_points(curve);
  const int width = points.dimension(), n = curve.degree(), d = curve.dimension();
  PointArray out = PointArray::zeros(d, 0);
  auto emit = [&](const double* row) {
    std::vector<double> p(row, row + d);
    if (curve.is_rational())
      for (double& c : p) c /= row[d];
    out.push_back(p);
  };
  // The seed's recursion: at depth 0 a polygon contributes its first point;
  // the very last point of the curve is appended at the end.
  std::function<void(std::vector<double>, int)> recurse = [&](std::vector<double> rows, int r) {
    if (r == 0) {
      emit(rows.data());
      return;
    }
    std::vector<double> left, right;
    split_rows(std::move(rows), n, width, t, left, right);
    recurse(std::move(left), r - 1);
    recurse(std::move(right), r - 1);
  };
  recurse({points.coordinates().begin(), points.coordinates().end()}, depth);
  emit(points.coordinates().data() + static_cast<std::size_t>(n) * width);
  return out;
}

}  // namespace casteljau

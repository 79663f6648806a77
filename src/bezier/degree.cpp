#include "casteljau/bezier/degree.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/evaluate.hpp"

namespace casteljau {
namespace {

/// One elevation step on rows of `width` (Farin §5.1).
std::vector<double> elevate_rows(const std::vector<double>& rows, int n, int width) {
  std::vector<double> out(static_cast<std::size_t>(n + 2) * width);
  for (int j = 0; j < width; ++j) {
    out[j] = rows[j];
    out[(n + 1) * width + j] = rows[n * width + j];
  }
  for (int i = 1; i <= n; ++i) {
    const double a = static_cast<double>(i) / (n + 1);
    for (int j = 0; j < width; ++j) out[i * width + j] = a * rows[(i - 1) * width + j] + (1.0 - a) * rows[i * width + j];
  }
  return out;
}

/// integral_0^1 B_{a,i} B_{b,j} dt = C(a,i) C(b,j) / ((a+b+1) C(a+b, i+j)).
double bernstein_product_integral(int a, int i, int b, int j) {
  return binomial(a, i) * binomial(b, j) / ((a + b + 1) * binomial(a + b, i + j));
}

}  // namespace

BezierCurve elevate_degree(const BezierCurve& curve, int times) {
  assert(times >= 0);
  const bool rational = curve.is_rational();
  const PointArray points = rational ? homogeneous_points(curve) : curve.control_points();
  const int width = points.dimension();
  std::vector<double> rows(points.coordinates().begin(), points.coordinates().end());
  for (int k = 0; k < times; ++k) rows = elevate_rows(rows, curve.degree() + k, width);
  PointArray result = PointArray::from_trusted(width, std::move(rows));
  return rational ? from_homogeneous(result) : BezierCurve::from_trusted(std::move(result));
}

Expected<DegreeReduction> reduce_degree(const BezierCurve& curve, DegreeReductionOptions options) {
  const int n = curve.degree(), d = curve.dimension(), m = n - 1;
  if (n == 0) return Error{"a curve of degree 0 cannot be reduced"};
  if (curve.is_rational()) return Error{"degree reduction of rational Bézier curves is not supported"};
  const auto& p = curve.control_points();
  Eigen::MatrixXd P(n + 1, d);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j < d; ++j) P(k, j) = p[k][j];
  Eigen::MatrixXd G(m + 1, m + 1), H(m + 1, n + 1);
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= m; ++j) G(i, j) = bernstein_product_integral(m, i, m, j);
    for (int k = 0; k <= n; ++k) H(i, k) = bernstein_product_integral(m, i, n, k);
  }
  Eigen::MatrixXd Q(m + 1, d);
  const bool keep_ends = options.keep_end_points && m >= 1;
  if (!keep_ends) {
    Q = G.ldlt().solve(H * P);
  } else {
    Q.row(0) = P.row(0);
    Q.row(m) = P.row(n);
    if (m >= 2) {
      const int inner = m - 1;
      Eigen::MatrixXd rhs = (H * P).middleRows(1, inner) - G.block(1, 0, inner, 1) * P.row(0) -
                            G.block(1, m, inner, 1) * P.row(n);
      Q.middleRows(1, inner) = G.block(1, 1, inner, inner).ldlt().solve(rhs);
    }
  }
  std::vector<double> rows(static_cast<std::size_t>(m + 1) * d);
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j < d; ++j) rows[i * d + j] = Q(i, j);
  BezierCurve reduced = BezierCurve::from_trusted(PointArray::from_trusted(d, std::move(rows)));
  // Guaranteed bound: C - R = sum (P_k - E_k) B_{n,k} with E = R elevated to n.
  const BezierCurve elevated = elevate_degree(reduced);
  double bound = 0.0;
  for (int k = 0; k <= n; ++k) bound = std::max(bound, distance(p[k], elevated.control_points()[k]));
  double sampled = 0.0;
  for (int i = 0; i <= 1024; ++i) {
    const double t = i / 1024.0;
    sampled = std::max(sampled, distance(point_at(curve, t), point_at(reduced, t)));
  }
  return DegreeReduction{std::move(reduced), bound, sampled};
}

BezierCurve repeat_control_point(const BezierCurve& curve, int index, int extra) {
  assert(index >= 0 && index <= curve.degree() && extra >= 0);
  const auto& p = curve.control_points();
  const int d = curve.dimension();
  std::vector<double> rows;
  std::vector<double> weights;
  for (int i = 0; i <= curve.degree(); ++i) {
    const int copies = (i == index) ? extra + 1 : 1;
    for (int c = 0; c < copies; ++c) {
      rows.insert(rows.end(), p[i].begin(), p[i].end());
      if (curve.is_rational()) weights.push_back(curve.weights()[i]);
    }
  }
  return BezierCurve::from_trusted(PointArray::from_trusted(d, std::move(rows)), std::move(weights));
}

}  // namespace casteljau

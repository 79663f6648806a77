#include "casteljau/ops/flatten.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"

namespace casteljau {
namespace {

/// Distance from point p to the segment [a, b] (any dimension).
double distance_to_segment(std::span<const double> p, std::span<const double> a, std::span<const double> b) {
  double ab2 = 0.0, apab = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    ab2 += (b[j] - a[j]) * (b[j] - a[j]);
    apab += (p[j] - a[j]) * (b[j] - a[j]);
  }
  const double u = ab2 > 0.0 ? std::clamp(apab / ab2, 0.0, 1.0) : 0.0;
  std::vector<double> q(p.size());
  for (std::size_t j = 0; j < p.size(); ++j) q[j] = a[j] + u * (b[j] - a[j]);
  return distance(p, q);
}

Status check_tolerance(Tolerance tolerance) {
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the flattening tolerance must be a finite distance > 0"};
  return {};
}

/// Recursive halving until the control polygon is within tolerance of its chord.
Status flatten_into(const BezierCurve& curve, double t0, double t1, double tolerance, Polyline& out, long& budget) {
  if (control_polygon_flatness(curve) <= tolerance) {
    if (--budget < 0) return Error{"flattening needs more than " + std::to_string(tolerances::kMaxFlattenSegments) + " segments at this tolerance"};
    const auto& p = curve.control_points();
    out.points.push_back(p[p.size() - 1]);
    out.parameters.push_back(t1);
    return {};
  }
  const auto [left, right] = split_at(curve, 0.5);
  const double tm = 0.5 * (t0 + t1);
  if (auto ok = flatten_into(left, t0, tm, tolerance, out, budget); !ok) return ok;
  return flatten_into(right, tm, t1, tolerance, out, budget);
}

}  // namespace

double control_polygon_flatness(const BezierCurve& curve) {
  const auto& p = curve.control_points();
  const auto a = p[0], b = p[p.size() - 1];
  double flatness = 0.0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) flatness = std::max(flatness, distance_to_segment(p[i], a, b));
  return flatness;
}

Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance) {
  if (auto ok = check_tolerance(tolerance); !ok) return ok.error();
  Polyline line{PointArray::zeros(curve.dimension(), 0), {}};
  line.points.push_back(curve.control_points()[0]);
  line.parameters.push_back(0.0);
  long budget = tolerances::kMaxFlattenSegments;
  if (auto ok = flatten_into(curve, 0.0, 1.0, tolerance.distance, line, budget); !ok) return ok.error();
  return line;
}

Expected<long> flatten_segment_count(const BezierCurve& curve, Tolerance tolerance) {
  auto line = flatten(curve, tolerance);
  if (!line) return line.error();
  return static_cast<long>(line->parameters.size()) - 1;
}

}  // namespace casteljau

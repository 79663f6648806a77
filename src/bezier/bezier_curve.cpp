#include "casteljau/bezier/bezier_curve.hpp"

#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/homogeneous.hpp"
#include "../core/weights.hpp"

#include <cassert>
#include <cmath>
#include <string>

namespace casteljau {

Expected<BezierCurve> BezierCurve::make(PointArray control_points, std::vector<double> weights) {
  if (control_points.empty()) return Error{"the control polygon is empty, a Bézier curve needs at least one control point"};
  if (control_points.size() > static_cast<std::size_t>(tolerances::kMaxBezierDegree) + 1) {
    return Error{std::to_string(control_points.size()) + " control points make a Bézier curve of degree " +
                 std::to_string(control_points.size() - 1) + ", above the limit " +
                 std::to_string(tolerances::kMaxBezierDegree) +
                 " (evaluation costs O(n^2) per point); interpolate the points or split them into pieces"};
  }
  if (auto ok = check_coordinates(control_points, "control point"); !ok) return ok.error();
  if (auto ok = detail::check_weights(weights, control_points.size()); !ok) return ok.error();
  return BezierCurve(std::move(control_points), std::move(weights));
}

BezierCurve BezierCurve::from_trusted(PointArray control_points, std::vector<double> weights) {
  assert(!control_points.empty());
  assert(weights.empty() || weights.size() == control_points.size());
  return BezierCurve(std::move(control_points), std::move(weights));
}

PointArray homogeneous_points(const BezierCurve& curve) {
  return detail::weighted_rows(curve.control_points(), curve.weights());
}

BezierCurve from_homogeneous(const PointArray& points) {
  auto [p, w] = detail::projected_rows(points);
  return BezierCurve::from_trusted(std::move(p), std::move(w));
}

}  // namespace casteljau

#include "casteljau/bezier/bezier_curve.hpp"

#include "casteljau/core/tolerance.hpp"
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
  for (std::size_t i = 0; i < control_points.coordinates().size(); ++i) {
    const std::size_t d = control_points.dimension();
    if (auto ok = check_finite(control_points.coordinates()[i],
                               "coordinate " + std::to_string(i % d) + " of control point " + std::to_string(i / d));
        !ok) {
      return ok.error();
    }
  }
  if (auto ok = detail::check_weights(weights, control_points.size()); !ok) return ok.error();
  return BezierCurve(std::move(control_points), std::move(weights));
}

BezierCurve BezierCurve::from_trusted(PointArray control_points, std::vector<double> weights) {
  assert(!control_points.empty());
  assert(weights.empty() || weights.size() == control_points.size());
  return BezierCurve(std::move(control_points), std::move(weights));
}

PointArray homogeneous_points(const BezierCurve& curve) {
  const int d = curve.dimension();
  const auto& p = curve.control_points();
  std::vector<double> h;
  h.reserve(p.size() * (d + 1));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double w = curve.is_rational() ? curve.weights()[i] : 1.0;
    for (double c : p[i]) h.push_back(w * c);
    h.push_back(w);
  }
  return PointArray::from_trusted(d + 1, std::move(h));
}

BezierCurve from_homogeneous(const PointArray& points) {
  const int d = points.dimension() - 1;
  assert(d >= 1);
  std::vector<double> p, w;
  p.reserve(points.size() * d);
  w.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto row = points[i];
    const double weight = row[d];
    assert(weight > 0.0);
    for (int j = 0; j < d; ++j) p.push_back(row[j] / weight);
    w.push_back(weight);
  }
  return BezierCurve::from_trusted(PointArray::from_trusted(d, std::move(p)), std::move(w));
}

}  // namespace casteljau

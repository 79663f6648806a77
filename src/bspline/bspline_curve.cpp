// BSplineCurve: validation and the homogeneous form.
#include "casteljau/bspline/bspline_curve.hpp"

#include <cassert>
#include <cmath>
#include <string>

#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "../core/homogeneous.hpp"
#include "../core/weights.hpp"

namespace casteljau {

Expected<BSplineCurve> BSplineCurve::make(int degree, std::vector<double> knots, PointArray control_points,
                                          std::vector<double> weights) {
  if (degree < 0 || degree > tolerances::kMaxBSplineDegree) {
    return Error{"degree " + std::to_string(degree) + " is outside [0, " +
                 std::to_string(tolerances::kMaxBSplineDegree) + "]"};
  }
  const std::size_t count = control_points.size();
  if (count > tolerances::kMaxControlPoints) {
    return Error{std::to_string(count) + " control points, above the limit " +
                 std::to_string(tolerances::kMaxControlPoints), ErrorKind::limit};
  }
  if (count < static_cast<std::size_t>(degree) + 1) {
    return Error{std::to_string(count) + " control points, a B-spline of degree " + std::to_string(degree) +
                 " needs at least " + std::to_string(degree + 1)};
  }
  if (auto ok = check_coordinates(control_points, "control point"); !ok) return ok.error();
  if (auto ok = validate_knots(knots, degree, count); !ok) return ok.error();
  if (auto ok = detail::check_weights(weights, count); !ok) return ok.error();
  return BSplineCurve(degree, std::move(knots), std::move(control_points), std::move(weights));
}

BSplineCurve BSplineCurve::from_trusted(int degree, std::vector<double> knots, PointArray control_points,
                                        std::vector<double> weights) {
  assert(degree >= 0 && control_points.size() >= static_cast<std::size_t>(degree) + 1);
  assert(knots.size() == control_points.size() + static_cast<std::size_t>(degree) + 1);
  assert(weights.empty() || weights.size() == control_points.size());
  assert(check_knot_structure(knots, degree, control_points.size()).has_value());
  return BSplineCurve(degree, std::move(knots), std::move(control_points), std::move(weights));
}

PointArray homogeneous_points(const BSplineCurve& curve) {
  return detail::weighted_rows(curve.control_points(), curve.weights());
}

BSplineCurve from_homogeneous(int degree, std::vector<double> knots, const PointArray& points) {
  auto [p, w] = detail::projected_rows(points);
  return BSplineCurve::from_trusted(degree, std::move(knots), std::move(p), std::move(w));
}

BSplineCurve to_bspline(const BezierCurve& curve) {
  const int n = curve.degree();
  std::vector<double> knots(2 * static_cast<std::size_t>(n) + 2, 0.0);
  for (int i = n + 1; i < 2 * n + 2; ++i) knots[static_cast<std::size_t>(i)] = 1.0;
  std::vector<double> weights(curve.weights().begin(), curve.weights().end());
  return BSplineCurve::from_trusted(n, std::move(knots), curve.control_points(), std::move(weights));
}

Expected<BSplineCurve> make_periodic(int degree, PointArray control_points, std::vector<double> weights,
                                     Interval domain) {
  if (degree < 1) return Error{"a closed B-spline needs degree >= 1, got " + std::to_string(degree)};
  const std::size_t m = control_points.size();
  if (m < static_cast<std::size_t>(degree) + 1) {
    return Error{std::to_string(m) + " control points, a closed B-spline of degree " + std::to_string(degree) +
                 " needs at least " + std::to_string(degree + 1)};
  }
  if (!weights.empty() && weights.size() != m) {
    return Error{std::to_string(weights.size()) + " weights for " + std::to_string(m) +
                 " control points, there must be one weight per control point"};
  }
  if (!(domain.lower < domain.upper) || !std::isfinite(domain.lower) || !std::isfinite(domain.upper)) {
    return Error{"the domain [" + detail::number_text(domain.lower) + ", " + detail::number_text(domain.upper) +
                 "] is not a finite non-empty interval"};
  }
  // Wrap: P_0..P_{m-1}, P_0..P_{p-1}; the weights likewise.
  for (int j = 0; j < degree; ++j) {
    const std::vector<double> first(control_points[static_cast<std::size_t>(j)].begin(),
                                    control_points[static_cast<std::size_t>(j)].end());
    control_points.push_back(first);
    if (!weights.empty()) weights.push_back(weights[static_cast<std::size_t>(j)]);
  }
  auto knots = periodic_knots(degree, m, domain);
  return BSplineCurve::make(degree, std::move(knots), std::move(control_points), std::move(weights));
}

}  // namespace casteljau

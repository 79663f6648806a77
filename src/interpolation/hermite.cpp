// Ferguson cubics and piecewise cubic Hermite interpolation as a B-spline
// with double knots (see hermite.hpp for the formulas and sources).
#include "casteljau/interpolation/hermite.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "input_checks.hpp"

namespace casteljau {
namespace {

Status check_vector(std::span<const double> v, const char* what) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      return Error{"coordinate " + std::to_string(k) + " of " + what + " is " +
                   (std::isnan(v[k]) ? "NaN" : "infinite")};
  return {};
}

}  // namespace

Expected<BezierCurve> ferguson_curve(std::span<const double> start, std::span<const double> start_tangent,
                                     std::span<const double> end, std::span<const double> end_tangent) {
  const std::size_t d = start.size();
  if (d == 0) return Error{"the start point of a Ferguson curve has no coordinates"};
  if (start_tangent.size() != d || end.size() != d || end_tangent.size() != d)
    return Error{"a Ferguson curve needs start point, start tangent, end point and end tangent of one "
                 "dimension, got " + std::to_string(d) + ", " + std::to_string(start_tangent.size()) + ", " +
                 std::to_string(end.size()) + ", " + std::to_string(end_tangent.size())};
  if (auto s = check_vector(start, "the start point"); !s) return s.error();
  if (auto s = check_vector(start_tangent, "the start tangent"); !s) return s.error();
  if (auto s = check_vector(end, "the end point"); !s) return s.error();
  if (auto s = check_vector(end_tangent, "the end tangent"); !s) return s.error();
  std::vector<double> coordinates(4 * d);
  for (std::size_t k = 0; k < d; ++k) {
    coordinates[k] = start[k];
    coordinates[d + k] = start[k] + start_tangent[k] / 3.0;
    coordinates[2 * d + k] = end[k] - end_tangent[k] / 3.0;
    coordinates[3 * d + k] = end[k];
  }
  // A sum of finite values can still overflow (1e308 + 1e308).
  for (std::size_t k = 0; k < coordinates.size(); ++k)
    if (!std::isfinite(coordinates[k]))
      return Error{"control point " + std::to_string(k / d) + " of the Ferguson curve overflows"};
  return BezierCurve::from_trusted(PointArray::from_trusted(static_cast<int>(d), std::move(coordinates)));
}

Expected<BSplineCurve> interpolate_hermite(const PointArray& points, const PointArray& tangents,
                                           std::span<const double> parameters, Closure closure) {
  const bool closed = closure == Closure::closed;
  const std::size_t count = points.size();
  const std::size_t needed = closed ? 3 : 2;
  if (count < needed)
    return Error{std::string(closed ? "a closed " : "") + "Hermite interpolation needs at least " +
                 std::to_string(needed) + " points, got " + std::to_string(count)};
  if (tangents.size() != count)
    return Error{"Hermite interpolation needs one tangent per point: " + std::to_string(count) + " points, " +
                 std::to_string(tangents.size()) + " tangents"};
  if (tangents.dimension() != points.dimension())
    return Error{"the tangents have dimension " + std::to_string(tangents.dimension()) + ", the points have " +
                 std::to_string(points.dimension())};
  const std::size_t segments = closed ? count : count - 1;
  if (parameters.size() != segments + 1)
    return Error{"Hermite interpolation of " + std::to_string(count) + (closed ? " points (closed)" : " points") +
                 " needs " + std::to_string(segments + 1) + " parameter values, got " +
                 std::to_string(parameters.size())};
  if (auto s = detail::check_coordinates(points, "point"); !s) return s.error();
  if (auto s = detail::check_coordinates(tangents, "tangent"); !s) return s.error();
  if (auto s = detail::check_increasing(parameters); !s) return s.error();
  if (closed && distance(points[count - 1], points[0]) <= tolerances::kJointRelativeGap * scale_of(points))
    return Error{"the last point of a closed curve repeats the first (point " + std::to_string(count - 1) +
                 "); the closing segment is added by itself, drop the repeated point"};

  const int d = points.dimension();
  const std::size_t ud = static_cast<std::size_t>(d);
  // Point and tangent j of the segment ends: the closed curve ends where it starts.
  auto point = [&](std::size_t j) { return points[j == count ? 0 : j]; };
  auto tangent = [&](std::size_t j) { return tangents[j == count ? 0 : j]; };

  std::vector<double> knots;
  knots.reserve(2 * segments + 6);
  knots.insert(knots.end(), 4, parameters[0]);
  for (std::size_t i = 1; i < segments; ++i) knots.insert(knots.end(), 2, parameters[i]);
  knots.insert(knots.end(), 4, parameters[segments]);

  std::vector<double> coordinates;
  coordinates.reserve((2 * segments + 2) * ud);
  const auto first = point(0);
  coordinates.insert(coordinates.end(), first.begin(), first.end());
  for (std::size_t i = 0; i < segments; ++i) {
    const double third = (parameters[i + 1] - parameters[i]) / 3.0;
    const auto p0 = point(i), t0 = tangent(i), p1 = point(i + 1), t1 = tangent(i + 1);
    for (std::size_t k = 0; k < ud; ++k) coordinates.push_back(p0[k] + third * t0[k]);
    for (std::size_t k = 0; k < ud; ++k) coordinates.push_back(p1[k] - third * t1[k]);
  }
  const auto last = point(segments);
  coordinates.insert(coordinates.end(), last.begin(), last.end());
  for (std::size_t k = 0; k < coordinates.size(); ++k)
    if (!std::isfinite(coordinates[k]))
      return Error{"a Bézier point of segment " + std::to_string(k / ud == 0 ? 0 : (k / ud - 1) / 2) +
                   " overflows (tangents times parameter steps too large)"};
  if (coordinates.size() / ud > tolerances::kMaxControlPoints)
    return Error{"Hermite interpolation of " + std::to_string(count) + " points needs more than " +
                 std::to_string(tolerances::kMaxControlPoints) + " control points", ErrorKind::limit};
  return BSplineCurve::from_trusted(3, std::move(knots), PointArray::from_trusted(d, std::move(coordinates)));
}

}  // namespace casteljau

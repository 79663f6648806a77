// Catmull–Rom splines: Barry–Goldman tangents, then the cubic Hermite
// interpolant (see catmull_rom.hpp for the formulas and sources).
#include "casteljau/interpolation/catmull_rom.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/interpolation/hermite.hpp"
#include "../core/number_text.hpp"
#include "input_checks.hpp"

namespace casteljau {

Expected<BSplineCurve> interpolate_catmull_rom(const PointArray& points, std::span<const double> parameters,
                                               Closure closure) {
  const bool closed = closure == Closure::closed;
  const std::size_t count = points.size();
  const std::size_t needed = closed ? 3 : 2;
  if (count < needed)
    return Error{std::string(closed ? "a closed " : "") + "Catmull-Rom spline needs at least " +
                 std::to_string(needed) + " points, got " + std::to_string(count)};
  const std::size_t segments = closed ? count : count - 1;
  if (parameters.size() != segments + 1)
    return Error{"a Catmull-Rom spline through " + std::to_string(count) +
                 (closed ? " points (closed)" : " points") + " needs " + std::to_string(segments + 1) +
                 " parameter values, got " + std::to_string(parameters.size())};
  // The tangents divide by the steps: check them here, before interpolate_hermite checks the rest.
  if (auto increasing = detail::check_increasing(parameters); !increasing) return increasing.error();

  const std::size_t d = static_cast<std::size_t>(points.dimension());
  if (auto finite = detail::check_coordinates(points); !finite) return finite.error();
  // Step j runs from point j to point j+1 (cyclically when closed).
  auto step = [&](std::size_t j) { return parameters[j + 1] - parameters[j]; };
  auto point = [&](std::size_t j) { return points[j == count ? 0 : j]; };
  std::vector<double> tangents(count * d);
  for (std::size_t i = 0; i < count; ++i) {
    double* tangent = tangents.data() + i * d;
    const bool has_previous = closed || i > 0;
    const bool has_next = closed || i + 1 < count;
    if (!has_previous || !has_next) {
      // Open end: the reflected phantom point makes both differences equal,
      // so the tangent is the one-sided difference over the end step.
      const std::size_t a = has_next ? i : i - 1;
      const double h = step(a);
      const auto p = point(a), q = point(a + 1);
      for (std::size_t k = 0; k < d; ++k) tangent[k] = (q[k] - p[k]) / h;
      continue;
    }
    const std::size_t previous = i == 0 ? count - 1 : i - 1;  // step index and point index coincide
    const double h0 = step(previous), h1 = step(i);
    const auto p0 = point(previous), p1 = point(i), p2 = point(i + 1);
    // Weighted mean of the two difference quotients: no cancellation between
    // the three terms of the pyramid form when the steps differ widely.
    const double w0 = h1 / (h0 + h1), w1 = h0 / (h0 + h1);
    for (std::size_t k = 0; k < d; ++k)
      tangent[k] = w0 * ((p1[k] - p0[k]) / h0) + w1 * ((p2[k] - p1[k]) / h1);
  }
  for (std::size_t j = 0; j < tangents.size(); ++j)
    if (!std::isfinite(tangents[j]))
      return Error{"the tangent at point " + std::to_string(j / d) +
                   " overflows (parameter steps too small for the distances between points)"};
  return interpolate_hermite(points, PointArray::from_trusted(points.dimension(), std::move(tangents)), parameters,
                             closure);
}

}  // namespace casteljau

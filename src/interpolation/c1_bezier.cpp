// Seed 000's C¹ curve of cubic Bézier pieces (formulas in c1_bezier.hpp).
#include "casteljau/interpolation/c1_bezier.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "input_checks.hpp"

namespace casteljau {

Expected<PiecewiseBezierCurve> interpolate_c1_bezier(const PointArray& points, double alpha, Closure closure) {
  const bool closed = closure == Closure::closed;
  const std::size_t count = points.size();
  const std::size_t needed = closed ? 3 : 2;
  if (count < needed)
    return Error{std::string(closed ? "a closed " : "") + "c1-bezier curve needs at least " +
                 std::to_string(needed) + " points, got " + std::to_string(count)};
  if (!std::isfinite(alpha) || !(alpha > 0.0))
    return Error{"alpha is " + detail::number_text(alpha) + ", it must be finite and > 0"};
  const std::size_t d = static_cast<std::size_t>(points.dimension());
  if (auto finite = detail::check_coordinates(points); !finite) return finite.error();
  if (closed && distance(points[count - 1], points[0]) <= tolerances::kJointRelativeGap * scale_of(points))
    return Error{"the last point of a closed curve repeats the first (point " + std::to_string(count - 1) +
                 "); the closing piece is added by itself, drop the repeated point"};

  const double three_alpha = 3.0 * alpha;
  const std::size_t pieces = closed ? count : count - 1;
  auto point = [&](std::size_t j) { return points[j % count]; };
  // (P_{i+1} − P_{i−1})/(3α), the offset of Q_i from P_i and of P_i from R_{i−1};
  // at an open end the seed's one-sided 2(P_1 − P_0)/(3α), 2(P_m − P_{m−1})/(3α).
  auto offset = [&](std::size_t i, std::size_t k) {
    if (!closed && i == 0) return 2.0 * (point(1)[k] - point(0)[k]) / three_alpha;
    if (!closed && i == count - 1) return 2.0 * (point(i)[k] - point(i - 1)[k]) / three_alpha;
    return (point(i + 1)[k] - point(i + count - 1)[k]) / three_alpha;
  };
  std::vector<BezierCurve> result;
  result.reserve(pieces);
  for (std::size_t i = 0; i < pieces; ++i) {
    std::vector<double> control(4 * d);
    const auto p0 = point(i), p1 = point(i + 1);
    for (std::size_t k = 0; k < d; ++k) {
      control[k] = p0[k];
      control[d + k] = p0[k] + offset(i, k);
      control[2 * d + k] = p1[k] - offset((i + 1) % count, k);
      control[3 * d + k] = p1[k];
    }
    for (std::size_t j = 0; j < control.size(); ++j)
      if (!std::isfinite(control[j]))
        return Error{"control point " + std::to_string(j / d) + " of piece " + std::to_string(i) +
                     " overflows (alpha too small for the coordinates)"};
    result.push_back(BezierCurve::from_trusted(PointArray::from_trusted(static_cast<int>(d), std::move(control))));
  }
  return PiecewiseBezierCurve::make(std::move(result));
}

}  // namespace casteljau

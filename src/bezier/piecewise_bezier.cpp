#include "casteljau/bezier/piecewise_bezier.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "casteljau/bezier/evaluate.hpp"

namespace casteljau {

Expected<PiecewiseBezierCurve> PiecewiseBezierCurve::make(std::vector<BezierCurve> pieces) {
  if (pieces.empty()) return Error{"a piecewise Bézier curve needs at least one piece"};
  for (std::size_t i = 1; i < pieces.size(); ++i)
    if (pieces[i].dimension() != pieces[0].dimension())
      return Error{"piece " + std::to_string(i) + " has dimension " + std::to_string(pieces[i].dimension()) +
                   ", piece 0 has " + std::to_string(pieces[0].dimension())};
  return PiecewiseBezierCurve(std::move(pieces));
}

std::pair<int, double> locate(const PiecewiseBezierCurve& curve, double u) {
  const int m = curve.size();
  // Clamped as a double first: converting a double beyond int's range to int
  // is undefined behaviour, and extrapolation accepts any finite u.
  const int i = static_cast<int>(std::clamp(std::floor(u), 0.0, static_cast<double>(m - 1)));
  return {i, u - i};
}

Point point_at(const PiecewiseBezierCurve& curve, double u) {
  const auto [i, t] = locate(curve, u);
  return point_at(curve.pieces()[i], t);
}

Point derivative_at(const PiecewiseBezierCurve& curve, double u, int order) {
  const auto [i, t] = locate(curve, u);
  return derivative_at(curve.pieces()[i], t, order);
}

void points_at(const PiecewiseBezierCurve& curve, std::span<const double> us, std::span<double> out) {
  const std::size_t d = curve.dimension();
  assert(out.size() == us.size() * d);
  for (std::size_t k = 0; k < us.size(); ++k) {
    const auto [i, t] = locate(curve, us[k]);
    points_at(curve.pieces()[i], std::span<const double>(&t, 1), out.subspan(k * d, d));
  }
}

}  // namespace casteljau

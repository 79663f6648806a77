#include "casteljau/render/figure.hpp"

#include <array>

namespace casteljau::render {

Color cycle_color(int index) {
  // matplotlib's "tab10" (Tableau 10), the default property cycle.
  static constexpr std::array<Color, 10> tab10{{{31, 119, 180},
                                                {255, 127, 14},
                                                {44, 160, 44},
                                                {214, 39, 40},
                                                {148, 103, 189},
                                                {140, 86, 75},
                                                {227, 119, 194},
                                                {127, 127, 127},
                                                {188, 189, 34},
                                                {23, 190, 207}}};
  const int i = ((index % 10) + 10) % 10;
  return tab10[static_cast<std::size_t>(i)];
}

Stroke solid(Color color, double width_points) {
  return Stroke{color, width_points * kPixelsPerPoint, {}};
}

Stroke dashed(Color color, double width_points) {
  // matplotlib's lines.dashed_pattern (3.7, 1.6), scaled by the line width.
  const double w = width_points * kPixelsPerPoint;
  return Stroke{color, w, {3.7 * w, 1.6 * w}};
}

Stroke dotted(Color color, double width_points) {
  // matplotlib's lines.dotted_pattern (1, 1.65), scaled by the line width.
  const double w = width_points * kPixelsPerPoint;
  return Stroke{color, w, {1.0 * w, 1.65 * w}};
}

std::vector<Vec2> plane_points(const PointArray& points) {
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto p = points[i];
    out.push_back(Vec2{{p[0], p.size() >= 2 ? p[1] : 0.0}});
  }
  return out;
}

Expected<BezierCurve> plane_curve(const BezierCurve& curve) {
  const int d = curve.dimension();
  if (d == 2) return curve;
  const auto& p = curve.control_points();
  const int n = curve.degree();
  std::vector<double> coordinates;
  coordinates.reserve(2 * p.size());
  if (d == 1) {
    if (curve.is_rational())
      return Error{"cannot plot a rational curve of dimension 1 (its graph is not a Bézier curve with points (k/n, x_k))"};
    for (int k = 0; k <= n; ++k) {
      coordinates.push_back(n == 0 ? 0.0 : static_cast<double>(k) / n);
      coordinates.push_back(p[static_cast<std::size_t>(k)][0]);
    }
    return BezierCurve::from_trusted(PointArray::from_trusted(2, std::move(coordinates)));
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    coordinates.push_back(p[i][0]);
    coordinates.push_back(p[i][1]);
  }
  return BezierCurve::from_trusted(PointArray::from_trusted(2, std::move(coordinates)),
                                   std::vector<double>(curve.weights().begin(), curve.weights().end()));
}

}  // namespace casteljau::render

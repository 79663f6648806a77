#include "casteljau/bezier/construction.hpp"

#include "de_casteljau.hpp"

namespace casteljau {

std::vector<PointArray> casteljau_construction(const BezierCurve& curve, double t) {
  const bool rational = curve.is_rational();
  const PointArray points = rational ? homogeneous_points(curve) : curve.control_points();
  const int width = points.dimension(), n = curve.degree(), d = curve.dimension();
  std::vector<double> rows(points.coordinates().begin(), points.coordinates().end());
  auto level = [&](int count) {
    std::vector<double> coords;
    coords.reserve(static_cast<std::size_t>(count) * d);
    for (int i = 0; i < count; ++i)
      for (int j = 0; j < d; ++j) coords.push_back(rational ? rows[i * width + j] / rows[i * width + d] : rows[i * width + j]);
    return PointArray::from_trusted(d, std::move(coords));
  };
  std::vector<PointArray> levels;
  levels.push_back(level(n + 1));
  const double s = 1.0 - t;
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i)
      for (int j = 0; j < width; ++j)
        rows[i * width + j] = detail::lerp_step(rows[i * width + j], rows[(i + 1) * width + j], s, t);
    levels.push_back(level(n + 1 - r));
  }
  return levels;
}

}  // namespace casteljau

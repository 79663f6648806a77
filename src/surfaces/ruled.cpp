// Ruled surfaces between two curves made compatible (The NURBS Book §10.3).
#include "casteljau/surfaces/ruled.hpp"

#include <cstddef>
#include <vector>

#include "casteljau/surfaces/compatible_curves.hpp"

namespace casteljau {

Expected<BSplineSurface> ruled_surface(const BSplineCurve& first, const BSplineCurve& second) {
  const BSplineCurve pair[2] = {first, second};
  auto compatible = make_compatible(pair);
  if (!compatible) return compatible.error();
  const BSplineCurve& c0 = (*compatible)[0];
  const BSplineCurve& c1 = (*compatible)[1];
  const std::size_t rows = c0.control_points().size();
  const int d = c0.dimension();
  const bool rational = c0.is_rational();
  std::vector<double> coordinates;
  coordinates.reserve(rows * 2 * static_cast<std::size_t>(d));
  std::vector<double> weights;
  for (std::size_t i = 0; i < rows; ++i) {
    for (const BSplineCurve* curve : {&c0, &c1}) {
      const auto point = curve->control_points()[i];
      coordinates.insert(coordinates.end(), point.begin(), point.end());
      if (rational) weights.push_back(curve->weights()[i]);
    }
  }
  const auto knots = c0.knots();
  return BSplineSurface::from_trusted(c0.degree(), 1, std::vector<double>(knots.begin(), knots.end()),
                                      {0.0, 0.0, 1.0, 1.0},
                                      ControlNet::from_trusted(rows, 2, PointArray::from_trusted(d, std::move(coordinates))),
                                      std::move(weights));
}

}  // namespace casteljau

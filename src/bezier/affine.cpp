#include "casteljau/bezier/affine.hpp"

#include <cassert>
#include <cmath>
#include <string>

#include "casteljau/core/precondition.hpp"

namespace casteljau {

Expected<AffineMap> AffineMap::make(int dimension, std::vector<double> linear, std::vector<double> translation) {
  if (dimension < 1) return Error{"affine map dimension " + std::to_string(dimension) + " is not >= 1"};
  const std::size_t d = dimension;
  if (linear.size() != d * d)
    return Error{"the linear part has " + std::to_string(linear.size()) + " entries, a " + std::to_string(d) + "x" +
                 std::to_string(d) + " matrix needs " + std::to_string(d * d)};
  if (translation.size() != d)
    return Error{"the translation has " + std::to_string(translation.size()) + " entries, expected " + std::to_string(d)};
  for (std::size_t i = 0; i < linear.size(); ++i)
    if (auto ok = check_finite(linear[i], "entry " + std::to_string(i) + " of the linear part"); !ok) return ok.error();
  for (std::size_t i = 0; i < d; ++i)
    if (auto ok = check_finite(translation[i], "entry " + std::to_string(i) + " of the translation"); !ok) return ok.error();
  return AffineMap{dimension, std::move(linear), std::move(translation)};
}

AffineMap AffineMap::identity(int dimension) { return scale(dimension, 1.0); }

AffineMap AffineMap::translate(std::vector<double> offset) {
  const int d = static_cast<int>(offset.size());
  AffineMap map = identity(d);
  map.translation = std::move(offset);
  return map;
}

AffineMap AffineMap::scale(int dimension, double factor) {
  assert(dimension >= 1);
  AffineMap map{dimension, std::vector<double>(dimension * dimension, 0.0), std::vector<double>(dimension, 0.0)};
  for (int i = 0; i < dimension; ++i) map.linear[i * dimension + i] = factor;
  return map;
}

AffineMap AffineMap::rotate_2d(double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return AffineMap{2, {c, -s, s, c}, {0.0, 0.0}};
}

AffineMap AffineMap::after(const AffineMap& first) const {
  detail::require(first.dimension == dimension, "AffineMap::after", "both maps must have one dimension");
  const int d = dimension;
  AffineMap result{d, std::vector<double>(d * d, 0.0), transformed_point(*this, first.translation)};
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      for (int k = 0; k < d; ++k) result.linear[i * d + j] += linear[i * d + k] * first.linear[k * d + j];
  return result;
}

Point transformed_point(const AffineMap& map, std::span<const double> x) {
  const int d = map.dimension;
  detail::require(static_cast<int>(x.size()) == d, "transformed_point", "x must have the map's dimension");
  Point y(map.translation.begin(), map.translation.end());
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) y[i] += map.linear[i * d + j] * x[j];
  return y;
}

Expected<PointArray> transformed_points(const AffineMap& map, const PointArray& points) {
  if (map.dimension != points.dimension())
    return Error{"the affine map acts on R^" + std::to_string(map.dimension) + ", the curve lives in R^" +
                 std::to_string(points.dimension())};
  PointArray result = PointArray::zeros(points.dimension(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) result.push_back(transformed_point(map, points[i]));
  return result;
}

Expected<BezierCurve> transformed(const BezierCurve& curve, const AffineMap& map) {
  auto points = transformed_points(map, curve.control_points());
  if (!points) return points.error();
  std::vector<double> weights(curve.weights().begin(), curve.weights().end());
  return BezierCurve::make(std::move(*points), std::move(weights));
}

}  // namespace casteljau

#include "casteljau/core/point_array.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace casteljau {

Status check_finite(double value, const std::string& what) {
  if (std::isnan(value)) return Error{what + " is NaN"};
  if (std::isinf(value)) return Error{what + " is infinite"};
  return {};
}

Expected<PointArray> PointArray::make(int dimension, std::vector<double> coordinates,
                                      const char* what) {
  if (dimension < 1) return Error{"dimension " + std::to_string(dimension) + " is not >= 1"};
  if (coordinates.size() % static_cast<std::size_t>(dimension) != 0) {
    return Error{std::to_string(coordinates.size()) + " coordinates do not make whole " +
                 std::to_string(dimension) + "-dimensional " + what + "s"};
  }
  for (std::size_t k = 0; k < coordinates.size(); ++k) {
    const std::size_t i = k / dimension, j = k % dimension;
    if (auto ok = check_finite(coordinates[k], "coordinate " + std::to_string(j) + " of " + what +
                                                   " " + std::to_string(i));
        !ok) {
      return ok.error();
    }
  }
  return PointArray(dimension, std::move(coordinates));
}

Expected<PointArray> PointArray::make(const std::vector<std::vector<double>>& rows,
                                      const char* what) {
  // No row gives no dimension: an empty set is made with its dimension,
  // make(d, {}), so that what is later added to it or built on it knows d.
  if (rows.empty())
    return Error{std::string("no ") + what + "s: an empty set has no dimension (make(dimension, {}) makes one)",
                 ErrorKind::invalid_argument};
  const std::size_t d = rows.front().size();
  if (d == 0) return Error{std::string(what) + " 0 has no coordinates"};
  std::vector<double> flat;
  flat.reserve(rows.size() * d);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].size() != d) {
      return Error{std::string(what) + " " + std::to_string(i) + " has " +
                   std::to_string(rows[i].size()) + " coordinates, " + what + " 0 has " +
                   std::to_string(d)};
    }
    flat.insert(flat.end(), rows[i].begin(), rows[i].end());
  }
  return make(static_cast<int>(d), std::move(flat), what);
}

PointArray PointArray::from_trusted(int dimension, std::vector<double> coordinates) {
  assert(dimension >= 1 && coordinates.size() % dimension == 0);
  return PointArray(dimension, std::move(coordinates));
}

PointArray PointArray::zeros(int dimension, std::size_t count) {
  assert(dimension >= 1);
  return PointArray(dimension, std::vector<double>(count * dimension, 0.0));
}

void PointArray::push_back(std::span<const double> point) {
  assert(static_cast<int>(point.size()) == dimension_);
  coordinates_.insert(coordinates_.end(), point.begin(), point.end());
}

double scale_of(const PointArray& points) {
  double scale = 0.0;
  for (double c : points.coordinates()) scale = std::max(scale, std::abs(c));
  return scale;
}

double distance(std::span<const double> a, std::span<const double> b) {
  assert(a.size() == b.size());
  // Scaled sum of squares: no overflow or underflow for extreme coordinates.
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(a[i] - b[i]));
  if (largest == 0.0 || !std::isfinite(largest)) return largest;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double r = (a[i] - b[i]) / largest;
    sum += r * r;
  }
  return largest * std::sqrt(sum);
}

}  // namespace casteljau

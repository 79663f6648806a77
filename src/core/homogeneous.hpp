#pragma once
// Homogeneous coordinates of weighted control points (The NURBS Book §4.2):
// P_i with weight w_i is the point (w_i P_i, w_i) of R^(d+1). Rational
// Bézier and B-spline curves both go through these two conversions.
// Internal to src/.

#include <cassert>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "casteljau/core/point_array.hpp"

namespace casteljau::detail {

/// (w_i P_i, w_i) for each point; w_i = 1 when `weights` is empty.
inline PointArray weighted_rows(const PointArray& points, std::span<const double> weights) {
  const int d = points.dimension();
  std::vector<double> h;
  h.reserve(points.size() * static_cast<std::size_t>(d + 1));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    for (double c : points[i]) h.push_back(w * c);
    h.push_back(w);
  }
  return PointArray::from_trusted(d + 1, std::move(h));
}

/// The inverse: points P_i = (first d coordinates) / w_i and weights w_i
/// (the last coordinate, asserted > 0).
inline std::pair<PointArray, std::vector<double>> projected_rows(const PointArray& rows) {
  const int d = rows.dimension() - 1;
  assert(d >= 1);
  std::vector<double> p;
  std::vector<double> w;
  p.reserve(rows.size() * static_cast<std::size_t>(d));
  w.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto row = rows[i];
    const double weight = row[static_cast<std::size_t>(d)];
    assert(weight > 0.0);
    for (int j = 0; j < d; ++j) p.push_back(row[static_cast<std::size_t>(j)] / weight);
    w.push_back(weight);
  }
  return {PointArray::from_trusted(d, std::move(p)), std::move(w)};
}

}  // namespace casteljau::detail

#pragma once
// The nearest point among several curves (a drawing's): for each query, which
// curve holds the point nearest to it, and that point. Each curve's bounding
// box (ops/bounds.hpp) bounds its distance from below, so the curves are
// visited nearest box first and the rest skipped once a box is farther than
// the best answer: a query near one element of a drawing of thousands
// measures a handful. Each curve's answer is closest_point's (ops/closest_point.hpp).

#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/ops/closest_point.hpp"

namespace casteljau {

/// The nearest point among curves: the curve's index in the list given, and
/// its nearest point (parameter in that curve's domain, distance, point).
struct NearestAmongCurves {
  std::size_t curve = 0;
  NearestPoint nearest;
};

/// For each of the n queries (n x d values, row-major), the nearest point of
/// all the curves: the global minimum of the distance over every curve, the
/// curve with the smallest index where two are equally near. Errors: no
/// curve, curves of different dimensions ("curve 3 lives in R^3, curve 0 in
/// R^2"), queries not a whole number of points of the curves' dimension, and
/// closest_point's (a coordinate not finite or too large: the query named).
Expected<std::vector<NearestAmongCurves>> closest_among_curves(std::span<const CurveView> curves,
                                                               std::span<const double> queries);

}  // namespace casteljau

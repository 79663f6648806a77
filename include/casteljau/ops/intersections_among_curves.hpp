#pragma once
// Every intersection within a set of curves (a drawing's): between every two
// of them and of each with itself. A sweep over the curves' bounding boxes
// (sorted by their lower x, each compared with the boxes still open: the
// "sort and sweep" of collision detection, D. Baraff, PhD thesis, Cornell
// 1992) finds the pairs whose boxes meet, in O(n log n + pairs) for n
// curves; only those are intersected (ops/intersection.hpp).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/ops/intersection.hpp"

namespace casteljau {

/// One intersection of a set: the indices of its two curves (a <= b; a == b
/// for a self-intersection) and the intersection as intersections() or
/// self_intersections() report it, its parameters on curves a and b.
struct IntersectionAmongCurves {
  std::size_t a = 0;
  std::size_t b = 0;
  CurveIntersection intersection;
};

/// Every intersection of every two curves of the list and every
/// self-intersection of each, sorted by (a, b, parameter on a). `tolerance`:
/// as intersections() takes it, the same for every pair; none: each pair's
/// default_intersection_tolerance (1e-9 of the larger curve's size). Boxes
/// are widened by the tolerance (and tolerances::kBoxRoundingMargin) before
/// they are compared, so curves that come within it are intersected.
/// Errors: curves of different dimensions or in R^1 (named), and those of
/// intersections() with the curves named ("curves 2 and 5: ...").
Expected<std::vector<IntersectionAmongCurves>> intersections_among_curves(std::span<const CurveView> curves,
                                                                          std::optional<Tolerance> tolerance);

}  // namespace casteljau

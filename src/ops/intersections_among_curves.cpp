// Every intersection within a set of curves (ops/intersections_among_curves.hpp):
// sort and sweep on the bounding boxes, then the pairs whose boxes meet.
#include "casteljau/ops/intersections_among_curves.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>

#include "casteljau/ops/bounds.hpp"

namespace casteljau {

Expected<std::vector<IntersectionAmongCurves>> intersections_among_curves(std::span<const CurveView> curves,
                                                                          std::optional<Tolerance> tolerance) {
  std::vector<IntersectionAmongCurves> found;
  if (curves.empty()) return found;
  const std::size_t d = static_cast<std::size_t>(curves.front().dimension());
  for (std::size_t c = 0; c < curves.size(); ++c) {
    if (curves[c].dimension() < 2)
      return Error{"intersections need curves in R^2 or more, curve " + std::to_string(c) + " lives in R^" +
                   std::to_string(curves[c].dimension())};
    if (static_cast<std::size_t>(curves[c].dimension()) != d)
      return Error{"intersections need curves in one space, curve " + std::to_string(c) + " lives in R^" +
                   std::to_string(curves[c].dimension()) + ", curve 0 in R^" + std::to_string(d)};
  }
  if (tolerance && !(std::isfinite(tolerance->distance) && tolerance->distance > 0.0))
    return Error{"the intersection tolerance must be a finite distance > 0"};

  // Each box widened by the distance within which its curve meets another
  // (the pair's default is the larger of the two curves' own).
  std::vector<Box> boxes;
  boxes.reserve(curves.size());
  for (const CurveView& curve : curves)
    boxes.push_back(
        pruning_box(curve, tolerance ? tolerance->distance : default_intersection_tolerance(curve, curve).distance));

  const auto add = [&](std::size_t a, std::size_t b, Expected<std::vector<CurveIntersection>> result) -> Status {
    if (!result)
      return with_context(result.error(), a == b ? "curve " + std::to_string(a)
                                                 : "curves " + std::to_string(a) + " and " + std::to_string(b));
    for (CurveIntersection& x : *result) found.push_back(IntersectionAmongCurves{a, b, std::move(x)});
    return {};
  };
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const Tolerance own = tolerance ? *tolerance : default_intersection_tolerance(curves[c], curves[c]);
    if (Status status = add(c, c, self_intersections(curves[c], own)); !status) return status.error();
  }

  // Sort and sweep on x: a box opens at its lower x, and meets the boxes still open whose other coordinates overlap.
  std::vector<std::size_t> order(curves.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return std::tie(boxes[i].lower[0], i) < std::tie(boxes[j].lower[0], j);
  });
  std::vector<std::size_t> open;
  for (const std::size_t i : order) {
    std::erase_if(open, [&](std::size_t j) { return boxes[j].upper[0] < boxes[i].lower[0]; });
    for (const std::size_t j : open) {
      bool meet = true;
      for (std::size_t k = 1; k < d && meet; ++k)
        meet = boxes[i].lower[k] <= boxes[j].upper[k] && boxes[j].lower[k] <= boxes[i].upper[k];
      if (!meet) continue;
      const std::size_t a = std::min(i, j), b = std::max(i, j);
      const Tolerance pair = tolerance ? *tolerance : default_intersection_tolerance(curves[a], curves[b]);
      if (Status status = add(a, b, intersections(curves[a], curves[b], pair)); !status) return status.error();
    }
    open.push_back(i);
  }
  std::sort(found.begin(), found.end(), [](const IntersectionAmongCurves& x, const IntersectionAmongCurves& y) {
    return std::tie(x.a, x.b, x.intersection.a.lower, x.intersection.b.lower) <
           std::tie(y.a, y.b, y.intersection.a.lower, y.intersection.b.lower);
  });
  return found;
}

}  // namespace casteljau

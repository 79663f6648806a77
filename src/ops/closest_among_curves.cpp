// The nearest point among several curves (ops/closest_among_curves.hpp):
// curves visited by the distance of their bounding boxes, nearest first.
#include "casteljau/ops/closest_among_curves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "casteljau/ops/bounds.hpp"

namespace casteljau {
namespace {

/// The distance from q to the box (0 inside it): no point of a curve inside
/// the box is nearer.
double distance_to_box(const Box& box, std::span<const double> q) {
  double squared = 0.0;
  for (std::size_t j = 0; j < q.size(); ++j) {
    const double below = box.lower[j] - q[j], above = q[j] - box.upper[j];
    const double gap = std::max({below, above, 0.0});
    squared += gap * gap;
  }
  return std::sqrt(squared);
}

}  // namespace

Expected<std::vector<NearestAmongCurves>> closest_among_curves(std::span<const CurveView> curves,
                                                               std::span<const double> queries) {
  if (curves.empty()) return Error{"the nearest point among curves needs at least one curve"};
  const std::size_t d = static_cast<std::size_t>(curves.front().dimension());
  for (std::size_t c = 1; c < curves.size(); ++c)
    if (static_cast<std::size_t>(curves[c].dimension()) != d)
      return Error{"curve " + std::to_string(c) + " lives in R^" + std::to_string(curves[c].dimension()) +
                   ", curve 0 in R^" + std::to_string(d)};
  if (queries.size() % d != 0)
    return Error{std::to_string(queries.size()) + " query coordinates are not whole points of R^" + std::to_string(d)};
  std::vector<Box> boxes;
  boxes.reserve(curves.size());
  for (const CurveView& curve : curves) boxes.push_back(pruning_box(curve, 0.0));

  std::vector<NearestAmongCurves> answers;
  std::vector<std::pair<double, std::size_t>> order(curves.size());
  for (std::size_t i = 0; i * d < queries.size(); ++i) {
    const std::span<const double> q = queries.subspan(i * d, d);
    for (std::size_t c = 0; c < curves.size(); ++c) order[c] = {distance_to_box(boxes[c], q), c};
    std::sort(order.begin(), order.end());
    NearestAmongCurves best;
    best.nearest.distance = std::numeric_limits<double>::infinity();
    bool found = false;
    for (const auto& [bound, c] : order) {
      if (found && bound > best.nearest.distance) break;  // every box left is farther than the answer
      auto nearest = closest_point(curves[c], q);
      if (!nearest) return with_context(nearest.error(), "query " + std::to_string(i));
      if (!found || nearest->distance < best.nearest.distance ||
          (nearest->distance == best.nearest.distance && c < best.curve)) {
        best = NearestAmongCurves{c, std::move(*nearest)};
        found = true;
      }
    }
    answers.push_back(std::move(best));
  }
  return answers;
}

}  // namespace casteljau

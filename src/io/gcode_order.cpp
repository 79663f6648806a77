// The cutting order of a toolpath (io/gcode_order.hpp): greedy nearest
// neighbour over a k-d tree of entry points, 2-opt on neighbour lists, closed
// contours rotated to their best joint.
#include "casteljau/io/gcode_order.hpp"

#include <algorithm>
#include <cstddef>
#include <deque>
#include <initializer_list>
#include <limits>
#include <utility>

#include "casteljau/io/tolerance.hpp"

namespace casteljau {

bool contour_is_closed(const GcodeContour& contour, Tolerance tolerance) {
  return !contour.empty() && distance(contour.front().start, contour.back().end) <= tolerance.distance;
}

GcodeContour reversed_contour(const GcodeContour& contour) {
  GcodeContour out;
  out.reserve(contour.size());
  for (auto it = contour.rbegin(); it != contour.rend(); ++it) out.push_back(ArcSegment{it->end, it->start, -it->bulge});
  return out;
}

Vec2 contour_exit(const GcodeContour& contour, Tolerance tolerance, int passes) {
  return contour_is_closed(contour, tolerance) || passes % 2 == 0 ? contour.front().start : contour.back().end;
}

double rapid_length_of(std::span<const GcodeContour> order, Tolerance tolerance, int passes) {
  Vec2 tool{};
  double length = 0.0;
  for (const GcodeContour& contour : order) {
    if (contour.empty()) continue;
    length += distance(tool, contour.front().start);
    tool = contour_exit(contour, tolerance, passes);
  }
  return length;
}

namespace {

double squared_distance(Vec2 a, Vec2 b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

/// Points of the plane, each known by its index in the list it was built
/// from, for nearest-point queries while points are taken out: a k-d tree
/// (Bentley 1975) in one array, the node of the range [lo, hi) at its middle,
/// the median of the range on the axis where the range spreads most. Every
/// node counts the points its range still holds, so a query skips emptied
/// subtrees and a removal costs one walk from the root.
class PointIndex {
 public:
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

  explicit PointIndex(std::span<const Vec2> points)
      : nodes_(points.size()), live_(points.size()), slot_(points.size()), removed_(points.size(), false) {
    for (std::size_t k = 0; k < points.size(); ++k) nodes_[k] = Node{points[k], k, 0};
    build(0, nodes_.size());
    for (std::size_t k = 0; k < nodes_.size(); ++k) slot_[nodes_[k].id] = k;
  }

  /// The index of a nearest point still held, the lowest of equally near
  /// ones, or `none` when empty.
  std::size_t nearest(Vec2 query) const {
    double bound = std::numeric_limits<double>::infinity();
    std::size_t best = none;
    auto offer = [&](double squared, std::size_t id) {
      if (squared < bound || id < best) {
        bound = squared;
        best = id;
      }
    };
    search(0, nodes_.size(), query, bound, offer);
    return best;
  }

  /// The indices of the `count` nearest points still held (fewer when it
  /// holds fewer), nearest first, the lowest index first among equally near.
  std::vector<std::size_t> nearest(Vec2 query, std::size_t count) const {
    std::vector<std::pair<double, std::size_t>> found;
    double bound = count == 0 ? 0.0 : std::numeric_limits<double>::infinity();
    auto offer = [&](double squared, std::size_t id) {
      if (found.size() == count && !(std::pair{squared, id} < found.back())) return;
      found.insert(std::upper_bound(found.begin(), found.end(), std::pair{squared, id}), std::pair{squared, id});
      if (found.size() > count) found.pop_back();
      if (found.size() == count) bound = found.back().first;
    };
    search(0, nodes_.size(), query, bound, offer);
    std::vector<std::size_t> ids;
    for (const auto& [squared, id] : found) ids.push_back(id);
    return ids;
  }

  /// Takes the point out (nothing if it is out already).
  void remove(std::size_t id) {
    if (removed_[id]) return;
    removed_[id] = true;
    const std::size_t slot = slot_[id];
    std::size_t lo = 0, hi = nodes_.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      --live_[mid];
      if (slot == mid) return;
      if (slot < mid) {
        hi = mid;
      } else {
        lo = mid + 1;
      }
    }
  }

 private:
  struct Node {
    Vec2 point{};
    std::size_t id = 0;
    int axis = 0;
  };

  void build(std::size_t lo, std::size_t hi) {
    if (lo >= hi) return;
    double lower[2] = {nodes_[lo].point[0], nodes_[lo].point[1]}, upper[2] = {lower[0], lower[1]};
    for (std::size_t k = lo; k < hi; ++k)
      for (int axis = 0; axis < 2; ++axis) {
        lower[axis] = std::min(lower[axis], nodes_[k].point[axis]);
        upper[axis] = std::max(upper[axis], nodes_[k].point[axis]);
      }
    const int axis = upper[1] - lower[1] > upper[0] - lower[0] ? 1 : 0;
    const std::size_t mid = lo + (hi - lo) / 2;
    std::nth_element(nodes_.begin() + static_cast<std::ptrdiff_t>(lo), nodes_.begin() + static_cast<std::ptrdiff_t>(mid),
                     nodes_.begin() + static_cast<std::ptrdiff_t>(hi),
                     [axis](const Node& a, const Node& b) { return a.point[axis] < b.point[axis]; });
    nodes_[mid].axis = axis;
    live_[mid] = hi - lo;
    build(lo, mid);
    build(mid + 1, hi);
  }

  /// Offers every held point of [lo, hi) as near as `bound` or nearer (a
  /// squared distance, which `offer` may lower): the side of the query
  /// first, the other only when its splitting line is that near. Points at
  /// the bound are offered for ties to be broken; only exact ties cost more
  /// than a search for the nearer.
  template <class Offer>
  void search(std::size_t lo, std::size_t hi, Vec2 query, double& bound, Offer& offer) const {
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (live_[mid] == 0) return;
      const Node& node = nodes_[mid];
      if (!removed_[node.id]) {
        const double squared = squared_distance(query, node.point);
        if (squared <= bound) offer(squared, node.id);
      }
      const double gap = query[node.axis] - node.point[node.axis];
      if (gap < 0.0) {
        search(lo, mid, query, bound, offer);
        lo = mid + 1;
      } else {
        search(mid + 1, hi, query, bound, offer);
        hi = mid;
      }
      if (!(gap * gap <= bound)) return;
    }
  }

  std::vector<Node> nodes_;
  std::vector<std::size_t> live_;  // points held in the range of the node at this slot
  std::vector<std::size_t> slot_;  // where each point's node is
  std::vector<bool> removed_;
};

/// The diagonal of the box of the points (1 when there are none).
double size_of(std::span<const Vec2> points) {
  if (points.empty()) return 1.0;
  Vec2 lower = points.front(), upper = lower;
  for (const Vec2& p : points)
    for (int k = 0; k < 2; ++k) {
      lower[k] = std::min(lower[k], p[k]);
      upper[k] = std::max(upper[k], p[k]);
    }
  return std::max(distance(lower, upper), 1.0);
}

}  // namespace

std::vector<GcodeContour> nearest_neighbour_order(std::span<const GcodeContour> contours, Tolerance tolerance,
                                                  int passes) {
  // Every way into every contour: a closed one at each joint, an open one at
  // either end; the ways into contour c are first[c] .. first[c + 1] - 1.
  struct Way {
    std::size_t contour = 0;
    std::size_t joint = 0;
    bool backwards = false;
  };
  std::vector<Vec2> points;
  std::vector<Way> ways;
  std::vector<std::size_t> first(contours.size() + 1);
  for (std::size_t c = 0; c < contours.size(); ++c) {
    first[c] = points.size();
    const GcodeContour& contour = contours[c];
    if (contour.empty()) continue;
    if (contour_is_closed(contour, tolerance)) {
      for (std::size_t j = 0; j < contour.size(); ++j) {
        points.push_back(contour[j].start);
        ways.push_back(Way{c, j, false});
      }
    } else {
      points.push_back(contour.front().start);
      ways.push_back(Way{c, 0, false});
      points.push_back(contour.back().end);
      ways.push_back(Way{c, 0, true});
    }
  }
  first[contours.size()] = points.size();
  PointIndex index(points);
  std::vector<GcodeContour> order;
  Vec2 tool{};
  for (std::size_t next = index.nearest(tool); next != PointIndex::none; next = index.nearest(tool)) {
    const Way way = ways[next];
    for (std::size_t k = first[way.contour]; k < first[way.contour + 1]; ++k) index.remove(k);
    GcodeContour entered = way.backwards ? reversed_contour(contours[way.contour]) : contours[way.contour];
    std::rotate(entered.begin(), entered.begin() + static_cast<std::ptrdiff_t>(way.joint), entered.end());
    tool = contour_exit(entered, tolerance, passes);
    order.push_back(std::move(entered));
  }
  return order;
}

void improve_order(std::vector<GcodeContour>& order, Tolerance tolerance, int passes) {
  std::erase_if(order, [](const GcodeContour& contour) { return contour.empty(); });
  const std::size_t n = order.size();
  if (n == 0) return;
  // By contour: where the tool enters and leaves it (swapped when it is run
  // the other way), whether running it the other way reverses it (an open
  // contour cut an odd number of times), and whether it is.
  std::vector<Vec2> entry(n), exit(n);
  std::vector<char> closed(n), reversible(n), flipped(n, 0);
  std::vector<std::size_t> at(n), position(n);  // the contour at a position, the position of a contour
  for (std::size_t c = 0; c < n; ++c) {
    closed[c] = contour_is_closed(order[c], tolerance);
    entry[c] = order[c].front().start;
    exit[c] = contour_exit(order[c], tolerance, passes);
    reversible[c] = !closed[c] && passes % 2 == 1;
    at[c] = position[c] = c;
  }

  // Each contour's nearest contours, by the distance between their ends, and the origin's.
  std::vector<Vec2> ends;
  std::vector<std::size_t> owner;
  for (std::size_t c = 0; c < n; ++c) {
    ends.push_back(entry[c]);
    owner.push_back(c);
    if (exit[c] != entry[c]) {
      ends.push_back(exit[c]);
      owner.push_back(c);
    }
  }
  const PointIndex index(ends);
  const auto nearest_contours = [&](std::initializer_list<Vec2> from, std::size_t self, std::size_t wanted) {
    std::vector<std::pair<double, std::size_t>> found;
    for (const Vec2& p : from)
      for (std::size_t id : index.nearest(p, 2 * wanted + 2))
        if (owner[id] != self) found.emplace_back(squared_distance(p, ends[id]), owner[id]);
    std::sort(found.begin(), found.end());
    std::vector<std::size_t> contours;
    for (const auto& [squared, c] : found)
      if (contours.size() < wanted && std::find(contours.begin(), contours.end(), c) == contours.end())
        contours.push_back(c);
    return contours;
  };
  std::vector<std::vector<std::size_t>> near(n);
  for (std::size_t c = 0; c < n; ++c)
    near[c] = nearest_contours({entry[c], exit[c]}, c, std::min(n - 1, tolerances::kGcodeTwoOptNeighbours));
  // The origin's list may hold every contour (the move that reverses the first one alone starts there).
  const std::vector<std::size_t> near_origin =
      nearest_contours({Vec2{}}, PointIndex::none, std::min(n, tolerances::kGcodeTwoOptNeighbours));

  const auto before = [&](std::size_t i) { return i == 0 ? Vec2{} : exit[at[i - 1]]; };
  // What reversing the run at positions i..j saves: the rapid moves
  // before(i) -> entry(i) and exit(j) -> entry(j + 1) become before(i) ->
  // exit(j) and entry(i) -> entry(j + 1).
  const auto saving = [&](std::size_t i, std::size_t j) {
    const Vec2 a = before(i), b = entry[at[i]], c = exit[at[j]];
    double now = distance(a, b), then = distance(a, c);
    if (j + 1 < n) {
      const Vec2 d = entry[at[j + 1]];
      now += distance(c, d);
      then += distance(b, d);
    }
    return now - then;
  };
  // A saving must beat the rounding of the distances compared.
  const double slack = 1e-12 * size_of(ends);

  std::deque<std::size_t> queue(at.begin(), at.end());
  std::vector<char> queued(n, 1);
  const auto wake = [&](std::size_t i) {
    if (i < n && !queued[at[i]]) {
      queued[at[i]] = 1;
      queue.push_back(at[i]);
    }
  };
  // Tries the moves that make a new rapid move start at before(i) or at
  // entry(i); makes the first that saves, and says whether it did.
  const auto improve_at = [&](std::size_t i) {
    std::pair<std::size_t, std::size_t> tried[4 * tolerances::kGcodeTwoOptNeighbours];
    std::size_t count = 0;
    // A new move before(i) -> exit(j): j is near the contour before i (or the origin).
    for (std::size_t c : i == 0 ? near_origin : near[at[i - 1]]) {
      const std::size_t p = position[c];
      if (p >= i) tried[count++] = {i, p};
      else if (p + 1 < i) tried[count++] = {p + 1, i - 1};
    }
    // A new move entry(i) -> entry(j + 1): j + 1 is near the contour at i.
    for (std::size_t c : near[at[i]]) {
      const std::size_t p = position[c];
      if (p > i) tried[count++] = {i, p - 1};
      else if (p < i) tried[count++] = {p, i - 1};
    }
    for (std::size_t k = 0; k < count; ++k) {
      const auto [s, t] = tried[k];
      if (!(saving(s, t) > slack)) continue;
      std::reverse(at.begin() + static_cast<std::ptrdiff_t>(s), at.begin() + static_cast<std::ptrdiff_t>(t + 1));
      for (std::size_t q = s; q <= t; ++q) {
        const std::size_t c = at[q];
        position[c] = q;
        std::swap(entry[c], exit[c]);
        flipped[c] ^= 1;
      }
      for (std::size_t q : {s - 1, s, t, t + 1}) wake(q);  // s - 1 wraps past n when s = 0
      return true;
    }
    return false;
  };
  while (!queue.empty()) {
    const std::size_t c = queue.front();
    queue.pop_front();
    queued[c] = 0;
    const std::size_t p = position[c];
    if (improve_at(p) || (p + 1 < n && improve_at(p + 1))) wake(position[c]);
  }

  // In turn, each closed contour entered at the joint, and each open one cut
  // an even number of times (back where it started) at the end, that makes
  // the rapid moves to it and on to the next entry shortest.
  for (std::size_t q = 0; q < n; ++q) {
    const std::size_t c = at[q];
    if (reversible[c]) continue;
    GcodeContour& contour = order[c];
    const Vec2 from = before(q);
    const auto cost = [&](Vec2 joint) {
      return distance(from, joint) + (q + 1 < n ? distance(joint, entry[at[q + 1]]) : 0.0);
    };
    if (closed[c]) {
      std::size_t best = 0;
      for (std::size_t j = 1; j < contour.size(); ++j)
        if (cost(contour[j].start) < cost(contour[best].start) - slack) best = j;
      std::rotate(contour.begin(), contour.begin() + static_cast<std::ptrdiff_t>(best), contour.end());
    } else if (cost(contour.back().end) < cost(contour.front().start) - slack) {
      contour = reversed_contour(contour);
    }
    entry[c] = exit[c] = contour.front().start;
  }

  std::vector<GcodeContour> improved;
  improved.reserve(n);
  for (std::size_t q = 0; q < n; ++q) {
    const std::size_t c = at[q];
    improved.push_back(flipped[c] && reversible[c] ? reversed_contour(order[c]) : std::move(order[c]));
  }
  order = std::move(improved);
}

std::vector<GcodeContour> cutting_order(std::span<const GcodeContour> contours, Tolerance tolerance, int passes) {
  std::vector<GcodeContour> order = nearest_neighbour_order(contours, tolerance, passes);
  std::vector<GcodeContour> given;
  for (const GcodeContour& contour : contours)
    if (!contour.empty()) given.push_back(contour);
  // The input's own order is worth improving only when it starts shorter
  // (2-opt from an order far from good spends long reversals).
  const bool try_given =
      rapid_length_of(given, tolerance, passes) < rapid_length_of(order, tolerance, passes);
  improve_order(order, tolerance, passes);
  if (!try_given) return order;
  improve_order(given, tolerance, passes);
  return rapid_length_of(given, tolerance, passes) < rapid_length_of(order, tolerance, passes) ? given : order;
}

}  // namespace casteljau

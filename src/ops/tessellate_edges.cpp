// Shared and collapsed patch edges of a tessellation (tessellate_edges.hpp).
#include "tessellate_edges.hpp"

#include <array>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace casteljau::tessellation {
namespace {

/// Normalized parameters at which two patch edges are compared: both ends
/// and interior values away from simple fractions, so that two edges that
/// agree at a few dyadic points only are not taken for one. Symmetric
/// (s and 1 - s), so that the reversed comparison reads the same list
/// backwards.
constexpr std::array<double, 7> kEdgeSamples = {0.0, 0.1234, 0.3141, 0.5, 0.6859, 0.8766, 1.0};

/// A plain union-find over integers.
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

EdgeStructure analyse_edges(const std::vector<Patch>& patches, double match_distance) {
  const std::size_t sides = patches.size() * 4;
  // Sample points of every side.
  std::vector<std::array<Vec3, kEdgeSamples.size()>> samples(sides);
  for (std::size_t p = 0; p < patches.size(); ++p) {
    for (int k = 0; k < 4; ++k) {
      for (std::size_t i = 0; i < kEdgeSamples.size(); ++i) {
        const auto uv = side_parameters(patches[p].surface, k, kEdgeSamples[i]);
        samples[p * 4 + k][i] = to_vec3(patches[p].surface.point_at(uv[0], uv[1]));
      }
    }
  }
  EdgeStructure edges;
  edges.degenerate.assign(sides, false);
  for (std::size_t a = 0; a < sides; ++a) {
    bool collapsed = true;
    for (const Vec3& point : samples[a]) collapsed = collapsed && norm(point - samples[a][0]) <= match_distance;
    edges.degenerate[a] = collapsed;
  }
  const std::size_t n = kEdgeSamples.size();
  DisjointSets corners(sides);  // corner ids also run 0 .. 4 * patches
  const auto corner_id = [](std::size_t side, bool end) {
    return static_cast<int>((side / 4) * 4) + (end ? kSideEnd[side % 4] : kSideStart[side % 4]);
  };
  std::vector<std::vector<std::pair<int, bool>>> matches(sides);
  for (std::size_t a = 0; a < sides; ++a) {
    if (edges.degenerate[a]) {
      corners.unite(corner_id(a, false), corner_id(a, true));
      continue;
    }
    for (std::size_t b = a + 1; b < sides; ++b) {
      if (edges.degenerate[b]) continue;
      bool forward = true, backward = true;
      for (std::size_t i = 0; i < n; ++i) {
        forward = forward && norm(samples[a][i] - samples[b][i]) <= match_distance;
        backward = backward && norm(samples[a][i] - samples[b][n - 1 - i]) <= match_distance;
      }
      if (!forward && !backward) continue;
      const bool flip = !forward;
      matches[a].push_back({static_cast<int>(b), flip});
      matches[b].push_back({static_cast<int>(a), flip});
      corners.unite(corner_id(a, false), corner_id(b, flip));
      corners.unite(corner_id(a, true), corner_id(b, !flip));
    }
  }
  // Two collapsed sides at the same point (the poles of two half spheres).
  for (std::size_t a = 0; a < sides; ++a) {
    for (std::size_t b = a + 1; b < sides && edges.degenerate[a]; ++b) {
      if (edges.degenerate[b] && norm(samples[a][0] - samples[b][0]) <= match_distance) {
        corners.unite(corner_id(a, false), corner_id(b, false));
      }
    }
  }
  // Groups by breadth-first search, each side's direction relative to the
  // first side of its group (a contradictory cycle keeps the first answer).
  edges.group.assign(sides, -1);
  edges.flipped.assign(sides, false);
  for (std::size_t start = 0; start < sides; ++start) {
    if (edges.group[start] >= 0) continue;
    edges.group[start] = static_cast<int>(start);
    std::vector<int> queue = {static_cast<int>(start)};
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int side = queue[head];
      for (const auto& [other, flip] : matches[side]) {
        if (edges.group[other] >= 0) continue;
        edges.group[other] = static_cast<int>(start);
        edges.flipped[other] = edges.flipped[side] != flip;
        queue.push_back(other);
      }
    }
  }
  edges.corner_class.resize(sides);
  for (std::size_t c = 0; c < sides; ++c) edges.corner_class[c] = corners.find(static_cast<int>(c));
  return edges;
}

}  // namespace casteljau::tessellation

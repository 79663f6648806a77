// mesh_topology: how the triangles of an indexed mesh meet along their edges.
// Every triangle contributes its three directed edges; sorting them by the
// undirected pair (smaller index first) puts the uses of one edge side by
// side, and each run tells boundary (1 use), manifold (2 uses, opposite
// directions), inconsistently oriented (2 uses, same direction) or
// non-manifold (3 or more). has_zero_area is the rounding test of a
// triangle's area that it and the tessellator share.
#include "casteljau/ops/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau {
namespace {

/// One use of an undirected edge: its end indices in increasing order and
/// whether the triangle runs it from the smaller to the larger.
struct EdgeUse {
  std::uint32_t low = 0;
  std::uint32_t high = 0;
  bool forward = false;
};

}  // namespace

bool has_zero_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e = b - a, f = c - a;
  return norm(cross(e, f)) <= tolerances::kRoundingSlack * norm(e) * norm(f);
}

MeshTopology mesh_topology(const TriangleMesh& mesh) {
  MeshTopology topology;
  topology.triangles = mesh.triangles.size();
  std::vector<EdgeUse> uses;
  uses.reserve(mesh.triangles.size() * 3);
  for (const auto& triangle : mesh.triangles) {
    if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[2] == triangle[0]) {
      // Its "edges" are not edges of a surface: count the triangle, skip them.
      ++topology.degenerate_triangles;
      continue;
    }
    const PointArray& x = mesh.vertices;
    if (has_zero_area(x.vec<3>(triangle[0]), x.vec<3>(triangle[1]), x.vec<3>(triangle[2]))) {
      ++topology.degenerate_triangles;
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t from = triangle[k], to = triangle[(k + 1) % 3];
      uses.push_back(EdgeUse{std::min(from, to), std::max(from, to), from < to});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.low != y.low ? x.low < y.low : x.high < y.high;
  });
  for (std::size_t first = 0; first < uses.size();) {
    std::size_t last = first + 1;
    while (last < uses.size() && uses[last].low == uses[first].low && uses[last].high == uses[first].high) ++last;
    const std::size_t count = last - first;
    if (count == 1) {
      ++topology.boundary_edges;
    } else if (count == 2) {
      if (uses[first].forward == uses[first + 1].forward) ++topology.inconsistently_oriented_edges;
    } else {
      ++topology.non_manifold_edges;
    }
    first = last;
  }
  return topology;
}

}  // namespace casteljau

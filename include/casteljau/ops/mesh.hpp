#pragma once
// TriangleMesh: the output of tessellation and the input of the mesh writers
// (OBJ, STL, PLY in io/). Vertices are shared between the triangles that use
// them, so the topology (which edges have two triangles) can be checked.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// An indexed triangle mesh in R^3 with one unit normal per vertex.
struct TriangleMesh {
  /// Vertex positions (dimension 3).
  PointArray vertices;
  /// One unit normal per vertex (dimension 3), the surface normal there.
  PointArray normals;
  /// Vertex indices, counter-clockwise seen from the side the normals point to.
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// How the triangles of a mesh meet along their edges.
struct MeshTopology {
  /// Edges used by exactly one triangle (the mesh's open boundary).
  std::size_t boundary_edges = 0;
  /// Edges used by three or more triangles.
  std::size_t non_manifold_edges = 0;
  /// Edges used twice with the same orientation (neighbours disagree about
  /// which side is outside).
  std::size_t inconsistently_oriented_edges = 0;
  /// Triangles with two equal vertex indices or zero area.
  std::size_t degenerate_triangles = 0;
  /// Closed and edge-manifold: every edge has exactly two triangles, used in
  /// opposite directions, and no triangle is degenerate.
  bool watertight() const noexcept {
    return boundary_edges == 0 && non_manifold_edges == 0 && inconsistently_oriented_edges == 0 &&
           degenerate_triangles == 0;
  }
};

/// Counts the mesh's boundary, non-manifold and inconsistently oriented edges
/// and degenerate triangles (an edge map, O(t log t)).
MeshTopology mesh_topology(const TriangleMesh& mesh);

}  // namespace casteljau

#pragma once
// TriangleMesh: the output of tessellation and the input of the mesh writers
// (OBJ, STL, PLY in io/). Vertices are shared between the triangles that use
// them, so the topology (which edges have two triangles) can be checked.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/vec.hpp"

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
  /// Triangles of the mesh.
  std::size_t triangles = 0;
  /// Edges used by exactly one triangle (the mesh's open boundary).
  std::size_t boundary_edges = 0;
  /// Edges used by three or more triangles.
  std::size_t non_manifold_edges = 0;
  /// Edges used twice with the same orientation (neighbours disagree about
  /// which side is outside).
  std::size_t inconsistently_oriented_edges = 0;
  /// Triangles with two equal vertex indices or zero area.
  std::size_t degenerate_triangles = 0;
  /// Closed and edge-manifold: there are triangles, every edge has exactly
  /// two, used in opposite directions, and no triangle is degenerate. A mesh
  /// without triangles encloses nothing: it is not watertight.
  bool watertight() const noexcept {
    return triangles > 0 && boundary_edges == 0 && non_manifold_edges == 0 && inconsistently_oriented_edges == 0 &&
           degenerate_triangles == 0;
  }
};

/// True when the triangle (a, b, c) has zero area to rounding: the cross
/// product of two of its edges is at most tolerances::kRoundingSlack ulps of
/// the product of their lengths (the sine of their angle is rounding noise).
bool has_zero_area(const Vec3& a, const Vec3& b, const Vec3& c);

/// Counts the mesh's boundary, non-manifold and inconsistently oriented edges
/// and degenerate triangles (an edge map, O(t log t)).
MeshTopology mesh_topology(const TriangleMesh& mesh);

}  // namespace casteljau

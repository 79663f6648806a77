// mesh_topology on small meshes whose edge structure is known by hand: a
// tetrahedron (closed, 6 edges each used twice in opposite directions) and
// variations of it that break exactly one property at a time.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "casteljau/ops/mesh.hpp"

namespace casteljau {
namespace {

/// The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) with its four faces
/// counter-clockwise seen from outside.
TriangleMesh tetrahedron() {
  TriangleMesh mesh;
  mesh.vertices = PointArray::from_trusted(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  mesh.normals = PointArray::from_trusted(3, {-0.57735026918962573, -0.57735026918962573, -0.57735026918962573,
                                              1, 0, 0, 0, 1, 0, 0, 0, 1});
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

TEST(MeshTopology, ClosedTetrahedronIsWatertight) {
  const MeshTopology topology = mesh_topology(tetrahedron());
  EXPECT_EQ(topology.boundary_edges, 0u);
  EXPECT_EQ(topology.non_manifold_edges, 0u);
  EXPECT_EQ(topology.inconsistently_oriented_edges, 0u);
  EXPECT_EQ(topology.degenerate_triangles, 0u);
  EXPECT_TRUE(topology.watertight());
}

TEST(MeshTopology, MissingFaceLeavesItsThreeEdgesOpen) {
  TriangleMesh mesh = tetrahedron();
  mesh.triangles.pop_back();
  const MeshTopology topology = mesh_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 3u);
  EXPECT_EQ(topology.inconsistently_oriented_edges, 0u);
  EXPECT_FALSE(topology.watertight());
}

TEST(MeshTopology, FlippedFaceDisagreesOnItsThreeEdges) {
  TriangleMesh mesh = tetrahedron();
  mesh.triangles[3] = {1, 3, 2};
  const MeshTopology topology = mesh_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 0u);
  EXPECT_EQ(topology.inconsistently_oriented_edges, 3u);
  EXPECT_FALSE(topology.watertight());
}

TEST(MeshTopology, FinOnAnEdgeIsNonManifold) {
  TriangleMesh mesh = tetrahedron();
  // A fifth vertex and a triangle on edge 0-1: that edge now has three triangles,
  // and the fin's two other edges are open.
  mesh.vertices.push_back(std::array<double, 3>{0.5, -1, 0});
  mesh.normals.push_back(std::array<double, 3>{0, 0, 1});
  mesh.triangles.push_back({0, 4, 1});
  const MeshTopology topology = mesh_topology(mesh);
  EXPECT_EQ(topology.non_manifold_edges, 1u);
  EXPECT_EQ(topology.boundary_edges, 2u);
  EXPECT_FALSE(topology.watertight());
}

TEST(MeshTopology, RepeatedIndexAndCollinearTrianglesAreDegenerate) {
  TriangleMesh mesh = tetrahedron();
  mesh.triangles.push_back({2, 2, 3});
  // (0,0,0), (1,0,0) and (2,0,0) lie on one line: zero area, distinct indices.
  mesh.vertices.push_back(std::array<double, 3>{2, 0, 0});
  mesh.normals.push_back(std::array<double, 3>{0, 0, 1});
  EXPECT_EQ(mesh_topology(mesh).degenerate_triangles, 1u);
  mesh.triangles.push_back({0, 1, 4});
  const MeshTopology topology = mesh_topology(mesh);
  EXPECT_EQ(topology.degenerate_triangles, 2u);
  EXPECT_FALSE(topology.watertight());
}

// Issue 15: a 0-triangle mesh (of a surface that is one point) was called
// watertight. It has no open edge, but it encloses nothing either.
TEST(MeshTopology, EmptyMeshHasNoEdgesAndIsNotWatertight) {
  const MeshTopology topology = mesh_topology(TriangleMesh{});
  EXPECT_EQ(topology.triangles, 0u);
  EXPECT_EQ(topology.boundary_edges, 0u);
  EXPECT_FALSE(topology.watertight());
}

}  // namespace
}  // namespace casteljau

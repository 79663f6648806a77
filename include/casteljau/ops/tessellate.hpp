#pragma once
// Tessellation of surfaces into triangle meshes within a distance tolerance.
//
// Each patch's parameter domain is refined adaptively (a quadtree of
// rectangles, starting from its knot spans) until the triangles are within
// the tolerance of the surface; each leaf is triangulated with every vertex
// its neighbours put on its sides, so there are no T-junctions inside a
// patch. Where patches share a boundary (the same curve, in either
// direction, or a patch's own seam such as the u = 0 and u = 1 edges of a
// surface of revolution), the boundary vertices are shared, so the mesh is
// watertight across it; edges collapsed to a point (poles) become one vertex.
// A request whose triangles cannot fit tolerances::kMaxMeshTriangles is
// refused up front, from an estimate of the cells each patch needs.
// See docs/surfaces.md for the method and its guarantees.
#include <span>
#include <utility>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/mesh.hpp"
#include "casteljau/surfaces/surface_view.hpp"

namespace casteljau {

/// A mesh of the patches within tolerance.distance: every point of a triangle
/// lies within the tolerance of the surface (measured at the parameters
/// interpolated linearly over the triangle). Normals are the surfaces' unit
/// normals at the vertices (normal_at). All patches must be in R^3.
/// `progress` hears the fraction done (at most
/// tolerances::kMeshProgressReports + 1 calls, non-decreasing, the last 1).
/// Errors: no patch, a tolerance not finite or <= 0 or below
/// tolerances::kMeshSmallestToleranceFactor ulps of the patches' scale, a
/// patch not in R^3 ("patch 2 is in R^2, tessellation needs 3D surfaces"),
/// more than tolerances::kMaxMeshTriangles triangles needed (refused before
/// any refinement when a lower bound from the surfaces' second differences
/// already exceeds it, with the tolerance that would fit; otherwise once the
/// count passes it), a degenerate patch that has no area to triangulate ("patch
/// 0 is degenerate: every point of it is (1, 2, 3)", or zero area: a curve).
Expected<TriangleMesh> tessellate(std::span<const SurfaceView> patches, Tolerance tolerance, Progress progress = {});
/// One surface on its own: tessellate(sphere, Tolerance{1e-3}).
inline Expected<TriangleMesh> tessellate(SurfaceView patch, Tolerance tolerance, Progress progress = {}) {
  return tessellate(std::span<const SurfaceView>(&patch, 1), tolerance, std::move(progress));
}

}  // namespace casteljau

// Tessellation of surfaces into triangle meshes within a distance tolerance.
//
// Method (docs/surfaces.md has the long form), with the file of each step:
//
// 1. Per patch, a quadtree over the parameter domain whose roots are the knot
//    spans, addressed by integers so that neighbours agree exactly on shared
//    vertices (tessellate_quadtree.hpp).
// 2. A cell is accepted when the surface sampled on a 7 x 7 grid of its
//    parameters is within tolerances::kMeshSampledDeviationFraction x
//    tolerance of the fan of four triangles from its centre and its corner
//    normals turn by at most tolerances::kMeshMaxNormalTurn; otherwise it is
//    halved in the direction(s) that explain the error
//    (tessellate_refinement.hpp).
// 3. Patch edges are compared with each other once: collapsed edges (poles)
//    and edges shared by two patches or by one patch with itself (a seam)
//    are found, and their corners unified (tessellate_edges.hpp).
// 4. Vertices: one per corner class, one per cell corner along shared edges
//    (the union of every side's), one per integer corner inside a patch;
//    normals from the surfaces (tessellate_assembly.hpp).
// 5. Each cell is triangulated as a fan from its centre through every vertex
//    on its sides: no T-junction, watertight across shared edges by
//    construction (tessellate_assembly.hpp).
// 6. Every final triangle is sampled against the surface at the linearly
//    interpolated parameters; cells whose triangles miss are split and
//    steps 4-6 repeat, so the check holds for the triangles actually written,
//    neighbours' vertices included (tessellate_refinement.hpp).
#include "casteljau/ops/tessellate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "tessellate_assembly.hpp"
#include "tessellate_edges.hpp"
#include "tessellate_quadtree.hpp"
#include "tessellate_refinement.hpp"

namespace casteljau {
namespace {

using tessellation::Cell;
using tessellation::EdgeStructure;
using tessellation::MeshAssembly;
using tessellation::Patch;
using tessellation::Triangle;

/// Steps 1-6 for the patches: the cells, refined until the cell test and the
/// triangle check pass, and their mesh.
Expected<TriangleMesh> tessellate_patches(std::span<const SurfaceView> views, double tolerance,
                                          double match_distance) {
  std::vector<Patch> patches;
  for (const SurfaceView& view : views) patches.emplace_back(view);
  const EdgeStructure edges = tessellation::analyse_edges(patches, match_distance);
  std::vector<std::vector<Cell>> cells(patches.size());
  std::size_t cell_total = 0;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    auto refined = tessellation::refine(patches[p], tolerance, patches[p].roots(), cells[p], cell_total);
    if (!refined) return refined.error();
    cell_total += cells[p].size();
  }
  MeshAssembly assembly(patches, edges, cells);
  for (;;) {
    assembly.assemble();
    std::vector<std::vector<bool>> failed(patches.size());
    bool any = false;
    for (std::size_t p = 0; p < patches.size(); ++p) failed[p].assign(cells[p].size(), false);
    for (const Triangle& triangle : assembly.triangles()) {
      if (!triangle.needs_check || failed[triangle.patch][triangle.cell]) continue;
      if (!tessellation::triangle_within_tolerance(patches[triangle.patch], triangle, assembly, tolerance)) {
        const Cell& cell = cells[triangle.patch][triangle.cell];
        if (cell.u1 - cell.u0 > 1 || cell.v1 - cell.v0 > 1) {
          failed[triangle.patch][triangle.cell] = true;
          any = true;
        }  // else: at the depth limit, kept as it is
      }
    }
    if (!any) break;
    cell_total = 0;
    for (std::size_t p = 0; p < patches.size(); ++p) {
      std::vector<Cell> kept;
      for (std::size_t c = 0; c < cells[p].size(); ++c) {
        if (!failed[p][c]) {
          kept.push_back(cells[p][c]);
          continue;
        }
        if (!tessellation::split(cells[p][c], true, true, kept)) kept.push_back(cells[p][c]);
      }
      cells[p] = std::move(kept);
      cell_total += cells[p].size();
    }
    if (auto counted = tessellation::check_cell_count(cell_total, tolerance); !counted) return counted.error();
  }
  return assembly.finish();
}

/// The largest absolute coordinate of the patches on a 9 x 9 parameter grid
/// each: the scale of the relative limits (tolerance floor, edge matching).
double scale_of_patches(std::span<const SurfaceView> patches) {
  constexpr int kSamples = 9;
  double scale = 0.0;
  for (const SurfaceView& patch : patches) {
    std::array<double, kSamples> us{}, vs{};
    for (int k = 0; k < kSamples; ++k) {
      us[k] = patch.domain_u().lerp(static_cast<double>(k) / (kSamples - 1));
      vs[k] = patch.domain_v().lerp(static_cast<double>(k) / (kSamples - 1));
    }
    std::vector<double> grid(kSamples * kSamples * 3);
    patch.grid_points_at(us, vs, grid);
    for (const double x : grid) scale = std::max(scale, std::abs(x));
  }
  return scale;
}

}  // namespace

Expected<TriangleMesh> tessellate(std::span<const SurfaceView> patches, Tolerance tolerance) {
  if (patches.empty()) return Error{"no surface to tessellate"};
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (patches[p].dimension() != 3) {
      return Error{"patch " + std::to_string(p) + " is in R^" + std::to_string(patches[p].dimension()) +
                   ", tessellation needs 3D surfaces"};
    }
  }
  const double e = tolerance.distance;
  if (!std::isfinite(e) || !(e > 0.0)) {
    return Error{"the tessellation tolerance is " + detail::number_text(e) + ", it must be finite and > 0"};
  }
  const double scale = scale_of_patches(patches);
  const double smallest = tolerances::kMeshSmallestToleranceFactor * 0x1p-52 * scale;
  if (e < smallest) {
    return Error{"the tessellation tolerance " + detail::number_text(e) + " is below what double precision can " +
                 "check on surfaces of size " + detail::number_text(scale) + " (at least " +
                 detail::number_text(smallest) + ")"};
  }
  // Shared edges agree to rounding; at least a tiny absolute distance so that
  // surfaces at the origin (scale 0) still compare.
  const double match_distance = std::max(tolerances::kMeshSharedEdgeRelative * scale, tolerances::kScaleFloor);
  return tessellate_patches(patches, e, match_distance);
}

}  // namespace casteljau

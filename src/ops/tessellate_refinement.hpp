#pragma once
// Internal to tessellate (ops/tessellate.hpp): the quadtree refinement and its
// deviation checks, steps 2 and 6 of the method in tessellate.cpp.
//
// The cell test (step 2): the surface on a 7 x 7 grid of the cell's
// parameters must be within tolerances::kMeshSampledDeviationFraction x
// tolerance of the fan of four triangles from the cell's centre to its
// corners, and the unit normals at its corners must turn by at most
// tolerances::kMeshMaxNormalTurn along every edge that is not flat at the
// tolerance's scale (so that sampling can be trusted). A cell that fails is
// halved in u, in v or both: in the direction(s) whose mid-line bends most (a
// cylinder is cut across its axis only), both when the error is a twist
// (z = uv). A cell that must be halved in a direction where it is already
// at the quadtree's depth limit is refused with where it is.
//
// The triangle check (step 6): every assembled triangle, neighbours' vertices
// included, is sampled (edge midpoints, centroid, three inner points) against
// the surface at the linearly interpolated parameters.
#include <cstddef>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "tessellate_assembly.hpp"
#include "casteljau/core/progress.hpp"
#include "tessellate_quadtree.hpp"

namespace casteljau::tessellation {

/// Refuses more than tolerances::kMaxMeshTriangles / 2 cells: every cell
/// gives at least two triangles.
Status check_cell_count(std::size_t cells, double tolerance);

/// The verdict of the cell test on one cell.
struct CellTest {
  bool needs_split = false;        ///< the cell fails: halve it
  bool in_u = false, in_v = false;  ///< in which direction(s)
  double error = 0.0;              ///< the sampled distance to its fan of triangles
};

/// The cell test (step 2).
CellTest test_cell(const Patch& patch, const Cell& cell, double tolerance);

/// Where refine() reports its progress: the part [from, to] of the whole
/// work, shared among the patch's roots (Patch::roots() order) in proportion
/// to `root_shares` (summing to 1), and within a root by the parameter area
/// accepted so far.
struct RefinementProgress {
  ProgressPart& progress;
  double from = 0.0, to = 0.0;
  const std::vector<double>& root_shares;
};

/// Refines the root cells of `patch` until each cell passes the cell test,
/// appending them to `accepted`; `other_cells` (the other patches' cells)
/// counts towards the limit of check_cell_count.
Status refine(const Patch& patch, double tolerance, std::vector<Cell>& accepted, std::size_t other_cells,
              const RefinementProgress& progress);

/// The triangle check of one triangle of `assembly` on its patch.
bool triangle_within_tolerance(const Patch& patch, const Triangle& triangle, const MeshAssembly& assembly,
                               double tolerance);

}  // namespace casteljau::tessellation

#pragma once
// Internal to tessellate (ops/tessellate.hpp): how many quadtree cells a
// tessellation needs at least, known before any refinement, so that a request
// beyond tolerances::kMaxMeshTriangles is refused at once instead of after
// minutes of work, with the tolerance that would fit.
//
// Where the cell test accepts a cell, the bottom and top rows of its 7 x 7
// samples lie on chords of the surface's u-lines (they are edges of the fan's
// triangles), so the chord deviation of each of those lines over the cell,
// about h_u^2 |S_uu| / 8 for a cell of width h_u, is at most
// eps = tolerances::kMeshSampledDeviationFraction x tolerance; likewise in v.
// Each knot span is cut into m x m subcells (m from the sample budget
// tolerances::kMeshEstimateSubcells) and the chord deviations d_u of three
// u-lines of each subcell (its two edges and its middle) are sampled: a
// subcell of width H then holds at least n_u = sqrt(d_u / eps) cells across,
// since d_u is H^2 / h_u^2 times the chord deviation over one of them (the
// mean of the three lines' square roots is taken; n_v alike). A cell never
// exceeds its knot span, so each subcell counts for at least 1/m across:
//
//     cells >= sum over subcells of max(n_u, 1/m) * max(n_v, 1/m).
//
// The bound assumes the second derivatives nearly constant over a subcell,
// which is what holds when it matters: it can only refuse when millions of
// cells are needed, each far smaller than a subcell. It ignores the other
// reasons to refine (twist, the turn of the normals, the triangle check) and
// that the quadtree halves (cells up to half the size needed each way), so
// the real count is larger: docs/surfaces.md gives the measured ratios.
#include <cstddef>
#include <vector>

#include "tessellate_quadtree.hpp"

namespace casteljau::tessellation {

/// The sampled bending of every subcell of every knot span of the patches,
/// from which the cells needed at any tolerance follow.
class CellEstimate {
 public:
  /// Samples the patches (tolerances::kMeshEstimateSubcells subcells in all,
  /// at least one per knot span): a grid batch of (2m + 1)^2 points per span.
  explicit CellEstimate(const std::vector<Patch>& patches);

  /// The number of knot spans (quadtree roots) of all patches, in patch order
  /// and each patch's Patch::roots() order.
  std::size_t roots() const noexcept { return root_begin_.size() - 1; }
  /// Cells needed at least in root `root` at `tolerance`.
  double root_cells(std::size_t root, double tolerance) const;
  /// Cells needed at least in all roots at `tolerance`.
  double cells(double tolerance) const;
  /// The smallest tolerance at which cells() is at most `cells` (relative
  /// precision 1e-6), or +infinity when no tolerance brings it that low
  /// (there are more roots than `cells`).
  double tolerance_for(double cells) const;

 private:
  /// Per subcell: the means of sqrt(chord deviation) of its u- and v-lines.
  std::vector<double> bend_u_, bend_v_;
  /// Subcells per knot span and direction.
  int m_ = 1;
  /// The first subcell of every root, and one past the last.
  std::vector<std::size_t> root_begin_;
};

}  // namespace casteljau::tessellation

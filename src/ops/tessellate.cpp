// Tessellation of surfaces into triangle meshes within a distance tolerance.
//
// Method (docs/surfaces.md has the long form), with the file of each step:
//
// 0. Before any refinement, a lower bound on the cells every knot span needs,
//    from chord deviations sampled on a grid of subcells; a request whose
//    bound already exceeds tolerances::kMaxMeshTriangles is refused at once,
//    with the tolerance that would fit (tessellate_estimate.hpp).
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
//    neighbours' vertices included (tessellate_refinement.hpp). A patch none
//    of whose triangles has an area (a point, a curve) is refused, named.
//
// The caller's Progress hears the refinement (weighted by the estimate) and
// each assembly pass (core/progress.hpp, ProgressPart).
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
#include "tessellate_estimate.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "tessellate_quadtree.hpp"
#include "tessellate_refinement.hpp"

namespace casteljau {
namespace {

using tessellation::Cell;
using tessellation::CellEstimate;
using tessellation::EdgeStructure;
using tessellation::MeshAssembly;
using tessellation::Patch;
using tessellation::Triangle;

/// The share of the progress that the refinement of step 2 owns; the
/// assembly passes (steps 4-6) own the rest, each half of what remains (their
/// number is known only at the end). Measured on the sphere: the first
/// refinement takes about a quarter of the time.
constexpr double kRefinementShare = 0.3;

/// The points of a patch on a 9 x 9 grid over its domain (x, y, z each).
std::vector<double> sample_grid(const SurfaceView& patch) {
  constexpr int kSamples = 9;
  std::array<double, kSamples> us{}, vs{};
  for (int k = 0; k < kSamples; ++k) {
    us[k] = patch.domain_u().lerp(static_cast<double>(k) / (kSamples - 1));
    vs[k] = patch.domain_v().lerp(static_cast<double>(k) / (kSamples - 1));
  }
  std::vector<double> grid(kSamples * kSamples * 3);
  patch.grid_points_at(us, vs, grid);
  return grid;
}

/// The largest absolute coordinate of the patches on their sample grids:
/// the scale of the relative limits (tolerance floor, edge matching).
double scale_of_patches(std::span<const SurfaceView> patches) {
  double scale = 0.0;
  for (const SurfaceView& patch : patches) {
    for (const double x : sample_grid(patch)) scale = std::max(scale, std::abs(x));
  }
  return scale;
}

/// x rounded up to two significant digits, as text: a tolerance to suggest.
std::string rounded_up(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return detail::number_text(std::ceil(x / unit * (1.0 - 1e-12)) * unit);
}

/// Refuses a patch that jumps across one of its knot lines (an interior knot
/// of multiplicity degree + 1: the two sides are separate surfaces; or a
/// weight 10^10 times its neighbours', continuous only in exact arithmetic). No cell
/// that ends at the line can meet the tolerance, since evaluation there takes
/// the other side's value: the quadtree was refined to its finest cells along
/// the whole line until the triangle limit stopped it, 48 s later (issue 42's
/// model_json fuzzer). The jump is the distance between the point at the knot
/// and the point a step 2^-30 of the span before it, at five v (u) values; a
/// jump is more than the tolerance and more than 100 times the same step
/// after the knot (where the surface is continuous both are its slope times
/// the step).
Status check_continuous_patches(std::span<const SurfaceView> patches, double tolerance) {
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const SurfaceView& surface = patches[p];
    for (const bool along_u : {true, false}) {
      const std::vector<double> knots = along_u ? surface.breakpoints_u() : surface.breakpoints_v();
      const Interval across = along_u ? surface.domain_v() : surface.domain_u();
      for (std::size_t k = 1; k + 1 < knots.size(); ++k) {
        const double step = 0x1p-30 * std::min(knots[k] - knots[k - 1], knots[k + 1] - knots[k]);
        for (int j = 0; j <= 4; ++j) {
          const double w = across.lower + j * (across.upper - across.lower) / 4;
          const auto at = [&](double x) { return along_u ? surface.point_at(x, w) : surface.point_at(w, x); };
          const Point before = at(knots[k] - step), on = at(knots[k]), after = at(knots[k] + step);
          const double jump = distance(before, on), smooth = distance(on, after);
          if (jump > tolerance && jump > 100.0 * smooth) {
            return Error{"patch " + std::to_string(p) + " is not continuous across " + (along_u ? "u" : "v") +
                         " = " + detail::number_text(knots[k]) + ": it jumps by " + detail::number_text(jump) +
                         " within 2^-30 of its knot span (a knot of multiplicity degree + 1 there, or weights many "
                         "orders of magnitude apart, make such a jump); split it at that knot and tessellate the two "
                         "parts, or bring its weights closer"};
          }
        }
      }
    }
  }
  return {};
}

/// Refuses, before any refinement, a request whose estimated cells
/// (tessellate_estimate.hpp, a lower bound) already exceed the limit, naming
/// the tolerance at which the estimate leaves tolerances::kMeshEstimateMargin
/// for the real count.
Status check_estimate(const CellEstimate& estimate, double tolerance) {
  const double most_cells = static_cast<double>(tolerances::kMaxMeshTriangles) / 2.0;
  const double cells = estimate.cells(tolerance);
  if (cells <= most_cells) return {};
  std::string message = "the tessellation needs at least " + std::to_string(static_cast<long long>(2.0 * cells)) +
                        " triangles at tolerance " + detail::number_text(tolerance) +
                        " (estimated from the surfaces' second differences), more than the limit of " +
                        std::to_string(tolerances::kMaxMeshTriangles);
  const double fits = estimate.tolerance_for(most_cells / tolerances::kMeshEstimateMargin);
  if (std::isfinite(fits)) {
    message += "; a tolerance of " + rounded_up(fits) + " or larger should fit";
  } else {
    message += "; the surfaces have " + std::to_string(estimate.roots()) +
               " knot spans, too many to fit at any tolerance";
  }
  return Error{message, ErrorKind::limit};
}

/// A patch of the assembled mesh none of whose triangles has an area: the
/// surface is a point or a curve, there is nothing to triangulate. Named with
/// what it is, from its sample grid.
Status check_degenerate_patches(const std::vector<Patch>& patches, const MeshAssembly& assembly,
                                double match_distance) {
  std::vector<bool> has_area(patches.size(), false);
  for (const Triangle& triangle : assembly.triangles()) {
    if (has_area[triangle.patch]) continue;
    const auto& c = triangle.corners;
    has_area[triangle.patch] = !has_zero_area(assembly.position(c[0].vertex), assembly.position(c[1].vertex),
                                              assembly.position(c[2].vertex));
  }
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (has_area[p]) continue;
    const std::vector<double> grid = sample_grid(patches[p].surface);
    const Vec3 first{{grid[0], grid[1], grid[2]}};
    bool one_point = true;
    for (std::size_t i = 0; i < grid.size(); i += 3) {
      one_point = one_point && norm(Vec3{{grid[i], grid[i + 1], grid[i + 2]}} - first) <= match_distance;
    }
    const std::string what =
        one_point ? "every point of it is (" + detail::number_text(first[0]) + ", " + detail::number_text(first[1]) +
                        ", " + detail::number_text(first[2]) + "), and a point has no triangles"
                  : "it has zero area (its points lie on one curve), so it has no triangles";
    return Error{"patch " + std::to_string(p) + " is degenerate: " + what};
  }
  return {};
}

/// Steps 1-6 for the patches: the cells, refined until the cell test and the
/// triangle check pass, and their mesh.
Expected<TriangleMesh> tessellate_patches(const std::vector<Patch>& patches, const CellEstimate& estimate,
                                          double tolerance, double match_distance, ProgressPart& progress) {
  const EdgeStructure edges = tessellation::analyse_edges(patches, match_distance);
  std::vector<std::vector<Cell>> cells(patches.size());
  std::size_t cell_total = 0;
  // The refinement's progress, shared among the roots by their estimated cells.
  const double estimated = estimate.cells(tolerance);
  double before = 0.0;
  std::size_t root = 0;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    std::vector<double> shares;
    double patch_cells = 0.0;
    const std::size_t roots = patches[p].roots().size();
    for (std::size_t r = 0; r < roots; ++r) {
      shares.push_back(estimate.root_cells(root++, tolerance));
      patch_cells += shares.back();
    }
    for (double& share : shares) share /= patch_cells;
    const double from = kRefinementShare * before / estimated;
    before += patch_cells;
    const tessellation::RefinementProgress stage{progress, from, kRefinementShare * before / estimated, shares};
    auto refined = tessellation::refine(patches[p], tolerance, cells[p], cell_total, stage);
    if (!refined) {
      Error error = refined.error();
      if (error.kind != ErrorKind::limit) error.message = "patch " + std::to_string(p) + ": " + error.message;
      return error;
    }
    cell_total += cells[p].size();
  }
  MeshAssembly assembly(patches, edges, cells);
  for (double remaining = 1.0 - kRefinementShare;; remaining /= 2.0) {
    assembly.assemble(progress, 1.0 - remaining, 1.0 - remaining / 2.0);
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
  if (auto whole = check_degenerate_patches(patches, assembly, match_distance); !whole) return whole.error();
  TriangleMesh mesh = assembly.finish();
  progress.finish();
  return mesh;
}

}  // namespace

Expected<TriangleMesh> tessellate(std::span<const SurfaceView> patches, Tolerance tolerance, Progress progress) {
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
  if (auto continuous = check_continuous_patches(patches, e); !continuous) return continuous.error();
  // Shared edges agree to rounding; at least a tiny absolute distance so that
  // surfaces at the origin (scale 0) still compare.
  const double match_distance = std::max(tolerances::kMeshSharedEdgeRelative * scale, tolerances::kScaleFloor);
  std::vector<Patch> prepared;
  for (const SurfaceView& view : patches) prepared.emplace_back(view);
  const CellEstimate estimate(prepared);
  if (auto fits = check_estimate(estimate, e); !fits) return fits.error();
  ProgressPart reporter(progress, 0.0, 1.0, 1.0 / tolerances::kMeshProgressReports);
  return tessellate_patches(prepared, estimate, e, match_distance, reporter);
}

}  // namespace casteljau

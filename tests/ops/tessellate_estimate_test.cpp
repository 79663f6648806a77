// The up-front estimate of a tessellation's cells (src/ops/tessellate_estimate.hpp):
// - against an exact reference: on the paraboloid z = a u^2 + b v^2 (a Bézier
//   patch of degree 2 x 2, so S_uu = (0, 0, 2a) and S_vv = (0, 0, 2b) are
//   constant and every chord deviation is exactly h^2 a / 4), the chord test
//   needs at least n_u = sqrt(a / (4 eps)) cells across in u and n_v =
//   sqrt(b / (4 eps)) in v, eps = kMeshSampledDeviationFraction x tolerance;
// - a lower bound on what tessellate() produces: twice the estimated cells
//   never exceed the triangles of the mesh, on a sphere, a torus, a bicubic
//   patch and a paraboloid (the ratios, printed as test properties, are what
//   kMeshEstimateMargin in ops/tolerance.hpp is measured from);
// - tolerance_for inverts cells(): the estimate at the tolerance it gives is
//   the requested count (to its precision), and a flat patch fits at any.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/tessellate.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "casteljau/surfaces/surface_view.hpp"
#include "support/sanitizers.hpp"
#include "support/test_surfaces.hpp"
#include "../../src/ops/tessellate_estimate.hpp"

namespace casteljau {
namespace {

using test::bicubic_patch;

using tessellation::CellEstimate;
using tessellation::Patch;

/// z = a u^2 + b v^2 over [0,1]^2 with x = u, y = v, as a Bézier patch of
/// degree 2 x 2: u = sum_i (i/2) B_i(u) and u^2 = B_2(u) in the Bernstein
/// basis, so P_ij = (i/2, j/2, a [i == 2] + b [j == 2]).
BezierSurface paraboloid(double a, double b) {
  std::vector<double> points;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) points.insert(points.end(), {i / 2.0, j / 2.0, (i == 2 ? a : 0.0) + (j == 2 ? b : 0.0)});
  }
  return BezierSurface::from_trusted(ControlNet::from_trusted(3, 3, PointArray::from_trusted(3, points)));
}

CellEstimate estimate_of(const SurfaceView& view) {
  std::vector<Patch> patches;
  patches.emplace_back(view);
  return CellEstimate(patches);
}

TEST(TessellateEstimate, ParaboloidGivesTheExactChordBound) {
  const double a = 3.0, b = 0.75;
  const BezierSurface surface = paraboloid(a, b);
  const CellEstimate estimate = estimate_of(surface);
  EXPECT_EQ(estimate.roots(), 1u);
  for (const double tolerance : {1e-3, 1e-5, 1e-8}) {
    const double eps = tolerances::kMeshSampledDeviationFraction * tolerance;
    const double expected = std::sqrt(a / (4 * eps)) * std::sqrt(b / (4 * eps));
    EXPECT_NEAR(estimate.cells(tolerance), expected, 1e-9 * expected) << tolerance;
    EXPECT_EQ(estimate.root_cells(0, tolerance), estimate.cells(tolerance));
  }
  // At a tolerance larger than the whole patch's chord deviation: one cell.
  EXPECT_DOUBLE_EQ(estimate.cells(10.0), 1.0);
}

TEST(TessellateEstimate, IsALowerBoundOnTheTessellation) {
  const std::vector<double> origin = {0, 0, 0}, axis = {0, 0, 1};
  const BSplineSurface sphere = make_sphere(origin, 2.0).value();
  const BSplineSurface torus = make_torus(origin, axis, 3.0, 1.0).value();
  const BezierSurface bicubic = bicubic_patch();
  const BezierSurface bowl = paraboloid(3.0, 0.75);
  const std::vector<std::pair<std::string, SurfaceView>> surfaces = {
      {"sphere", sphere}, {"torus", torus}, {"bicubic", bicubic}, {"paraboloid", bowl}};
  for (const auto& [name, view] : surfaces) {
    const CellEstimate estimate = estimate_of(view);
    // Under the sanitizers the coarser tolerance only: the same code paths.
    for (const double tolerance : test::kUnderSanitizers ? std::vector<double>{1e-2} : std::vector<double>{1e-2, 3e-3}) {
      auto mesh = tessellate(std::span<const SurfaceView>(&view, 1), Tolerance{tolerance});
      ASSERT_TRUE(mesh.has_value()) << name << ": " << mesh.error().message;
      const double estimated = 2.0 * estimate.cells(tolerance);
      const double triangles = static_cast<double>(mesh->triangles.size());
      EXPECT_LE(estimated, triangles) << name << " at " << tolerance;
      EXPECT_LE(triangles, tolerances::kMeshEstimateMargin * estimated) << name << " at " << tolerance;
      ::testing::Test::RecordProperty(name + "_" + std::to_string(tolerance) + "_triangles_over_estimate",
                                      std::to_string(triangles / estimated));
    }
  }
}

TEST(TessellateEstimate, ToleranceForInvertsTheCount) {
  const BSplineSurface sphere = make_sphere(std::vector<double>{0, 0, 0}, 1.0).value();
  const CellEstimate estimate = estimate_of(sphere);
  for (const double cells : {1e3, 1e6, 1e9}) {
    const double tolerance = estimate.tolerance_for(cells);
    EXPECT_LE(estimate.cells(tolerance), cells);
    EXPECT_GE(estimate.cells(tolerance * (1 - 1e-5)), cells * (1 - 1e-4));
  }
  // Fewer cells than knot spans: no tolerance fits.
  EXPECT_EQ(estimate.tolerance_for(0.5 * static_cast<double>(estimate.roots())), INFINITY);
  const BezierSurface flat = paraboloid(0.0, 0.0);
  EXPECT_EQ(estimate_of(flat).tolerance_for(10.0), 0.0);
  EXPECT_EQ(estimate_of(flat).cells(1e-12), 1.0);
}

}  // namespace
}  // namespace casteljau

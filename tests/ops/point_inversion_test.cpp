// Point inversion against closed forms (the NURBS sphere: along the ray from
// the centre, poles included; the torus: | sqrt((rho - R)^2 + z^2) - r |,
// across its seams) and against a brute-force oracle ten times denser than
// the search's grid (the nearest of 640 x 640 samples) on a bicubic patch and
// a wavy bicubic NURBS surface of 5 x 5 spans: no answer may be farther than the oracle's by more than
// 1e-9 of the size, and each answer's distance is that of its (u, v).
#include "casteljau/ops/point_inversion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "casteljau/surfaces/revolution.hpp"
#include "support/sanitizers.hpp"
#include "support/splitmix.hpp"
#include "support/test_surfaces.hpp"

namespace casteljau {
namespace {

double euclidean_norm(const std::vector<double>& p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); }

TEST(PointInversion, OnTheSphereIsAlongTheRayPolesIncluded) {
  const std::vector<double> centre{1.0, -2.0, 0.5};
  const BSplineSurface sphere = make_sphere(centre, 2.0).value();
  test::SplitMix random{11};
  double worst = 0.0;
  for (int i = 0; i < test::sample_count(500, 100); ++i) {
    std::vector<double> q(3);
    for (double& x : q) x = 8 * random.unit() - 4;
    const double r = euclidean_norm({q[0] - centre[0], q[1] - centre[1], q[2] - centre[2]});
    const SurfaceNearestPoint nearest = closest_point(sphere, q).value();
    worst = std::max(worst, std::abs(nearest.distance - std::abs(r - 2.0)));
    EXPECT_NEAR(euclidean_norm({nearest.point[0] - q[0], nearest.point[1] - q[1], nearest.point[2] - q[2]}), nearest.distance, 1e-12);
  }
  EXPECT_LT(worst, 1e-12);
  // Straight above a pole: the pole itself, at distance 3.
  const SurfaceNearestPoint pole = closest_point(sphere, std::vector<double>{1.0, -2.0, 5.5}).value();
  EXPECT_NEAR(pole.distance, 3.0, 1e-12);
  EXPECT_NEAR(pole.point[2], 2.5, 1e-12);
}

TEST(PointInversion, OnTheTorusAcrossItsSeams) {
  const std::vector<double> centre{0, 0, 0}, axis{0, 0, 1};
  const BSplineSurface torus = make_torus(centre, axis, 3.0, 1.0).value();
  test::SplitMix random{12};
  double worst = 0.0;
  for (int i = 0; i < test::sample_count(500, 100); ++i) {
    std::vector<double> q(3);
    for (double& x : q) x = 10 * random.unit() - 5;
    q[2] *= 0.5;
    const double rho = std::hypot(q[0], q[1]);
    if (rho < 1e-3) continue;  // on the axis every point of the inner circle is nearest
    const double expected = std::abs(std::hypot(rho - 3.0, q[2]) - 1.0);
    worst = std::max(worst, std::abs(closest_point(torus, q).value().distance - expected));
  }
  EXPECT_LT(worst, 1e-12);
}

/// The nearest of a dense grid of samples: a distance from above.
double oracle(SurfaceView surface, const std::vector<double>& grid, const std::vector<double>& q) {
  double best = INFINITY;
  for (std::size_t k = 0; k < grid.size(); k += 3) {
    const double dx = grid[k] - q[0], dy = grid[k + 1] - q[1], dz = grid[k + 2] - q[2];
    best = std::min(best, dx * dx + dy * dy + dz * dz);
  }
  (void)surface;
  return std::sqrt(best);
}

void against_oracle(SurfaceView surface, std::uint64_t seed) {
  constexpr int kDense = 640;
  std::vector<double> us(kDense), vs(kDense);
  for (int i = 0; i < kDense; ++i) {
    us[i] = surface.domain_u().lerp(i / (kDense - 1.0));
    vs[i] = surface.domain_v().lerp(i / (kDense - 1.0));
  }
  std::vector<double> grid(kDense * kDense * 3);
  surface.grid_points_at(us, vs, grid);
  double lower[3] = {INFINITY, INFINITY, INFINITY}, upper[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t k = 0; k < grid.size(); ++k) lower[k % 3] = std::min(lower[k % 3], grid[k]), upper[k % 3] = std::max(upper[k % 3], grid[k]);
  const double size = std::hypot(upper[0] - lower[0], upper[1] - lower[1], upper[2] - lower[2]);
  test::SplitMix random{seed};
  int missed = 0;
  double worst = 0.0;
  // Each query scans the 409,600 points of the grid (test code at -O0 under the sanitizers: fewer there).
  const int queries = test::sample_count(300, 60);
  for (int i = 0; i < queries; ++i) {
    std::vector<double> q(3);
    for (int j = 0; j < 3; ++j) q[j] = lower[j] - size / 2 + (upper[j] - lower[j] + size) * random.unit();
    const SurfaceNearestPoint nearest = closest_point(surface, q).value();
    const double excess = (nearest.distance - oracle(surface, grid, q)) / size;
    worst = std::max(worst, excess);
    if (excess > 1e-9) ++missed;
  }
  std::printf("point inversion oracle: %d queries, %d missed, worst excess %.3g of the size\n", queries, missed, worst);
  EXPECT_EQ(missed, 0);
}

TEST(PointInversionOracle, BicubicPatch) {
  const BezierSurface patch = test::bicubic_patch();
  against_oracle(patch, 21);
}

TEST(PointInversionOracle, WavyRationalBSplineSurface) {
  // A bicubic NURBS surface on 5 x 5 spans: a height field with random
  // heights in [0, 2) over an 8 x 8 grid of unit spacing, random weights.
  test::SplitMix random{22};
  std::vector<double> coordinates, weights;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      coordinates.insert(coordinates.end(), {static_cast<double>(i), static_cast<double>(j), 2 * random.unit()});
      weights.push_back(0.5 + random.unit());
    }
  const std::vector<double> knots{0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5};
  const BSplineSurface surface =
      BSplineSurface::make(3, 3, knots, knots, ControlNet::make(8, 8, PointArray::make(3, coordinates).value()).value(),
                           weights)
          .value();
  against_oracle(surface, 23);
}

TEST(PointInversion, RefusesBadQueries) {
  const BezierSurface patch = test::bicubic_patch();
  EXPECT_EQ(closest_point(patch, std::vector<double>{1, 2}).error().message,
            "the query point has 2 coordinates, the surface lives in R^3");
  EXPECT_EQ(closest_point(patch, std::vector<double>{1, 2, NAN}).error().message,
            "coordinate 2 of the query point is NaN");
}

}  // namespace
}  // namespace casteljau

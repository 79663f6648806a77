// Ruled surfaces between two curves.
#include "casteljau/surfaces/ruled.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "support/bspline_generators.hpp"

namespace casteljau {
namespace {

RC_GTEST_PROP(RuledSurface, IsTheLinearInterpolationOfTheTwoCurves, ()) {
  // Reference: (1 - v) C0(u) + v C1(u) from the curves themselves, each on
  // its own domain mapped to [0, 1].
  const auto c0 = *test::bspline_curve({.max_degree = 5, .dimension = 3, .max_extra_points = 6, .rational = test::Rational::never});
  const auto c1 = *test::bspline_curve({.max_degree = 5, .dimension = 3, .max_extra_points = 6, .rational = test::Rational::never});
  const auto surface = ruled_surface(c0, c1).value();
  RC_ASSERT(surface.degree_v() == 1);
  RC_ASSERT(surface.degree_u() == std::max(c0.degree(), c1.degree()));
  const double tol = 1e-12 * std::max({1.0, scale_of(c0.control_points()), scale_of(c1.control_points())});
  for (int k = 0; k < 20; ++k) {
    const double u = *test::unit_parameter(), v = *test::unit_parameter();
    const Point a = point_at(c0, c0.domain().lerp(u));
    const Point b = point_at(c1, c1.domain().lerp(u));
    const Point s = point_at(surface, u, v);
    for (int c = 0; c < 3; ++c) RC_ASSERT(std::abs(s[c] - ((1 - v) * a[c] + v * b[c])) <= tol);
  }
}

TEST(RuledSurface, RationalCurvesGiveStraightRulings) {
  // A cylinder-like band between a quarter circle and a lifted, larger arc:
  // every iso-curve u = const is the segment from C0(u) to C1(u).
  const ConicFrame low{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const ConicFrame high{{0, 0, 2}, {1, 0, 0}, {0, 1, 0}};
  const auto c0 = make_arc(low, 1.0, 0.0, std::numbers::pi / 2).value();
  const auto c1 = make_arc(high, 2.0, 0.0, std::numbers::pi).value();  // two pieces: refinement needed
  const auto surface = ruled_surface(c0, c1).value();
  ASSERT_TRUE(surface.is_rational());
  double worst_end = 0.0, worst_line = 0.0;
  for (int i = 0; i <= 32; ++i) {
    const double u = i / 32.0;
    const Point a = point_at(c0, u), b = point_at(c1, u);
    worst_end = std::max({worst_end, distance(point_at(surface, u, 0.0), a), distance(point_at(surface, u, 1.0), b)});
    for (double v : {0.25, 0.5, 0.9}) {
      // Distance from S(u,v) to the line through a and b.
      const Point s = point_at(surface, u, v);
      double ab2 = 0, t = 0;
      for (int c = 0; c < 3; ++c) {
        ab2 += (b[c] - a[c]) * (b[c] - a[c]);
        t += (s[c] - a[c]) * (b[c] - a[c]);
      }
      t /= ab2;
      Point foot(3);
      for (int c = 0; c < 3; ++c) foot[c] = a[c] + t * (b[c] - a[c]);
      worst_line = std::max(worst_line, distance(s, foot));
      EXPECT_GT(t, 0.0);
      EXPECT_LT(t, 1.0);
    }
  }
  EXPECT_LE(worst_end, 1e-15 * 2 * 4);
  EXPECT_LE(worst_line, 1e-15 * 2 * 4);
}

TEST(RuledSurface, TwoSegmentsGiveTheBilinearPatch) {
  const auto a = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0, 0}, {4, 0, 1}}).value()).value();
  const auto b = BSplineCurve::make(1, {5, 5, 7, 7}, PointArray::make({{0, 2, 0}, {4, 3, -1}}).value()).value();
  const auto surface = ruled_surface(a, b).value();
  EXPECT_EQ(surface.knots_u().size(), 4u);
  EXPECT_EQ(surface.control_net().rows(), 2u);
  EXPECT_EQ(surface.control_net().columns(), 2u);
  const Point p = point_at(surface, 0.25, 0.5);  // exact in binary
  EXPECT_EQ(p, (Point{1.0, 1.125, 0.0}));
}

TEST(RuledSurface, RefusesCurvesOfDifferentDimensions) {
  const auto a = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0, 0}, {4, 0, 1}}).value()).value();
  const auto b = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 2}, {4, 3}}).value()).value();
  const auto surface = ruled_surface(a, b);
  ASSERT_FALSE(surface.has_value());
  EXPECT_EQ(surface.error().message, "curve 1 has 2 coordinates, curve 0 has 3; compatible curves need one dimension");
}

}  // namespace
}  // namespace casteljau

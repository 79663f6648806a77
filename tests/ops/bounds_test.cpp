// The tight bounding box against exact boxes (the NURBS circle and arcs:
// centre +- radius, or the arc's extreme angles; a parabola whose extreme is
// known) and, on random curves of every kind, against dense sampling: every
// sampled point inside, every face touched by the curve, and never larger
// than the control points' box.
#include "casteljau/ops/bounds.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "support/bspline_generators.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

TEST(BoundingBox, OfTheNurbsCircleIsCentrePlusMinusRadius) {
  const BSplineCurve circle = make_circle(1.0, -2.0, 3.0).value();
  const Box box = bounding_box(circle);
  EXPECT_NEAR(box.lower[0], -2.0, 1e-14);
  EXPECT_NEAR(box.upper[0], 4.0, 1e-14);
  EXPECT_NEAR(box.lower[1], -5.0, 1e-14);
  EXPECT_NEAR(box.upper[1], 1.0, 1e-14);
}

TEST(BoundingBox, OfAnArcReachesItsExtremeAngles) {
  // From 30 to 150 degrees on the unit circle: y up to 1 (at 90), x from cos 150 to cos 30.
  const double pi = std::numbers::pi;
  const BSplineCurve arc = make_arc(0.0, 0.0, 1.0, pi / 6, 2 * pi / 3).value();
  const Box box = bounding_box(arc);
  EXPECT_NEAR(box.upper[1], 1.0, 1e-14);
  EXPECT_NEAR(box.lower[1], 0.5, 1e-14);
  EXPECT_NEAR(box.lower[0], -std::sqrt(3.0) / 2, 1e-14);
  EXPECT_NEAR(box.upper[0], std::sqrt(3.0) / 2, 1e-14);
}

TEST(BoundingBox, OfAParabolaIsTighterThanItsPolygon) {
  // (0,0), (1,2), (2,0): y = 4t(1-t) peaks at 1 (t = 1/2), the polygon reaches 2.
  const auto parabola = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 0}}).value()).value();
  const Box box = bounding_box(parabola);
  EXPECT_EQ(box.lower, (Point{0, 0}));
  EXPECT_NEAR(box.upper[0], 2.0, 1e-15);
  EXPECT_NEAR(box.upper[1], 1.0, 1e-15);
}

void check_against_samples(CurveView curve) {
  const Box box = bounding_box(curve);
  const int d = curve.dimension();
  const double slack = 1e-12 * std::max(1.0, scale_of(curve));
  std::vector<double> nearest_lower(d, INFINITY), nearest_upper(d, INFINITY);
  // 2000 samples on each Bézier piece (a piece's speed is bounded by its
  // polygon, so the samples of a fast piece are as dense as a slow one's).
  for (const BezierCurve& piece : to_bezier_pieces(curve).pieces)
    for (int i = 0; i <= 2000; ++i) {
      const Point p = point_at(piece, i / 2000.0);
      for (int j = 0; j < d; ++j) {
        RC_ASSERT(p[j] >= box.lower[j] - slack);
        RC_ASSERT(p[j] <= box.upper[j] + slack);
        nearest_lower[j] = std::min(nearest_lower[j], p[j] - box.lower[j]);
        nearest_upper[j] = std::min(nearest_upper[j], box.upper[j] - p[j]);
      }
    }
  // Tight: near an extreme a coordinate is flat, so the samples come within
  // (spacing)^2 x curvature of it; 1e-4 of the scale bounds that generously.
  const double reach = 1e-4 * std::max(1.0, scale_of(curve));
  for (int j = 0; j < d; ++j) {
    RC_ASSERT(nearest_lower[j] <= reach);
    RC_ASSERT(nearest_upper[j] <= reach);
  }
}

RC_GTEST_PROP(BoundingBox, HoldsTheSamplesAndTouchesEveryFaceOnBezierCurves, ()) {
  const BezierCurve curve = *test::any_bezier_curve(6);
  check_against_samples(curve);
}

RC_GTEST_PROP(BoundingBox, HoldsTheSamplesAndTouchesEveryFaceOnBSplines, ()) {
  const BSplineCurve curve = *test::bspline_curve({.max_degree = 4});
  check_against_samples(curve);
}

}  // namespace
}  // namespace casteljau

namespace casteljau {
namespace {

TEST(PruningBox, TheTightBoxWidenedByTheMarginAndTheRounding) {
  // The unit circle about (3, 4): tight box [2, 4] x [3, 5], diagonal 2 sqrt 2,
  // largest |coordinate| 5; widened by 0.5 and by 1e-9 (2 sqrt 2 + 5).
  const BSplineCurve circle = make_circle(3.0, 4.0, 1.0).value();
  const Box box = pruning_box(circle, 0.5);
  const double rounding = tolerances::kBoxRoundingMargin * (2.0 * std::sqrt(2.0) + 5.0);
  EXPECT_NEAR(box.lower[0], 2.0 - 0.5 - rounding, 1e-15);
  EXPECT_NEAR(box.upper[0], 4.0 + 0.5 + rounding, 1e-15);
  EXPECT_NEAR(box.lower[1], 3.0 - 0.5 - rounding, 1e-15);
  EXPECT_NEAR(box.upper[1], 5.0 + 0.5 + rounding, 1e-15);
  // With no margin, still strictly around the tight box.
  const Box tight = bounding_box(circle), pruning = pruning_box(circle, 0.0);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_LT(pruning.lower[j], tight.lower[j]);
    EXPECT_GT(pruning.upper[j], tight.upper[j]);
  }
}

}  // namespace
}  // namespace casteljau

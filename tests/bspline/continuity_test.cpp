// Continuity at knots: predicted p - m (seed 001, corrected: the knot's
// multiplicity m, not a doubled control point) against the measured order.
#include "casteljau/bspline/continuity.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/knot_insertion.hpp"
#include "support/bspline_generators.hpp"

namespace casteljau {
namespace {

RC_GTEST_PROP(ContinuityAtKnots, MeasuredIsAtLeastPredicted, ()) {
  const auto curve = *test::bspline_curve({.allow_jumps = true});
  const auto knots = continuity_at_knots(curve);
  for (const auto& k : knots) {
    RC_ASSERT(k.predicted == curve.degree() - k.multiplicity);
    RC_ASSERT(k.measured.parametric >= k.predicted);
    RC_ASSERT(k.measured.parametric <= curve.degree());
    if (k.measured.parametric >= 1) RC_ASSERT(k.measured.tangent);
  }
}

RC_GTEST_PROP(ContinuityAtKnots, GenericPolynomialCurvesAreExactlyAsPredicted, ()) {
  // Random control points of a polynomial curve on clamped knots: the jump in
  // the (p-m+1)-th derivative is a generic nonzero combination, so the
  // measured order is the predicted one, not more.
  const auto curve = *test::bspline_curve({.rational = test::Rational::never, .allow_unclamped = false});
  for (const auto& k : continuity_at_knots(curve)) RC_ASSERT(k.measured.parametric == k.predicted);
}

TEST(ContinuityAtKnots, HandExampleWithEveryMultiplicity) {
  // Cubic, knots 0000 1 2 2 3 3 3 4 4 4 4 4: interior multiplicities 1, 2, 3
  // give C2, C1, C0 (The NURBS Book §2.2 property P2.5 and §3.2), with points in general position.
  const auto curve = BSplineCurve::make(3, {0, 0, 0, 0, 1, 2, 2, 3, 3, 3, 4, 4, 4, 4},
                                        PointArray::make({{0, 0}, {1, 3}, {2, 1}, {4, 4}, {5, -1}, {7, 2}, {8, 5},
                                                          {9, 1}, {11, 3}, {12, 0}})
                                            .value())
                         .value();
  const auto knots = continuity_at_knots(curve);
  ASSERT_EQ(knots.size(), 3u);
  const int multiplicity[] = {1, 2, 3};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(knots[i].value, i + 1.0);
    EXPECT_EQ(knots[i].multiplicity, multiplicity[i]);
    EXPECT_EQ(knots[i].predicted, 3 - multiplicity[i]);
    EXPECT_EQ(knots[i].measured.parametric, 3 - multiplicity[i]) << "knot " << i + 1;
  }
  EXPECT_TRUE(knots[0].measured.tangent);
  EXPECT_FALSE(knots[2].measured.tangent);  // a C0 corner in general position
}

TEST(ContinuityAtKnots, AnInsertedKnotIsAsSmoothAsTheCurve) {
  // Inserting u twice predicts C1 there, but the curve is one polynomial: C^p.
  const auto curve = BSplineCurve::make(3, {0, 0, 0, 0, 1, 1, 1, 1},
                                        PointArray::make({{0, 0}, {1, 3}, {2, -1}, {4, 1}}).value(), {1, 2, 1, 3})
                         .value();
  const auto refined = insert_knot(curve, 0.3, 2).value();
  const auto knots = continuity_at_knots(refined);
  ASSERT_EQ(knots.size(), 1u);
  EXPECT_EQ(knots[0].predicted, 1);
  EXPECT_EQ(knots[0].measured.parametric, 3);
  EXPECT_TRUE(knots[0].measured.tangent);
}

TEST(ContinuityAtKnots, GeometricButNotParametricTangentContinuity) {
  // Two cubics whose tangents at the joint are parallel with lengths 3 and 6:
  // C0 only, but G1 (same direction).
  const auto a = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}, {2, 1}, {3, 1}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{3, 1}, {5, 1}, {6, 0}, {7, -2}}).value()).value();
  const auto spline = from_bezier_pieces({{0, 1, 2}, {a, b}}).value();
  const auto knots = continuity_at_knots(spline);
  ASSERT_EQ(knots.size(), 1u);
  EXPECT_EQ(knots[0].measured.parametric, 0);
  EXPECT_TRUE(knots[0].measured.tangent);
  // A jump: multiplicity p+1 with different points.
  const auto jump = BSplineCurve::make(3, {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2},
                                       PointArray::make({{0, 0}, {1, 1}, {2, 1}, {3, 1}, {3, 2}, {5, 1}, {6, 0}, {7, -2}})
                                           .value())
                        .value();
  const auto jumps = continuity_at_knots(jump);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_EQ(jumps[0].predicted, -1);
  EXPECT_EQ(jumps[0].measured.parametric, -1);
  EXPECT_FALSE(jumps[0].measured.tangent);
}

}  // namespace
}  // namespace casteljau

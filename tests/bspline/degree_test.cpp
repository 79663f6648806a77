// Degree elevation (exact) and reduction (within a tolerance) of B-spline curves.
#include "casteljau/bspline/degree.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "casteljau/bezier/degree.hpp"
#include "casteljau/bspline/continuity.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/tolerance.hpp"
#include "support/bspline_generators.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

RC_GTEST_PROP(BSplineElevateDegree, KeepsTheShapeAndTheContinuity, ()) {
  const auto curve = *test::bspline_curve({.max_degree = 6});
  const int times = *rc::gen::inRange(1, 4);
  const auto elevated = elevate_degree(curve, times).value();
  RC_ASSERT(elevated.degree() == curve.degree() + times);
  RC_ASSERT(elevated.domain() == curve.domain());
  RC_ASSERT(test::largest_distance(curve, elevated) <= test::shape_tolerance(curve, 1e-11));
  // Every interior knot keeps its continuity p - m: multiplicity m + times.
  const auto before = knot_multiplicities(curve.knots());
  const auto after = knot_multiplicities(elevated.knots());
  for (const auto& k : before) {
    if (!(curve.domain().lower < k.value && k.value < curve.domain().upper)) continue;
    RC_ASSERT(multiplicity_of(elevated.knots(), k.value) == k.multiplicity + times);
  }
  // No knot appears that was not there.
  for (const auto& k : after) RC_ASSERT(multiplicity_of(curve.knots(), k.value) > 0);
}

TEST(BSplineElevateDegree, APolylineBecomesAC0Quadratic) {
  // Degree 1, knots 0 0 1 2 2: elevation gives knots 0 0 0 1 1 2 2 2 and the
  // points P0, (P0+P1)/2, P1, (P1+P2)/2, P2 (each segment's quadratic form).
  const auto line = BSplineCurve::make(1, {0, 0, 1, 2, 2}, PointArray::make({{0, 0}, {2, 4}, {6, 0}}).value()).value();
  const auto quadratic = elevate_degree(line).value();
  EXPECT_EQ(std::vector<double>(quadratic.knots().begin(), quadratic.knots().end()),
            (std::vector<double>{0, 0, 0, 1, 1, 2, 2, 2}));
  const double expected[5][2] = {{0, 0}, {1, 2}, {2, 4}, {4, 2}, {6, 0}};
  ASSERT_EQ(quadratic.control_points().size(), 5u);
  for (int i = 0; i < 5; ++i)
    for (int c = 0; c < 2; ++c) EXPECT_EQ(quadratic.control_points()[i][c], expected[i][c]) << i;
}

TEST(BSplineElevateDegree, ABezierCurveElevatesLikeABezierCurve) {
  const auto bezier = BezierCurve::make(PointArray::make({{0.1, 3}, {1.7, -2}, {2.2, 2.5}, {4, 1}}).value(),
                                        {1, 2, 0.5, 1.5})
                          .value();
  const auto spline = elevate_degree(to_bspline(bezier), 2).value();
  const auto reference = to_bspline(elevate_degree(bezier, 2));
  ASSERT_EQ(spline.control_points().size(), reference.control_points().size());
  for (std::size_t i = 0; i < spline.control_points().size(); ++i) {
    EXPECT_LE(distance(spline.control_points()[i], reference.control_points()[i]), 1e-14 * 8) << i;
    EXPECT_NEAR(spline.weights()[i], reference.weights()[i], 1e-15 * 4) << i;
  }
}

TEST(BSplineElevateDegree, RefusesBadCounts) {
  const auto line = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 1}}).value()).value();
  auto negative = elevate_degree(line, -1);
  ASSERT_FALSE(negative.has_value());
  EXPECT_EQ(negative.error().message, "the degree cannot be elevated -1 times, it must be >= 0");
  auto huge = elevate_degree(line, tolerances::kMaxBSplineDegree);
  ASSERT_FALSE(huge.has_value());
  EXPECT_NE(huge.error().message.find("above the limit"), std::string::npos);
  EXPECT_EQ(elevate_degree(line, 0).value(), line);
}

RC_GTEST_PROP(BSplineReduceDegree, UndoesAnElevation, ()) {
  const auto curve = *test::bspline_curve({.min_degree = 2, .max_degree = 5, .max_extra_points = 6, .rational = test::Rational::never});
  const auto elevated = elevate_degree(curve).value();
  const double tol = test::shape_tolerance(curve, 1e-8);
  const auto reduced = reduce_degree(elevated, Tolerance{tol}).value();
  RC_ASSERT(reduced.curve.degree() == curve.degree());
  RC_ASSERT(reduced.error_bound <= tol);
  RC_ASSERT(test::largest_distance(curve, reduced.curve) <= tol);
  // The exact lower-degree curve has the original knots: all removed again.
  RC_ASSERT(reduced.curve.control_points().size() <= elevated.control_points().size());
}

RC_GTEST_PROP(BSplineReduceDegree, StaysWithinTheReportedBound, ()) {
  const auto curve = *test::bspline_curve({.min_degree = 2, .max_degree = 6, .max_extra_points = 6, .rational = test::Rational::never});
  const double tol = std::max(1.0, scale_of(curve.control_points())) * 0.5;
  const auto reduced = reduce_degree(curve, Tolerance{tol});
  if (!reduced) {
    RC_ASSERT(reduced.error().message.find("cannot be reduced within") != std::string::npos);
    return;
  }
  RC_ASSERT(reduced->curve.degree() == curve.degree() - 1);
  RC_ASSERT(reduced->error_bound <= tol);
  RC_ASSERT(test::largest_distance(curve, reduced->curve, 256) <=
            reduced->error_bound + test::shape_tolerance(curve, 1e-11));
}

TEST(BSplineReduceDegree, RefusesWhatItCannotDo) {
  const auto cubic = BSplineCurve::make(3, {0, 0, 0, 0, 1, 1, 1, 1},
                                        PointArray::make({{0, 0}, {1, 3}, {2, -3}, {3, 0}}).value())
                         .value();
  auto tight = reduce_degree(cubic, Tolerance{1e-6});
  ASSERT_FALSE(tight.has_value());
  EXPECT_NE(tight.error().message.find("degree 3 cannot be reduced within 1e-06: piece 0 on [0, 1]"),
            std::string::npos);
  EXPECT_FALSE(reduce_degree(cubic, Tolerance{0.0}).has_value());
  EXPECT_FALSE(reduce_degree(cubic, Tolerance{std::nan("")}).has_value());
  const auto line = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 1}}).value()).value();
  EXPECT_FALSE(reduce_degree(line, Tolerance{1.0}).has_value());
  const auto rational = BSplineCurve::make(2, {0, 0, 0, 1, 1, 1}, PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(),
                                           {1, 0.7, 1})
                            .value();
  auto r = reduce_degree(rational, Tolerance{1.0});
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("rational"), std::string::npos);
}

}  // namespace
}  // namespace casteljau

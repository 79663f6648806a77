// Joining two curves: the inverse of splitting, different degrees, gaps.
#include "casteljau/bspline/join.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/bspline/transform.hpp"
#include "support/bspline_generators.hpp"

namespace casteljau {
namespace {

RC_GTEST_PROP(Join, UndoesASplit, ()) {
  const auto curve = *test::bspline_curve();
  const Interval domain = curve.domain();
  const double u = *test::parameter_in(curve);
  RC_PRE(domain.lower < u && u < domain.upper);
  const auto [left, right] = split_at(curve, u).value();
  const auto joined = join(left, right).value();
  RC_ASSERT(joined.gap == 0.0);
  RC_ASSERT(joined.joint == u);
  RC_ASSERT(joined.curve.domain() == domain);
  RC_ASSERT(test::largest_distance(curve, joined.curve) <= test::shape_tolerance(curve));
  // The joint is as smooth as the curve was there.
  const int predicted = curve.degree() - multiplicity_of(curve.knots(), u);
  RC_ASSERT(joined.continuity.parametric >= predicted);
}

RC_GTEST_PROP(Join, ShiftsTheSecondDomainAndKeepsBothShapes, ()) {
  const auto a = *test::bspline_curve({.max_degree = 4});
  auto b = *test::bspline_curve({.max_degree = 4, .dimension = a.dimension()});
  // Move b so that it starts where a ends (a translation of its control points).
  const Point end = point_at(a, a.domain().upper), start = point_at(b, b.domain().lower);
  PointArray moved = b.control_points();
  for (std::size_t i = 0; i < moved.size(); ++i)
    for (int c = 0; c < b.dimension(); ++c) moved[i][c] += end[c] - start[c];
  std::vector<double> weights(b.weights().begin(), b.weights().end());
  b = BSplineCurve::make(b.degree(), {b.knots().begin(), b.knots().end()}, moved, weights).value();
  const auto joined = join(a, b).value();
  RC_ASSERT(joined.curve.degree() == std::max(a.degree(), b.degree()));
  const double length = a.domain().length() + b.domain().length();
  RC_ASSERT(std::abs(joined.curve.domain().length() - length) <= 1e-12 * length);
  const double tol = std::max(test::shape_tolerance(a, 1e-11), test::shape_tolerance(b, 1e-11)) + joined.gap;
  RC_ASSERT(test::largest_distance(a, joined.curve) <= tol);
  const double shift = a.domain().upper - b.domain().lower;
  RC_ASSERT(test::largest_distance(b, joined.curve, [&](double u) { return std::max(u + shift, a.domain().upper); }) <=
            tol + 1e-9 * std::max(1.0, scale_of(b.control_points())));
  RC_ASSERT(joined.continuity.parametric >= 0);
}

TEST(Join, ALineAndACubicGiveAC0Cubic) {
  const auto line = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {3, 0}}).value()).value();
  const auto cubic = BSplineCurve::make(3, {5, 5, 5, 5, 7, 7, 7, 7},
                                        PointArray::make({{3, 0}, {4, 1}, {5, 1}, {6, 0}}).value())
                         .value();
  const auto joined = join(line, cubic).value();
  EXPECT_EQ(joined.curve.degree(), 3);
  EXPECT_EQ(joined.curve.domain(), (Interval{0, 3}));
  EXPECT_EQ(std::vector<double>(joined.curve.knots().begin(), joined.curve.knots().end()),
            (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 3, 3, 3, 3}));
  EXPECT_EQ(joined.continuity.parametric, 0);
  EXPECT_FALSE(joined.continuity.tangent);  // (1,0) then (1,1): a 45 degree corner
  EXPECT_EQ(point_at(joined.curve, 2.0), point_at(cubic, 6.0));
}

TEST(Join, ASmoothJoinIsMeasuredSmooth) {
  // The line y = 0 from (0,0) to (1,0) on [0,1], then from (1,0) to (3,0) on [0,2]:
  // the same speed, so C^inf, and p = 1 caps the measure at 1.
  const auto a = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 0}}).value()).value();
  const auto b = BSplineCurve::make(1, {0, 0, 2, 2}, PointArray::make({{1, 0}, {3, 0}}).value()).value();
  const auto joined = join(a, b).value();
  EXPECT_EQ(joined.continuity.parametric, 1);
  EXPECT_TRUE(joined.continuity.tangent);
}

TEST(Join, RefusesCurvesThatDoNotMeet) {
  const auto a = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 0}}).value()).value();
  const auto b = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{1, 0.5}, {2, 0}}).value()).value();
  auto r = join(a, b);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().message,
            "the curves do not meet: the first ends at (1, 0), the second starts at (1, 0.5), a gap of 0.5 "
            "(more than 2e-09 allowed at their scale)");
  const auto c3 = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{1, 0, 0}, {2, 0, 0}}).value()).value();
  auto dimension = join(a, c3);
  ASSERT_FALSE(dimension.has_value());
  EXPECT_EQ(dimension.error().message, "cannot join a curve of dimension 2 to one of dimension 3");
}

TEST(Join, RationalAndPolynomial) {
  // A quarter circle (NURBS) followed by a straight line: weights scaled to agree.
  const double s = std::sqrt(0.5);
  const auto arc = BSplineCurve::make(2, {0, 0, 0, 1, 1, 1}, PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(),
                                      {2, 2 * s, 2})
                       .value();
  const auto line = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 1}, {-1, 1}}).value()).value();
  const auto joined = join(arc, line).value();
  ASSERT_TRUE(joined.curve.is_rational());
  for (int i = 0; i <= 20; ++i) {
    const Point p = point_at(joined.curve, i / 20.0);
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 1e-15 * 4);
  }
  EXPECT_TRUE(joined.continuity.tangent);  // the arc's end tangent is (-1, 0), like the line
  EXPECT_LE(distance(point_at(joined.curve, 1.5), Point{-0.5, 1}), 1e-15 * 4);
}

}  // namespace
}  // namespace casteljau

// Reversal, reparameterization, clamping and splitting keep the shape.
#include "casteljau/bspline/transform.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "support/bspline_generators.hpp"

namespace casteljau {
namespace {

RC_GTEST_PROP(BSplineReversed, TraversesTheSameCurveBackwards, ()) {
  const auto curve = *test::bspline_curve();
  const auto back = reversed(curve);
  const Interval domain = curve.domain();
  RC_ASSERT(back.domain() == domain);
  const double sum = domain.lower + domain.upper;
  RC_ASSERT(test::largest_distance(curve, back, [&](double u) { return sum - u; }) <= test::shape_tolerance(curve));
  // Twice is the original shape again (the knots may differ by rounding).
  RC_ASSERT(test::largest_distance(curve, reversed(back)) <= test::shape_tolerance(curve));
}

TEST(BSplineReversed, MirrorsTheKnotsExactlyOnDyadicData) {
  const auto curve = BSplineCurve::make(2, {0, 0, 0, 0.25, 1, 1, 1},
                                        PointArray::make({{0, 0}, {1, 2}, {3, 1}, {4, 0}}).value(), {1, 2, 3, 4})
                         .value();
  const auto back = reversed(curve);
  EXPECT_EQ(std::vector<double>(back.knots().begin(), back.knots().end()),
            (std::vector<double>{0, 0, 0, 0.75, 1, 1, 1}));
  EXPECT_EQ(back.control_points()[0][0], 4.0);
  EXPECT_EQ(back.weights()[0], 4.0);
  EXPECT_EQ(point_at(back, 0.0), point_at(curve, 1.0));
}

RC_GTEST_PROP(BSplineReparameterized, MapsTheDomainAffinely, ()) {
  const auto curve = *test::bspline_curve();
  const double c = *rc::gen::inRange(-100, 100) / 4.0;
  const double length = *rc::gen::inRange(1, 400) / 8.0;
  const auto moved = reparameterized(curve, {c, c + length}).value();
  RC_ASSERT(moved.domain() == (Interval{c, c + length}));
  const Interval domain = curve.domain();
  const auto map = [&](double u) { return u == domain.upper ? c + length : c + (u - domain.lower) * length / domain.length(); };
  RC_ASSERT(test::largest_distance(curve, moved, map) <= test::shape_tolerance(curve, 1e-11));
  // First derivatives scale by (b - a) / (d - c) (chain rule).
  const double u = domain.lerp(0.37);
  const Point d0 = derivative_at(curve, u, 1), d1 = derivative_at(moved, map(u), 1);
  const double ratio = domain.length() / length;
  double worst = 0.0, size = 1.0;
  for (std::size_t i = 0; i < d0.size(); ++i) {
    worst = std::max(worst, std::abs(d1[i] - d0[i] * ratio));
    size = std::max(size, std::abs(d0[i] * ratio));
  }
  RC_ASSERT(worst <= 1e-9 * size);
}

TEST(BSplineReparameterized, RefusesAnEmptyOrInfiniteDomain) {
  const auto curve = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 1}}).value()).value();
  auto empty = reparameterized(curve, {2, 2});
  ASSERT_FALSE(empty.has_value());
  EXPECT_EQ(empty.error().message, "the new domain [2, 2] must be finite with lower < upper");
  EXPECT_FALSE(reparameterized(curve, {0, INFINITY}).has_value());
  EXPECT_FALSE(reparameterized(curve, {3, 1}).has_value());
}

RC_GTEST_PROP(BSplineClamped, KeepsTheShapeAndInterpolatesTheEnds, ()) {
  const auto curve = *test::bspline_curve();
  const auto c = clamped(curve);
  RC_ASSERT(c.domain() == curve.domain());
  const int p = curve.degree();
  RC_ASSERT(multiplicity_of(c.knots(), c.domain().lower) == p + 1);
  RC_ASSERT(multiplicity_of(c.knots(), c.domain().upper) == p + 1);
  RC_ASSERT(test::largest_distance(curve, c) <= test::shape_tolerance(curve));
  const double tol = test::shape_tolerance(curve);
  RC_ASSERT(distance(c.control_points()[0], point_at(curve, curve.domain().lower)) <= tol);
  RC_ASSERT(distance(c.control_points()[c.control_points().size() - 1], point_at(curve, curve.domain().upper)) <= tol);
}

RC_GTEST_PROP(BSplineSplitAt, BothPartsFollowTheCurve, ()) {
  const auto curve = *test::bspline_curve({.allow_jumps = true});
  const Interval domain = curve.domain();
  const double u = *test::parameter_in(curve);
  RC_PRE(domain.lower < u && u < domain.upper);
  const auto [left, right] = split_at(curve, u).value();
  RC_ASSERT(left.domain() == (Interval{domain.lower, u}));
  RC_ASSERT(right.domain() == (Interval{u, domain.upper}));
  const double tol = test::shape_tolerance(curve);
  // Each part against the curve on its own domain (the part is the reference there).
  RC_ASSERT(test::largest_distance(right, curve) <= tol);
  if (multiplicity_of(curve.knots(), u) > curve.degree()) {
    // A jump at u: the curve takes its right limit there, the left part the
    // left one; compare before u only.
    for (int i = 0; i < 64; ++i) {
      const double t = left.domain().lerp(i / 64.0);
      RC_ASSERT(distance(point_at(left, t), point_at(curve, t)) <= tol);
    }
  } else {
    RC_ASSERT(test::largest_distance(left, curve) <= tol);
    const auto& lp = left.control_points();
    // A continuous curve: both parts share the cut point, which is C(u).
    RC_ASSERT(distance(lp[lp.size() - 1], right.control_points()[0]) == 0.0);
    RC_ASSERT(distance(lp[lp.size() - 1], point_at(curve, u)) <= tol);
  }
}

TEST(BSplineSplitAt, RefusesParametersNotInsideTheDomain) {
  const auto curve = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 1}}).value()).value();
  for (double u : {0.0, 1.0, -3.0}) {
    auto r = split_at(curve, u);
    ASSERT_FALSE(r.has_value());
    EXPECT_NE(r.error().message.find("is not strictly inside the domain [0, 1]"), std::string::npos) << u;
  }
  auto nan = split_at(curve, std::nan(""));
  ASSERT_FALSE(nan.has_value());
  EXPECT_EQ(nan.error().message, "the split parameter is NaN");
}

}  // namespace
}  // namespace casteljau

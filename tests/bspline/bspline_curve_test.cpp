// BSplineCurve::make's checks, the homogeneous form, Bézier and periodic curves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"

namespace casteljau {
namespace {

PointArray points(std::vector<std::vector<double>> rows) { return *PointArray::make(rows); }

std::string make_error(int p, std::vector<double> knots, PointArray cps, std::vector<double> weights = {}) {
  auto curve = BSplineCurve::make(p, std::move(knots), std::move(cps), std::move(weights));
  return curve ? std::string("(no error)") : curve.error().message;
}

TEST(BSplineCurveMake, RefusesBadInputWithOneMessage) {
  const auto square = points({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const std::vector<double> knots{0, 0, 0, 0.5, 1, 1, 1};
  EXPECT_TRUE(BSplineCurve::make(2, knots, square));
  EXPECT_EQ(make_error(-1, knots, square), "degree -1 is outside [0, 10000]");
  EXPECT_EQ(make_error(4, {0, 0, 0, 0, 0, 1, 1, 1, 1}, square),
            "4 control points, a B-spline of degree 4 needs at least 5");
  EXPECT_EQ(make_error(2, {0, 0, 0, 1, 1, 1}, square),
            "6 knots given, a B-spline of this degree and control point count needs 7 (control points + degree + 1)");
  EXPECT_EQ(make_error(2, {0, 0, 0, 0.5, 0.4, 1, 1}, square),
            "knot 4 (0.4) is smaller than knot 3 (0.5), knots must be non-decreasing");
  EXPECT_EQ(make_error(2, knots, square, {1, 0, 1, 1}), "weight 1 is 0, weights must be > 0");
  EXPECT_EQ(make_error(2, knots, square, {1, 1, -2.5, 1}), "weight 2 is -2.5, weights must be > 0");
  EXPECT_EQ(make_error(2, knots, square, {1, 1, 1}),
            "3 weights for 4 control points, there must be one weight per control point");
  EXPECT_EQ(make_error(2, knots, square, {1, std::numeric_limits<double>::infinity(), 1, 1}), "weight 1 is infinite");
  auto with_nan = square;
  with_nan[2][1] = std::nan("");
  EXPECT_EQ(make_error(2, knots, with_nan), "coordinate 1 of control point 2 is NaN");
}

TEST(BSplineCurve, DomainIsFromKnotPToKnotNPlusOne) {
  const auto curve = *BSplineCurve::make(2, {-1, 0, 1, 2, 3, 4, 5}, points({{0}, {1}, {3}, {2}}));
  EXPECT_EQ(curve.domain(), (Interval{1, 3}));
  EXPECT_FALSE(curve.is_rational());
}

TEST(BSplineCurve, HomogeneousFormRoundTrips) {
  const auto curve = *BSplineCurve::make(2, {0, 0, 0, 0.5, 1, 1, 1}, points({{0, 0}, {1, 0}, {1, 1}, {0, 1}}),
                                         {1, 0.5, 2, 1});
  const PointArray h = homogeneous_points(curve);
  EXPECT_EQ(h.dimension(), 3);
  EXPECT_EQ(h[2][0], 2.0);
  EXPECT_EQ(h[2][2], 2.0);
  const BSplineCurve back = from_homogeneous(2, std::vector<double>(curve.knots().begin(), curve.knots().end()), h);
  EXPECT_EQ(back, curve);
}

TEST(BSplineCurve, ABezierCurveIsAClampedBSplineWithoutInteriorKnots) {
  // Seed 001 §1.2.3: with knots 0...0 1...1 the B-spline basis is Bernstein's.
  const auto bezier = *BezierCurve::make(points({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}}), {1, 2, 0.5, 1, 3});
  const BSplineCurve spline = to_bspline(bezier);
  EXPECT_EQ(spline.degree(), 4);
  EXPECT_EQ(std::vector<double>(spline.knots().begin(), spline.knots().end()),
            (std::vector<double>{0, 0, 0, 0, 0, 1, 1, 1, 1, 1}));
  for (int i = 0; i <= 32; ++i) {
    const double t = i / 32.0;
    const Point a = point_at(bezier, t);
    const Point b = point_at(spline, t);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(a[k], b[k], 1e-14 * 4);
  }
}

TEST(MakePeriodic, ClosesWithCpMinusOneContinuity) {
  const auto polygon = points({{0, 0}, {2, -1}, {4, 0}, {4, 3}, {1, 4}, {-1, 2}});
  for (int p = 1; p <= 4; ++p) {
    const auto curve = make_periodic(p, polygon, {}, {0, 6});
    ASSERT_TRUE(curve) << curve.error().message;
    EXPECT_EQ(curve->control_points().size(), polygon.size() + p);
    EXPECT_EQ(curve->domain(), (Interval{0, 6}));
    for (int k = 0; k < p; ++k) {
      const Point start = derivative_at(*curve, 0.0, k);
      const Point end = derivative_at(*curve, 6.0, k);
      for (int c = 0; c < 2; ++c) EXPECT_NEAR(start[c], end[c], 1e-12 * std::pow(10.0, k)) << "p=" << p << " k=" << k;
    }
  }
  const auto too_few = make_periodic(3, points({{0, 0}, {1, 0}, {1, 1}}));
  ASSERT_FALSE(too_few);
  EXPECT_EQ(too_few.error().message, "3 control points, a closed B-spline of degree 3 needs at least 4");
  EXPECT_EQ(make_periodic(0, polygon).error().message, "a closed B-spline needs degree >= 1, got 0");
}

}  // namespace
}  // namespace casteljau

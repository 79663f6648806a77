// Cubic approximation (ops/cubic_approximation.hpp): pieces of degree <= 3
// kept bit for bit; circles, arcs, high degrees and rational curves within the
// tolerance, measured against an independent reference (the circle's radius,
// closest_point's distances both ways), never above the certified bound.
#include "casteljau/ops/cubic_approximation.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// The largest distance from a sample of `from` (64 per piece) to `to`.
double one_sided_distance(CurveView from, CurveView to) {
  double largest = 0.0;
  const Interval domain = from.domain();
  const int samples = 64 * static_cast<int>(breakpoints(from).size());
  for (int k = 0; k <= samples; ++k) {
    const Point p = point_at(from, domain.lower + (domain.upper - domain.lower) * k / samples);
    largest = std::max(largest, closest_point(to, p).value().distance);
  }
  return largest;
}

TEST(CubicApproximation, KeepsPolynomialPiecesOfDegreeAtMostThreeExactly) {
  const auto line = BezierCurve::make(PointArray::make(2, {0, 0, 1, 1}).value()).value();
  const auto quadratic = BezierCurve::make(PointArray::make(2, {1, 1, 2, 3, 4, 1}).value()).value();
  const auto cubic = BezierCurve::make(PointArray::make(2, {4, 1, 5, 0, 6, 2, 7, 1}).value()).value();
  const auto curve = PiecewiseBezierCurve::make({line, quadratic, cubic}).value();
  const auto result = approximate_by_cubics(CurveView(curve), Tolerance{1e-9}).value();
  EXPECT_EQ(result.curve, curve);
  EXPECT_EQ(result.approximated_pieces, 0u);
  EXPECT_EQ(result.deviation_bound, 0.0);
}

TEST(CubicApproximation, TheNurbsCircleWithinEachTolerance) {
  const auto circle = make_circle(1.0, -2.0, 5.0).value();
  std::size_t previous = 0;
  for (double relative : {1e-2, 1e-4, 1e-6, 1e-9, 1e-11}) {
    const double tolerance = relative * 5.0;
    const auto result = approximate_by_cubics(CurveView(circle), Tolerance{tolerance}).value();
    EXPECT_EQ(result.approximated_pieces, 4u);
    EXPECT_LE(result.deviation_bound, tolerance);
    double radial = 0.0;  // the radius is the reference: no code under test
    for (const BezierCurve& piece : result.curve.pieces()) {
      ASSERT_FALSE(piece.is_rational());
      ASSERT_EQ(piece.degree(), 3);
      for (int k = 0; k <= 200; ++k) {
        const Point p = point_at(piece, k / 200.0);
        radial = std::max(radial, std::abs(std::hypot(p[0] - 1.0, p[1] + 2.0) - 5.0));
      }
    }
    EXPECT_LE(radial, result.deviation_bound + 1e-14 * 5.0) << relative;
    // Hermite error O(h^4): about 2^(log(10^k)/4) more cubics per decade, not more.
    EXPECT_GT(result.curve.pieces().size(), previous);
    previous = result.curve.pieces().size();
    EXPECT_LE(previous, 4u * static_cast<std::size_t>(std::ceil(std::pow(2.0, std::log2(1e-2 / relative) / 4.0 + 3))));
  }
  // Joints stay joints: each cubic starts where the previous ends, bit for bit.
  const auto fine = approximate_by_cubics(CurveView(circle), Tolerance{1e-6}).value();
  for (std::size_t j = 1; j < fine.curve.pieces().size(); ++j) {
    const auto& a = fine.curve.pieces()[j - 1].control_points();
    const auto& b = fine.curve.pieces()[j].control_points();
    EXPECT_EQ(a[3][0], b[0][0]);
    EXPECT_EQ(a[3][1], b[0][1]);
  }
}

TEST(CubicApproximation, RefusesToleranceItCannotCertify) {
  const auto circle = make_circle(0.0, 0.0, 1.0).value();
  EXPECT_FALSE(approximate_by_cubics(CurveView(circle), Tolerance{0.0}));
  EXPECT_FALSE(approximate_by_cubics(CurveView(circle), Tolerance{std::nan("")}));
  const auto tiny = approximate_by_cubics(CurveView(circle), Tolerance{1e-15});
  ASSERT_FALSE(tiny);
  EXPECT_NE(tiny.error().message.find("below what double precision can certify"), std::string::npos);
}

// Any curve: the approximation is cubic, within the tolerance of the curve
// both ways (sampled, against closest_point), under the certified bound.
RC_GTEST_PROP(CubicApproximation, WithinTheToleranceOfAnyPlaneCurve, ()) {
  const BezierCurve curve = *rc::gen::oneOf(test::bezier_curve(4, 9, false, 2), test::bezier_curve(1, 6, true, 2));
  const double size = size_of(CurveView(curve));
  RC_PRE(size > 1e-3);
  const double tolerance = size * *rc::gen::element(1e-2, 1e-4, 1e-6);
  const auto result = approximate_by_cubics(CurveView(curve), Tolerance{tolerance});
  RC_ASSERT(result.has_value());
  RC_ASSERT(result->deviation_bound <= tolerance);
  for (const BezierCurve& piece : result->curve.pieces()) {
    RC_ASSERT(!piece.is_rational());
    RC_ASSERT(piece.degree() <= 3);
  }
  const CurveView approximation(result->curve);
  RC_ASSERT(one_sided_distance(approximation, CurveView(curve)) <= tolerance * (1 + 1e-9));
  RC_ASSERT(one_sided_distance(CurveView(curve), approximation) <= tolerance * (1 + 1e-9));
}

}  // namespace
}  // namespace casteljau

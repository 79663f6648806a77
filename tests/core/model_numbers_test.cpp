// The ranges of valid model numbers (core/model_numbers.hpp): each bound is
// accepted and the next double beyond it refused, with one message naming
// the value; and the curve makes use them (issue 15: 1e308 coordinates were
// "finite" but their differences overflow, a weight of 1e-320 was
// "positive"). The bounds themselves come from core/tolerance.hpp.

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <string>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/tolerance.hpp"
#include "support/make.hpp"

namespace casteljau {
namespace {

using test::message_of;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ModelNumbers, CoordinatesUpToTheBoundAreValid) {
  const double bound = tolerances::kMaxCoordinate;
  for (const double x : {0.0, -0.0, 5e-324, 1e-310, -1.0, bound, -bound}) {
    EXPECT_TRUE(check_coordinate(x, "x").has_value()) << x;
    EXPECT_TRUE(is_valid_coordinate(x)) << x;
  }
  EXPECT_EQ(message_of(check_coordinate(std::nextafter(bound, kInf), "coordinate 1 of control point 3")),
            "coordinate 1 of control point 3 is 1.0000000000000002e+100, outside [-1e+100, 1e+100], the range of "
            "coordinates");
  EXPECT_EQ(message_of(check_coordinate(-1e308, "x")), "x is -1e+308, outside [-1e+100, 1e+100], the range of coordinates");
  EXPECT_EQ(message_of(check_coordinate(std::nan(""), "x")), "x is NaN");
  EXPECT_EQ(message_of(check_coordinate(-kInf, "x")), "x is infinite");
}

TEST(ModelNumbers, CheckCoordinatesNamesTheFirstBadOne) {
  const PointArray points = PointArray::from_trusted(2, {0, 1, 2, DBL_MAX, 1e308, 0});
  EXPECT_EQ(message_of(check_coordinates(points, "control point")),
            "coordinate 1 of control point 1 is 1.7976931348623157e+308, outside [-1e+100, 1e+100], the range of "
            "coordinates");
  EXPECT_TRUE(check_coordinates(PointArray::from_trusted(1, {1e100, -1e100}), "point").has_value());
}

TEST(ModelNumbers, WeightsWithinTheirRange) {
  for (const double w : {tolerances::kMinWeight, 1.0, tolerances::kMaxWeight}) {
    EXPECT_TRUE(check_weight(w, "weight 0").has_value()) << w;
  }
  EXPECT_EQ(message_of(check_weight(-1.0, "weight 2")), "weight 2 is -1, weights must be > 0");
  EXPECT_EQ(message_of(check_weight(0.0, "weight 2")), "weight 2 is 0, weights must be > 0");
  EXPECT_EQ(message_of(check_weight(1e-320, "weight 2")),
            "weight 2 is 1e-320, outside [1e-50, 1e+50], the range of weights");
  EXPECT_EQ(message_of(check_weight(std::nextafter(tolerances::kMinWeight, 0.0), "w")),
            "w is 9.999999999999999e-51, outside [1e-50, 1e+50], the range of weights");
  EXPECT_EQ(message_of(check_weight(std::nextafter(tolerances::kMaxWeight, kInf), "w")),
            "w is 1.0000000000000003e+50, outside [1e-50, 1e+50], the range of weights");
  EXPECT_EQ(message_of(check_weight(kInf, "w")), "w is infinite");
}

TEST(ModelNumbers, KnotsAndSpans) {
  EXPECT_TRUE(check_knot(tolerances::kMaxKnot, "knot 0").has_value());
  EXPECT_EQ(message_of(check_knot(-1e308, "knot 0")), "knot 0 is -1e+308, outside [-1e+100, 1e+100], the range of knots");
  // Equal knots (a multiplicity) and spans of at least the bound are valid;
  // so is a span of one ulp at 1 (2.2e-16, far above the bound).
  EXPECT_TRUE(check_span(0.5, 0.5, "knots 1 and 2").has_value());
  EXPECT_TRUE(check_span(0.0, tolerances::kMinKnotSpan, "knots 1 and 2").has_value());
  EXPECT_TRUE(check_span(1.0, std::nextafter(1.0, 2.0), "knots 1 and 2").has_value());
  EXPECT_EQ(message_of(check_span(0.0, 5e-324, "knots 1 and 2")),
            "knots 1 and 2 (0 and 5e-324) are 5e-324 apart, less than the narrowest "
            "knot span 1e-100");
  EXPECT_EQ(message_of(check_span(0.0, std::nextafter(tolerances::kMinKnotSpan, 0.0), "parameters 0 and 1")),
            "parameters 0 and 1 (0 and 9.999999999999999e-101) are 9.999999999999999e-101 apart, less than the "
            "narrowest knot span 1e-100");
}

TEST(ModelNumbers, CurveMakesRefuseCoordinatesAndWeightsBeyondTheRanges) {
  EXPECT_EQ(message_of(BezierCurve::make(PointArray::from_trusted(2, {-1e308, 0, 1e308, 0}))),
            "coordinate 0 of control point 0 is -1e+308, outside [-1e+100, 1e+100], the range of coordinates");
  EXPECT_EQ(message_of(BezierCurve::make(PointArray::from_trusted(1, {0, 1}), {1, 1e-320})),
            "weight 1 is 1e-320, outside [1e-50, 1e+50], the range of weights");
  EXPECT_EQ(message_of(BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::from_trusted(2, {0, 0, 1, 1e101}))),
            "coordinate 1 of control point 1 is 1e+101, outside [-1e+100, 1e+100], the range of coordinates");
  EXPECT_EQ(message_of(BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::from_trusted(1, {0, 1}), {DBL_MAX, 1})),
            "weight 0 is 1.7976931348623157e+308, outside [1e-50, 1e+50], the range of weights");
}

TEST(ModelNumbers, TheCornerOfTheRangesStillHasFiniteFirstDerivatives) {
  // The worst case of core/tolerance.hpp's bound in one span: coordinates
  // +-1e100, the narrowest span, the widest weight ratio. By hand (a
  // rational line): C'(0) = (w1 / w0) (P1 - P0) / h = 1e100 * 2e100 / 1e-100.
  const auto curve = BSplineCurve::make(1, {0, 0, 1e-100, 1e-100}, PointArray::from_trusted(1, {-1e100, 1e100}),
                                        {tolerances::kMinWeight, tolerances::kMaxWeight});
  ASSERT_TRUE(curve.has_value()) << curve.error().message;
  EXPECT_NEAR(derivative_at(*curve, 0.0, 1)[0] / 2e300, 1.0, 1e-14);
  for (const double u : {0.0, 1e-120, 5e-101, 1e-100}) {
    EXPECT_TRUE(std::isfinite(point_at(*curve, u)[0])) << u;
    EXPECT_TRUE(std::isfinite(derivative_at(*curve, u, 1)[0])) << u;
  }
  // A Bézier curve of the largest degree with the extreme coordinates: C'
  // is n (P1 - P0) at t = 0 when the other points equal P1.
  std::vector<double> coordinates(static_cast<std::size_t>(tolerances::kMaxBezierDegree) + 1, 1e100);
  coordinates[0] = -1e100;
  const auto bezier = BezierCurve::make(PointArray::from_trusted(1, coordinates));
  ASSERT_TRUE(bezier.has_value());
  EXPECT_EQ(derivative_at(*bezier, 0.0, 1)[0], tolerances::kMaxBezierDegree * 2e100);
}

}  // namespace
}  // namespace casteljau

// The safe spellings of code that would otherwise dangle, run under the
// sanitizers (make test's asan build): a value moved out of a temporary
// Expected lives as long as the reference or loop bound to it; accessors of a
// temporary curve hand over what they return. The unsafe spellings do not
// compile (tests/misuse/lifetimes.cpp). Also PointArray's iterators and the
// fixed-size scalar evaluation that needs no allocation.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <numeric>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/nurbs/conics.hpp"

namespace casteljau {
namespace {

Expected<PointArray> triangle() { return PointArray::make(2, {0.0, 0.0, 1.0, 2.0, 2.0, 0.0}); }

TEST(Lifetime, AReferenceToATemporaryExpectedsValueKeepsItAlive) {
  const PointArray& points = *triangle();  // operator* on a temporary moves the value out
  EXPECT_EQ(points.size(), 3u);
  EXPECT_EQ(points[1][1], 2.0);
  const auto& circle = make_circle(0.0, 0.0, 2.0).value();
  EXPECT_EQ(circle.knots().front(), 0.0);
}

TEST(Lifetime, ARangeForOverATemporaryExpectedIteratesALiveValue) {
  double sum = 0.0;
  for (auto point : *triangle()) sum += point[0] + point[1];
  EXPECT_EQ(sum, 5.0);
}

TEST(Lifetime, AccessorsOfATemporaryCurveHandOverTheirValue) {
  const PointArray polygon = BezierCurve::make(*triangle()).value().control_points();
  EXPECT_EQ(polygon, *triangle());
  double sum = 0.0;
  for (auto point : BezierCurve::make(*triangle()).value().control_points()) sum += point[0];
  EXPECT_EQ(sum, 3.0);
  const BezierCurve line = BezierCurve::make(PointArray::make(2, {0.0, 0.0, 1.0, 1.0}).value()).value();
  const std::vector<BezierCurve> pieces = PiecewiseBezierCurve::make({line, line}).value().pieces();
  EXPECT_EQ(pieces.size(), 2u);
}

TEST(PointArrayIterators, VisitEveryPointInOrderAsASpan) {
  const PointArray points = *triangle();
  static_assert(std::random_access_iterator<PointArray::const_iterator>);
  EXPECT_EQ(std::distance(points.begin(), points.end()), 3);
  std::vector<double> xs;
  for (auto point : points) {
    ASSERT_EQ(point.size(), 2u);
    xs.push_back(point[0]);
  }
  EXPECT_EQ(xs, (std::vector<double>{0.0, 1.0, 2.0}));
  EXPECT_EQ(points.begin()[2][0], 2.0);
  EXPECT_EQ((*(points.end() - 1))[1], 0.0);
  const auto highest = std::max_element(points.begin(), points.end(), [](auto a, auto b) { return a[1] < b[1]; });
  EXPECT_EQ(highest - points.begin(), 1);
}

TEST(PointArrayIterators, WriteThroughAMutableArray) {
  PointArray points = *triangle();
  for (auto point : points) point[1] += 1.0;
  EXPECT_EQ(points[0][1], 1.0);
  EXPECT_EQ(points[1][1], 3.0);
  PointArray::const_iterator first = points.begin();  // mutable converts to const
  EXPECT_EQ((*first)[1], 1.0);
}

TEST(PointArrayIterators, AnEmptyArrayHasNoPoints) {
  const PointArray none;
  EXPECT_EQ(none.begin(), none.end());
  EXPECT_EQ(none.end() - none.begin(), 0);
  const PointArray empty_plane = PointArray::make(2, {}).value();
  EXPECT_EQ(std::distance(empty_plane.begin(), empty_plane.end()), 0);
}

TEST(FixedSizeEvaluation, MatchesPointAtBitForBitOnEveryKind) {
  const BezierCurve cubic =
      BezierCurve::make(PointArray::make(2, {0.0, 0.0, 1.0, 3.0, 2.5, -1.0, 4.0, 0.5}).value()).value();
  const BezierCurve rational = BezierCurve::make(*triangle(), {1.0, 0.25, 2.0}).value();
  const BSplineCurve circle = make_circle(1.0, -2.0, 3.0).value();
  const PiecewiseBezierCurve both = PiecewiseBezierCurve::make({cubic, rational}).value();
  for (CurveView curve : {CurveView(cubic), CurveView(rational), CurveView(circle), CurveView(both)}) {
    const Interval domain = curve.domain();
    for (int k = 0; k <= 16; ++k) {
      const double u = domain.lower + (domain.upper - domain.lower) * k / 16.0;
      const Vec2 fixed = point_at<2>(curve, u);
      const Point general = point_at(curve, u);
      EXPECT_EQ(fixed[0], general[0]) << u;
      EXPECT_EQ(fixed[1], general[1]) << u;
      const Vec2 velocity = derivative_at<2>(curve, u, 1);
      const Point expected = derivative_at(curve, u, 1);
      EXPECT_EQ(velocity[0], expected[0]) << u;
      EXPECT_EQ(velocity[1], expected[1]) << u;
    }
  }
}

TEST(PointArray, RowsWithoutAnyRowAreRefusedForWantOfADimension) {
  const auto none = PointArray::make({});
  ASSERT_FALSE(none.has_value());
  EXPECT_EQ(none.error().message, "no points: an empty set has no dimension (make(dimension, {}) makes one)");
  EXPECT_TRUE(PointArray::make(3, {}).has_value());
}

}  // namespace
}  // namespace casteljau

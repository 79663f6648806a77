// Subdivision: halves reproduce the curve, the split point is point_at bit
// for bit (lib2geom's rule), seed 004's recursive subdivision gives 2^r + 1 points.
#include "casteljau/bezier/split.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "casteljau/bezier/evaluate.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

double max_distance(const Point& a, const Point& b) { return distance(a, b); }

RC_GTEST_PROP(SplitAt, HalvesReproduceTheCurve, ()) {
  const auto curve = *test::any_bezier_curve(15);
  const double t = *rc::gen::map(rc::gen::inRange(1, 1000), [](int i) { return i / 1000.0; });
  const auto [left, right] = split_at(curve, t).value();
  RC_ASSERT(left.degree() == curve.degree() && right.degree() == curve.degree());
  const double tol = 1e-12 * std::max(1.0, scale_of(curve.control_points()));
  for (int i = 0; i <= 16; ++i) {
    const double u = i / 16.0;
    RC_ASSERT(max_distance(point_at(left, u), point_at(curve, t * u)) <= tol);
    RC_ASSERT(max_distance(point_at(right, u), point_at(curve, t + (1 - t) * u)) <= tol);
  }
}

RC_GTEST_PROP(SplitAt, SplitPointIsPointAtBitForBit, ()) {
  const auto curve = *test::any_bezier_curve(20);
  const double t = *test::unit_parameter();
  RC_PRE(t > 0.0 && t < 1.0);
  const auto [left, right] = split_at(curve, t).value();
  const Point p = point_at(curve, t);
  const auto& l = left.control_points();
  const auto& r = right.control_points();
  RC_ASSERT(Point(l[l.size() - 1].begin(), l[l.size() - 1].end()) == p);
  RC_ASSERT(Point(r[0].begin(), r[0].end()) == p);
}

RC_GTEST_PROP(ExtendedSegment, ReproducesTheCurveOnItsInterval, ()) {
  const auto curve = *test::any_bezier_curve(10);
  const double t0 = *test::unit_parameter(), t1 = *test::unit_parameter();
  const auto piece = extended_segment(curve, t0, t1);
  const double tol = 1e-12 * std::max(1.0, scale_of(curve.control_points()));
  for (int i = 0; i <= 8; ++i) {
    const double u = i / 8.0;
    RC_ASSERT(max_distance(point_at(piece, u), point_at(curve, t0 + (t1 - t0) * u)) <= tol);
  }
}

TEST(ExtendedSegment, HighDegreeReversedAndExtrapolatedPieces) {
  // Two subdivisions, O(n^2): at degree 1000 a piece costs about as much as
  // three evaluations (one blossom per control point cost O(n^3), a billion
  // steps here). Reference: point_at on the whole curve, at every kind of
  // interval: forward, reversed, from or to 0, a single point, outside [0, 1].
  std::vector<double> coordinates;
  for (int i = 0; i <= 1000; ++i) coordinates.insert(coordinates.end(), {std::cos(0.37 * i), std::sin(0.91 * i)});
  const auto curve = BezierCurve::make(PointArray::make(2, std::move(coordinates)).value()).value();
  const double pieces[][2] = {{0.2, 0.3}, {0.7, 0.25}, {0.0, 0.01}, {0.99, 1.0}, {0.0, 0.0}, {0.4, 0.4}, {1.0, 0.0}};
  for (const auto& [t0, t1] : pieces) {
    const auto piece = extended_segment(curve, t0, t1);
    ASSERT_EQ(piece.degree(), 1000);
    for (int i = 0; i <= 8; ++i) {
      const double u = i / 8.0;
      EXPECT_LE(max_distance(point_at(piece, u), point_at(curve, t0 + (t1 - t0) * u)), 1e-12) << t0 << " " << t1;
    }
  }
  // A cubic, and a rational quadratic (a quarter circle: weights positive beyond [0, 1] too).
  const auto cubic = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {3, 2}, {4, 0}}).value()).value();
  const auto arc = BezierCurve::make(PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(), {1.0, std::sqrt(0.5), 1.0}).value();
  for (const auto* c : {&cubic, &arc})
    for (const auto& [t0, t1] : {std::pair{-0.5, 1.5}, std::pair{1.2, -0.3}, std::pair{-1.0, 0.0}, std::pair{1.1, 1.3}}) {
      const auto piece = extended_segment(*c, t0, t1);
      for (int i = 0; i <= 8; ++i) {
        const double u = i / 8.0;
        EXPECT_LE(max_distance(point_at(piece, u), point_at(*c, t0 + (t1 - t0) * u)), 1e-12) << t0 << " " << t1;
      }
    }
}

TEST(Segment, IsTheExtendedSegmentInsideTheDomainAndRefusesTheRest) {
  const auto cubic = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {3, 2}, {4, 0}}).value()).value();
  EXPECT_EQ(segment(cubic, 0.25, 0.75).value(), extended_segment(cubic, 0.25, 0.75));
  EXPECT_EQ(segment(cubic, 0.0, 1.0).value(), extended_segment(cubic, 0.0, 1.0));
  EXPECT_EQ(segment(cubic, 0.75, 0.25).error().message, "the segment [0.75, 0.25] needs its start below its end");
  EXPECT_EQ(segment(cubic, -0.5, 0.5).error().message, "the segment [-0.5, 0.5] is not inside the domain [0, 1]");
  EXPECT_EQ(segment(cubic, 0.5, 1.5).error().message, "the segment [0.5, 1.5] is not inside the domain [0, 1]");
  EXPECT_EQ(segment(cubic, 0.5, 0.5).error().message, "the segment [0.5, 0.5] needs its start below its end");
  EXPECT_EQ(segment(cubic, std::nan(""), 0.5).error().message, "the segment's start is NaN");
  EXPECT_EQ(split_at(cubic, 0.0).error().message, "the split parameter 0 is not strictly inside the domain [0, 1]");
  EXPECT_EQ(split_at(cubic, 1.0).error().message, "the split parameter 1 is not strictly inside the domain [0, 1]");
  EXPECT_EQ(split_at(cubic, INFINITY).error().message, "the split parameter is infinite");
}

RC_GTEST_PROP(Reversed, TraversesBackwards, ()) {
  const auto curve = *test::any_bezier_curve(10);
  const double t = *test::unit_parameter();
  const double tol = 1e-12 * std::max(1.0, scale_of(curve.control_points()));
  RC_ASSERT(max_distance(point_at(reversed(curve), t), point_at(curve, 1 - t)) <= tol);
}

TEST(SubdivideRecursive, SeedNotebookGives1025Points) {
  // Seed 004: bezier(Ps, 10) with Ps = (0,0),(1,2),(2,3),(4,1),(5,3) has 1025 points.
  const auto curve = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 3}, {4, 1}, {5, 3}}).value()).value();
  const auto points = subdivide_recursive(curve, 10).value();
  ASSERT_EQ(points.size(), 1025u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point p = point_at(curve, i / 1024.0);
    EXPECT_LE(distance(points[i], p), 1e-14 * 5) << i;
  }
  EXPECT_EQ(subdivide_recursive(curve, 0).value().size(), 2u);
}

TEST(SubdivideRecursive, RefusesHugeOrBadRequests) {
  const auto curve = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value()).value();
  EXPECT_FALSE(subdivide_recursive(curve, -1).has_value());
  const auto huge = subdivide_recursive(curve, 40);
  ASSERT_FALSE(huge.has_value());
  EXPECT_NE(huge.error().message.find("depth 40"), std::string::npos);
  EXPECT_FALSE(subdivide_recursive(curve, 3, 1.0).has_value());
  EXPECT_FALSE(subdivide_recursive(curve, 3, NAN).has_value());
}

}  // namespace
}  // namespace casteljau

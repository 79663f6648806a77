// The cutting order (io/gcode_order.hpp). The reference for nearest
// neighbour is the plain search (support/greedy_order_oracle.hpp: every way
// into every contour left, at every step); 2-opt and the joints are checked by what they must
// keep: every contour cut once, as the same segments, and the rapid moves
// never longer (rapidcheck, integer coordinates for many ties), plus cases
// worked by hand.
#include "casteljau/io/gcode_order.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "support/greedy_order_oracle.hpp"

namespace casteljau {
namespace {

constexpr Tolerance kOrderTolerance{0.01};

/// A closed polygon through the points, or an open polyline.
GcodeContour order_polyline(const std::vector<Vec2>& points, bool closed) {
  GcodeContour contour;
  for (std::size_t k = 1; k < points.size(); ++k) contour.push_back(ArcSegment{points[k - 1], points[k], 0.0});
  if (closed) contour.push_back(ArcSegment{points.back(), points.front(), 0.0});
  return contour;
}

/// Seeded contours scattered in a 1000 x 1000 field: small triangles
/// (closed) and two-segment open polylines, with a bulge on some segments.
std::vector<GcodeContour> scattered_contours(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> place(0.0, 1000.0), step(-3.0, 3.0), bulge(-0.5, 0.5);
  std::vector<GcodeContour> contours;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec2 a{{place(random), place(random)}};
    const Vec2 b = a + Vec2{{step(random), step(random)}}, c = b + Vec2{{step(random), step(random)}};
    GcodeContour contour = order_polyline({a, b, c}, k % 3 != 0);
    contour.front().bulge = bulge(random);
    contours.push_back(contour);
  }
  return contours;
}

/// A contour as a set of segments, whatever its rotation and direction.
std::vector<std::tuple<double, double, double, double, double>> segment_set(const GcodeContour& contour) {
  std::vector<std::tuple<double, double, double, double, double>> set;
  for (const ArcSegment& s : contour) {
    const bool forward = std::pair{s.start[0], s.start[1]} < std::pair{s.end[0], s.end[1]};
    const Vec2 a = forward ? s.start : s.end, b = forward ? s.end : s.start;
    set.emplace_back(a[0], a[1], b[0], b[1], std::abs(s.bulge));
  }
  std::sort(set.begin(), set.end());
  return set;
}

/// Whether two lists hold the same contours (as segment sets), each once.
bool same_contours(const std::vector<GcodeContour>& a, const std::vector<GcodeContour>& b) {
  std::vector<std::vector<std::tuple<double, double, double, double, double>>> sa, sb;
  for (const GcodeContour& c : a) sa.push_back(segment_set(c));
  for (const GcodeContour& c : b) sb.push_back(segment_set(c));
  std::sort(sa.begin(), sa.end());
  std::sort(sb.begin(), sb.end());
  return sa == sb;
}

/// Whether every contour of the order chains: each segment starts where the one before ends.
bool chains(const std::vector<GcodeContour>& order) {
  for (const GcodeContour& contour : order)
    for (std::size_t k = 1; k < contour.size(); ++k)
      if (contour[k].start != contour[k - 1].end) return false;
  return true;
}

TEST(GcodeOrder, NearestNeighbourIsThePlainGreedyOrder) {
  for (int passes : {1, 2}) {
    const std::vector<GcodeContour> contours = scattered_contours(2000, 20261206 + passes);
    const std::vector<GcodeContour> order = nearest_neighbour_order(contours, kOrderTolerance, passes);
    ASSERT_EQ(order.size(), contours.size());
    EXPECT_TRUE(same_contours(order, contours));
    EXPECT_TRUE(chains(order));
    const double plain = test::plain_greedy_length(contours, kOrderTolerance, passes);
    EXPECT_NEAR(rapid_length_of(order, kOrderTolerance, passes), plain, 1e-9 * plain) << passes << " passes";
  }
}

TEST(GcodeOrder, TwoOptShortensTheGreedyOrderOfManyContours) {
  // 20,000 contours: every-pair 2-opt was skipped beyond 2000.
  const std::vector<GcodeContour> contours = scattered_contours(20000, 7);
  std::vector<GcodeContour> order = nearest_neighbour_order(contours, kOrderTolerance, 1);
  const double greedy = rapid_length_of(order, kOrderTolerance, 1);
  improve_order(order, kOrderTolerance, 1);
  const double improved = rapid_length_of(order, kOrderTolerance, 1);
  std::cout << "[measured] 20,000 contours: rapid moves " << greedy << " nearest neighbour, " << improved
            << " after 2-opt and joints\n";
  EXPECT_LT(improved, 0.95 * greedy);
  EXPECT_TRUE(same_contours(order, contours));
  EXPECT_TRUE(chains(order));
}

TEST(GcodeOrder, AnOpenContourEnteredAtItsFarEndIsTurned) {
  // A line from (10, 0) to (1, 0) in this order: 10 to its front, 1 to its end.
  std::vector<GcodeContour> order{order_polyline({Vec2{{10, 0}}, Vec2{{1, 0}}}, false)};
  improve_order(order, kOrderTolerance, 1);
  EXPECT_EQ(order.front().front().start, (Vec2{{1, 0}}));
  EXPECT_DOUBLE_EQ(rapid_length_of(order, kOrderTolerance, 1), 1.0);
  // With two passes the tool comes back to its entry: (1, 0) still.
  std::vector<GcodeContour> twice{order_polyline({Vec2{{10, 0}}, Vec2{{1, 0}}}, false)};
  improve_order(twice, kOrderTolerance, 2);
  EXPECT_EQ(twice.front().front().start, (Vec2{{1, 0}}));
}

TEST(GcodeOrder, ClosedContoursAreEnteredAtTheJointBetweenTheirNeighbours) {
  // Squares at x = 0, 10, 20 (y from 0 to 4), each entered at its top left
  // corner: 4 + 10 + 10. In turn, each is entered at the joint that makes
  // the moves to it and to the next entry shortest: the first at (0, 0)
  // (0 + |(10, 4)|), then the middle one at (14, 4) (|(14, 4)| + 6 against
  // |(10, 0)| + |(10, 4)| at (10, 0)), the last at (20, 4), 6 away.
  std::vector<GcodeContour> order;
  for (double x : {0.0, 10.0, 20.0})
    order.push_back(order_polyline({Vec2{{x, 4}}, Vec2{{x, 0}}, Vec2{{x + 4, 0}}, Vec2{{x + 4, 4}}}, true));
  EXPECT_DOUBLE_EQ(rapid_length_of(order, kOrderTolerance, 1), 24.0);
  improve_order(order, kOrderTolerance, 1);
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(order[0].front().start, (Vec2{{0, 0}}));
  EXPECT_EQ(order[1].front().start, (Vec2{{14, 4}}));
  EXPECT_EQ(order[2].front().start, (Vec2{{20, 4}}));
  EXPECT_DOUBLE_EQ(rapid_length_of(order, kOrderTolerance, 1), std::hypot(14.0, 4.0) + 6.0);
  EXPECT_TRUE(chains(order));
}

TEST(GcodeOrder, EmptyInputsAndEmptyContours) {
  EXPECT_TRUE(nearest_neighbour_order({}, kOrderTolerance, 1).empty());
  EXPECT_TRUE(cutting_order({}, kOrderTolerance, 1).empty());
  const std::vector<GcodeContour> some{{}, order_polyline({Vec2{{1, 1}}, Vec2{{2, 1}}}, false), {}};
  EXPECT_EQ(cutting_order(some, kOrderTolerance, 1).size(), 1u);
  std::vector<GcodeContour> order = some;
  improve_order(order, kOrderTolerance, 3);
  EXPECT_EQ(order.size(), 1u);
}

// Integer coordinates in a small field: many equal distances, shared and
// repeated points, contours of one point; passes 1 to 3.
RC_GTEST_PROP(GcodeOrder, KeepsEveryContourAndNeverLengthensTheRapidMoves, ()) {
  const auto count = *rc::gen::inRange<std::size_t>(0, 40);
  const int passes = *rc::gen::inRange(1, 4);
  std::vector<GcodeContour> contours;
  for (std::size_t k = 0; k < count; ++k) {
    const auto corners = *rc::gen::container<std::vector<std::pair<int, int>>>(
        *rc::gen::inRange<std::size_t>(2, 5), rc::gen::pair(rc::gen::inRange(-4, 5), rc::gen::inRange(-4, 5)));
    std::vector<Vec2> points;
    for (const auto& [x, y] : corners) points.push_back(Vec2{{double(x), double(y)}});
    contours.push_back(order_polyline(points, *rc::gen::arbitrary<bool>()));
  }
  const std::vector<GcodeContour> greedy = nearest_neighbour_order(contours, kOrderTolerance, passes);
  RC_ASSERT(same_contours(greedy, contours));
  std::vector<GcodeContour> improved = greedy;
  improve_order(improved, kOrderTolerance, passes);
  RC_ASSERT(same_contours(improved, contours));
  RC_ASSERT(chains(improved));
  const double before = rapid_length_of(greedy, kOrderTolerance, passes);
  RC_ASSERT(rapid_length_of(improved, kOrderTolerance, passes) <= before + 1e-9 * (1.0 + before));
  const std::vector<GcodeContour> cut = cutting_order(contours, kOrderTolerance, passes);
  RC_ASSERT(same_contours(cut, contours));
  RC_ASSERT(rapid_length_of(cut, kOrderTolerance, passes) <= before + 1e-9 * (1.0 + before));
}

}  // namespace
}  // namespace casteljau

// Distances to and between segments (src/ops/segment_distance.hpp), the
// bounds intersection.cpp's chord test and flatten.cpp's flatness rest on:
// cases worked by hand (crossing, parallel, collinear, skew in space, a point
// for a segment, coordinates near the largest double, NaN), and a property
// against a grid of the two segments' points.
#include "../../src/ops/segment_distance.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace casteljau {
namespace {

using detail::distance_between_segments;
using detail::distance_to_segment;

using Points = std::vector<double>;

double between(const Points& p0, const Points& p1, const Points& q0, const Points& q1) {
  return distance_between_segments(p0, p1, q0, q1);
}

TEST(SegmentDistance, CasesWorkedByHand) {
  // Crossing diagonals of the unit square.
  EXPECT_EQ(between({0, 0}, {1, 1}, {0, 1}, {1, 0}), 0.0);
  // Parallel, overlapping in x: one apart; parallel and end to end: the ends.
  EXPECT_DOUBLE_EQ(between({0, 0}, {2, 0}, {1, 1}, {3, 1}), 1.0);
  EXPECT_DOUBLE_EQ(between({0, 0}, {1, 0}, {4, 4}, {5, 4}), 5.0);  // (1, 0) to (4, 4)
  // Collinear and disjoint.
  EXPECT_DOUBLE_EQ(between({0, 0}, {1, 0}, {3, 0}, {4, 0}), 2.0);
  // An end against the other's interior.
  EXPECT_DOUBLE_EQ(between({0, 0}, {1, 0}, {2, -1}, {2, 1}), 1.0);
  // Skew in space: the x axis and the line x = 0, y = 1 along z.
  EXPECT_DOUBLE_EQ(between({-1, 0, 0}, {1, 0, 0}, {0, 1, 1}, {0, 1, -1}), 1.0);
  // Points for segments: 3-4-5, and a point against a segment.
  EXPECT_DOUBLE_EQ(between({0, 0}, {0, 0}, {3, 4}, {3, 4}), 5.0);
  EXPECT_DOUBLE_EQ(between({0, 2}, {0, 2}, {-1, 0}, {1, 0}), 2.0);
  EXPECT_DOUBLE_EQ(between({-1, 0}, {1, 0}, {0, 2}, {0, 2}), 2.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Points{0, 2}, Points{-1, 0}, Points{1, 0}), 2.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Points{3, 4}, Points{0, 0}, Points{0, 0}), 5.0);
  // Near the largest double the squares would overflow: taken relative.
  const double huge = 1e307;
  EXPECT_DOUBLE_EQ(between({0, 0}, {huge, 0}, {0, huge}, {huge, huge}), huge);
  EXPECT_DOUBLE_EQ(between({-huge, -huge}, {huge, huge}, {-huge, huge}, {huge, -huge}), 0.0);
  // Not a number: NaN, so that a test `gap > bound` is false.
  EXPECT_TRUE(std::isnan(between({0, NAN}, {1, 0}, {0, 1}, {1, 1})));
  EXPECT_TRUE(std::isnan(between({0, 0}, {1, 0}, {0, INFINITY}, {1, 1})));
}

/// The distance is at most that of any two points of the segments, and at
/// least the least over a grid of 65 x 65 pairs less half a grid step of each.
RC_GTEST_PROP(SegmentDistance, LiesBetweenTheGridsLeastAndItsStep, ()) {
  const int dimension = *rc::gen::inRange(2, 4);
  const auto coordinates = *rc::gen::container<std::vector<int>>(4 * dimension, rc::gen::inRange(-1000, 1001));
  Points p0, p1, q0, q1;
  for (int j = 0; j < dimension; ++j) {
    p0.push_back(coordinates[j]), p1.push_back(coordinates[dimension + j]);
    q0.push_back(coordinates[2 * dimension + j]), q1.push_back(coordinates[3 * dimension + j]);
  }
  const double d = between(p0, p1, q0, q1);
  const int steps = 64;
  double least = INFINITY, length_p = 0.0, length_q = 0.0;
  for (int j = 0; j < dimension; ++j) {
    length_p += (p1[j] - p0[j]) * (p1[j] - p0[j]);
    length_q += (q1[j] - q0[j]) * (q1[j] - q0[j]);
  }
  for (int i = 0; i <= steps; ++i)
    for (int k = 0; k <= steps; ++k) {
      const double s = double(i) / steps, t = double(k) / steps;
      double squared = 0.0;
      for (int j = 0; j < dimension; ++j) {
        const double gap = (p0[j] + s * (p1[j] - p0[j])) - (q0[j] + t * (q1[j] - q0[j]));
        squared += gap * gap;
      }
      least = std::min(least, std::sqrt(squared));
    }
  const double slack = 1e-9 * 4000.0;  // rounding, relative to coordinates of 1e3
  RC_ASSERT(d <= least + slack);
  RC_ASSERT(d >= least - 0.5 * (std::sqrt(length_p) + std::sqrt(length_q)) / steps - slack);
}

}  // namespace
}  // namespace casteljau

// ControlNet: validated construction from nested rows and from a flat
// PointArray, each refusal with its message; the transpose.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "casteljau/surfaces/control_net.hpp"

namespace casteljau {
namespace {

using Rows = std::vector<std::vector<std::vector<double>>>;

TEST(ControlNet, BuildsFromRowsRowByRow) {
  const auto net = ControlNet::make(Rows{{{0, 0, 0}, {1, 0, 2}, {2, 0, 0}}, {{0, 1, 1}, {1, 1, 3}, {2, 1, 1}}});
  ASSERT_TRUE(net.has_value()) << net.error().message;
  EXPECT_EQ(net->rows(), 2u);
  EXPECT_EQ(net->columns(), 3u);
  EXPECT_EQ(net->dimension(), 3);
  EXPECT_EQ((*net)(1, 1)[2], 3.0);
  // Row by row: P_ij is point i * columns + j.
  EXPECT_EQ(net->points()[4][2], 3.0);
}

TEST(ControlNet, RefusesARaggedRow) {
  const auto net = ControlNet::make(Rows{{{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {1, 1}, {2, 1}}, {{0, 2}, {1, 2}}});
  ASSERT_FALSE(net.has_value());
  EXPECT_EQ(net.error().message, "row 2 of the control net has 2 points, row 0 has 3");
}

TEST(ControlNet, RefusesPointsOfDifferentDimensions) {
  const auto net = ControlNet::make(Rows{{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1}}});
  ASSERT_FALSE(net.has_value());
  EXPECT_EQ(net.error().message, "control point [1][1] has 2 coordinates, [0][0] has 3");
}

TEST(ControlNet, RefusesNonFiniteCoordinates) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto net = ControlNet::make(Rows{{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, nan, 0}}});
  ASSERT_FALSE(net.has_value());
  EXPECT_EQ(net.error().message, "coordinate 1 of control point [1][1] is NaN");
  const auto infinite = ControlNet::make(Rows{{{0, INFINITY}}});
  ASSERT_FALSE(infinite.has_value());
  EXPECT_EQ(infinite.error().message, "coordinate 1 of control point [0][0] is infinite");
}

TEST(ControlNet, RefusesEmptyNets) {
  const auto none = ControlNet::make(Rows{});
  ASSERT_FALSE(none.has_value());
  EXPECT_EQ(none.error().message, "the control net has no rows");
  const auto empty_row = ControlNet::make(Rows{{}});
  ASSERT_FALSE(empty_row.has_value());
  EXPECT_EQ(empty_row.error().message, "row 0 of the control net has no points");
  const auto no_coordinates = ControlNet::make(Rows{{{}}});
  ASSERT_FALSE(no_coordinates.has_value());
  EXPECT_EQ(no_coordinates.error().message, "control point [0][0] has no coordinates");
}

TEST(ControlNet, FlatPointsMustFillTheShape) {
  const auto points = PointArray::make(3, std::vector<double>(33, 1.0));
  ASSERT_TRUE(points.has_value());
  const auto net = ControlNet::make(3, 4, *points);
  ASSERT_FALSE(net.has_value());
  EXPECT_EQ(net.error().message, "a control net of 3 x 4 needs 12 points, found 11");
  const auto empty = ControlNet::make(0, 4, *points);
  ASSERT_FALSE(empty.has_value());
  EXPECT_EQ(empty.error().message, "a control net of 0 x 4 is empty, it needs at least one row and one column");
  const auto fits = ControlNet::make(11, 1, *points);
  ASSERT_TRUE(fits.has_value());
  EXPECT_EQ(fits->rows(), 11u);
}

TEST(ControlNet, TransposeExchangesRowsAndColumns) {
  const auto net = *ControlNet::make(Rows{{{1, 2}, {3, 4}, {5, 6}}, {{7, 8}, {9, 10}, {11, 12}}});
  const ControlNet t = transposed(net);
  ASSERT_EQ(t.rows(), 3u);
  ASSERT_EQ(t.columns(), 2u);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_EQ(t(j, i)[0], net(i, j)[0]);
      EXPECT_EQ(t(j, i)[1], net(i, j)[1]);
    }
  EXPECT_EQ(transposed(t), net);
}

}  // namespace
}  // namespace casteljau

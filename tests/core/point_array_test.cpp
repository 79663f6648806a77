#include "casteljau/core/point_array.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace casteljau {
namespace {

TEST(PointArray, ShapeAndAccess) {
  const auto p = PointArray::make(3, {1, 2, 3, 4, 5, 6}).value();
  EXPECT_EQ(p.size(), 2u);
  EXPECT_EQ(p.dimension(), 3);
  EXPECT_EQ(p[1][2], 6.0);
  EXPECT_EQ(p.vec<3>(0), (Vec3{{1, 2, 3}}));
  EXPECT_EQ(scale_of(p), 6.0);
}

// Rows of coordinates (as model JSON and the Python module give them): one
// dimension for all, named by the first row; each refusal names the row.
TEST(PointArray, RowsShareTheFirstRowsDimension) {
  const auto rows = PointArray::make({{1, 2}, {3, 4}, {5, 6}}).value();
  EXPECT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows.dimension(), 2);
  EXPECT_EQ(rows[2][1], 6.0);
  EXPECT_EQ(PointArray::make({{}, {1, 2}}, "control point").error().message, "control point 0 has no coordinates");
  EXPECT_EQ(PointArray::make({{1, 2}, {3, 4}, {5}}, "control point").error().message,
            "control point 2 has 1 coordinates, control point 0 has 2");
  EXPECT_EQ(PointArray::make({{1, 2}, {3, std::nan("")}}).error().message, "coordinate 1 of point 1 is NaN");
  EXPECT_EQ(PointArray::make(2, {1, 2, 3}).error().message, "3 coordinates do not make whole 2-dimensional points");
}

// Every error kind has the name its enumerator has (logs and the Python
// module's messages use them).
TEST(Expected, ErrorKindsAreNamedAsWritten) {
  EXPECT_STREQ(name_of(ErrorKind::invalid_argument), "invalid_argument");
  EXPECT_STREQ(name_of(ErrorKind::out_of_domain), "out_of_domain");
  EXPECT_STREQ(name_of(ErrorKind::parse), "parse");
  EXPECT_STREQ(name_of(ErrorKind::io), "io");
  EXPECT_STREQ(name_of(ErrorKind::limit), "limit");
  EXPECT_STREQ(name_of(ErrorKind::singular), "singular");
}

TEST(Distance, NoOverflowForHugeCoordinates) {
  const double big = 1e300;
  const std::vector<double> a{big, big}, b{-big, -big};
  EXPECT_NEAR(distance(a, b) / (2 * std::sqrt(2.0) * big), 1.0, 1e-15);
  const std::vector<double> c{3e-300, 0}, d{0, 4e-300};
  EXPECT_NEAR(distance(c, d) / 5e-300, 1.0, 1e-15);
  // Equal points are 0 apart, and a point at infinity infinitely far.
  EXPECT_EQ(distance(a, a), 0.0);
  const std::vector<double> far{std::numeric_limits<double>::infinity(), 0};
  EXPECT_EQ(distance(far, c), std::numeric_limits<double>::infinity());
}

TEST(Expected, CarriesValueOrError) {
  Expected<int> good = 3;
  Expected<int> bad = Error{"nope"};
  EXPECT_TRUE(good && *good == 3);
  EXPECT_FALSE(bad);
  EXPECT_EQ(bad.error().message, "nope");
  EXPECT_EQ(with_context(Error{"x is NaN"}, "in 'a.json'").message, "in 'a.json': x is NaN");
  Status ok;
  EXPECT_TRUE(ok);
}

}  // namespace
}  // namespace casteljau

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

TEST(Distance, NoOverflowForHugeCoordinates) {
  const double big = 1e300;
  const std::vector<double> a{big, big}, b{-big, -big};
  EXPECT_NEAR(distance(a, b) / (2 * std::sqrt(2.0) * big), 1.0, 1e-15);
  const std::vector<double> c{3e-300, 0}, d{0, 4e-300};
  EXPECT_NEAR(distance(c, d) / 5e-300, 1.0, 1e-15);
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

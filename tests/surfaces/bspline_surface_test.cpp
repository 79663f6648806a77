// BSplineSurface: validation (each refusal with its message), the
// homogeneous net, the transpose, the domain.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>

#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "support/surface_generators.hpp"

namespace casteljau {
namespace {

ControlNet grid_net(std::size_t rows, std::size_t columns) {
  std::vector<double> c;
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < columns; ++j) {
      c.push_back(static_cast<double>(i));
      c.push_back(static_cast<double>(j));
      c.push_back(static_cast<double>((i * 7 + j * 3) % 5));
    }
  return *ControlNet::make(rows, columns, *PointArray::make(3, std::move(c)));
}

TEST(BSplineSurface, BuildsAValidBicubic) {
  const auto s = BSplineSurface::make(3, 2, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, grid_net(5, 3));
  ASSERT_TRUE(s.has_value()) << s.error().message;
  EXPECT_EQ(s->degree(Direction::u), 3);
  EXPECT_EQ(s->degree(Direction::v), 2);
  EXPECT_EQ(s->domain_u(), (Interval{0, 1}));
  EXPECT_FALSE(s->is_rational());
  EXPECT_EQ(s->dimension(), 3);
}

TEST(BSplineSurface, DomainOfUnclampedKnots) {
  const auto s = BSplineSurface::make(2, 1, {0, 1, 2, 3, 4, 5, 6}, {0, 1, 2, 3}, grid_net(4, 2));
  ASSERT_TRUE(s.has_value()) << s.error().message;
  EXPECT_EQ(s->domain(Direction::u), (Interval{2, 4}));
  EXPECT_EQ(s->domain(Direction::v), (Interval{1, 2}));
}

TEST(BSplineSurface, RefusesTooFewRowsOrColumnsForTheDegree) {
  const auto rows = BSplineSurface::make(3, 1, {0, 0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, grid_net(3, 2));
  ASSERT_FALSE(rows.has_value());
  EXPECT_EQ(rows.error().message, "the control net has 3 rows, a surface of degree 3 in u needs at least 4");
  const auto columns = BSplineSurface::make(1, 2, {0, 0, 1, 1}, {0, 0, 1, 1}, grid_net(2, 2));
  ASSERT_FALSE(columns.has_value());
  EXPECT_EQ(columns.error().message, "the control net has 2 columns, a surface of degree 2 in v needs at least 3");
}

TEST(BSplineSurface, RefusesADegreeOutOfRange) {
  const auto s = BSplineSurface::make(-1, 1, {0, 1}, {0, 0, 1, 1}, grid_net(2, 2));
  ASSERT_FALSE(s.has_value());
  EXPECT_EQ(s.error().message, "degree_u -1 is outside [0, 10000]");
}

TEST(BSplineSurface, RefusesDecreasingKnotsNamingTheDirection) {
  const auto s = BSplineSurface::make(1, 1, {0, 0, 1, 1}, {0, 0, 0.7, 0.5, 1, 1}, grid_net(2, 4));
  ASSERT_FALSE(s.has_value());
  EXPECT_EQ(s.error().message, "knots_v: knot 3 (0.5) is smaller than knot 2 (0.7), knots must be non-decreasing");
  const auto count = BSplineSurface::make(1, 1, {0, 0, 1}, {0, 0, 1, 1}, grid_net(2, 2));
  ASSERT_FALSE(count.has_value());
  EXPECT_EQ(count.error().message,
            "knots_u: 3 knots given, a B-spline of this degree and control point count needs 4 "
            "(control points + degree + 1)");
  const auto nan = BSplineSurface::make(1, 1, {0, 0, NAN, 1}, {0, 0, 1, 1}, grid_net(2, 2));
  ASSERT_FALSE(nan.has_value());
  EXPECT_EQ(nan.error().message, "knots_u: knot 2 is NaN");
}

TEST(BSplineSurface, RefusesWeightsThatDoNotMatchTheNet) {
  const auto w = BSplineSurface::make(1, 1, {0, 0, 0.5, 1, 1}, {0, 0, 0.3, 0.6, 1, 1}, grid_net(3, 4),
                                      std::vector<double>(11, 1.0));
  ASSERT_FALSE(w.has_value());
  EXPECT_EQ(w.error().message,
            "the weights have 11 entries, the control net has 12 points (3 x 4), there must be one weight per "
            "control point");
}

TEST(BSplineSurface, RefusesNonPositiveOrNonFiniteWeights) {
  std::vector<double> weights(12, 1.0);
  weights[2 * 4 + 1] = -1.0;
  const auto negative =
      BSplineSurface::make(1, 1, {0, 0, 0.5, 1, 1}, {0, 0, 0.3, 0.6, 1, 1}, grid_net(3, 4), weights);
  ASSERT_FALSE(negative.has_value());
  EXPECT_EQ(negative.error().message, "weight [2][1] is -1, weights must be > 0");
  weights[2 * 4 + 1] = 0.0;
  const auto zero = BSplineSurface::make(1, 1, {0, 0, 0.5, 1, 1}, {0, 0, 0.3, 0.6, 1, 1}, grid_net(3, 4), weights);
  ASSERT_FALSE(zero.has_value());
  EXPECT_EQ(zero.error().message, "weight [2][1] is 0, weights must be > 0");
  weights[2 * 4 + 1] = 1.0;
  weights[3] = std::numeric_limits<double>::quiet_NaN();
  const auto nan = BSplineSurface::make(1, 1, {0, 0, 0.5, 1, 1}, {0, 0, 0.3, 0.6, 1, 1}, grid_net(3, 4), weights);
  ASSERT_FALSE(nan.has_value());
  EXPECT_EQ(nan.error().message, "weight [0][3] is NaN");
}

TEST(BSplineSurface, HomogeneousNetRoundTrips) {
  std::vector<double> weights;
  for (int k = 0; k < 12; ++k) weights.push_back(0.5 + 0.25 * k);
  const auto s = *BSplineSurface::make(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 0.25, 0.5, 1, 1}, grid_net(3, 4), weights);
  const ControlNet h = homogeneous_net(s);
  ASSERT_EQ(h.dimension(), 4);
  EXPECT_EQ(h(2, 1)[3], weights[9]);
  EXPECT_EQ(h(2, 1)[0], weights[9] * s.control_net()(2, 1)[0]);
  const BSplineSurface back = from_homogeneous(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 0.25, 0.5, 1, 1}, h);
  // Weights are powers-of-two multiples, so w P / w is exact.
  EXPECT_EQ(back, s);
  // A polynomial surface's homogeneous net has weight 1.
  const auto plain = *BSplineSurface::make(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 0.25, 0.5, 1, 1}, grid_net(3, 4));
  const ControlNet homogeneous = homogeneous_net(plain);
  EXPECT_EQ(homogeneous(1, 3)[3], 1.0);
}

RC_GTEST_PROP(BSplineSurfaceProperties, TransposeExchangesTheParameters, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const BSplineSurface t = transposed(s);
  RC_ASSERT(t.degree_u() == s.degree_v());
  RC_ASSERT(t.domain_u() == s.domain_v());
  RC_ASSERT(transposed(t) == s);
  const double u = *test::parameter_in(s, Direction::u), v = *test::parameter_in(s, Direction::v);
  const Point a = point_at(s, u, v), b = point_at(t, v, u);
  RC_ASSERT(distance(a, b) <= test::surface_tolerance(s));
}

}  // namespace
}  // namespace casteljau

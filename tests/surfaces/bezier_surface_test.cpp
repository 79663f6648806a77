// BezierSurface: validation (each refusal with its message) and the exact
// B-spline form.
#include <gtest/gtest.h>

#include <cmath>

#include "casteljau/surfaces/bezier_surface.hpp"

namespace casteljau {
namespace {

ControlNet net_of(std::size_t rows, std::size_t columns) {
  std::vector<double> c;
  for (std::size_t k = 0; k < rows * columns; ++k) c.insert(c.end(), {k * 1.0, k * 0.5, 1.0});
  return *ControlNet::make(rows, columns, *PointArray::make(3, c));
}

TEST(BezierSurface, DegreesComeFromTheNet) {
  const auto patch = BezierSurface::make(net_of(4, 3));
  ASSERT_TRUE(patch.has_value()) << patch.error().message;
  EXPECT_EQ(patch->degree_u(), 3);
  EXPECT_EQ(patch->degree_v(), 2);
  EXPECT_FALSE(patch->is_rational());
}

TEST(BezierSurface, RefusesWeightsThatDoNotMatchTheNet) {
  const auto patch = BezierSurface::make(net_of(2, 3), {1, 1, 1, 1, 1});
  ASSERT_FALSE(patch.has_value());
  EXPECT_EQ(patch.error().message,
            "the weights have 5 entries, the control net has 6 points (2 x 3), there must be one weight per "
            "control point");
}

TEST(BezierSurface, RefusesNonPositiveOrNonFiniteWeights) {
  const auto negative = BezierSurface::make(net_of(2, 2), {1, 1, -0.5, 1});
  ASSERT_FALSE(negative.has_value());
  EXPECT_EQ(negative.error().message, "weight [1][0] is -0.5, weights must be > 0");
  const auto nan = BezierSurface::make(net_of(2, 2), {1, NAN, 1, 1});
  ASSERT_FALSE(nan.has_value());
  EXPECT_EQ(nan.error().message, "weight [0][1] is NaN");
}

TEST(BezierSurface, RefusesADegreeAboveTheLimit) {
  const auto patch = BezierSurface::make(net_of(1, 10'002));
  ASSERT_FALSE(patch.has_value());
  EXPECT_EQ(patch.error().message, "the control net has 10002 columns, degree 10001 in v is above the limit 10000");
}

TEST(BezierSurface, BSplineFormHasBernsteinKnots) {
  const auto patch = *BezierSurface::make(net_of(3, 2), {1, 2, 3, 4, 5, 6});
  const BSplineSurface s = to_bspline_surface(patch);
  EXPECT_EQ(std::vector<double>(s.knots_u().begin(), s.knots_u().end()), (std::vector<double>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(std::vector<double>(s.knots_v().begin(), s.knots_v().end()), (std::vector<double>{0, 0, 1, 1}));
  EXPECT_EQ(s.control_net(), patch.control_net());
  EXPECT_EQ(std::vector<double>(s.weights().begin(), s.weights().end()), (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

}  // namespace
}  // namespace casteljau

// Preconditions that protect memory are checked in every build type (this
// binary is built without assertions): a short output span or a negative
// derivative order aborts with the function and the requirement instead of
// writing past a buffer (death tests on every curve kind and a surface).
#include "casteljau/core/precondition.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/evaluate.hpp"

namespace casteljau {
namespace {

const BezierCurve& cubic() {
  static const BezierCurve curve =
      BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 2}, {3, 0}}).value()).value();
  return curve;
}

TEST(PreconditionDeathTest, ShortOutputSpansAbortWithTheRequirement) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::vector<double> ts{0.0, 0.5, 1.0};
  std::vector<double> out(5);  // 3 points of R^2 need 6
  EXPECT_DEATH(points_at(cubic(), ts, out),
               "casteljau: points_at: out must hold ts.size\\(\\) \\* dimension\\(\\) values");
  EXPECT_DEATH(derivatives_at(cubic(), ts, 1, out), "casteljau: derivatives_at: out must hold");
  const BSplineCurve spline = to_bspline(cubic());
  EXPECT_DEATH(points_at(spline, ts, out),
               "casteljau: points_at: out must hold us.size\\(\\) \\* dimension\\(\\) values");
  const PiecewiseBezierCurve two = PiecewiseBezierCurve::make({cubic(), cubic()}).value();
  EXPECT_DEATH(points_at(two, ts, out), "casteljau: points_at: out must hold");
  const PointArray corners = PointArray::make({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}).value();
  const BezierSurface patch = BezierSurface::make(ControlNet::make(2, 2, corners).value()).value();
  const std::vector<double> two_vs{0.0, 1.0};
  std::vector<double> room(9);
  EXPECT_DEATH(points_at(patch, ts, two_vs, room), "casteljau: points_at: us and vs must have one size");
}

TEST(PreconditionDeathTest, NegativeDerivativeOrdersAbort) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH((void)derivative_at(cubic(), 0.5, -1), "casteljau: derivative_at: the derivative order must be >= 0");
  EXPECT_DEATH((void)derivative_at(to_bspline(cubic()), 0.5, -1), "casteljau: derivative_at: the derivative order");
  const std::vector<double> ts{0.5};
  std::vector<double> out(2);
  EXPECT_DEATH(derivatives_at(cubic(), ts, -2, out), "casteljau: derivatives_at: the derivative order must be >= 0");
}

TEST(Precondition, CorrectCallsPass) {
  const std::vector<double> ts{0.0, 0.5, 1.0};
  std::vector<double> out(6);
  points_at(cubic(), ts, out);
  EXPECT_EQ(out[2], 1.5);  // C(1/2) = (1.5, 1.5)
  EXPECT_EQ(out[3], 1.5);
}

}  // namespace
}  // namespace casteljau

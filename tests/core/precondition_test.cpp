// Preconditions that protect memory are checked in every build type (this
// binary is built without assertions): a short output span or a negative
// derivative order aborts with the function and the requirement instead of
// writing past a buffer (death tests on every curve kind and a surface).
#include "casteljau/core/precondition.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "casteljau/bezier/affine.hpp"
#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/curves/differential_geometry.hpp"
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

TEST(PreconditionDeathTest, WrongDimensionsAbortInsteadOfReadingPastAPoint) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // A planar patch: its normal would read a third coordinate that is not there.
  const PointArray flat = PointArray::make({{0, 0}, {1, 0}, {0, 1}, {1, 1}}).value();
  const BezierSurface plane = BezierSurface::make(ControlNet::make(2, 2, flat).value()).value();
  EXPECT_DEATH((void)normal_at(plane, 0.5, 0.5), "casteljau: normal_at: the surface must lie in 3D");
  EXPECT_DEATH((void)torsion_at(cubic(), 0.5), "casteljau: torsion_at: the curve must lie in 3D");
  EXPECT_DEATH((void)binormal_at(cubic(), 0.5), "casteljau: binormal_at: the curve must lie in 3D");
  EXPECT_DEATH((void)point_at<3>(cubic(), 0.5), "casteljau: point_at<D>: D must be the curve's dimension");
  const std::vector<double> point3{1.0, 2.0, 3.0};
  EXPECT_DEATH((void)transformed_point(AffineMap::identity(2), point3),
               "casteljau: transformed_point: x must have the map's dimension");
}

TEST(PreconditionDeathTest, BasisKernelsCheckTheirSpansAndOrders) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::vector<double> knots{0, 0, 0, 1, 1, 1};
  std::vector<double> two(2), three(3);
  EXPECT_DEATH(basis_functions(knots, 2, 2, 0.5, two), "casteljau: basis_functions: out must hold degree \\+ 1");
  EXPECT_DEATH(basis_functions(knots, 2, 4, 0.5, three), "casteljau: basis_functions: span must index");
  EXPECT_DEATH(bernstein_all(3, 0.5, three), "casteljau: bernstein_all: n must be >= 0 and out must hold");
  EXPECT_DEATH((void)derivatives_up_to(cubic(), 0.5, -1), "casteljau: derivatives_up_to: max_order must be >= 0");
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

// The text form of points and curves (io/format.hpp): the exact strings for
// each kind, the spec applied to every number, and operator<< agreeing with
// fmt. Expected strings are written by hand from the documented form.
#include "casteljau/io/format.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "casteljau/bspline/bspline_curve.hpp"

namespace casteljau {
namespace {

PointArray triangle() { return PointArray::make(2, {0.0, 0.0, 1.0, 2.5, 2.0, 0.0}).value(); }

TEST(Format, PointsAndPointArrays) {
  EXPECT_EQ(fmt::format("{}", Vec2{{1.0, 2.5}}), "(1, 2.5)");
  EXPECT_EQ(fmt::format("{}", Vec3{{0.1, -0.0, 1e-17}}), "(0.1, -0, 1e-17)");
  EXPECT_EQ(fmt::format("{}", triangle()), "[(0, 0), (1, 2.5), (2, 0)]");
  EXPECT_EQ(fmt::format("{}", PointArray::make(3, {}).value()), "[]");
}

TEST(Format, TheSpecAppliesToEveryNumber) {
  EXPECT_EQ(fmt::format("{:.3f}", Vec2{{1.0, 2.5}}), "(1.000, 2.500)");
  EXPECT_EQ(fmt::format("{:.1e}", triangle()), "[(0.0e+00, 0.0e+00), (1.0e+00, 2.5e+00), (2.0e+00, 0.0e+00)]");
}

TEST(Format, CurvesNameTheirKindDegreeAndDimension) {
  const BezierCurve polynomial = BezierCurve::make(triangle()).value();
  EXPECT_EQ(fmt::format("{}", polynomial), "bezier degree 2 in R^2 [(0, 0), (1, 2.5), (2, 0)]");
  const BezierCurve rational = BezierCurve::make(triangle(), {1.0, 0.5, 1.0}).value();
  EXPECT_EQ(fmt::format("{}", rational), "bezier degree 2 in R^2 [(0, 0), (1, 2.5), (2, 0)] weights [1, 0.5, 1]");
  const BezierCurve line = BezierCurve::make(PointArray::make(2, {2.0, 0.0, 3.0, 1.0}).value()).value();
  const PiecewiseBezierCurve two = PiecewiseBezierCurve::make({polynomial, line}).value();
  EXPECT_EQ(fmt::format("{}", two),
            "piecewise_bezier of 2 pieces in R^2 [degree 2 [(0, 0), (1, 2.5), (2, 0)], degree 1 [(2, 0), (3, 1)]]");
  const BSplineCurve spline = to_bspline(polynomial);
  EXPECT_EQ(fmt::format("{}", spline), "bspline degree 2 in R^2 knots [0, 0, 0, 1, 1, 1] [(0, 0), (1, 2.5), (2, 0)]");
}

TEST(Format, StreamsWriteTheSameText) {
  std::ostringstream out;
  const BezierCurve curve = BezierCurve::make(triangle()).value();
  out << Vec2{{1.0, 2.0}} << "; " << triangle() << "; " << curve;
  EXPECT_EQ(out.str(), "(1, 2); [(0, 0), (1, 2.5), (2, 0)]; " + fmt::format("{}", curve));
}

}  // namespace
}  // namespace casteljau

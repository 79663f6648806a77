// Curves made compatible: one domain, degree and knot vector, same shapes.
#include "casteljau/surfaces/compatible_curves.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "support/bspline_generators.hpp"

namespace casteljau {
namespace {

RC_GTEST_PROP(MakeCompatible, SameDegreeKnotsAndDomainAndTheSameCurves, ()) {
  const int count = *rc::gen::inRange(1, 5);
  std::vector<BSplineCurve> curves;
  for (int k = 0; k < count; ++k)
    curves.push_back(*test::bspline_curve({.max_degree = 5, .dimension = 3, .max_extra_points = 6}));
  const auto compatible = make_compatible(curves).value();
  RC_ASSERT(compatible.size() == curves.size());
  int degree = 0;
  bool rational = false;
  for (const auto& c : curves) {
    degree = std::max(degree, c.degree());
    rational = rational || c.is_rational();
  }
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const auto& c = compatible[k];
    RC_ASSERT(c.degree() == degree);
    RC_ASSERT(c.domain() == (Interval{0.0, 1.0}));
    RC_ASSERT(c.is_rational() == rational);
    RC_ASSERT(std::equal(c.knots().begin(), c.knots().end(), compatible[0].knots().begin(), compatible[0].knots().end()));
    RC_ASSERT(c.control_points().size() == compatible[0].control_points().size());
    // The same curve: C_new(s) = C(a + s (b - a)).
    const Interval domain = curves[k].domain();
    const double gap = test::largest_distance(
        curves[k], c, [&](double u) { return (u - domain.lower) / domain.length(); }, 48);
    RC_ASSERT(gap <= test::shape_tolerance(curves[k], 1e-11));
  }
}

TEST(MakeCompatible, ALineAndAParabolaWorkedExample) {
  // The line (0,0)-(2,2) on [0, 2] becomes the quadratic on [0, 1] with
  // control points (0,0), (1,1), (2,2); the parabola's knot 0.25 is then
  // inserted into it at (0,0), (0.25,0.25), (1.25,1.25), (2,2).
  const auto line = BSplineCurve::make(1, {0, 0, 2, 2}, PointArray::make({{0, 0}, {2, 2}}).value()).value();
  const auto parabola =
      BSplineCurve::make(2, {0, 0, 0, 0.25, 1, 1, 1}, PointArray::make({{0, 1}, {1, 3}, {2, 0}, {3, 1}}).value()).value();
  const BSplineCurve both[2] = {line, parabola};
  const auto compatible = make_compatible(both).value();
  const std::vector<double> knots{0, 0, 0, 0.25, 1, 1, 1};
  for (const auto& c : compatible) EXPECT_EQ(std::vector<double>(c.knots().begin(), c.knots().end()), knots);
  EXPECT_EQ(compatible[1], parabola);  // already compatible: unchanged
  const double expected[4][2] = {{0, 0}, {0.25, 0.25}, {1.25, 1.25}, {2, 2}};
  ASSERT_EQ(compatible[0].control_points().size(), 4u);
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 2; ++c) EXPECT_DOUBLE_EQ(compatible[0].control_points()[i][c], expected[i][c]) << i;
}

TEST(MakeCompatible, PolynomialCurvesBesideANurbsCurveGetUnitWeights) {
  const auto arc = make_arc(0, 0, 1, 0, std::numbers::pi / 2).value();
  const auto line = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{1, 0}, {0, 1}}).value()).value();
  const BSplineCurve both[2] = {arc, line};
  const auto compatible = make_compatible(both).value();
  ASSERT_TRUE(compatible[1].is_rational());
  for (double w : compatible[1].weights()) EXPECT_EQ(w, 1.0);
  EXPECT_EQ(compatible[0], arc);
  EXPECT_LE(test::largest_distance(line, compatible[1]), 1e-15);
}

TEST(MakeCompatible, RefusesNoCurvesAndDifferentDimensions) {
  auto none = make_compatible({});
  ASSERT_FALSE(none.has_value());
  EXPECT_EQ(none.error().message, "no curve to make compatible");
  const auto flat = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 1}}).value()).value();
  const auto space = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0, 0}, {1, 1, 1}}).value()).value();
  const BSplineCurve three[3] = {flat, flat, space};
  auto mixed = make_compatible(three);
  ASSERT_FALSE(mixed.has_value());
  EXPECT_EQ(mixed.error().message, "curve 2 has 3 coordinates, curve 0 has 2; compatible curves need one dimension");
}

}  // namespace
}  // namespace casteljau

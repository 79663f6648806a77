// Ferguson cubics and piecewise Hermite interpolation: the Hermite basis
// evaluated exactly, cubic polynomials reproduced, a hand-worked example
// that scipy's CubicHermiteSpline agrees with, closed curves, errors.
#include "casteljau/interpolation/hermite.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "support/exact.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// The cubic Hermite form h00 P0 + h10 T0 + h01 P1 + h11 T1 on [0,1]
/// (Farin §7.1) at s, exactly.
mpq_class hermite_form(double p0, double t0, double p1, double t1, const mpq_class& s) {
  const mpq_class s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * t0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * t1;
}

TEST(Ferguson, ControlPointsAndHermiteData) {
  const auto curve = ferguson_curve(std::vector<double>{0, 0}, std::vector<double>{3, 0},
                                    std::vector<double>{1, 1}, std::vector<double>{0, 3});
  ASSERT_TRUE(curve) << curve.error().message;
  EXPECT_EQ(curve->control_points(), PointArray::make(2, {0, 0, 1, 0, 1, 0, 1, 1}).value());
  EXPECT_EQ(derivative_at(*curve, 0.0, 1), (Point{3, 0}));
  EXPECT_EQ(derivative_at(*curve, 1.0, 1), (Point{0, 3}));
}

RC_GTEST_PROP(Ferguson, EqualsTheHermiteFormExactly, ()) {
  const int d = *rc::gen::inRange(1, 4);
  auto vec = [&] { return *rc::gen::container<std::vector<double>>(d, test::coordinate()); };
  const auto p0 = vec(), t0 = vec(), p1 = vec(), t1 = vec();
  const auto curve = ferguson_curve(p0, t0, p1, t1).value();
  const double scale = std::max({1.0, scale_of(curve.control_points())});
  for (int j = 0; j <= 8; ++j) {
    const double s = j / 8.0;
    const Point c = point_at(curve, s);
    for (int k = 0; k < d; ++k)
      RC_ASSERT(test::error_of(c[k], hermite_form(p0[k], t0[k], p1[k], t1[k], mpq_class(s))) <= 1e-14 * scale);
  }
}

TEST(Ferguson, RefusesBadInput) {
  const std::vector<double> a{0, 0}, b{1, 1}, c{1};
  auto e = ferguson_curve(a, b, c, b);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message,
            "a Ferguson curve needs start point, start tangent, end point and end tangent of one dimension, got 2, "
            "2, 1, 2");
  e = ferguson_curve(a, b, a, std::vector<double>{1, std::nan("")});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "coordinate 1 of the end tangent is NaN");
  EXPECT_FALSE(ferguson_curve(std::vector<double>{}, std::vector<double>{}, std::vector<double>{},
                              std::vector<double>{}));
}

// Worked by hand with the Hermite basis on each interval
// (u = (t − x_i)/h, p = h00 y_i + h10 h m_i + h01 y_{i+1} + h11 h m_{i+1}):
// x = 0, 1, 3; y = 0, 2, 1; dy/dx = 1, 0, −1.
//   t = 1/2: u = 1/2, h = 1: 0 + 1/8·1 + 1/2·2 − 1/8·0 = 9/8;  p' = 11/4
//   t = 2:   u = 1/2, h = 2: 1/2·2 + 0 + 1/2·1 + (−1/8)·2·(−1) = 7/4;  p' = −1/2
//   t = 5/2: u = 3/4, h = 2: 5/32·2 + 3/64·2·0 + 27/32·1 − 9/64·2·(−1) = 23/16;  p' = −3/4
// scipy 1.10 CubicHermiteSpline([0,1,3], [0,2,1], [1,0,-1]) gives the same
// values (1.125, 1.75, 1.4375) and derivatives (2.75, −0.5, −0.75).
TEST(Hermite, HandWorkedExampleThatScipyAgreesWith) {
  const PointArray graph = PointArray::make(2, {0, 0, 1, 2, 3, 1}).value();
  const PointArray tangents = PointArray::make(2, {1, 1, 1, 0, 1, -1}).value();  // (1, dy/dx)
  const std::vector<double> x{0, 1, 3};
  const auto curve = interpolate_hermite(graph, tangents, x);
  ASSERT_TRUE(curve) << curve.error().message;
  EXPECT_EQ(curve->domain(), (Interval{0, 3}));
  EXPECT_EQ(curve->degree(), 3);
  const std::vector<double> knots{0, 0, 0, 0, 1, 1, 3, 3, 3, 3};
  EXPECT_TRUE(std::equal(knots.begin(), knots.end(), curve->knots().begin(), curve->knots().end()));
  const struct { double t, y, slope; } expected[] = {{0.5, 1.125, 2.75}, {2.0, 1.75, -0.5}, {2.5, 1.4375, -0.75}};
  for (const auto& e : expected) {
    const Point p = point_at(*curve, e.t), dp = derivative_at(*curve, e.t, 1);
    EXPECT_NEAR(p[0], e.t, 1e-15) << e.t;  // x(t) = t: the tangents (1, m) make the curve a graph
    EXPECT_NEAR(p[1], e.y, 1e-15) << e.t;
    EXPECT_NEAR(dp[0], 1.0, 1e-14) << e.t;
    EXPECT_NEAR(dp[1], e.slope, 1e-14) << e.t;
  }
}

/// Values and derivatives of a cubic polynomial curve with dyadic
/// coefficients, exactly.
struct Cubic {
  std::vector<std::vector<double>> coefficients;  // per coordinate: a0..a3
  mpq_class value(int k, const mpq_class& t) const {
    const auto& a = coefficients[static_cast<std::size_t>(k)];
    return ((mpq_class(a[3]) * t + a[2]) * t + a[1]) * t + a[0];
  }
  mpq_class slope(int k, const mpq_class& t) const {
    const auto& a = coefficients[static_cast<std::size_t>(k)];
    return (3 * mpq_class(a[3]) * t + 2 * mpq_class(a[2])) * t + a[1];
  }
};

RC_GTEST_PROP(Hermite, ReproducesCubicPolynomials, ()) {
  const int d = *rc::gen::inRange(1, 4);
  const int count = *rc::gen::inRange(2, 9);
  Cubic cubic;
  for (int k = 0; k < d; ++k)
    cubic.coefficients.push_back(*rc::gen::container<std::vector<double>>(
        4, rc::gen::map(rc::gen::inRange(-64, 65), [](int i) { return i / 8.0; })));
  // Strictly increasing dyadic parameters (steps 1/16 .. 2): data exact in double.
  std::vector<double> parameters{*rc::gen::map(rc::gen::inRange(-32, 33), [](int i) { return i / 16.0; })};
  for (int i = 1; i < count; ++i)
    parameters.push_back(parameters.back() + *rc::gen::inRange(1, 33) / 16.0);
  std::vector<double> values, slopes;
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < d; ++k) {
      values.push_back(cubic.value(k, mpq_class(parameters[static_cast<std::size_t>(i)])).get_d());
      slopes.push_back(cubic.slope(k, mpq_class(parameters[static_cast<std::size_t>(i)])).get_d());
    }
  const auto curve =
      interpolate_hermite(PointArray::make(d, values).value(), PointArray::make(d, slopes).value(), parameters);
  RC_ASSERT(curve.has_value());
  const double scale = std::max(1.0, scale_of(PointArray::make(d, values).value()));
  for (int j = 0; j <= 64; ++j) {
    const double t = parameters.front() + (parameters.back() - parameters.front()) * j / 64.0;
    const Point c = point_at(*curve, t);
    for (int k = 0; k < d; ++k) RC_ASSERT(test::error_of(c[k], cubic.value(k, mpq_class(t))) <= 1e-13 * scale);
  }
}

TEST(Hermite, ReproducesTheDataOnBothSidesOfEveryKnot) {
  // Points and tangents of no particular shape, uneven steps.
  const PointArray points = PointArray::make(2, {0, 0, 2, 1, 3, -1, 7, 2, 8, 0}).value();
  const PointArray tangents = PointArray::make(2, {1, 0, 0, 5, -2, 1, 3, 3, 0, -1}).value();
  const std::vector<double> parameters{0, 0.25, 1.5, 1.75, 4};
  for (bool closed : {false, true}) {
    std::vector<double> ts = parameters;
    if (closed) ts.push_back(5.5);
    const auto curve = interpolate_hermite(points, tangents, ts, closed ? Closure::closed : Closure::open);
    ASSERT_TRUE(curve) << curve.error().message;
    const BezierPieces pieces = to_bezier_pieces(*curve);
    const std::size_t segments = ts.size() - 1;
    ASSERT_EQ(pieces.pieces.size(), segments);
    for (std::size_t i = 0; i < segments; ++i) {
      const double h = ts[i + 1] - ts[i];
      const std::size_t next = (i + 1) % points.size();
      const auto& piece = pieces.pieces[i];
      const Point start = point_at(piece, 0.0), end = point_at(piece, 1.0);
      const Point d_start = derivative_at(piece, 0.0, 1), d_end = derivative_at(piece, 1.0, 1);
      for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_NEAR(start[k], points[i][k], 1e-14 * 8) << "segment " << i;
        EXPECT_NEAR(end[k], points[next][k], 1e-14 * 8) << "segment " << i;
        EXPECT_NEAR(d_start[k] / h, tangents[i][k], 1e-13 * 8 / h) << "segment " << i;
        EXPECT_NEAR(d_end[k] / h, tangents[next][k], 1e-13 * 8 / h) << "segment " << i;
      }
    }
    if (closed) {
      EXPECT_EQ(point_at(*curve, ts.back()), point_at(*curve, ts.front()));
      EXPECT_EQ(curve->domain(), (Interval{0, 5.5}));
    }
  }
}

TEST(Hermite, RefusesBadInput) {
  const PointArray points = PointArray::make(2, {0, 0, 1, 0, 1, 1}).value();
  const PointArray tangents = PointArray::make(2, {1, 0, 0, 1, -1, 0}).value();
  const std::vector<double> t{0, 1, 2};
  auto e = interpolate_hermite(PointArray::make(2, {0, 0}).value(), PointArray::make(2, {1, 0}).value(),
                               std::vector<double>{0});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "Hermite interpolation needs at least 2 points, got 1");
  e = interpolate_hermite(points, PointArray::make(2, {1, 0, 0, 1}).value(), t);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "Hermite interpolation needs one tangent per point: 3 points, 2 tangents");
  e = interpolate_hermite(points, PointArray::make(3, {1, 0, 0, 0, 1, 0, -1, 0, 0}).value(), t);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "the tangents have dimension 3, the points have 2");
  e = interpolate_hermite(points, tangents, t, Closure::closed);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "Hermite interpolation of 3 points (closed) needs 4 parameter values, got 3");
  e = interpolate_hermite(points, tangents, std::vector<double>{0, 2, 1});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "parameters must increase strictly: parameter 2 is 1, parameter 1 is 2");
  e = interpolate_hermite(points, PointArray::from_trusted(2, {1, 0, 0, std::nan(""), -1, 0}), t);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "coordinate 1 of tangent 1 is NaN");
  e = interpolate_hermite(points, tangents, std::vector<double>{0, 1, std::numeric_limits<double>::infinity()});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "parameter 2 is infinite");
  const PointArray repeated = PointArray::make(2, {0, 0, 1, 0, 0, 0}).value();
  e = interpolate_hermite(repeated, tangents, std::vector<double>{0, 1, 2, 3}, Closure::closed);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("repeats the first"), std::string::npos) << e.error().message;
}

}  // namespace
}  // namespace casteljau

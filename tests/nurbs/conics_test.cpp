// Exact conics (nurbs/conics.hpp). References: the circle itself (|C(u) - O|
// must be R), an exact rational evaluation of the NURBS with GMP (mpq
// Cox–de Boor, independent of the code under test), and seed 003's worked
// example (the cubic semicircle's radial error of about 0.055).
#include "casteljau/nurbs/conics.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "support/exact.hpp"

namespace casteljau {
namespace {

constexpr double kPi = std::numbers::pi;

/// A measured number for RecordProperty (three significant digits).
std::string measured(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

/// The largest | |C(u) - O| - R | / R over `count` evenly spaced parameters
/// of the domain (both ends included), with the distance summed in long
/// double so that measuring adds no error of its own beyond the subtraction.
double max_radial_error(const BSplineCurve& curve, const Point& center, double radius, int count) {
  std::vector<double> us(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) us[static_cast<std::size_t>(i)] = curve.domain().lerp(static_cast<double>(i) / (count - 1));
  const auto d = static_cast<std::size_t>(curve.dimension());
  std::vector<double> out(us.size() * d);
  points_at(curve, us, out);
  double worst = 0.0;
  for (std::size_t i = 0; i < us.size(); ++i) {
    long double sum = 0.0L;
    for (std::size_t j = 0; j < d; ++j) {
      const long double delta = static_cast<long double>(out[i * d + j]) - static_cast<long double>(center[j]);
      sum += delta * delta;
    }
    const double error = static_cast<double>(std::fabs(std::sqrt(sum) - static_cast<long double>(radius)));
    worst = std::max(worst, error / radius);
  }
  return worst;
}

// ---------------------------------------------------------------------------
// The circle: radius error over 1e5 parameters.

TEST(Circle, RadiusErrorBelow1e15RelativeOver1e5ParametersIn2D) {
  for (const double radius : {1.0, 3.0, 1e-3, 0.7, 12345.678, 1e6}) {
    const auto circle = make_circle(0.0, 0.0, radius);
    ASSERT_TRUE(circle.has_value()) << circle.error().message;
    const double error = max_radial_error(*circle, {0.0, 0.0}, radius, 100'000);
    EXPECT_LE(error, 1e-15) << "radius " << radius;
    RecordProperty("radius_error_R_" + measured(radius), measured(error));
  }
}

TEST(Circle, RadiusErrorBelow1e15RelativeOn3DPlanesAndOffCentre) {
  // A tilted plane in 3D: X and Y are unit and orthogonal only up to rounding.
  const double s = 1.0 / std::sqrt(2.0), q = 1.0 / std::sqrt(6.0);
  const ConicFrame tilted{{0.5, -0.25, 2.0}, {s, -s, 0.0}, {q, q, -2 * q}};
  const ConicFrame planes[] = {
      ConicFrame{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
      ConicFrame{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}},
      tilted,
      // Centre of the same size as the radius: |C - O| loses only the
      // rounding of C's coordinates (about |O| ulp), still below 1e-15 R.
      ConicFrame{{1.5, 2.0}, {0.6, 0.8}, {-0.8, 0.6}},
  };
  for (const auto& frame : planes) {
    const auto circle = make_circle(frame, 2.0);
    ASSERT_TRUE(circle.has_value()) << circle.error().message;
    EXPECT_LE(max_radial_error(*circle, frame.center, 2.0, 100'000), 1e-15);
  }
}

TEST(Circle, FarFromTheOriginTheErrorScalesWithTheCentreNotTheRadius) {
  // Why 1e-15 x R needs a centre of about R's size: a point 1e6 away from
  // the origin carries 1e6 x 1.1e-16 of rounding in each coordinate whatever
  // the radius. With R = 1 the radial error is then about 1e-10 x R, yet
  // still a few ulps of the coordinates' scale |O| + R.
  const Point center{1e6, -1e6};
  const auto circle = make_circle(center[0], center[1], 1.0);
  ASSERT_TRUE(circle.has_value());
  const double error = max_radial_error(*circle, center, 1.0, 100'000);
  EXPECT_LE(error, 4 * 2.2e-16 * (1e6 + 1.0));
}

TEST(Circle, NinePointNetOfTheNurbsBook) {
  const auto circle = make_circle(0.0, 0.0, 2.0);
  ASSERT_TRUE(circle.has_value());
  EXPECT_EQ(circle->degree(), 2);
  const std::vector<double> knots{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  EXPECT_EQ(std::vector<double>(circle->knots().begin(), circle->knots().end()), knots);
  const std::vector<double> points{2, 0, 2, 2, 0, 2, -2, 2, -2, 0, -2, -2, 0, -2, 2, -2, 2, 0};
  const auto coordinates = circle->control_points().coordinates();
  EXPECT_EQ(std::vector<double>(coordinates.begin(), coordinates.end()), points);
  const double h = std::sqrt(0.5);
  EXPECT_EQ(std::vector<double>(circle->weights().begin(), circle->weights().end()),
            (std::vector<double>{1, h, 1, h, 1, h, 1, h, 1}));
}

// ---------------------------------------------------------------------------
// Exact rational reference: the NURBS evaluated in mpq arithmetic.

/// N_{i,p}(u) by the Cox–de Boor recursion in exact rationals (0/0 := 0; the
/// last non-empty span closed at the end of the domain).
mpq_class exact_basis(const std::vector<mpq_class>& knots, int i, int p, const mpq_class& u, const mpq_class& end) {
  if (p == 0) {
    const bool inside = knots[i] <= u && u < knots[i + 1];
    const bool last = u == end && knots[i] < knots[i + 1] && knots[i + 1] == end;
    return (inside || last) ? mpq_class(1) : mpq_class(0);
  }
  mpq_class value = 0;
  if (knots[i + p] != knots[i]) value += (u - knots[i]) / (knots[i + p] - knots[i]) * exact_basis(knots, i, p - 1, u, end);
  if (knots[i + p + 1] != knots[i + 1]) {
    value += (knots[i + p + 1] - u) / (knots[i + p + 1] - knots[i + 1]) * exact_basis(knots, i + 1, p - 1, u, end);
  }
  return value;
}

/// sum w_i P_i N_i(u) / sum w_i N_i(u), exactly, from the curve's doubles.
std::vector<mpq_class> exact_nurbs_point(const BSplineCurve& curve, const mpq_class& u) {
  std::vector<mpq_class> knots;
  for (const double k : curve.knots()) knots.emplace_back(k);
  const int p = curve.degree(), d = curve.dimension();
  const auto n = curve.control_points().size();
  const mpq_class end(curve.domain().upper);
  std::vector<mpq_class> numerator(static_cast<std::size_t>(d), mpq_class(0));
  mpq_class denominator = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const mpq_class basis = exact_basis(knots, static_cast<int>(i), p, u, end);
    if (basis == 0) continue;
    const mpq_class wn = mpq_class(curve.weights()[i]) * basis;
    denominator += wn;
    for (int j = 0; j < d; ++j) numerator[j] += wn * mpq_class(curve.control_points()[i][j]);
  }
  for (auto& c : numerator) c /= denominator;
  return numerator;
}

TEST(Circle, QuarterCircleMatchesAnExactRationalEvaluation) {
  const auto quarter = make_arc(0.0, 0.0, 1.0, 0.0, kPi / 2);
  ASSERT_TRUE(quarter.has_value());
  ASSERT_EQ(quarter->control_points().size(), 3u);  // one rational quadratic piece
  double worst_point = 0.0, worst_shape = 0.0;
  for (int k = 0; k <= 1024; ++k) {
    const double u = k / 1024.0;  // exact dyadic parameters
    const auto exact = exact_nurbs_point(*quarter, mpq_class(u));
    const Point computed = point_at(*quarter, u);
    for (int j = 0; j < 2; ++j) worst_point = std::max(worst_point, test::error_of(computed[j], exact[j]));
    // The exact rational curve of the rounded weight √½ lies on the unit
    // circle up to that rounding (|w - cos 45°| <= 2^-54): x² + y² - 1 is tiny.
    const mpq_class residual = exact[0] * exact[0] + exact[1] * exact[1] - 1;
    worst_shape = std::max(worst_shape, std::abs(residual.get_d()));
  }
  EXPECT_LE(worst_point, 4.5e-16);  // a couple of ulps of the unit scale
  EXPECT_LE(worst_shape, 2.5e-16);
  RecordProperty("quarter_circle_worst_point_error", measured(worst_point));
  RecordProperty("quarter_circle_worst_exact_residual", measured(worst_shape));
}

TEST(Circle, FullCircleMatchesAnExactRationalEvaluationAcrossItsKnots) {
  const auto circle = make_circle(0.0, 0.0, 5.0);
  ASSERT_TRUE(circle.has_value());
  for (int k = 0; k <= 256; ++k) {
    const double u = k / 256.0;  // hits every knot 1/4, 1/2, 3/4 exactly
    const auto exact = exact_nurbs_point(*circle, mpq_class(u));
    const Point computed = point_at(*circle, u);
    for (int j = 0; j < 2; ++j) EXPECT_LE(test::error_of(computed[j], exact[j]), 5.0 * 4.5e-16) << "u = " << u;
  }
}

// ---------------------------------------------------------------------------
// Arcs of any sweep: end points and tangents.

TEST(Arc, PieceCountFollowsA71) {
  const std::pair<double, std::size_t> cases[] = {{0.1, 3},         {kPi / 2, 3},      {kPi / 2 + 1e-9, 5},
                                                  {kPi, 5},         {-kPi, 5},         {1.5 * kPi, 7},
                                                  {1.5 * kPi + 1e-9, 9}, {2 * kPi, 9}, {-2 * kPi, 9}};
  for (const auto& [sweep, count] : cases) {
    const auto arc = make_arc(0.0, 0.0, 1.0, 0.3, sweep);
    ASSERT_TRUE(arc.has_value()) << sweep;
    EXPECT_EQ(arc->control_points().size(), count) << "sweep " << sweep;
    EXPECT_EQ(arc->domain(), (Interval{0.0, 1.0}));
  }
}

TEST(Arc, EndPointsAndTangentsAreExact) {
  for (const double start : {0.0, 0.3, kPi / 2, -2.0, 3 * kPi}) {
    for (const double sweep : {0.01, 0.5, kPi / 2, 2.0, kPi, -kPi, 4.0, 1.5 * kPi, -5.5, 2 * kPi, -2 * kPi}) {
      const double radius = 2.5;
      const auto arc = make_arc(1.0, -1.0, radius, start, sweep);
      ASSERT_TRUE(arc.has_value());
      const auto& net = arc->control_points();
      // A clamped curve interpolates its end control points bit for bit.
      EXPECT_EQ(point_at(*arc, 0.0), Point(net[0].begin(), net[0].end()));
      EXPECT_EQ(point_at(*arc, 1.0), Point(net[net.size() - 1].begin(), net[net.size() - 1].end()));
      // ... which are the points of the circle at start and start + sweep.
      // (std::cos of the rounded angle a + sweep is off by up to an ulp of
      // the angle: the reference has that error, casteljau's exact eighth
      // turns do not.)
      const double end = start + sweep;
      const double end_tolerance = 4e-16 * radius * std::max(1.0, std::abs(end));
      EXPECT_NEAR(net[0][0], 1.0 + radius * std::cos(start), end_tolerance);
      EXPECT_NEAR(net[0][1], -1.0 + radius * std::sin(start), end_tolerance);
      EXPECT_NEAR(net[net.size() - 1][0], 1.0 + radius * std::cos(end), end_tolerance);
      EXPECT_NEAR(net[net.size() - 1][1], -1.0 + radius * std::sin(end), end_tolerance);
      // Tangents: along the circle, in the direction of the sweep, of length
      // 2 k R sin(dθ/2) for k pieces on [0,1] (C'(0) = 2 w (P_1 - P_0) / Δu).
      // The derivative's control points 2 k w (P_1 - P_0) are differences of
      // coordinates of size |O| + R: their rounding (a few ulps of that
      // scale, times 2k) is the tolerance, whatever the sweep (a short arc's
      // tangent is small, its absolute error is not).
      const int pieces = static_cast<int>(net.size() - 1) / 2;
      const double speed = 2 * pieces * radius * std::sin(std::abs(sweep) / pieces / 2);
      const double direction = sweep > 0 ? 1.0 : -1.0;
      const double tolerance = 2 * pieces * 4 * 2.220446049250313e-16 * (radius + std::sqrt(2.0));
      for (const auto& [u, angle] : {std::pair{0.0, start}, std::pair{1.0, end}}) {
        const Point tangent = derivative_at(*arc, u, 1);
        EXPECT_NEAR(tangent[0], -direction * speed * std::sin(angle), tolerance) << start << " " << sweep;
        EXPECT_NEAR(tangent[1], direction * speed * std::cos(angle), tolerance) << start << " " << sweep;
      }
      EXPECT_LE(max_radial_error(*arc, {1.0, -1.0}, radius, 2001), 1e-15);
    }
  }
}

TEST(Arc, AFullTurnFromAnyAngleClosesExactly) {
  for (const double start : {0.1, 1.0, -2.5, 100.0}) {
    for (const double sweep : {2 * kPi, -2 * kPi}) {
      const auto arc = make_arc(0.5, 0.25, 3.0, start, sweep);
      ASSERT_TRUE(arc.has_value());
      EXPECT_EQ(point_at(*arc, 0.0), point_at(*arc, 1.0)) << start << " " << sweep;
    }
  }
}

TEST(Arc, QuarterTurnAnglesGiveExactControlPoints) {
  // std::cos(π/2) is 6e-17: without exact eighth-turn values the control
  // points would be off the axes by that much.
  const auto arc = make_arc(0.0, 0.0, 1.0, kPi / 2, kPi / 2);
  ASSERT_TRUE(arc.has_value());
  const auto coordinates = arc->control_points().coordinates();
  EXPECT_EQ(std::vector<double>(coordinates.begin(), coordinates.end()), (std::vector<double>{0, 1, -1, 1, -1, 0}));
}

RC_GTEST_PROP(Arc, EveryArcStaysOnItsCircle, ()) {
  const double radius = std::ldexp(1.0 + *rc::gen::inRange(0, 1000) / 1000.0, *rc::gen::inRange(-10, 11));
  const double start = *rc::gen::inRange(-7000, 7001) / 1000.0;
  const int sweep_milli = *rc::gen::inRange(-6283, 6284);
  RC_PRE(sweep_milli != 0);
  const double sweep = sweep_milli / 1000.0;
  const double cx = radius * *rc::gen::inRange(-1000, 1001) / 1000.0;
  const double cy = radius * *rc::gen::inRange(-1000, 1001) / 1000.0;
  const auto arc = make_arc(cx, cy, radius, start, sweep);
  RC_ASSERT(arc.has_value());
  // The coordinates are of size |O| + R (up to 2.4 R here) and each carries
  // a few ulps of that: relative to R the bound is 1e-15 (|O| + R) / R.
  const double scale = (radius + std::hypot(cx, cy)) / radius;
  RC_ASSERT(max_radial_error(*arc, {cx, cy}, radius, 513) <= 1e-15 * scale);
}

// ---------------------------------------------------------------------------
// Ellipse.

TEST(Ellipse, PointsSatisfyTheImplicitEquation) {
  const double a = 4.0, b = 1.5;
  const auto ellipse = make_ellipse(ConicFrame{{1, 2, 3}, {0, 1, 0}, {0, 0, -1}}, a, b);
  ASSERT_TRUE(ellipse.has_value());
  double worst = 0.0;
  for (int i = 0; i <= 20'000; ++i) {
    const Point p = point_at(*ellipse, i / 20'000.0);
    EXPECT_EQ(p[0], 1.0);  // stays in its plane x = 1
    const double x = (p[1] - 2.0) / a, y = -(p[2] - 3.0) / b;
    worst = std::max(worst, std::abs(x * x + y * y - 1.0));
  }
  // The coordinates are of size |O| + a = 7.7 while b = 1.5: a few ulps of
  // 7.7 divided by b, doubled by squaring, is the rounding floor here.
  EXPECT_LE(worst, 8 * 2.220446049250313e-16 * 7.7 / b);
  EXPECT_EQ(point_at(*ellipse, 0.0), (Point{1, 6, 3}));
  EXPECT_EQ(point_at(*ellipse, 0.25), (Point{1, 2, 1.5}));
}

TEST(Ellipse, AxisAlignedIn2D) {
  const auto ellipse = make_ellipse(0.0, 0.0, 2.0, 1.0);
  ASSERT_TRUE(ellipse.has_value());
  EXPECT_EQ(point_at(*ellipse, 0.5), (Point{-2, 0}));
  EXPECT_EQ(point_at(*ellipse, 0.75), (Point{0, -1}));
}

// ---------------------------------------------------------------------------
// Seed 003: the semicircle, cubic against exact.

TEST(Semicircle, CubicApproximationIsOff0055WhileTheNurbsIsExact) {
  const BezierCurve cubic = seed_semicircle_cubic();
  double cubic_error = 0.0;
  for (int i = 0; i <= 100'000; ++i) {
    const Point p = point_at(cubic, i / 100'000.0);
    cubic_error = std::max(cubic_error, std::abs(std::hypot(p[0], p[1]) - 3.0));
  }
  // Seed 003 claims about 1/100; the true value (seeds.md corrections) is 0.055.
  EXPECT_GT(cubic_error, 0.054);
  EXPECT_LT(cubic_error, 0.056);
  const BSplineCurve exact = seed_semicircle();
  const double nurbs_error = max_radial_error(exact, {0.0, 0.0}, 3.0, 100'001);
  EXPECT_LE(nurbs_error, 1e-15);
  RecordProperty("semicircle_cubic_max_radial_error", measured(cubic_error));
  RecordProperty("semicircle_nurbs_max_radial_error_relative", measured(nurbs_error));
}

TEST(Semicircle, SameEndsAndDirectionAsTheSeedsCubic) {
  const BSplineCurve exact = seed_semicircle();
  EXPECT_EQ(point_at(exact, 0.0), (Point{-3, 0}));
  EXPECT_EQ(point_at(exact, 0.5), (Point{0, 3}));
  EXPECT_EQ(point_at(exact, 1.0), (Point{3, 0}));
  const auto coordinates = exact.control_points().coordinates();
  EXPECT_EQ(std::vector<double>(coordinates.begin(), coordinates.end()),
            (std::vector<double>{-3, 0, -3, 3, 0, 3, 3, 3, 3, 0}));
  // Both start going up (+y) at A.
  EXPECT_GT(derivative_at(exact, 0.0, 1)[1], 0.0);
  EXPECT_GT(derivative_at(seed_semicircle_cubic(), 0.0, 1)[1], 0.0);
}

// ---------------------------------------------------------------------------
// Bad input: one message naming what is wrong.

void expect_error(const Expected<BSplineCurve>& result, const std::string& expected) {
  ASSERT_FALSE(result.has_value()) << expected;
  EXPECT_NE(result.error().message.find(expected), std::string::npos) << result.error().message;
}

TEST(Conics, RefuseBadInput) {
  const double nan = std::nan(""), inf = INFINITY;
  expect_error(make_circle(0, 0, 0.0), "the radius is 0, it must be finite and > 0");
  expect_error(make_circle(0, 0, -1.0), "the radius is -1");
  expect_error(make_circle(0, 0, nan), "the radius is NaN, it must be finite and > 0");
  expect_error(make_circle(0, 0, inf), "the radius is infinite");
  expect_error(make_arc(0, 0, 1, 0, 0.0), "the sweep is 0");
  expect_error(make_arc(0, 0, 1, 0, 7.0), "the sweep is 7, more than a full turn");
  expect_error(make_arc(0, 0, 1, 0, -6.3), "more than a full turn");
  expect_error(make_arc(0, 0, 1, 0, nan), "the sweep is NaN");
  expect_error(make_arc(0, 0, 1, inf, 1.0), "the start angle is infinite");
  expect_error(make_arc(nan, 0, 1, 0, 1.0), "coordinate 0 of the centre is NaN");
  expect_error(make_circle(ConicFrame{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}, 1.0), "the axes are not orthonormal");
  expect_error(make_circle(ConicFrame{{0, 0, 0}, {1, 0, 0}, {0.6, 0.8, 0}}, 1.0), "x axis . y axis = 0.6");
  expect_error(make_circle(ConicFrame{{0, 0, 0}, {1, 0}, {0, 1}}, 1.0), "the axes have 2 and 2 coordinates");
  expect_error(make_circle(ConicFrame{{0}, {1}, {1}}, 1.0), "a conic needs a plane");
  expect_error(make_ellipse(0, 0, 1.0, 0.0), "the semi-axis along y is 0");
  expect_error(make_ellipse(0, 0, -2.0, 1.0), "the semi-axis along x is -2");
  // Radii and centres are coordinates (core/tolerance.hpp: kMaxCoordinate),
  // and the control points r / cos(dθ/2) from the centre must be too.
  expect_error(make_arc(0, 0, 1.79e308, 0.1, 3.0),
               "the radius is 1.79e+308, outside (0, 1e+100], the range of coordinates");
  expect_error(make_circle(0, 1e308, 1.0), "coordinate 1 of the centre is 1e+308, outside [-1e+100, 1e+100]");
  expect_error(make_arc(0, 0, 1e100, -0.5, 1.0), "the conic reaches outside the range of coordinates: coordinate 0 "
                                                 "of control point 1 is 1.139");
  expect_error(make_ellipse(0, 0, 1.0, 2e100), "the semi-axis along y is 2e+100, outside (0, 1e+100]");
}

TEST(Conics, AxesOffByRoundingAreAccepted) {
  const double s = std::sqrt(0.5);
  const auto circle = make_circle(ConicFrame{{0, 0, 0}, {s, s, 0}, {-s, s, 1e-13}}, 1.0);
  ASSERT_TRUE(circle.has_value()) << circle.error().message;
  EXPECT_LE(max_radial_error(*circle, {0, 0, 0}, 1.0, 10'001), 1e-15);
}

}  // namespace
}  // namespace casteljau

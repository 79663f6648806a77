// Arc length, its inverse and equal-arc-length sampling against closed forms:
// straight lines (one uneven parameterization among them), the parabola
// y = x^2 (L = [x sqrt(1+4x^2)/2 + asinh(2x)/4]), the semicubical parabola
// (s^2, s^3) with its cusp (L = 2 ((13)^(3/2) - 8) / 27), the NURBS circle and
// arcs (R x angle), each at every requested accuracy from 1e-1 to 1e-13 of
// the curve's size, and on every curve kind. The ellipse against scipy's
// complete elliptic integral is in tests/python/test_module_arc_length.py.
#include "casteljau/ops/arc_length.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "support/bspline_generators.hpp"
#include "support/make.hpp"

namespace casteljau {
namespace {

using test::bezier;

constexpr double kPi = std::numbers::pi;

/// Length of y = x^2 from 0 to x.
double parabola_length(double x) { return 0.5 * x * std::sqrt(1 + 4 * x * x) + 0.25 * std::asinh(2 * x); }

struct ExactCase {
  const char* name;
  BSplineCurve curve;  // every kind becomes a B-spline here; the kinds are compared below
  double length;
};

std::vector<ExactCase> exact_cases() {
  std::vector<ExactCase> cases;
  cases.push_back({"segment (0,0)-(3,4)", to_bspline(bezier({{0, 0}, {3, 4}})), 5.0});
  // The same segment with control points bunched unevenly (monotone: still 5).
  cases.push_back({"uneven straight cubic", to_bspline(bezier({{0, 0}, {0.3, 0.4}, {2.1, 2.8}, {3, 4}})), 5.0});
  // x = 2t, y = 4t^2: y = x^2 on [0, 2].
  cases.push_back({"parabola", to_bspline(bezier({{0, 0}, {1, 0}, {2, 4}})), parabola_length(2.0)});
  // (s^2, s^3), s = 2t - 1: a cusp at t = 1/2.
  cases.push_back({"semicubical cusp", to_bspline(bezier({{1, -1}, {-1.0 / 3, 1}, {-1.0 / 3, -1}, {1, 1}})),
                   2 * (std::pow(13.0, 1.5) - 8) / 27});
  cases.push_back({"circle R = 3", make_circle(1.0, 2.0, 3.0).value(), 2 * kPi * 3.0});
  cases.push_back({"arc of 100 degrees", make_arc(0.0, 0.0, 2.0, 0.3, 100.0 * kPi / 180).value(), 2.0 * 100.0 * kPi / 180});
  cases.push_back({"arc of 300 degrees", make_arc(0.0, 0.0, 0.5, -1.0, 300.0 * kPi / 180).value(), 0.5 * 300.0 * kPi / 180});
  return cases;
}

TEST(ArcLength, MeetsEveryRequestedAccuracyOnExactCases) {
  for (const ExactCase& c : exact_cases()) {
    const double size = size_of(c.curve);
    double worst_ratio = 0.0;
    for (int k = 1; k <= 13; ++k) {
      const double tolerance = std::pow(10.0, -k) * size;
      const auto length = arc_length(c.curve, Tolerance{tolerance});
      ASSERT_TRUE(length.has_value()) << c.name << ": " << length.error().message;
      const double error = std::abs(*length - c.length);
      EXPECT_LE(error, tolerance) << c.name << " at 1e-" << k << " of the size";
      worst_ratio = std::max(worst_ratio, error / tolerance);
    }
    std::printf("arc length %-22s largest error / requested accuracy over 1e-1..1e-13: %.2g\n", c.name, worst_ratio);
  }
}

TEST(ArcLength, EveryKindGivesTheSameLength) {
  // The parabola as a Bézier curve, as a B-spline, and as a piecewise curve of its halves.
  const BezierCurve parabola = bezier({{0, 0}, {1, 0}, {2, 4}});
  const auto halves = split_at(parabola, 0.25).value();
  const PiecewiseBezierCurve piecewise = PiecewiseBezierCurve::make({halves.first, halves.second}).value();
  const BSplineCurve as_bspline = to_bspline(parabola);  // named: a view must not outlive its curve
  for (const CurveView view : {CurveView(parabola), CurveView(as_bspline), CurveView(piecewise)})
    EXPECT_NEAR(arc_length(view, Tolerance{1e-13}).value(), parabola_length(2.0), 1e-13);
  // A rational Bézier quarter circle of radius 2.
  const BezierCurve quarter = bezier({{2, 0}, {2, 2}, {0, 2}}, {1, std::sqrt(0.5), 1});
  EXPECT_NEAR(arc_length(quarter, Tolerance{1e-13}).value(), kPi, 1e-13);
  // A single point has length 0.
  const BezierCurve point = bezier({{1, 1}, {1, 1}});
  EXPECT_EQ(arc_length(point, Tolerance{1e-9}).value(), 0.0);
}

TEST(ArcLength, OfASubInterval) {
  const BezierCurve parabola = bezier({{0, 0}, {1, 0}, {2, 4}});  // x = 2t
  EXPECT_NEAR(arc_length(parabola, Interval{0.25, 0.75}, Tolerance{1e-13}).value(),
              parabola_length(1.5) - parabola_length(0.5), 1e-13);
  EXPECT_EQ(arc_length(parabola, Interval{0.5, 0.5}, Tolerance{1e-13}).value(), 0.0);
  // Across the knots of the circle (its quarter arcs are pieces).
  const BSplineCurve circle = make_circle(0.0, 0.0, 1.0).value();
  const Interval domain = circle.domain();
  const double half = arc_length(circle, Interval{domain.lower, domain.lerp(0.5)}, Tolerance{1e-13}).value();
  EXPECT_NEAR(half, kPi, 1e-13);
}

TEST(ArcLength, ParameterAtLengthInvertsIt) {
  const BezierCurve parabola = bezier({{0, 0}, {1, 0}, {2, 4}});
  const double total = parabola_length(2.0);
  for (double fraction : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    const double s = fraction * total;
    const double u = parameter_at_length(parabola, s, Tolerance{1e-12}).value();
    EXPECT_NEAR(parabola_length(2 * u), s, 1e-12) << fraction;
  }
  // A line of uniform speed: u = s / 5 to rounding.
  const BezierCurve line = bezier({{0, 0}, {3, 4}});
  EXPECT_NEAR(parameter_at_length(line, 2.0, Tolerance{1e-12}).value(), 0.4, 1e-13);
  // Through the cusp: half the length is the cusp itself, t = 1/2.
  const BezierCurve cusp = bezier({{1, -1}, {-1.0 / 3, 1}, {-1.0 / 3, -1}, {1, 1}});
  const double cusp_length = 2 * (std::pow(13.0, 1.5) - 8) / 27;
  EXPECT_NEAR(parameter_at_length(cusp, cusp_length / 2, Tolerance{1e-12}).value(), 0.5, 1e-6);
}

TEST(ArcLength, EqualArcLengthSamplesOfTheCircleAreEquallySpaced) {
  const double radius = 3.0;
  const BSplineCurve circle = make_circle(1.0, 2.0, radius).value();
  const int n = 13;
  const auto us = equal_arc_length_parameters(circle, n, Tolerance{1e-11}).value();
  ASSERT_EQ(us.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(us.front(), circle.domain().lower);
  EXPECT_EQ(us.back(), circle.domain().upper);
  const double chord = 2 * radius * std::sin(kPi / (n - 1));
  for (int i = 0; i + 1 < n; ++i) {
    EXPECT_LT(us[i], us[i + 1]);
    EXPECT_NEAR(distance(point_at(circle, us[i]), point_at(circle, us[i + 1])), chord, 1e-10) << i;
  }
}

/// Invariants on random B-splines and NURBS (every kind reaches the same
/// quadrature through its Bézier pieces): the chord is the shortest path, the
/// control polygons of the pieces the longest (the convex hull property of
/// their hodographs' integral), and length adds up across a split.
/// The value, or the property fails with the error's message.
template <class T>
T checked(Expected<T> result) {
  if (!result) RC_FAIL(result.error().message);
  return *result;
}

RC_GTEST_PROP(ArcLength, LiesBetweenChordAndPolygonAndAddsUp, ()) {
  const BSplineCurve curve = *test::bspline_curve({.max_degree = 5});
  const double tolerance = 1e-9 * std::max(1.0, size_of(curve));
  const double length = checked(arc_length(curve, Tolerance{tolerance}));
  const Interval domain = curve.domain();
  RC_ASSERT(distance(point_at(curve, domain.lower), point_at(curve, domain.upper)) <= length + tolerance);
  double polygon = 0.0;
  for (const BezierCurve& piece : to_bezier_pieces(curve).pieces)
    for (std::size_t i = 0; i + 1 < piece.control_points().size(); ++i)
      polygon += distance(piece.control_points()[i], piece.control_points()[i + 1]);
  RC_ASSERT(length <= polygon + tolerance);
  const double u = domain.lerp(*rc::gen::inRange(1, 1000) * 1e-3);
  const double left = checked(arc_length(curve, Interval{domain.lower, u}, Tolerance{tolerance}));
  const double right = checked(arc_length(curve, Interval{u, domain.upper}, Tolerance{tolerance}));
  RC_ASSERT(std::abs(left + right - length) <= 3 * tolerance);
  // The inverse lands where the length says.
  const double back = checked(parameter_at_length(curve, left, Tolerance{tolerance}));
  RC_ASSERT(std::abs(checked(arc_length(curve, Interval{domain.lower, back}, Tolerance{tolerance})) - left) <=
            3 * tolerance);
}

TEST(ArcLength, OfRationalCurvesWithExtremeWeights) {
  // Issue 39: (0,0), (1,1), (2,0) with weights 1, w, 1 gave a length of 0 for
  // w = 1e20 and 1e50 (all but the corner within 1e-10 of the parameter's
  // ends) and was refused for w = 1e10. The conic is convex and symmetric, and
  // passes through (1, h), h = w / (1 + w), with a horizontal tangent: its
  // length lies between the inscribed polygon (0,0), (1,h), (2,0) and the
  // circumscribed one (0,0), (h,h), (2-h,h), (2,0) (both exact bounds; for
  // w >= 1e20 they agree to rounding), and half of it is reached at t = 1/2.
  for (const double w : {1e5, 1e10, 1e20, 1e50}) {
    const double h = w / (1.0 + w);
    const double below = 2.0 * std::sqrt(1.0 + h * h), above = 2.0 * std::sqrt(2.0) * h + 2.0 * (1.0 - h);
    for (const std::vector<double>& weights : {std::vector<double>{1.0, w, 1.0}, std::vector<double>{1.0 / std::sqrt(w), std::sqrt(w), 1.0 / std::sqrt(w)}}) {
      const BezierCurve corner = bezier({{0, 0}, {1, 1}, {2, 0}}, weights);
      const double tolerance = 1e-12;
      const double length = arc_length(corner, Tolerance{tolerance}).value();
      EXPECT_GE(length, below - tolerance) << w;
      EXPECT_LE(length, above + tolerance) << w;
      EXPECT_NEAR(arc_length(corner, Interval{0.0, 0.5}, Tolerance{tolerance}).value(), length / 2, tolerance) << w;
      // Where the curve turns its corner it barely moves (|C'(1/2)| = 2 / (1 + w)):
      // the parameter of half the length is known only through its point,
      // within the tolerance of (1, h).
      const Point apex{1.0, h};
      const double half = parameter_at_length(corner, length / 2, Tolerance{tolerance}).value();
      EXPECT_LE(distance(point_at(corner, half), apex), 2 * tolerance) << w;
      const double middle = equal_arc_length_parameters(corner, 3, Tolerance{tolerance}).value()[1];
      EXPECT_LE(distance(point_at(corner, middle), apex), 2 * tolerance) << w;
    }
  }
  // The other way: weights 1, 1e-50, 1 leave the chord by 1e-50.
  const BezierCurve flat = bezier({{0, 0}, {1, 1}, {2, 0}}, {1.0, 1e-50, 1.0});
  EXPECT_NEAR(arc_length(flat, Tolerance{1e-12}).value(), 2.0, 1e-12);
}

TEST(ArcLength, OfCurvesFarFromTheOrigin) {
  // Issue 39: a unit circle at (1e6, 1e6) (survey and UTM coordinates) was
  // refused at the default tolerance, 1e-12 of its size: the rational speed
  // cancelled the distance from the origin. Its length is 2 pi to that
  // tolerance wherever it lies, and so is a quarter at the quarter length.
  for (const double far : {1e6, 1e9, -3e12}) {
    const BSplineCurve circle = make_circle(far, far, 1.0).value();
    const Tolerance tolerance = default_arc_length_tolerance(circle);
    EXPECT_NEAR(arc_length(circle, tolerance).value(), 2 * kPi, tolerance.distance) << far;
    const double quarter = parameter_at_length(circle, kPi / 2, tolerance).value();
    EXPECT_NEAR(arc_length(circle, Interval{0.0, quarter}, tolerance).value(), kPi / 2, 2 * tolerance.distance) << far;
  }
}

/// A random weight, log-uniform over the valid range [1e-50, 1e50].
double extreme_weight() { return std::pow(10.0, *rc::gen::inRange(-500, 501) / 10.0); }

RC_GTEST_PROP(ArcLength, OfAnyWeightsLiesBetweenChordAndPolygonAndAddsUp, ()) {
  // A plane rational curve with positive weights is variation diminishing: no
  // line crosses it more often than its control polygon, so by Crofton's
  // formula it is no longer than the polygon, and no shorter than its chord.
  const int degree = *rc::gen::inRange(2, 5);
  std::vector<std::vector<double>> rows;
  std::vector<double> weights;
  for (int i = 0; i <= degree; ++i) {
    rows.push_back({*rc::gen::inRange(-100, 101) / 10.0, *rc::gen::inRange(-100, 101) / 10.0});
    weights.push_back(extreme_weight());
  }
  const BezierCurve curve = bezier(rows, weights);
  const double tolerance = 1e-9 * std::max(1.0, size_of(curve));
  const double length = checked(arc_length(curve, Tolerance{tolerance}));
  double polygon = 0.0;
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) polygon += std::hypot(rows[i + 1][0] - rows[i][0], rows[i + 1][1] - rows[i][1]);
  RC_ASSERT(std::hypot(rows.back()[0] - rows[0][0], rows.back()[1] - rows[0][1]) <= length + tolerance);
  RC_ASSERT(length <= polygon + tolerance);
  const double u = *rc::gen::inRange(1, 1000) * 1e-3;
  const double left = checked(arc_length(curve, Interval{0.0, u}, Tolerance{tolerance}));
  const double right = checked(arc_length(curve, Interval{u, 1.0}, Tolerance{tolerance}));
  RC_ASSERT(std::abs(left + right - length) <= 3 * tolerance);
}

TEST(ArcLength, RefusesBadRequestsNamingThem) {
  const BezierCurve parabola = bezier({{0, 0}, {1, 0}, {2, 4}});
  EXPECT_EQ(arc_length(parabola, Tolerance{0.0}).error().message,
            "the arc-length tolerance is 0, it must be finite and > 0");
  EXPECT_EQ(arc_length(parabola, Tolerance{NAN}).error().message,
            "the arc-length tolerance is nan, it must be finite and > 0");
  EXPECT_EQ(arc_length(parabola, Tolerance{1e-15}).error().message.substr(0, 40),
            "the arc-length tolerance 1e-15 is below ");
  EXPECT_EQ(arc_length(parabola, Interval{-0.5, 0.5}, Tolerance{1e-9}).error().message,
            "the arc-length range's start -0.5 is outside the domain [0, 1]");
  EXPECT_EQ(arc_length(parabola, Interval{0.75, 0.25}, Tolerance{1e-9}).error().message,
            "the arc-length range [0.75, 0.25] runs backwards");
  EXPECT_EQ(parameter_at_length(parabola, -1.0, Tolerance{1e-9}).error().message.substr(0, 31),
            "the length -1 is outside [0, 4.");
  EXPECT_FALSE(parameter_at_length(parabola, 100.0, Tolerance{1e-9}).has_value());
  EXPECT_EQ(equal_arc_length_parameters(parabola, 1, Tolerance{1e-9}).error().message.substr(0, 46),
            "the number of equal-arc-length samples is 1, i");
}

}  // namespace
}  // namespace casteljau

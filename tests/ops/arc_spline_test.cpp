// Arc splines (ops/arc_spline.hpp): the certified bound is checked by an
// independent measurement (distances from samples of the curve to the arcs,
// computed from the arcs' centres and radii, and from samples of the arcs to
// the curve by closest_point), exact conics become single arcs, and the
// count grows as tolerance^(-1/3).
#include "casteljau/ops/arc_spline.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "support/examples_dir.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// The x,y rows of an examples/ CSV (comment and header lines skipped).
PointArray example_points(const std::string& name) {
  std::ifstream in(test::examples_dir() / name);
  EXPECT_TRUE(in) << name;
  std::vector<double> xy;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    double x = 0.0, y = 0.0;
    row >> x >> y;
    xy.push_back(x), xy.push_back(y);
  }
  return PointArray::make(2, xy).value();
}

/// The C² not-a-knot cubic through a seed's points, chord-length parameters.
BSplineCurve seed_interpolant(const std::string& name) {
  const PointArray points = example_points(name);
  const auto parameters = parameter_values(points, Parameterization::chord_length).value();
  return interpolate_cubic(points, parameters, CubicEnds{}).value();
}

/// The distance from q to one element of the chain, from its centre and
/// radius (arcs) or its line (segments): not from the fitting code's polynomials.
double distance_to(const ArcSegment& arc, Vec2 q) {
  if (arc.bulge == 0.0) {
    const Vec2 u = arc.end - arc.start;
    const double t = std::clamp(dot(q - arc.start, u) / dot(u, u), 0.0, 1.0);
    return distance(q, arc.start + t * u);
  }
  const Vec2 c = center_of(arc);
  const double sweep = sweep_of(arc);
  double angle = std::atan2(cross(arc.start - c, q - c), dot(arc.start - c, q - c));
  if (angle * sweep < 0.0) angle += (sweep > 0.0 ? 2.0 : -2.0) * std::numbers::pi;
  if (std::abs(angle) <= std::abs(sweep)) return std::abs(distance(q, c) - radius_of(arc));
  return std::min(distance(q, arc.start), distance(q, arc.end));
}

/// The measured Hausdorff distance between the curve and its arc spline:
/// `samples` curve points to the nearest element, 32 points of each element
/// to the curve.
double measured_deviation(CurveView curve, const ArcSpline& spline, int samples = 4000) {
  double worst = 0.0;
  const Interval domain = curve.domain();
  for (int i = 0; i <= samples; ++i) {
    const double u = domain.lower + domain.length() * i / samples;
    const Vec2 p = point_at<2>(curve, u);
    double nearest = std::numeric_limits<double>::infinity();
    for (const ArcSegment& arc : spline.segments) nearest = std::min(nearest, distance_to(arc, p));
    worst = std::max(worst, nearest);
  }
  for (const ArcSegment& arc : spline.segments)
    for (int i = 0; i <= 32; ++i) {
      const Vec2 q = point_along(arc, i / 32.0);
      worst = std::max(worst, closest_point(curve, {q[0], q[1]}).value().distance);
    }
  return worst;
}

/// What every arc spline must be: a chain from the curve's start to its end
/// (bit for bit), within the tolerance by its bound and by measurement, its
/// parameters increasing over the domain.
void expect_valid(CurveView curve, const ArcSpline& spline, double tolerance) {
  ASSERT_FALSE(spline.segments.empty());
  ASSERT_EQ(spline.parameters.size(), spline.segments.size() + 1);
  const Interval domain = curve.domain();
  EXPECT_EQ(spline.parameters.front(), domain.lower);
  EXPECT_EQ(spline.parameters.back(), domain.upper);
  for (std::size_t i = 0; i + 1 < spline.parameters.size(); ++i) EXPECT_LT(spline.parameters[i], spline.parameters[i + 1]);
  const Point first = point_at(curve, domain.lower), last = point_at(curve, domain.upper);
  EXPECT_EQ(spline.segments.front().start, (Vec2{{first[0], first[1]}}));
  EXPECT_EQ(spline.segments.back().end, (Vec2{{last[0], last[1]}}));
  for (std::size_t i = 0; i + 1 < spline.segments.size(); ++i) EXPECT_EQ(spline.segments[i].end, spline.segments[i + 1].start);
  EXPECT_LE(spline.deviation_bound, tolerance);
  EXPECT_LE(measured_deviation(curve, spline), tolerance);
}

/// The largest angle between the tangents leaving and arriving at a joint.
double largest_tangent_break(const ArcSpline& spline) {
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < spline.segments.size(); ++i) {
    const Vec2 a = tangent_along(spline.segments[i], 1.0), b = tangent_along(spline.segments[i + 1], 0.0);
    worst = std::max(worst, std::abs(std::atan2(cross(a, b), dot(a, b))));
  }
  return worst;
}

TEST(ArcSegment, GeometryOfAHalfCircle) {
  // From (-3, 0) over the top to (3, 0): clockwise, bulge -1, centre 0, radius 3.
  const ArcSegment arc{{{-3.0, 0.0}}, {{3.0, 0.0}}, -1.0};
  EXPECT_DOUBLE_EQ(sweep_of(arc), -std::numbers::pi);
  EXPECT_NEAR(center_of(arc)[0], 0.0, 1e-15);
  EXPECT_NEAR(center_of(arc)[1], 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(radius_of(arc), 3.0);
  EXPECT_DOUBLE_EQ(curvature_of(arc), -1.0 / 3.0);
  EXPECT_DOUBLE_EQ(length_of(arc), 3.0 * std::numbers::pi);
  const Vec2 top = point_along(arc, 0.5);
  EXPECT_NEAR(top[0], 0.0, 1e-15);
  EXPECT_NEAR(top[1], 3.0, 1e-15);
  const Vec2 up = tangent_along(arc, 0.0);
  EXPECT_NEAR(up[0], 0.0, 1e-15);
  EXPECT_NEAR(up[1], 1.0, 1e-15);
  const ArcSegment segment{{{0.0, 0.0}}, {{3.0, 4.0}}, 0.0};
  EXPECT_EQ(sweep_of(segment), 0.0);
  EXPECT_EQ(curvature_of(segment), 0.0);
  EXPECT_DOUBLE_EQ(length_of(segment), 5.0);
}

TEST(FitArcs, TheExactHalfCircleIsOneArc) {
  // examples/semicircle.json: the NURBS half circle of radius 3.
  const auto half = make_arc(0.0, 0.0, 3.0, std::numbers::pi, -std::numbers::pi).value();
  for (const double tolerance : {0.1, 0.01, 1e-4, 1e-8}) {
    const ArcSpline spline = fit_arcs(half, Tolerance{tolerance}).value();
    ASSERT_EQ(spline.segments.size(), 1u) << tolerance;
    EXPECT_NEAR(spline.segments[0].bulge, -1.0, 1e-12);
    EXPECT_NEAR(radius_of(spline.segments[0]), 3.0, 1e-12);
    expect_valid(half, spline, tolerance);
  }
}

TEST(FitArcs, AWholeCircleIsTwoArcs) {
  const auto circle = make_circle(1.0, -2.0, 5.0).value();
  const ArcSpline spline = fit_arcs(circle, Tolerance{1e-6}).value();
  ASSERT_EQ(spline.segments.size(), 2u);
  for (const ArcSegment& arc : spline.segments) {
    EXPECT_NEAR(radius_of(arc), 5.0, 1e-10);
    EXPECT_NEAR(center_of(arc)[0], 1.0, 1e-10);
    EXPECT_NEAR(center_of(arc)[1], -2.0, 1e-10);
  }
  EXPECT_NEAR(sweep_of(spline.segments[0]) + sweep_of(spline.segments[1]), 2.0 * std::numbers::pi, 1e-10);
  expect_valid(circle, spline, 1e-6);
}

TEST(FitArcs, AnArcOfAnyOpeningIsOneArc) {
  for (const double sweep : {0.3, 1.0, 2.0, 3.0, 4.5, 5.5}) {
    const auto arc = make_arc(2.0, 1.0, 0.5, 0.25, sweep).value();
    const ArcSpline spline = fit_arcs(arc, Tolerance{1e-7}).value();
    ASSERT_EQ(spline.segments.size(), 1u) << sweep;
    EXPECT_NEAR(sweep_of(spline.segments[0]), sweep, 1e-12);
    expect_valid(arc, spline, 1e-7);
  }
}

TEST(FitArcs, StraightCurvesAreOneSegment) {
  const auto line = BezierCurve::make(*PointArray::make(2, {0, 0, 3, 4})).value();
  const auto collinear = BezierCurve::make(*PointArray::make(2, {0, 0, 1, 1, 2, 2, 5, 5})).value();
  for (const BezierCurve* curve : {&line, &collinear}) {
    const ArcSpline spline = fit_arcs(*curve, Tolerance{1e-6}).value();
    ASSERT_EQ(spline.segments.size(), 1u);
    EXPECT_EQ(spline.segments[0].bulge, 0.0);
    expect_valid(*curve, spline, 1e-6);
  }
}

TEST(FitArcs, TheSeedsCubicHalfCircleNeedsMoreThanOneArcBelowItsError) {
  // Seed 003's cubic A(-3,0) B(-3,4) C(3,4) D(3,0) is 0.055 from the circle:
  // one biarc at 0.1, more below.
  const auto cubic = BezierCurve::make(*PointArray::make(2, {-3, 0, -3, 4, 3, 4, 3, 0})).value();
  const ArcSpline coarse = fit_arcs(cubic, Tolerance{0.1}).value();
  EXPECT_LE(coarse.segments.size(), 2u);
  expect_valid(cubic, coarse, 0.1);
  const ArcSpline fine = fit_arcs(cubic, Tolerance{1e-4}).value();
  EXPECT_GT(fine.segments.size(), 2u);
  expect_valid(cubic, fine, 1e-4);
  EXPECT_LE(largest_tangent_break(fine), 1e-9);
}

TEST(FitArcs, TheHeadAndTheCarAtEveryTolerance) {
  for (const std::string name : {"head.csv", "car.csv"}) {
    const BSplineCurve curve = seed_interpolant(name);
    std::vector<std::size_t> counts;
    for (const double tolerance : {0.1, 0.01, 1e-3, 1e-4}) {
      const ArcSpline spline = fit_arcs(curve, Tolerance{tolerance}).value();
      expect_valid(curve, spline, tolerance);
      // G1 within rounding: the interpolant is C².
      EXPECT_LE(largest_tangent_break(spline), 1e-9) << name << " " << tolerance;
      counts.push_back(spline.segments.size());
      RecordProperty(name + "@" + std::to_string(tolerance), static_cast<int>(spline.segments.size()));
    }
    // O(tolerance^(-1/3)): a factor 100 in the tolerance, about 100^(1/3) = 4.6
    // times the arcs (the exponent between 0.25 and 0.45).
    const double exponent = std::log(static_cast<double>(counts[3]) / counts[1]) / std::log(100.0);
    EXPECT_GT(exponent, 0.25) << name;
    EXPECT_LT(exponent, 0.45) << name;
  }
}

TEST(FitArcs, CrossesInflectionsAndKeepsCorners) {
  // An S (one inflection at t = 1/2): biarcs need no cut there. Then an S
  // followed by a piece that leaves at a right angle: the chain breaks at the
  // corner, and only there.
  const auto s = BezierCurve::make(*PointArray::make(2, {0, 0, 1, 2, 2, -2, 3, 0})).value();
  const ArcSpline smooth = fit_arcs(s, Tolerance{1e-3}).value();
  expect_valid(s, smooth, 1e-3);
  EXPECT_LE(largest_tangent_break(smooth), 1e-9);
  const auto up = BezierCurve::make(*PointArray::make(2, {3, 0, 3, 1, 4, 2})).value();
  const auto cornered = PiecewiseBezierCurve::make({s, up}).value();
  const ArcSpline spline = fit_arcs(cornered, Tolerance{1e-3}).value();
  expect_valid(cornered, spline, 1e-3);
  const auto corner = std::find(spline.parameters.begin(), spline.parameters.end(), 1.0);
  ASSERT_NE(corner, spline.parameters.end());
  const std::size_t i = static_cast<std::size_t>(corner - spline.parameters.begin());
  EXPECT_EQ(spline.segments[i].start, (Vec2{{3.0, 0.0}}));
  const Vec2 in = tangent_along(spline.segments[i - 1], 1.0), out = tangent_along(spline.segments[i], 0.0);
  // The S arrives at (3, 0) along (1, 2) / sqrt(5), the next piece leaves upwards.
  EXPECT_NEAR(std::atan2(cross(in, out), dot(in, out)), std::atan2(1.0, 2.0), 1e-9);
}

TEST(FitArcs, CuspsAndLoops) {
  // A cusp at t = 1/2 (P1 - P0 and P3 - P2 crossing symmetric) and a loop.
  const auto cusp = BezierCurve::make(*PointArray::make(2, {0, 0, 2, 1, -1, 1, 1, 0})).value();
  const auto loop = BezierCurve::make(*PointArray::make(2, {0, 0, 3, 3, -2, 3, 1, 0})).value();
  for (const BezierCurve* curve : {&cusp, &loop}) {
    const ArcSpline spline = fit_arcs(*curve, Tolerance{1e-4}).value();
    expect_valid(*curve, spline, 1e-4);
  }
}

TEST(FitArcs, DegenerateCurvesDoNotHang) {
  // The two last control points equal (the end velocity vanishes), and a point.
  const auto repeated_end = BezierCurve::make(*PointArray::make(2, {0, 0, 1, 2, 3, 1, 3, 1})).value();
  const ArcSpline spline = fit_arcs(repeated_end, Tolerance{1e-4}).value();
  expect_valid(repeated_end, spline, 1e-4);
  const auto point = BezierCurve::make(*PointArray::make(2, {1, 1, 1, 1, 1, 1})).value();
  const auto zero = fit_arcs(point, Tolerance{1e-4});
  ASSERT_FALSE(zero.has_value());
  EXPECT_NE(zero.error().message.find("length"), std::string::npos) << zero.error().message;
}

TEST(FitArcs, RefusesWhatItCannotFit) {
  const auto space = BezierCurve::make(*PointArray::make(3, {0, 0, 0, 1, 1, 1})).value();
  const auto r = fit_arcs(space, Tolerance{0.1});
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().message, "arc fitting needs a plane curve, this one lives in R^3");
  const auto line = BezierCurve::make(*PointArray::make(2, {0, 0, 3, 4})).value();
  for (const double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity(), 1e-300}) {
    const auto e = fit_arcs(line, Tolerance{bad});
    ASSERT_FALSE(e.has_value()) << bad;
    EXPECT_NE(e.error().message.find("tolerance"), std::string::npos) << e.error().message;
  }
}

TEST(FitArcs, ADegreeSevenBezier) {
  const auto curve =
      BezierCurve::make(*PointArray::make(2, {0, 0, 1, 3, 3, 4, 4, 1, 6, 0, 7, 3, 9, 4, 10, 0})).value();
  for (const double tolerance : {0.1, 0.01, 1e-3, 1e-4}) {
    const ArcSpline spline = fit_arcs(curve, Tolerance{tolerance}).value();
    expect_valid(curve, spline, tolerance);
  }
}

// ---- property: random plane cubics, rational or not --------------------------

RC_GTEST_PROP(FitArcs, RandomCubicsAreWithinTolerance, ()) {
  std::vector<double> xy;
  for (int i = 0; i < 8; ++i) xy.push_back(*test::coordinate_on_grid(10));
  std::vector<double> weights;
  if (*rc::gen::inRange(0, 3) == 0)
    for (int i = 0; i < 4; ++i) weights.push_back(*rc::gen::map(rc::gen::inRange(2, 41), [](int k) { return k / 10.0; }));
  const auto curve = BezierCurve::make(*PointArray::make(2, xy), weights).value();
  const double size = size_of(curve);
  RC_PRE(size > 1.0);
  const double tolerance = size * std::pow(10.0, -*rc::gen::inRange(1, 5));
  const auto spline = fit_arcs(curve, Tolerance{tolerance});
  RC_ASSERT(spline.has_value());
  RC_ASSERT(spline->deviation_bound <= tolerance);
  RC_ASSERT(measured_deviation(curve, *spline, 1000) <= tolerance);
  for (std::size_t i = 0; i + 1 < spline->segments.size(); ++i) RC_ASSERT(spline->segments[i].end == spline->segments[i + 1].start);
}

}  // namespace
}  // namespace casteljau

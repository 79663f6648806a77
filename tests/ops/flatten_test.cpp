// flatten(): the polyline stays within tolerance of the curve. The deviation is
// measured here independently of the method: the curve is evaluated by the
// Bernstein sum in long double (not de Casteljau, not the power form flatten
// uses), densely sampled on every segment's parameter interval and refined by
// golden-section search around the worst sample, against the segment joining
// that interval's end vertices (stricter than the Hausdorff distance).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "support/bspline_generators.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

using Real = long double;

/// C(t) by the rational Bernstein sum, in long double (independent reference).
std::vector<Real> bernstein_point(const BezierCurve& curve, Real t) {
  const int n = curve.degree(), d = curve.dimension();
  std::vector<Real> sum(d, 0.0L);
  Real weight_sum = 0.0L, binomial = 1.0L;
  for (int k = 0; k <= n; ++k) {
    if (k > 0) binomial = binomial * (n - k + 1) / k;
    const Real w = curve.is_rational() ? curve.weights()[k] : 1.0L;
    const Real basis = binomial * std::pow(t, Real(k)) * std::pow(1.0L - t, Real(n - k)) * w;
    for (int j = 0; j < d; ++j) sum[j] += basis * curve.control_points()[k][j];
    weight_sum += basis;
  }
  for (Real& c : sum) c /= weight_sum;
  return sum;
}

Real distance_to_segment(const std::vector<Real>& p, std::span<const double> a, std::span<const double> b) {
  Real ab2 = 0.0L, apab = 0.0L;
  for (std::size_t j = 0; j < p.size(); ++j) {
    ab2 += (Real(b[j]) - a[j]) * (Real(b[j]) - a[j]);
    apab += (p[j] - a[j]) * (Real(b[j]) - a[j]);
  }
  const Real u = ab2 > 0.0L ? std::clamp(apab / ab2, 0.0L, 1.0L) : 0.0L;
  Real sum = 0.0L;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const Real e = p[j] - (a[j] + u * (Real(b[j]) - a[j]));
    sum += e * e;
  }
  return std::sqrt(sum);
}

/// Largest distance from C on [t0, t1] to the segment [a, b]: `samples` samples,
/// then golden-section refinement on the two sample intervals around the worst.
double sampled_deviation(const BezierCurve& curve, double t0, double t1, std::span<const double> a,
                         std::span<const double> b, int samples = 64) {
  auto f = [&](Real t) { return distance_to_segment(bernstein_point(curve, t), a, b); };
  Real worst = 0.0L;
  int worst_k = 0;
  for (int k = 0; k <= samples; ++k) {
    const Real v = f(t0 + (Real(t1) - t0) * k / samples);
    if (v > worst) worst = v, worst_k = k;
  }
  Real lo = t0 + (Real(t1) - t0) * std::max(worst_k - 1, 0) / samples;
  Real hi = t0 + (Real(t1) - t0) * std::min(worst_k + 1, samples) / samples;
  const Real r = 0.5L * (std::sqrt(5.0L) - 1.0L);
  Real x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 60; ++i) {
    if (f1 > f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - r * (hi - lo), f1 = f(x1);
    else lo = x1, x1 = x2, f1 = f2, x2 = lo + r * (hi - lo), f2 = f(x2);
  }
  return static_cast<double>(std::max({worst, f1, f2}));
}

/// The largest sampled deviation over all segments of the polyline.
double polyline_deviation(const BezierCurve& curve, const Polyline& line) {
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < line.parameters.size(); ++i)
    worst = std::max(worst, sampled_deviation(curve, line.parameters[i], line.parameters[i + 1], line.points[i],
                                              line.points[i + 1]));
  return worst;
}

/// Every structural promise of flatten(): parameters from exactly 0 to exactly
/// 1, strictly increasing; end vertices equal to the end control points; the
/// other vertices equal to point_at bit for bit; within tolerance.
void check_polyline(const BezierCurve& curve, double tolerance, const Polyline& line) {
  const auto& p = curve.control_points();
  RC_ASSERT(line.parameters.size() >= 2u);
  RC_ASSERT(line.points.size() == line.parameters.size());
  RC_ASSERT(line.points.dimension() == curve.dimension());
  RC_ASSERT(line.parameters.front() == 0.0);
  RC_ASSERT(line.parameters.back() == 1.0);
  for (std::size_t i = 0; i + 1 < line.parameters.size(); ++i) RC_ASSERT(line.parameters[i] < line.parameters[i + 1]);
  RC_ASSERT(std::equal(line.points[0].begin(), line.points[0].end(), p[0].begin()));
  RC_ASSERT(std::equal(line.points[line.points.size() - 1].begin(), line.points[line.points.size() - 1].end(),
                       p[p.size() - 1].begin()));
  for (std::size_t i = 1; i + 1 < line.parameters.size(); ++i) {
    const Point q = point_at(curve, line.parameters[i]);
    RC_ASSERT(std::equal(q.begin(), q.end(), line.points[i].begin()));
  }
  const double deviation = polyline_deviation(curve, line);
  RC_ASSERT(deviation <= tolerance);
}

// ---- generators ---------------------------------------------------------------

BezierCurve random_curve(int degree, int dimension, bool rational) {
  std::vector<double> xs;
  for (int i = 0; i < (degree + 1) * dimension; ++i) xs.push_back(*test::coordinate_on_grid(100));
  std::vector<double> weights;
  if (rational)
    for (int i = 0; i <= degree; ++i) weights.push_back(*rc::gen::map(rc::gen::inRange(1, 101), [](int k) { return k / 10.0; }));
  return BezierCurve::make(*PointArray::make(dimension, xs), weights).value();
}

/// A tolerance 10^-k times the curve's extent (at least 1), k in [1, 5].
double random_tolerance(const BezierCurve& curve) {
  const double scale = std::max(1.0, scale_of(curve.control_points()));
  return scale * std::pow(10.0, -*rc::gen::inRange(1, 6));
}

void check_random(int degree, int dimension, bool rational) {
  const BezierCurve curve = random_curve(degree, dimension, rational);
  const double tolerance = random_tolerance(curve);
  const auto line = flatten(curve, Tolerance{tolerance});
  RC_ASSERT(line.has_value());
  check_polyline(curve, tolerance, *line);
  const auto count = flatten_segment_count(curve, Tolerance{tolerance});
  RC_ASSERT(count.has_value());
  RC_ASSERT(*count == static_cast<long>(line->parameters.size()) - 1);
}

RC_GTEST_PROP(Flatten, PlaneCubicsStayWithinTolerance, ()) { check_random(3, 2, false); }
RC_GTEST_PROP(Flatten, PlaneQuadraticsStayWithinTolerance, ()) { check_random(2, 2, false); }
RC_GTEST_PROP(Flatten, LinesAndPointsStayWithinTolerance, ()) { check_random(*rc::gen::inRange(0, 2), 2, false); }
RC_GTEST_PROP(Flatten, HigherDegreesStayWithinTolerance, ()) { check_random(*rc::gen::inRange(4, 9), 2, false); }
RC_GTEST_PROP(Flatten, RationalCurvesStayWithinTolerance, ()) { check_random(*rc::gen::inRange(1, 6), 2, true); }

TEST(Flatten, HighDegreesKeepEveryPromiseWithTheUnsplitHull) {
  // Above degree 16 the hull bound is taken on the piece itself (no midpoint
  // split) and each trial reuses the end point of C split at b as the vertex:
  // still within tolerance (sampled in long double), vertices point_at bit for bit.
  for (int degree : {17, 40})
    for (bool rational : {false, true}) {
      std::vector<double> xs, weights;
      for (int i = 0; i <= degree; ++i) {
        xs.insert(xs.end(), {10.0 * std::cos(0.9 * i), 10.0 * std::sin(1.7 * i)});
        if (rational) weights.push_back(1.5 + std::sin(2.3 * i));
      }
      const BezierCurve curve = BezierCurve::make(*PointArray::make(2, xs), weights).value();
      const double tolerance = 1e-2;
      const auto line = flatten(curve, Tolerance{tolerance});
      ASSERT_TRUE(line.has_value()) << line.error().message;
      EXPECT_EQ(line->parameters.front(), 0.0);
      EXPECT_EQ(line->parameters.back(), 1.0);
      for (std::size_t i = 1; i + 1 < line->parameters.size(); ++i) {
        const Point q = point_at(curve, line->parameters[i]);
        EXPECT_TRUE(std::equal(q.begin(), q.end(), line->points[i].begin())) << degree << " vertex " << i;
      }
      EXPECT_LE(polyline_deviation(curve, *line), tolerance) << degree << (rational ? " rational" : "");
      EXPECT_EQ(*flatten_segment_count(curve, Tolerance{tolerance}), static_cast<long>(line->parameters.size()) - 1);
    }
}
/// Any curve kind through CurveView: the pieces' polylines joined, on the
/// curve's own parameters, each segment within tolerance of its piece.
void check_any_kind(CurveView curve, double tolerance) {
  const auto line = flatten(curve, Tolerance{tolerance});
  RC_ASSERT(line.has_value());
  const BezierPieces pieces = to_bezier_pieces(curve);
  const Interval domain = curve.domain();
  RC_ASSERT(line->parameters.front() == domain.lower);
  RC_ASSERT(line->parameters.back() == domain.upper);
  std::size_t piece = 0;
  for (std::size_t i = 0; i + 1 < line->parameters.size(); ++i) {
    const double a = line->parameters[i], b = line->parameters[i + 1];
    if (a == b) {  // a jump between pieces that do not meet: both ends kept
      RC_ASSERT(std::find(pieces.breakpoints.begin(), pieces.breakpoints.end(), a) != pieces.breakpoints.end());
      continue;
    }
    RC_ASSERT(a < b);
    while (b > pieces.breakpoints[piece + 1]) ++piece;  // the piece this segment lies on
    const double lower = pieces.breakpoints[piece], width = pieces.breakpoints[piece + 1] - lower;
    RC_ASSERT(a >= lower);
    RC_ASSERT(sampled_deviation(pieces.pieces[piece], (a - lower) / width, (b - lower) / width, line->points[i],
                                line->points[i + 1], 16) <= tolerance * (1 + 1e-9));
  }
}

RC_GTEST_PROP(Flatten, BSplineCurvesStayWithinToleranceOnTheirOwnParameters, ()) {
  const BSplineCurve curve = *test::bspline_curve({.max_degree = 5});
  check_any_kind(curve, std::max(1.0, scale_of(curve.control_points())) * std::pow(10.0, -*rc::gen::inRange(1, 5)));
}

RC_GTEST_PROP(Flatten, PiecewiseCurvesStayWithinToleranceOnTheirOwnParameters, ()) {
  std::vector<BezierCurve> pieces;
  for (int i = *rc::gen::inRange(1, 4); i > 0; --i) pieces.push_back(random_curve(*rc::gen::inRange(1, 5), 2, false));
  const auto curve = PiecewiseBezierCurve::make(std::move(pieces)).value();
  check_any_kind(curve, 0.01);
}

TEST(Flatten, AnyKindKeepsAJointVertexOnceAndAJumpTwice) {
  const auto a = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{1, 1}, {2, 0}}).value()).value();
  const auto c = BezierCurve::make(PointArray::make({{5, 5}, {6, 5}}).value()).value();
  const PiecewiseBezierCurve ab = PiecewiseBezierCurve::make({a, b}).value();
  const auto joined = flatten(ab, Tolerance{0.1}).value();
  EXPECT_EQ(joined.parameters, (std::vector<double>{0, 1, 2}));
  const PiecewiseBezierCurve ac = PiecewiseBezierCurve::make({a, c}).value();
  const auto jump = flatten(ac, Tolerance{0.1}).value();
  EXPECT_EQ(jump.parameters, (std::vector<double>{0, 1, 1, 2}));
}

RC_GTEST_PROP(Flatten, SpaceCurvesStayWithinTolerance, ()) { check_random(*rc::gen::inRange(2, 6), 3, false); }
RC_GTEST_PROP(Flatten, LineCurvesStayWithinTolerance, ()) { check_random(*rc::gen::inRange(1, 6), 1, false); }
RC_GTEST_PROP(Flatten, FourDimensionalRationalCurvesStayWithinTolerance, ()) { check_random(3, 4, true); }

/// The bound never falls below the sampled deviation of an arbitrary piece.
RC_GTEST_PROP(Flatten, ChordDeviationBoundIsAnUpperBound, ()) {
  const int degree = *rc::gen::inRange(1, 6), dimension = *rc::gen::inRange(1, 4);
  const BezierCurve curve = random_curve(degree, dimension, *rc::gen::arbitrary<bool>());
  const double t0 = *rc::gen::inRange(0, 1000) / 1000.0;
  const double t1 = t0 + (1.0 - t0) * *rc::gen::inRange(1, 1001) / 1000.0;
  const Point a = point_at(curve, t0), b = point_at(curve, t1);
  const double bound = chord_deviation_bound(curve, t0, t1);
  const double slack = tolerances::kFlattenRoundingAllowance * std::max(1.0, scale_of(curve.control_points()));
  RC_ASSERT(sampled_deviation(curve, t0, t1, a, b, 400) <= bound + slack);
}

// ---- the W6 shapes and other explicit cases ------------------------------------

BezierCurve plane_curve(std::vector<double> xy, std::vector<double> weights = {}) {
  return BezierCurve::make(*PointArray::make(2, std::move(xy)), std::move(weights)).value();
}

struct Shape {
  const char* name;
  std::vector<double> points;
  long optimum;  // greedy furthest reach with a dense check, shared/docs/performance.md (W6)
};

const std::vector<Shape>& w6_shapes() {
  static const std::vector<Shape> shapes = {
      {"gentle arc", {0, 0, 30, 40, 70, 40, 100, 0}, 53},
      {"S-curve", {0, 0, 100, 0, 0, 100, 100, 100}, 77},
      {"near-cusp", {0, 0, 100, 100, 5, 100, 100, 0}, 52},
  };
  return shapes;
}

TEST(Flatten, W6ShapesStayWithinEveryTolerance) {
  for (const Shape& shape : w6_shapes()) {
    const BezierCurve curve = plane_curve(shape.points);
    for (int k = 1; k <= 6; ++k) {
      const double tolerance = 100.0 * std::pow(10.0, -k);
      const auto line = flatten(curve, Tolerance{tolerance});
      ASSERT_TRUE(line.has_value()) << shape.name;
      EXPECT_LE(polyline_deviation(curve, *line), tolerance) << shape.name << " at " << tolerance;
      EXPECT_EQ(line->parameters.front(), 0.0);
      EXPECT_EQ(line->parameters.back(), 1.0);
    }
  }
}

TEST(Flatten, W6CountsAreWithinFivePercentOfTheOptimum) {
  for (const Shape& shape : w6_shapes()) {
    const auto count = flatten_segment_count(plane_curve(shape.points), Tolerance{0.01});
    ASSERT_TRUE(count.has_value());
    EXPECT_GE(*count, shape.optimum) << shape.name << ": fewer than the optimum means a wrong optimum or a wrong bound";
    EXPECT_LE(static_cast<double>(*count), 1.05 * static_cast<double>(shape.optimum)) << shape.name;
  }
}

TEST(Flatten, W6PolylinesKeepEveryStructuralPromiseAtEveryTolerance) {
  // From a few segments to tens of thousands: the plane cubics' fast path
  // (proposals certified in batches, a sweep, greedy steps at inflections and
  // cusps) keeps vertices on the curve bit for bit and agrees with the count.
  for (const Shape& shape : w6_shapes()) {
    const BezierCurve curve = plane_curve(shape.points);
    for (double tolerance : {50.0, 10.0, 1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
      const auto line = flatten(curve, Tolerance{tolerance});
      ASSERT_TRUE(line.has_value()) << shape.name << " at " << tolerance;
      const auto& t = line->parameters;
      ASSERT_EQ(line->points.size(), t.size());
      ASSERT_GE(t.size(), 2u);
      EXPECT_EQ(t.front(), 0.0);
      EXPECT_EQ(t.back(), 1.0);
      for (std::size_t i = 0; i + 1 < t.size(); ++i) ASSERT_LT(t[i], t[i + 1]) << shape.name << " at " << tolerance;
      for (std::size_t i = 0; i < t.size(); ++i) {
        const Point q = point_at(curve, t[i]);
        ASSERT_TRUE(std::equal(q.begin(), q.end(), line->points[i].begin())) << shape.name << " vertex " << i;
      }
      EXPECT_EQ(*flatten_segment_count(curve, Tolerance{tolerance}), static_cast<long>(t.size()) - 1);
      if (t.size() < 2000) {
        EXPECT_LE(polyline_deviation(curve, *line), tolerance) << shape.name << " at " << tolerance;
      }
    }
  }
}

TEST(Flatten, TheCapIsExact) {
  // A cap of exactly the count is met; one less is refused, not truncated.
  for (const Shape& shape : w6_shapes()) {
    const BezierCurve curve = plane_curve(shape.points);
    for (double tolerance : {1.0, 0.01, 1e-4}) {
      const long count = *flatten_segment_count(curve, Tolerance{tolerance});
      const auto met = flatten(curve, Tolerance{tolerance}, count);
      ASSERT_TRUE(met.has_value()) << shape.name;
      EXPECT_EQ(static_cast<long>(met->parameters.size()) - 1, count);
      const auto refused = flatten(curve, Tolerance{tolerance}, count - 1);
      ASSERT_FALSE(refused.has_value()) << shape.name;
      EXPECT_NE(refused.error().message.find("more than " + std::to_string(count - 1) + " segments"), std::string::npos)
          << refused.error().message;
    }
  }
}

TEST(Flatten, PlaneCubicsWithInflectionsAndSharpTurnsStayWithinTolerance) {
  // Where the deviation of a piece does not grow like its step squared (an
  // inflection, a near-cusp, a loop's crossing), proposals from an additive
  // measure fail or fall short and the sweep replaces them by greedy steps.
  const std::vector<std::vector<double>> cases = {
      {0, 0, 100, 0, 0, 100, 100, 100},   // one inflection (the W6 S-curve)
      {0, 0, 100, 60, -40, 60, 60, 0},    // two inflections
      {0, 0, 100, 100, 1, 100, 100, 0},   // sharper than the W6 near-cusp
      {0, 0, 100, 100, 0, 100, 100, 0},   // a cusp-like turn through crossing tangents
      {0, 0, 150, 100, -50, 100, 100, 0}, // a loop
      {0, 0, 1e-3, 0, 100, 50, 100, 50.001}, // nearly repeated end control points
      {0, 0, 100, 0, -100, 1, 1, 1},      // nearly collinear, doubling back twice: pieces across
      {0, 0, 100, 1, -100, 1, 1, 0},      //   a turn run past their chord's ends (the overshoot)
  };
  for (const auto& xy : cases) {
    const BezierCurve curve = plane_curve(xy);
    for (double tolerance : {1.0, 1e-2, 1e-4}) {
      const auto line = flatten(curve, Tolerance{tolerance});
      ASSERT_TRUE(line.has_value());
      EXPECT_LE(polyline_deviation(curve, *line), tolerance) << xy[2] << " at " << tolerance;
      EXPECT_EQ(*flatten_segment_count(curve, Tolerance{tolerance}), static_cast<long>(line->parameters.size()) - 1);
    }
  }
}

TEST(Flatten, PieceWithAChordShorterThanTheToleranceIsCertifiedByItsHull) {
  // Found by a random search: at 0.1 the last piece proposed for this cubic
  // has a chord shorter than the tolerance (its direction is unreliable), and
  // the convex hull bound that then takes over refuses it (a ratio above 1),
  // so the sweep must replace it by greedy steps.
  const BezierCurve curve = plane_curve({-0.54, -5.1, -37.02, 45.62, 71.95, 72.19, 62.65, 69.96});
  for (double tolerance : {0.1, 0.05, 0.2}) {
    const auto line = flatten(curve, Tolerance{tolerance});
    ASSERT_TRUE(line.has_value());
    EXPECT_LE(polyline_deviation(curve, *line), tolerance) << tolerance;
  }
}

TEST(Flatten, StraightCurvesNeedOneSegment) {
  // Collinear control points in order along the line: the curve is the chord.
  for (const auto& xy : std::vector<std::vector<double>>{
           {0, 0, 1, 2}, {0, 0, 1, 1, 3, 3}, {0, 0, 1, 0.5, 2, 1, 3, 1.5}, {-5, 7, -5, 7, 4, -2, 4, -2}}) {
    const auto count = flatten_segment_count(plane_curve(xy), Tolerance{1e-9});
    ASSERT_TRUE(count.has_value());
    EXPECT_EQ(*count, 1);
  }
  const auto space = BezierCurve::make(*PointArray::make(3, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}));
  EXPECT_EQ(*flatten_segment_count(*space, Tolerance{1e-9}), 1);
}

TEST(Flatten, CollinearCurveThatDoublesBack) {
  // Along the x axis 0 -> 2 -> -1 -> 1: x(t) = 6 t (1-t)^2 - 3 t^2 (1-t) + t^3
  // turns at t = (5 -+ sqrt 5)/10 with x = 0.72 and 0.28, inside the chord
  // [0, 1]: the curve lies on its chord's segment, one segment is exact.
  EXPECT_EQ(*flatten_segment_count(plane_curve({0, 0, 2, 0, -1, 0, 1, 0}), Tolerance{1e-6}), 1);
  // 0 -> 5 -> -4 -> 1: x(1/4) = 1.5625 and x(3/4) = -0.5625, past both ends of
  // the chord: the distance to the segment is the overshoot, not 0.
  const BezierCurve curve = plane_curve({0, 0, 5, 0, -4, 0, 1, 0});
  const auto line = flatten(curve, Tolerance{0.01});
  ASSERT_TRUE(line.has_value());
  EXPECT_GT(line->parameters.size(), 2u);
  EXPECT_LE(polyline_deviation(curve, *line), 0.01);
}

TEST(Flatten, ZeroLengthCurveIsOneSegment) {
  const BezierCurve curve = plane_curve({3, 4, 3, 4, 3, 4, 3, 4});
  const auto line = flatten(curve, Tolerance{0.1});
  ASSERT_TRUE(line.has_value());
  ASSERT_EQ(line->parameters.size(), 2u);
  EXPECT_EQ(line->points[0][0], 3.0);
  EXPECT_EQ(line->points[1][1], 4.0);
  const BezierCurve single = plane_curve({1, 2});
  EXPECT_EQ(*flatten_segment_count(single, Tolerance{0.1}), 1);
}

TEST(Flatten, CuspLoopAndClosedCurvesStayWithinTolerance) {
  const std::vector<std::vector<double>> cases = {
      {-1, 0, 1, 1, -1, 1, 1, 0},    // exact cusp at t = 1/2: C'(1/2) = 0
      {0, 0, 3, 3, -2, 3, 1, 0},     // a loop
      {0, 0, 10, 10, -10, 10, 0, 0}, // closed: C(0) = C(1), the whole chord has zero length
      {0, 0, 0, 0, 5, 5, 5, 5},      // coincident end control points: C'(0) = C'(1) = 0
  };
  for (const auto& xy : cases) {
    const BezierCurve curve = plane_curve(xy);
    for (double tolerance : {1e-1, 1e-3, 1e-5}) {
      const auto line = flatten(curve, Tolerance{tolerance});
      ASSERT_TRUE(line.has_value());
      EXPECT_LE(polyline_deviation(curve, *line), tolerance);
    }
  }
}

TEST(Flatten, QuarterCircleAsRationalQuadratic) {
  // The rational quadratic (1,0) (1,1) (0,1) with weights 1, 1/sqrt(2), 1 is a
  // quarter of the unit circle (The NURBS Book, §7.2): a chord spanning the
  // angle theta deviates 1 - cos(theta/2), so the count is known exactly.
  const BezierCurve curve = plane_curve({1, 0, 1, 1, 0, 1}, {1, std::sqrt(0.5), 1});
  const double tolerance = 1e-3;
  const auto line = flatten(curve, Tolerance{tolerance});
  ASSERT_TRUE(line.has_value());
  EXPECT_LE(polyline_deviation(curve, *line), tolerance);
  const double chord_angle = 2.0 * std::acos(1.0 - tolerance);
  const long fewest = static_cast<long>(std::ceil((std::numbers::pi / 2) / chord_angle));
  EXPECT_GE(static_cast<long>(line->parameters.size()) - 1, fewest);
  EXPECT_LE(static_cast<long>(line->parameters.size()) - 1, 2 * fewest);  // hull bound: not tight
}

TEST(Flatten, RefusesBadTolerances) {
  const BezierCurve curve = plane_curve({0, 0, 30, 40, 70, 40, 100, 0});
  for (double tolerance : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const auto line = flatten(curve, Tolerance{tolerance});
    ASSERT_FALSE(line.has_value());
    EXPECT_NE(line.error().message.find("tolerance"), std::string::npos) << line.error().message;
    EXPECT_FALSE(flatten_segment_count(curve, Tolerance{tolerance}).has_value());
  }
  // Below what double precision can certify for coordinates of size 100.
  const auto tiny = flatten(curve, Tolerance{1e-13});
  ASSERT_FALSE(tiny.has_value());
  EXPECT_NE(tiny.error().message.find("double precision"), std::string::npos) << tiny.error().message;
}

TEST(Flatten, RefusesMoreSegmentsThanTheCap) {
  const BezierCurve curve = plane_curve({0, 0, 30, 40, 70, 40, 100, 0});
  const auto capped = flatten(curve, Tolerance{0.01}, 10);
  ASSERT_FALSE(capped.has_value());
  EXPECT_NE(capped.error().message.find("more than 10 segments"), std::string::npos) << capped.error().message;
  const BezierCurve space = *BezierCurve::make(*PointArray::make(3, {0, 0, 0, 30, 40, 5, 70, 40, -5, 100, 0, 0}));
  EXPECT_FALSE(flatten(space, Tolerance{0.01}, 10).has_value());
  EXPECT_TRUE(flatten(curve, Tolerance{0.01}, 100).has_value());
}

TEST(Flatten, ControlPolygonFlatnessBoundsTheCurve) {
  const BezierCurve curve = plane_curve({0, 0, 30, 40, 70, 40, 100, 0});
  // Largest distance from (30,40), (70,40) to the chord y = 0 is 40; the curve
  // peaks at y = 30 (t = 1/2: (0 + 3*40 + 3*40 + 0) / 8).
  EXPECT_DOUBLE_EQ(control_polygon_flatness(curve), 40.0);
  EXPECT_NEAR(chord_deviation_bound(curve, 0.0, 1.0), 30.0, 1e-12);
}

}  // namespace
}  // namespace casteljau

namespace casteljau {
namespace {

TEST(Flatten, HugeAndTinyCoordinatesGiveTheScaledFlattening) {
  // Scaling by a power of two is exact: the flattening of 2^k C within 2^k e has
  // the same parameters as C within e, and vertices exactly 2^k times as large,
  // even where the bounds' squared terms would overflow (2^300 ~ 2e90) or
  // underflow (2^-300) without the internal rescaling.
  for (const Shape& shape : w6_shapes()) {
    const BezierCurve curve = plane_curve(shape.points);
    const auto reference = flatten(curve, Tolerance{0.01}).value();
    for (int k : {300, -300}) {
      std::vector<double> scaled_points = shape.points;
      for (double& c : scaled_points) c = std::ldexp(c, k);
      const auto line = flatten(plane_curve(scaled_points), Tolerance{std::ldexp(0.01, k)});
      ASSERT_TRUE(line.has_value()) << shape.name << " k=" << k;
      EXPECT_EQ(line->parameters, reference.parameters) << shape.name << " k=" << k;
      for (std::size_t i = 0; i < line->points.coordinates().size(); ++i)
        EXPECT_EQ(line->points.coordinates()[i], std::ldexp(reference.points.coordinates()[i], k));
      EXPECT_EQ(flatten_segment_count(plane_curve(scaled_points), Tolerance{std::ldexp(0.01, k)}).value(),
                static_cast<long>(reference.parameters.size()) - 1);
    }
  }
}

}  // namespace
}  // namespace casteljau

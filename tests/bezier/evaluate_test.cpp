// Evaluation and derivatives against exact arithmetic (support/exact.hpp),
// the seed notebook's worked example, and finite differences.
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/curves/differential_geometry.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "support/exact.hpp"
#include "support/generators.hpp"
#include "support/sanitizers.hpp"

namespace casteljau {
namespace {

BezierCurve curve_from(std::vector<std::vector<double>> rows, std::vector<double> weights = {}) {
  return BezierCurve::make(PointArray::make(rows).value(), std::move(weights)).value();
}

/// cycle(n) from seed 004: P_k = (cos t_k, sin t_k) / (k+1), t_k = -pi/2 + 2 k pi / n.
BezierCurve cycle(int n) {
  std::vector<std::vector<double>> rows;
  for (int k = 0; k <= n; ++k) {
    const double t = -M_PI / 2 + 2 * k * M_PI / n;
    rows.push_back({std::cos(t) / (k + 1), std::sin(t) / (k + 1)});
  }
  return curve_from(rows);
}

/// Random curve of degree n in [0,100)^d from a fixed seed.
BezierCurve random_curve(int n, int d, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 100.0);
  std::vector<double> c((n + 1) * d);
  for (double& x : c) x = u(rng);
  return BezierCurve::make(PointArray::make(d, c).value()).value();
}

/// Largest error of `evaluate` against exact de Casteljau over `samples` parameters.
template <class Evaluate>
double max_error(const BezierCurve& curve, int samples, Evaluate evaluate) {
  double worst = 0.0;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < samples; ++i) {
    const double t = (i < 2) ? i : u(rng);
    const Point p = evaluate(curve, t);
    const auto exact = test::exact_point(curve, t);
    for (int j = 0; j < curve.dimension(); ++j) worst = std::max(worst, test::error_of(p[j], exact[j]));
  }
  return worst;
}

TEST(PointAt, NotebookPolygonAtOneHalf) {
  // Seed 004: control points (0,0),(1,2),(2,2),(4,1),(4,0) give B(0.5) = (2.25, 1.5).
  const auto curve = curve_from({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}});
  EXPECT_EQ(point_at(curve, 0.5), (Point{2.25, 1.5}));
  EXPECT_EQ(point_at_bernstein_sum(curve, 0.5), (Point{2.25, 1.5}));
}

TEST(PointAt, InterpolatesEndPointsExactly) {
  const auto curve = random_curve(9, 3, 1);
  EXPECT_EQ(point_at(curve, 0.0), Point(curve.control_points()[0].begin(), curve.control_points()[0].end()));
  EXPECT_EQ(point_at(curve, 1.0), Point(curve.control_points()[9].begin(), curve.control_points()[9].end()));
}

TEST(PointAt, WithinOneEMinus14OfExactUpToDegree30) {
  for (int n = 1; n <= 30; ++n)
    for (int d : {2, 3}) {
      const auto curve = random_curve(n, d, 100 + n);
      const double err = max_error(curve, test::sample_count(200, 25), [](const auto& c, double t) { return point_at(c, t); });
      EXPECT_LE(err, 1e-14 * scale_of(curve.control_points())) << "degree " << n;
    }
}

TEST(PointAt, DegreeTwoHundredAgainstExactAndDirectSum) {
  // The seed's claim: the direct Bernstein sum breaks down for large n. Measure both.
  double casteljau_worst = 0.0, sum_worst = 0.0;
  const int samples = test::sample_count(60, 12);
  for (const auto& curve : {cycle(200), random_curve(200, 2, 200)}) {
    const double scale = scale_of(curve.control_points());
    casteljau_worst = std::max(casteljau_worst, max_error(curve, samples, [](const auto& c, double t) { return point_at(c, t); }) / scale);
    sum_worst = std::max(sum_worst, max_error(curve, samples, [](const auto& c, double t) { return point_at_bernstein_sum(c, t); }) / scale);
  }
  std::cout << "[measured] degree 200, relative to scale: de Casteljau " << casteljau_worst << ", direct sum "
            << sum_worst << '\n';
  RecordProperty("degree200_casteljau_relative_error", std::to_string(casteljau_worst));
  RecordProperty("degree200_direct_sum_relative_error", std::to_string(sum_worst));
  EXPECT_LE(casteljau_worst, 1e-13);
}

TEST(PointAtBernsteinSum, BreaksDownWhenBinomialsOverflow) {
  const auto curve = random_curve(1100, 2, 5);
  const Point p = point_at_bernstein_sum(curve, 0.5);
  EXPECT_FALSE(std::isfinite(p[0]));  // inf * 0 or inf - inf: the sum is lost
  const Point q = point_at(curve, 0.5);
  EXPECT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]));
}

TEST(PointAt, RationalAgainstExactRationals) {
  const auto curve = curve_from({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1});
  for (double t : {0.0, 0.1, 0.25, 0.5, 0.9, 1.0}) {
    const Point p = point_at(curve, t);
    const auto exact = test::exact_rational_point(curve, t);
    for (int j = 0; j < 2; ++j) EXPECT_LE(test::error_of(p[j], exact[j]), 4e-16);
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 4e-16);  // a quarter of the unit circle
  }
}

RC_GTEST_PROP(PointAt, MatchesExactRationalReference, ()) {
  const auto curve = *test::any_bezier_curve(15);
  const double t = *test::unit_parameter();
  const Point p = point_at(curve, t);
  const auto exact = test::exact_rational_point(curve, t);
  // Rational: the projection adds an error proportional to the weights' spread.
  double spread = 1.0;
  if (curve.is_rational()) {
    const auto [lo, hi] = std::minmax_element(curve.weights().begin(), curve.weights().end());
    spread = *hi / *lo;
  }
  const double tol = 4e-16 * (curve.degree() + 2) * spread * std::max(1.0, scale_of(curve.control_points()));
  for (int j = 0; j < curve.dimension(); ++j) RC_ASSERT(test::error_of(p[j], exact[j]) <= tol);
}

RC_GTEST_PROP(Derivatives, MatchExactHodographs, ()) {
  const auto curve = *test::bezier_curve(0, 12, false);
  const double t = *test::unit_parameter();
  const int k = *rc::gen::inRange(0, 5);
  const Point p = derivative_at(curve, t, k);
  const auto exact = test::exact_derivative(curve, t, k);
  const double scale = std::max(1.0, scale_of(curve.control_points()));
  const double tol = 1e-15 * scale * std::pow(2.0 * (curve.degree() + 1), k + 1);
  for (int j = 0; j < curve.dimension(); ++j) RC_ASSERT(test::error_of(p[j], exact[j]) <= tol);
}

RC_GTEST_PROP(Derivatives, EndTangentsAreNTimesFirstAndLastLegs, ()) {
  const auto curve = *test::bezier_curve(1, 20, false);
  const int n = curve.degree();
  const auto& P = curve.control_points();
  const Point d0 = derivative_at(curve, 0.0, 1), d1 = derivative_at(curve, 1.0, 1);
  for (int j = 0; j < curve.dimension(); ++j) {
    RC_ASSERT(std::abs(d0[j] - n * (P[1][j] - P[0][j])) <= 1e-13 * n * 200);
    RC_ASSERT(std::abs(d1[j] - n * (P[n][j] - P[n - 1][j])) <= 1e-13 * n * 200);
  }
}

RC_GTEST_PROP(Derivatives, RationalMatchCentralDifferences, ()) {
  const auto curve = *test::bezier_curve(1, 6, true, 2);
  const double t = 0.05 + 0.9 * *rc::gen::map(rc::gen::inRange(0, 1001), [](int i) { return i / 1000.0; });
  const double h = 1e-5;
  const auto ders = derivatives_up_to(curve, t, 2);
  const Point a = point_at(curve, t - h), b = point_at(curve, t + h), c = point_at(curve, t);
  double second_scale = 1.0;
  for (double v : ders[2]) second_scale = std::max(second_scale, std::abs(v));
  double first_scale = 1.0;
  for (double v : ders[1]) first_scale = std::max(first_scale, std::abs(v));
  for (int j = 0; j < 2; ++j) {
    const double first = (b[j] - a[j]) / (2 * h);
    const double second = (b[j] - 2 * c[j] + a[j]) / (h * h);
    RC_ASSERT(std::abs(first - ders[1][j]) <= 1e-5 * (first_scale + second_scale));
    RC_ASSERT(std::abs(second - ders[2][j]) <= 2e-2 * second_scale);
  }
  RC_ASSERT(ders[0] == c);
}

TEST(Hodograph, ControlPointsAreScaledDifferences) {
  const auto curve = curve_from({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}});
  const auto h = derivative_curve(curve, 1).value();
  EXPECT_EQ(h.control_points(), PointArray::make({{4, 8}, {4, 0}, {8, -4}, {0, -4}}).value());
  EXPECT_EQ(derivative_curve(curve, 5).value().control_points(), PointArray::make({{0, 0}}).value());
  EXPECT_FALSE(derivative_curve(curve_from({{0, 0}, {1, 1}}, {1, 2}), 1).has_value());
}

TEST(Tangent, RepeatedEndPointUsesTheNextLeg) {
  // P0 = P1: C'(0) = 0, the tangent is the limit direction (P2 - P0).
  const auto curve = curve_from({{0, 0}, {0, 0}, {3, 4}, {5, 0}});
  const Point t0 = unit_tangent_at(curve, 0.0);
  EXPECT_NEAR(t0[0], 0.6, 1e-15);
  EXPECT_NEAR(t0[1], 0.8, 1e-15);
  // P2 = P3: toward increasing t the curve arrives from P1, so the tangent is (P3 - P1) direction.
  const auto back = curve_from({{0, 0}, {3, 4}, {6, 0}, {6, 0}});
  const Point t1 = unit_tangent_at(back, 1.0);
  EXPECT_NEAR(t1[0], 3 / 5.0, 1e-15);
  EXPECT_NEAR(t1[1], -4 / 5.0, 1e-15);
  const auto point = curve_from({{2, 2}, {2, 2}});
  EXPECT_EQ(unit_tangent_at(point, 0.5), (Point{0, 0}));
}

TEST(Curvature, QuarterCircleHasCurvatureOne) {
  const auto arc = curve_from({{1, 0}, {1, 1}, {0, 1}}, {1, std::sqrt(0.5), 1});
  for (double t : {0.0, 0.3, 0.5, 1.0}) {
    EXPECT_NEAR(curvature_at(arc, t), 1.0, 1e-14);
    EXPECT_NEAR(signed_curvature_at(arc, t), 1.0, 1e-14);  // counter-clockwise: turns left
    const Point p = point_at(arc, t), nrm = unit_normal_at(arc, t);
    EXPECT_NEAR(nrm[0], -p[0], 1e-14);  // the principal normal points to the centre
    EXPECT_NEAR(nrm[1], -p[1], 1e-14);
  }
}

TEST(Curvature, StraightLineHasZeroCurvatureAndLeftNormal) {
  const auto line = curve_from({{0, 0}, {1, 0}, {2, 0}});
  EXPECT_EQ(curvature_at(line, 0.4), 0.0);
  const Point nrm = unit_normal_at(line, 0.4);
  EXPECT_NEAR(nrm[0], 0.0, 1e-15);
  EXPECT_NEAR(nrm[1], 1.0, 1e-15);
}

TEST(Curvature, CuspIsInfinite) {
  const auto cusp = curve_from({{0, 0}, {2, 2}, {0, 2}, {2, 0}});  // C'(1/2) = 0 by symmetry
  EXPECT_TRUE(std::isinf(curvature_at(cusp, 0.5)));
}

TEST(PointAt, ExtrapolatesOutsideTheDomain) {
  // Documented choice: the polynomial is evaluated, not clamped.
  const auto line = curve_from({{0, 0}, {1, 2}});
  EXPECT_EQ(point_at(line, 2.0), (Point{2, 4}));
  EXPECT_EQ(point_at(line, -1.0), (Point{-1, -2}));
}

}  // namespace
}  // namespace casteljau

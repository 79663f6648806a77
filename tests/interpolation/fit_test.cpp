// B-spline fitting (interpolation/fit.hpp). References:
// - exact rational arithmetic (GMP): the normal equations of least squares and
//   of smoothing built from the Cox–de Boor recursion in rationals
//   (tests/support/exact_basis.hpp), the penalty ∫ N_j'' N_k'' by Milne's rule
//   (exact for the quadratic integrands of a cubic), solved by exact Gaussian
//   elimination; the trace of the hat matrix from the exact inverse;
// - The NURBS Book eq. 9.68–9.69 worked by hand for the knots;
// - Eigen's dense LDLᵀ and inverse for the banded factorization;
// - facts that hold whatever the algorithm: polynomial data of degree <= p are
//   reproduced, the tolerance is met (checked with point_at), a huge λ leaves
//   the least-squares line, the GCV choice is a minimum of GCV.
// scipy cross-checks run through the CLI in tests/python/test_fit_scipy.py.

#include "casteljau/interpolation/fit.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../../src/interpolation/banded_qr.hpp"
#include "../../src/interpolation/fit_banded.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "support/exact_basis.hpp"
#include "support/exact_linear.hpp"
#include "support/make.hpp"
#include "support/splitmix.hpp"

namespace casteljau {
namespace {

using test::exact_basis;
using test::exact_basis_derivative;
using test::message_of;
using test::points_of;
using test::solve_exactly;
using test::RationalMatrix;

/// ∫_a^b N_j'' N_k'' exactly for degree 3: on each knot span the integrand is
/// quadratic and Milne's rule (b − a)/3 (2 f(a+h/4) − f(a+h/2) + 2 f(a+3h/4))
/// is exact for cubics. The quarter points must be exact doubles (dyadic knots).
RationalMatrix exact_penalty(std::span<const double> knots, int p) {
  const std::size_t count = knots.size() - static_cast<std::size_t>(p) - 1;
  RationalMatrix omega(count, std::vector<mpq_class>(count, 0));
  for (std::size_t s = 0; s + 1 < knots.size(); ++s) {
    const double a = knots[s], b = knots[s + 1];
    if (!(a < b)) continue;
    const double h = b - a;
    const double nodes[3] = {a + h / 4, a + h / 2, a + 3 * h / 4};
    const mpq_class weights[3] = {2, -1, 2};
    for (int g = 0; g < 3; ++g) {
      EXPECT_EQ(mpq_class(nodes[g]), mpq_class(a) + mpq_class(h) * mpq_class(g + 1, 4)) << "nodes not exact";
      std::vector<mpq_class> second(count);
      for (std::size_t j = 0; j < count; ++j) second[j] = exact_basis_derivative(knots, static_cast<int>(j), p, 2, nodes[g]);
      for (std::size_t j = 0; j < count; ++j)
        for (std::size_t k = 0; k < count; ++k) omega[j][k] += mpq_class(h) / 3 * weights[g] * second[j] * second[k];
    }
  }
  return omega;
}

/// The exact solution of the (penalized) least-squares problem on `knots`:
/// control points and tr H. Interpolated ends: Q_0 = P_0, Q_n = P_m, the
/// other rows and columns as in The NURBS Book eq. 9.63–9.67.
struct ExactFit {
  RationalMatrix control_points;  // n+1 rows of d
  mpq_class trace;
};
ExactFit exact_fit(const PointArray& points, std::span<const double> t, std::span<const double> knots, int p,
                   FitEnds ends, const mpq_class& lambda, bool penalty) {
  const std::size_t count = knots.size() - static_cast<std::size_t>(p) - 1, d = points.dimension();
  const bool clamp = ends == FitEnds::interpolated;
  const std::size_t first_row = clamp ? 1 : 0, end_row = clamp ? points.size() - 1 : points.size();
  const std::size_t first = clamp ? 1 : 0, free = clamp ? count - 2 : count;
  RationalMatrix basis(points.size(), std::vector<mpq_class>(count));
  for (std::size_t k = 0; k < points.size(); ++k)
    for (std::size_t j = 0; j < count; ++j) basis[k][j] = exact_basis(knots, static_cast<int>(j), p, t[k]);
  RationalMatrix omega = penalty ? exact_penalty(knots, p) : RationalMatrix(count, std::vector<mpq_class>(count, 0));
  RationalMatrix fixed(count, std::vector<mpq_class>(d, 0));  // Q_0, Q_n when clamped
  if (clamp) {
    for (std::size_t c = 0; c < d; ++c) {
      fixed[0][c] = points[0][c];
      fixed[count - 1][c] = points[points.size() - 1][c];
    }
  }
  RationalMatrix a(free, std::vector<mpq_class>(free, 0)), gram = a, rhs(free, std::vector<mpq_class>(d, 0));
  for (std::size_t k = first_row; k < end_row; ++k) {
    std::vector<mpq_class> target(d);
    for (std::size_t c = 0; c < d; ++c) {
      target[c] = points[k][c];
      for (std::size_t j = 0; j < count; ++j) target[c] -= basis[k][j] * fixed[j][c];
    }
    for (std::size_t i = 0; i < free; ++i) {
      for (std::size_t c = 0; c < d; ++c) rhs[i][c] += basis[k][i + first] * target[c];
      for (std::size_t j = 0; j < free; ++j) gram[i][j] += basis[k][i + first] * basis[k][j + first];
    }
  }
  for (std::size_t i = 0; i < free; ++i) {
    for (std::size_t j = 0; j < free; ++j) a[i][j] = gram[i][j] + lambda * omega[i + first][j + first];
    for (std::size_t c = 0; c < d; ++c)
      for (std::size_t j = 0; j < count; ++j) rhs[i][c] -= lambda * omega[i + first][j] * fixed[j][c];
  }
  const RationalMatrix interior = solve_exactly(a, rhs);
  const RationalMatrix inverse_times_gram = solve_exactly(a, gram);
  ExactFit fit{fixed, clamp ? mpq_class(2) : mpq_class(0)};
  for (std::size_t i = 0; i < free; ++i) {
    fit.control_points[i + first] = interior[i];
    fit.trace += inverse_times_gram[i][i];
  }
  return fit;
}

double largest_error(const PointArray& computed, const RationalMatrix& exact) {
  double worst = 0.0;
  for (std::size_t i = 0; i < computed.size(); ++i)
    for (std::size_t c = 0; c < exact[i].size(); ++c)
      worst = std::max(worst, std::abs(mpq_class(mpq_class(computed[i][c]) - exact[i][c]).get_d()));
  return worst;
}

/// 12 points with dyadic coordinates and dyadic, unevenly spaced parameters.
const std::vector<double> kParameters{0, 0.0625, 0.125, 0.25, 0.3125, 0.375, 0.5, 0.625, 0.6875, 0.75, 0.875, 1};
PointArray dyadic_points() {
  return points_of(2, {0, 0, 1, 2.5, 2, 3, 3.5, 2.75, 4, 1, 5, 0.5, 6.25, 1.5, 7, 3, 7.5, 4.25, 8, 4, 9, 2, 10, 0.25});
}

// --- knots -------------------------------------------------------------------------

TEST(ApproximationKnots, FollowTheNurbsBookEquation) {
  // m + 1 = 10 parameters i/10, p = 3, n + 1 = 6: d = 10/3; j = 1: i = 3, α = 1/3,
  // u_4 = (2/3) t_2 + (1/3) t_3 = 7/30; j = 2: i = 6, α = 2/3, u_5 = (1/3) t_5 + (2/3) t_6 = 17/30.
  std::vector<double> t;
  for (int i = 0; i < 10; ++i) t.push_back(i / 10.0);
  const auto knots = approximation_knots(t, 3, 6);
  ASSERT_EQ(knots.size(), 10u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(knots[i], 0.0);
    EXPECT_EQ(knots[6 + i], 0.9);
  }
  EXPECT_NEAR(knots[4], 7.0 / 30.0, 1e-16);
  EXPECT_NEAR(knots[5], 17.0 / 30.0, 1e-16);
}

// --- least squares: exact reference ------------------------------------------------

TEST(FitLeastSquares, EqualsTheExactNormalEquations) {
  const PointArray points = dyadic_points();
  for (int p : {1, 2, 3, 4}) {
    for (std::size_t count : {std::size_t(p + 1), std::size_t(7), std::size_t(12)}) {
      for (FitEnds ends : {FitEnds::interpolated, FitEnds::free}) {
        SCOPED_TRACE("p = " + std::to_string(p) + ", " + std::to_string(count) + " control points, " +
                     (ends == FitEnds::free ? "free ends" : "interpolated ends"));
        const auto fit = fit_least_squares(points, kParameters, p, count, ends);
        ASSERT_TRUE(fit) << message_of(fit);
        const auto knots = approximation_knots(kParameters, p, count);
        EXPECT_EQ(std::vector<double>(fit->curve.knots().begin(), fit->curve.knots().end()), knots);
        const ExactFit exact = exact_fit(points, kParameters, knots, p, ends, 0, false);
        // The normal equations square B's condition; n = m on eq. 9.69 knots is the worst case here.
        EXPECT_LE(largest_error(fit->curve.control_points(), exact.control_points), 1e-10 * 10);
        EXPECT_EQ(fit->effective_degrees_of_freedom, static_cast<double>(count));
        EXPECT_EQ(fit->smoothing, 0.0);
        if (count == points.size()) {
          EXPECT_LE(fit->max_error, 1e-11 * 10);  // n = m interpolates (normal equations: cond²)
        }
        if (ends == FitEnds::interpolated) {
          EXPECT_EQ(fit->errors.front(), 0.0);
          EXPECT_EQ(fit->errors.back(), 0.0);
        }
      }
    }
  }
}

TEST(FitLeastSquares, ReportsTheErrorsOfTheCurve) {
  const PointArray points = dyadic_points();
  const auto fit = fit_least_squares(points, kParameters, 3, 6, FitEnds::free);
  ASSERT_TRUE(fit);
  ASSERT_EQ(fit->errors.size(), points.size());
  double worst = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double e = distance(point_at(fit->curve, kParameters[i]), points[i]);
    EXPECT_NEAR(fit->errors[i], e, 1e-14 * 10);
    worst = std::max(worst, e);
    sum += e * e;
  }
  EXPECT_NEAR(fit->max_error, worst, 1e-14 * 10);
  EXPECT_EQ(fit->errors[fit->worst_point], fit->max_error);
  EXPECT_NEAR(fit->rms_error, std::sqrt(sum / 12), 1e-14 * 10);
  // GCV of plain least squares: (RSS/N) / (1 − (n+1)/N)².
  EXPECT_NEAR(fit->gcv_score, sum / 12 / std::pow(1 - 6.0 / 12, 2), 1e-12 * fit->gcv_score);
}

/// Random polynomial data of degree q <= p at jittered increasing parameters:
/// least squares reproduces them to rounding, whatever n and the ends.
RC_GTEST_PROP(FitLeastSquares, ReproducesPolynomialsOfDegreeAtMostP, ()) {
  const int p = *rc::gen::inRange(1, 6);
  const int q = *rc::gen::inRange(0, p + 1);
  const int count = *rc::gen::inRange(p + 1, 40);
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  test::SplitMix random{seed};
  std::vector<double> t(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) t[static_cast<std::size_t>(i)] = (i + 0.8 * random.unit()) / count;
  std::vector<double> coefficients(2 * static_cast<std::size_t>(q + 1));
  for (double& c : coefficients) c = 20 * random.unit() - 10;
  std::vector<double> coordinates;
  for (double u : t) {
    for (int c = 0; c < 2; ++c) {
      double value = 0.0;  // Horner, centred at 1/2 so the values stay O(10)
      for (int k = q; k >= 0; --k) value = value * (u - 0.5) + coefficients[2 * static_cast<std::size_t>(k) + c];
      coordinates.push_back(value);
    }
  }
  const PointArray points = points_of(2, coordinates);
  const auto control_points = static_cast<std::size_t>(*rc::gen::inRange(p + 1, count + 1));
  const FitEnds ends = *rc::gen::element(FitEnds::interpolated, FitEnds::free);
  const auto fit = fit_least_squares(points, t, p, control_points, ends);
  RC_ASSERT(fit.has_value());
  RC_ASSERT(fit->max_error <= 1e-9 * std::max(1.0, scale_of(points)));
}

// --- smoothing: exact reference -----------------------------------------------------

TEST(FitSmoothing, EqualsTheExactPenalizedSystem) {
  const PointArray points = dyadic_points();
  for (FitEnds ends : {FitEnds::free, FitEnds::interpolated}) {
    for (double lambda : {0.0009765625, 0.015625, 2.0}) {
      SCOPED_TRACE("λ = " + std::to_string(lambda) + (ends == FitEnds::free ? ", free ends" : ", interpolated ends"));
      SmoothingOptions options;
      options.smoothing = lambda;
      options.ends = ends;
      const auto fit = fit_smoothing(points, kParameters, options);
      ASSERT_TRUE(fit) << message_of(fit);
      // Knots at every parameter: t_0⁴, t_1..t_10, t_11⁴, so m + p = 14 control points.
      std::vector<double> knots{0, 0, 0};
      knots.insert(knots.end(), kParameters.begin(), kParameters.end());
      knots.insert(knots.end(), {1, 1, 1});
      ASSERT_EQ(std::vector<double>(fit->curve.knots().begin(), fit->curve.knots().end()), knots);
      const ExactFit exact = exact_fit(points, kParameters, knots, 3, ends, mpq_class(lambda), true);
      EXPECT_LE(largest_error(fit->curve.control_points(), exact.control_points), 1e-10 * 10);
      EXPECT_NEAR(fit->effective_degrees_of_freedom, exact.trace.get_d(), 1e-11 * 12);
      EXPECT_EQ(fit->smoothing, lambda);
      EXPECT_FALSE(fit->smoothing_from_gcv);
      double sum = 0.0;
      for (double e : fit->errors) sum += e * e;
      const double n = 12.0, denominator = 1 - exact.trace.get_d() / n;
      EXPECT_NEAR(fit->gcv_score, sum / n / (denominator * denominator), 1e-9 * fit->gcv_score);
    }
  }
}

TEST(FitSmoothing, PenalizedFitWithFixedControlPointCountEqualsExactSystem) {
  // 9 parameters and 6 control points: d = 9/3 = 3 is a whole number, so the
  // interior knots of eq. 9.69 are parameters (t_2, t_5) and dyadic.
  const std::vector<double> t{0, 0.125, 0.25, 0.375, 0.4375, 0.5, 0.625, 0.75, 1};
  const PointArray points = points_of(1, {1, 3, 2, -1, 0.5, 4, 2, 2.5, -2});
  const auto knots = approximation_knots(t, 3, 6);
  ASSERT_EQ(knots, (std::vector<double>{0, 0, 0, 0, 0.25, 0.5, 1, 1, 1, 1}));
  for (FitEnds ends : {FitEnds::free, FitEnds::interpolated}) {
    SmoothingOptions options;
    options.control_point_count = 6;
    options.smoothing = 0.0078125;
    options.ends = ends;
    const auto fit = fit_smoothing(points, t, options);
    ASSERT_TRUE(fit) << message_of(fit);
    const ExactFit exact = exact_fit(points, t, knots, 3, ends, mpq_class(0.0078125), true);
    EXPECT_LE(largest_error(fit->curve.control_points(), exact.control_points), 1e-11 * 4);
    EXPECT_NEAR(fit->effective_degrees_of_freedom, exact.trace.get_d(), 1e-11 * 9);
  }
}

/// GCV(λ) of the fit at a given λ.
double gcv_at(const PointArray& points, std::span<const double> t, double lambda) {
  SmoothingOptions options;
  options.smoothing = lambda;
  return fit_smoothing(points, t, options).value().gcv_score;
}

PointArray noisy_sine(std::size_t count, std::uint64_t seed, std::vector<double>& t) {
  test::SplitMix random{seed};
  std::vector<double> coordinates;
  t.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const double x = static_cast<double>(i) / static_cast<double>(count - 1);
    t.push_back(x);
    coordinates.push_back(std::sin(6 * x) + 0.2 * (random.unit() - 0.5));
  }
  return points_of(1, coordinates);
}

TEST(FitSmoothing, GcvChoiceMinimizesGcv) {
  std::vector<double> t;
  const PointArray points = noisy_sine(80, 7, t);
  const auto fit = fit_smoothing(points, t, SmoothingOptions{});
  ASSERT_TRUE(fit) << message_of(fit);
  EXPECT_TRUE(fit->smoothing_from_gcv);
  const double lambda = fit->smoothing;
  EXPECT_GT(lambda, 0.0);
  // A minimum: GCV does not fall a step away in either direction, and the
  // reported score is GCV at the reported λ.
  EXPECT_NEAR(fit->gcv_score, gcv_at(points, t, lambda), 1e-12 * fit->gcv_score);
  for (double factor : {1.01, 1.1, 2.0, 10.0}) {
    EXPECT_LE(fit->gcv_score, gcv_at(points, t, lambda * factor) * (1 + 1e-12)) << factor;
    EXPECT_LE(fit->gcv_score, gcv_at(points, t, lambda / factor) * (1 + 1e-12)) << factor;
  }
  // Noise of standard deviation 0.2/sqrt(12) ≈ 0.058: the smoothed residuals are of that size,
  // and the fit uses far fewer degrees of freedom than the 80 points.
  EXPECT_GT(fit->rms_error, 0.03);
  EXPECT_LT(fit->rms_error, 0.08);
  EXPECT_GT(fit->effective_degrees_of_freedom, 4.0);
  EXPECT_LT(fit->effective_degrees_of_freedom, 30.0);
}

// Weights multiply the squared residuals: weights all equal to c are the
// unweighted fit at λ / c (the objective is c times the other), and weight 0
// leaves a point out of the data term; bad weights are named. (scipy's
// make_smoothing_spline(w=...) in tests/python/test_module_scipy_like.py.)
TEST(FitSmoothing, WeightsMultiplyTheSquaredResiduals) {
  std::vector<double> t;
  const PointArray points = noisy_sine(60, 5, t);
  SmoothingOptions plain;
  plain.smoothing = 0.01;
  const auto unweighted = fit_smoothing(points, t, plain);
  ASSERT_TRUE(unweighted) << message_of(unweighted);
  SmoothingOptions scaled = plain;
  scaled.smoothing = 0.04;
  scaled.weights.assign(60, 4.0);
  const auto weighted = fit_smoothing(points, t, scaled);
  ASSERT_TRUE(weighted) << message_of(weighted);
  const PointArray& a = unweighted->curve.control_points();
  const PointArray& b = weighted->curve.control_points();
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i][0], b[i][0], 1e-12) << i;
  EXPECT_NEAR(weighted->effective_degrees_of_freedom, unweighted->effective_degrees_of_freedom, 1e-10);
  // A point with weight 0 may lie anywhere: moving it changes nothing.
  SmoothingOptions dropped = plain;
  dropped.weights.assign(60, 1.0);
  dropped.weights[20] = 0.0;
  PointArray moved = points;
  moved[20][0] += 100.0;  // y(t): the sine's points are 1-D
  const auto left_out = fit_smoothing(points, t, dropped), moved_out = fit_smoothing(moved, t, dropped);
  ASSERT_TRUE(left_out && moved_out);
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(left_out->curve.control_points()[i][0], moved_out->curve.control_points()[i][0], 1e-12) << i;
  SmoothingOptions bad = plain;
  bad.weights.assign(59, 1.0);
  EXPECT_EQ(message_of(fit_smoothing(points, t, bad)), "59 weights for 60 points, a weighted fit needs one weight per point");
  bad.weights.assign(60, 1.0);
  bad.weights[7] = -1.0;
  EXPECT_EQ(message_of(fit_smoothing(points, t, bad)), "weight 7 is -1, weights must be >= 0");
}

TEST(FitSmoothing, EffectiveDegreesOfFreedomFallWithLambdaTowardsALine) {
  std::vector<double> t;
  const PointArray points = noisy_sine(40, 3, t);
  double previous = 1e300;
  for (double lambda : {1e-8, 1e-6, 1e-4, 1e-2, 1.0, 100.0}) {
    SmoothingOptions options;
    options.smoothing = lambda;
    const auto fit = fit_smoothing(points, t, options);
    ASSERT_TRUE(fit) << message_of(fit);
    EXPECT_LT(fit->effective_degrees_of_freedom, previous);
    EXPECT_GT(fit->effective_degrees_of_freedom, 2.0);
    previous = fit->effective_degrees_of_freedom;
  }
  // λ = 1e5 (10^5 times the data's weight here): the penalty leaves almost only lines,
  // so the fit is the least-squares line y = a + b t (closed form from the two sums).
  SmoothingOptions options;
  options.smoothing = 1e5;
  const auto fit = fit_smoothing(points, t, options);
  ASSERT_TRUE(fit);
  double st = 0, sy = 0, stt = 0, sty = 0;
  const double n = 40;
  for (std::size_t i = 0; i < 40; ++i) {
    st += t[i];
    sy += points[i][0];
    stt += t[i] * t[i];
    sty += t[i] * points[i][0];
  }
  const double b = (n * sty - st * sy) / (n * stt - st * st), a = (sy - b * st) / n;
  for (double u : {0.0, 0.3, 1.0}) EXPECT_NEAR(point_at(fit->curve, u)[0], a + b * u, 1e-4);
  EXPECT_NEAR(fit->effective_degrees_of_freedom, 2.0, 1e-3);
}

// --- tolerance ---------------------------------------------------------------------

RC_GTEST_PROP(FitToTolerance, MeetsTheTolerance, ()) {
  const int p = *rc::gen::inRange(1, 5);
  const double relative = std::pow(10.0, -*rc::gen::inRange(1, 7));
  const FitEnds ends = *rc::gen::element(FitEnds::interpolated, FitEnds::free);
  const std::size_t count = 300;
  std::vector<double> coordinates, t;
  for (std::size_t i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / (count - 1);
    t.push_back(s);
    coordinates.push_back(3 * std::cos(4 * s) + std::cos(17 * s));
    coordinates.push_back(2 * std::sin(5 * s));
  }
  const PointArray points = points_of(2, coordinates);
  const double tolerance = relative * scale_of(points);
  const auto fit = fit_to_tolerance(points, t, p, Tolerance{tolerance}, ends);
  RC_ASSERT(fit.has_value());
  for (std::size_t i = 0; i < count; ++i) RC_ASSERT(distance(point_at(fit->curve, t[i]), points[i]) <= tolerance);
  RC_ASSERT(fit->max_error <= tolerance);
  // At worst the fit interpolates every point (degree 1 at a tolerance finer than the
  // chords' sagitta needs them all): never more control points than data points.
  RC_ASSERT(fit->curve.control_points().size() <= count);
  RC_ASSERT(fit->curve.degree() == p);
}

TEST(FitToTolerance, UsesFewControlPointsForSmoothData) {
  // A cubic's data need one Bézier piece: no knot is added.
  std::vector<double> t, coordinates;
  for (int i = 0; i <= 50; ++i) {
    const double s = i / 50.0;
    t.push_back(s);
    coordinates.push_back(s * s * s - 2 * s);
  }
  const auto fit = fit_to_tolerance(points_of(1, coordinates), t, 3, Tolerance{1e-9});
  ASSERT_TRUE(fit) << message_of(fit);
  EXPECT_EQ(fit->curve.control_points().size(), 4u);
}

TEST(FitToTolerance, RefusesATolerancePastRounding) {
  std::vector<double> t;
  const PointArray points = noisy_sine(30, 1, t);
  const auto fit = fit_to_tolerance(points, t, 3, Tolerance{1e-300});
  ASSERT_FALSE(fit);
  EXPECT_NE(message_of(fit).find("the tolerance 1e-300 is not reached: max error "), std::string::npos) << message_of(fit);
}

// --- the banded factorization ------------------------------------------------------

/// Random banded rows of p+1 values (a few negative, as penalty rows are),
/// first columns not decreasing, covering every column: m rows for n columns.
struct BandedRows {
  Eigen::MatrixXd dense;
  std::vector<std::size_t> first;
};
BandedRows banded_rows(test::SplitMix& random, std::size_t rows, std::size_t n, int p) {
  const auto width = static_cast<std::size_t>(p) + 1;
  BandedRows result{Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(n)), {}};
  for (std::size_t k = 0; k < rows; ++k) {
    const std::size_t last_first = n > width ? n - width : 0;
    const std::size_t first = rows == 1 ? 0 : k * last_first / (rows - 1);
    result.first.push_back(first);
    for (std::size_t j = first; j < std::min(n, first + width); ++j)
      result.dense(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = random.unit() - 0.25;
  }
  return result;
}

TEST(BandedQr, SolvesLeastSquaresAndTracesTheInverseLikeDenseEigen) {
  test::SplitMix random{42};
  for (int p = 1; p <= 5; ++p) {
    for (std::size_t n : {std::size_t(1), std::size_t(2), std::size_t(7), std::size_t(30)}) {
      const std::size_t m = 3 * n + 2;
      const BandedRows rows = banded_rows(random, m, n, p);
      const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(static_cast<Eigen::Index>(m), 3);
      detail::BandedQr qr(n, p, 3);
      for (std::size_t k = 0; k < m; ++k) {
        std::vector<double> values(static_cast<std::size_t>(p) + 1, 0.0), target(3);
        for (std::size_t j = rows.first[k]; j < std::min(n, rows.first[k] + values.size()); ++j)
          values[j - rows.first[k]] = rows.dense(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j));
        for (std::size_t c = 0; c < 3; ++c) target[c] = rhs(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(c));
        qr.add_row(rows.first[k], values, target, 1.0);
      }
      const Eigen::MatrixXd normal = rows.dense.transpose() * rows.dense;
      std::vector<double> norms(n);
      for (std::size_t i = 0; i < n; ++i) norms[i] = normal(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
      ASSERT_TRUE(qr.regular(norms));
      std::vector<double> x(n * 3);
      qr.solve(x);
      const Eigen::MatrixXd expected = rows.dense.colPivHouseholderQr().solve(rhs);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < 3; ++c)
          EXPECT_NEAR(x[i * 3 + c], expected(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)), 1e-12);
      // RᵀR = AᵀA as L D Lᵀ: tr((AᵀA)⁻¹ E) for E with a single band entry (i, j) set to 1 (and its
      // mirror) is z_ii, or 2 z_ij off the diagonal: every entry of the band of the inverse.
      detail::SymmetricBand factored(0, p);
      qr.factored_normal_matrix(factored);
      const Eigen::MatrixXd inverse = normal.inverse();
      detail::SymmetricBand original(n, p);
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = original.first_column(i); j <= i; ++j) {
          original.at(i, j) = normal(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
          detail::SymmetricBand unit(n, p);
          unit.at(i, j) = 1.0;
          const double entry = inverse(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
          EXPECT_NEAR(factored.trace_of_inverse_times(unit), i == j ? entry : 2.0 * entry,
                      1e-12 * std::max(1.0, std::abs(entry)));
        }
      }
      // tr((AᵀA)⁻¹ AᵀA) = n from the band alone.
      EXPECT_NEAR(factored.trace_of_inverse_times(original), static_cast<double>(n), 1e-11 * static_cast<double>(n));
    }
  }
}

TEST(BandedQr, RefusesASingularSystem) {
  // Rows (1, 1, 0) twice and (0, 0, 1): columns 0 and 1 are equal.
  detail::BandedQr qr(3, 2, 1);
  qr.add_row(0, std::vector<double>{1, 1, 0}, std::vector<double>{1}, 1.0);
  qr.add_row(0, std::vector<double>{1, 1, 0}, std::vector<double>{2}, 1.0);
  qr.add_row(2, std::vector<double>{1}, std::vector<double>{3}, 1.0);
  EXPECT_FALSE(qr.regular(std::vector<double>{2, 2, 1}));
  // The first and third columns alone: regular, the first the mean of 1 and 2.
  detail::BandedQr two(2, 1, 1);
  two.add_row(0, std::vector<double>{1}, std::vector<double>{1}, 1.0);
  two.add_row(0, std::vector<double>{1}, std::vector<double>{2}, 1.0);
  two.add_row(1, std::vector<double>{1}, std::vector<double>{3}, 1.0);
  ASSERT_TRUE(two.regular(std::vector<double>{2, 1}));
  std::vector<double> x(2);
  two.solve(x);
  EXPECT_DOUBLE_EQ(x[0], 1.5);
  EXPECT_DOUBLE_EQ(x[1], 3.0);
}

// --- bad input ---------------------------------------------------------------------

TEST(Fit, RefusesBadInputWithOneClearMessage) {
  const PointArray points = dyadic_points();
  const std::vector<double> t = kParameters;
  EXPECT_EQ(message_of(fit_least_squares(points_of(2, {0, 0, 1, 1, 2, 0}), std::vector<double>{0, 0.5, 1}, 3, 4)),
            "a fit of degree 3 needs at least 4 points, got 3");
  EXPECT_EQ(message_of(fit_least_squares(points, t, 3, 3)), "a fit of degree 3 needs at least 4 control points, got 3");
  EXPECT_EQ(message_of(fit_least_squares(points, t, 3, 13)),
            "13 control points for 12 points: a least-squares fit takes at most as many control points as points");
  EXPECT_EQ(message_of(fit_least_squares(points, std::span<const double>(t).first(11), 3, 5)),
            "a fit needs one parameter per point: 11 parameters for 12 points");
  EXPECT_EQ(message_of(fit_least_squares(points, t, 0, 5)), "degree 0 is outside 1..10000");
  std::vector<double> repeated = t;
  repeated[4] = repeated[3];
  EXPECT_EQ(message_of(fit_least_squares(points, repeated, 3, 5)),
            "parameters must increase strictly: parameter 4 is 0.25, parameter 3 is 0.25");
  std::vector<double> nan_parameter = t;
  nan_parameter[2] = std::nan("");
  EXPECT_EQ(message_of(fit_least_squares(points, nan_parameter, 3, 5)), "parameter 2 is NaN");
  PointArray nan_point = points;
  nan_point[5][1] = std::nan("");
  EXPECT_EQ(message_of(fit_least_squares(nan_point, t, 3, 5)), "coordinate 1 of point 5 is NaN");

  SmoothingOptions negative;
  negative.smoothing = -1.0;
  EXPECT_EQ(message_of(fit_smoothing(points, t, negative)), "the smoothing λ is -1, it must be >= 0");
  SmoothingOptions linear;
  linear.degree = 1;
  EXPECT_EQ(message_of(fit_smoothing(points, t, linear)),
            "smoothing needs degree 2 or more (the penalty integrates C''), got degree 1");
  SmoothingOptions zero;
  zero.smoothing = 0.0;
  EXPECT_EQ(message_of(fit_smoothing(points, t, zero)),
            "the smoothing λ = 0 leaves 14 control points (knots at every parameter) for 12 points: give λ > 0 or "
            "fewer control points");
  zero.control_point_count = 8;  // then λ = 0 is plain least squares
  const auto plain = fit_smoothing(points, t, zero);
  ASSERT_TRUE(plain) << message_of(plain);
  EXPECT_EQ(plain->curve, fit_least_squares(points, t, 3, 8, FitEnds::free).value().curve);

  EXPECT_EQ(message_of(fit_to_tolerance(points, t, 3, Tolerance{0.0})), "the tolerance is 0, it must be > 0");
  EXPECT_EQ(message_of(fit_to_tolerance(points, t, 3, Tolerance{-1.0})), "the tolerance is -1, it must be > 0");
  EXPECT_EQ(message_of(fit_to_tolerance(points, t, 3, Tolerance{std::nan("")})), "the tolerance is NaN");
}

// GCV does not depend on the parameter's units: stretching x from [0, 1] to
// [0, L] multiplies the penalty by L^-3, so the chosen λ scales by L³ and the
// fit is the same. Near interpolation GCV is 0/0 and rounding once made it
// pick λ ≈ 4e-14 (an interpolant) on [0, 6] (tolerances::kGcvNearInterpolation).
TEST(FitSmoothing, GcvChoiceIsTheSameInAnyUnitOfX) {
  test::SplitMix random{2026};
  const std::size_t count = 41;
  std::vector<double> unit_x(count), coordinates;
  for (std::size_t i = 0; i < count; ++i) {
    unit_x[i] = static_cast<double>(i) / (count - 1);
    const double noise = 0.2 * (random.unit() - 0.5) + 0.2 * (random.unit() - 0.5);
    coordinates.push_back(std::sin(6.0 * unit_x[i]) + noise);
  }
  const auto values = PointArray::make(1, coordinates).value();
  SmoothingOptions options;
  const auto reference = fit_smoothing(values, unit_x, options);
  ASSERT_TRUE(reference.has_value());
  EXPECT_TRUE(reference->smoothing_from_gcv);
  EXPECT_LT(reference->effective_degrees_of_freedom, 20.0);  // it smooths
  for (const double length : {6.0, 100.0, 1e-3}) {
    std::vector<double> x(count);
    for (std::size_t i = 0; i < count; ++i) x[i] = unit_x[i] * length;
    const auto fit = fit_smoothing(values, x, options);
    ASSERT_TRUE(fit.has_value());
    EXPECT_NEAR(fit->effective_degrees_of_freedom, reference->effective_degrees_of_freedom, 1e-3) << length;
    EXPECT_NEAR(fit->smoothing / (length * length * length), reference->smoothing, 1e-4 * reference->smoothing)
        << length;
    EXPECT_NEAR(fit->rms_error, reference->rms_error, 1e-6) << length;
  }
}

// Issue 15: --smoothing 1e308 answered "normal equations are singular". A λ
// whose penalty swamps the data (free ends: Ω alone is singular on lines) is
// called too large, a λ too small to determine m + p control points from m + 1
// points too small; both name the range GCV searches. λ₀ = tr(BᵀB)/tr(Ω).
TEST(FitSmoothing, ALambdaThatMakesTheSystemSingularIsCalledTooLargeOrTooSmall) {
  std::vector<double> t;
  const PointArray points = noisy_sine(80, 7, t);
  SmoothingOptions options;
  options.smoothing = 1e308;
  const std::string large = message_of(fit_smoothing(points, t, options));
  EXPECT_EQ(large.find("the smoothing λ = 1e+308 is too large for these data: λ·tr(Ω) outweighs tr(BᵀB) by about "
                       "10^"),
            0u)
      << large;
  EXPECT_NE(large.find("(heavily smoothed, towards a straight line) is the range GCV searches here (λ₀·10^-10 to "
                       "λ₀·10^6, λ₀ = tr(BᵀB)/tr(Ω) = "),
            std::string::npos)
      << large;
  EXPECT_NE(large.find("): give a λ there, or let GCV choose it"), std::string::npos) << large;
  EXPECT_EQ(fit_smoothing(points, t, options).error().kind, ErrorKind::singular);
  options.smoothing = 1e-308;
  EXPECT_EQ(fit_smoothing(points, t, options).error().kind, ErrorKind::singular);
  const std::string small = message_of(fit_smoothing(points, t, options));
  EXPECT_EQ(small.find("the smoothing λ = 1e-308 is too small for these data: λ·tr(Ω) is about 10^"), 0u) << small;
  EXPECT_NE(small.find("too little to determine 82 control points from 80 points"), std::string::npos) << small;
  options.control_point_count = 10;  // fewer control points than points: a tiny λ is least squares
  EXPECT_TRUE(fit_smoothing(points, t, options).has_value());
}

/// Records what a computation reports to its Progress.
struct Reports {
  std::vector<double> fractions;
  Progress callback() {
    return Progress{[](void* self, double f) { static_cast<Reports*>(self)->fractions.push_back(f); }, this};
  }
  /// Non-decreasing in [0, 1], ending at 1, at most a few hundred.
  void expect_sound(std::size_t at_least) const {
    ASSERT_GE(fractions.size(), at_least);
    EXPECT_LE(fractions.size(), 300u);
    EXPECT_EQ(fractions.back(), 1.0);
    for (std::size_t i = 0; i < fractions.size(); ++i) {
      EXPECT_GE(fractions[i], 0.0);
      EXPECT_LE(fractions[i], 1.0);
      if (i > 0) {
        EXPECT_GE(fractions[i], fractions[i - 1]) << i;
      }
    }
  }
};

// Fits of 10⁶ points take seconds (GCV, a tolerance near the noise): they say how far they are.
TEST(FitProgress, GcvAndToleranceReportNonDecreasingFractionsEndingAtOne) {
  std::vector<double> t;
  const PointArray points = noisy_sine(200, 11, t);
  Reports gcv;
  ASSERT_TRUE(fit_smoothing(points, t, SmoothingOptions{}, gcv.callback()).has_value());
  gcv.expect_sound(34);  // one report per GCV evaluation (the grid alone has 33), and the end
  std::printf("GCV evaluations: %zu\n", gcv.fractions.size() - 1);
  Reports tolerance;
  ASSERT_TRUE(fit_to_tolerance(points, t, 3, Tolerance{0.06}, FitEnds::interpolated, tolerance.callback()));
  tolerance.expect_sound(1);
}


// Issue 43: the accuracy of the fits against the exact solve (GMP), on the
// seed's head (19 points, parameters k/32: dyadic, so that the penalty's
// Milne nodes are exact): least squares with 4 to 19 control points, and the
// smoothing spline (knots at every parameter) at λ = 10^k, k = −6..6, with
// free and interpolated ends. The largest control point error relative to
// the data's scale (its largest coordinate, 9.5), and tr H's error, printed
// as the table docs/interpolation.md quotes. Least squares is held to 32 ulps
// times the condition number κ of its free design matrix (Eigen's SVD): a
// backward stable solve's bound (the square case, 19 control points, has
// κ = 3.0e6); the normal equations' error grows as κ² (0.43 of the scale
// there, 1.5e-5 for the smoothing spline at λ = 1e6).
TEST(FitAccuracy, AgainstTheExactSolveOnTheHead) {
  const PointArray head = points_of(2, {9.5, 5,  5.5,  5,    1,    7,  -3.5, 9.5, -9.5, 8,    -9.5, -2.5, -8.5,
                                        -4.5, -5, -5,   -4.5, -2.5, -0.5, -9,  0,    -7,  -1,   -4.5, 2,    -5,
                                        3,    -1.5, 2.5, -5,  5,    -4.5, 7.5, -5,  6.5,  -0.5, 9.5,  -0.5});
  std::vector<double> t;
  for (int k = 0; k < 19; ++k) t.push_back(k / 32.0);
  const double scale = 9.5;
  double worst_least_squares = 0.0, worst_smoothing = 0.0, worst_trace = 0.0;
  for (FitEnds ends : {FitEnds::free, FitEnds::interpolated}) {
    const char* end_name = ends == FitEnds::free ? "free" : "interpolated";
    for (std::size_t count = 4; count <= 19; ++count) {
      const auto fit = fit_least_squares(head, t, 3, count, ends);
      ASSERT_TRUE(fit) << message_of(fit);
      const auto knots = approximation_knots(t, 3, count);
      const ExactFit exact = exact_fit(head, t, knots, 3, ends, 0, false);
      const double error = largest_error(fit->curve.control_points(), exact.control_points) / scale;
      const bool clamp = ends == FitEnds::interpolated;
      const std::size_t first = clamp ? 1 : 0, rows = clamp ? 17 : 19, columns = clamp ? count - 2 : count;
      Eigen::MatrixXd design(rows, columns);
      for (std::size_t k = 0; k < rows; ++k)
        for (std::size_t j = 0; j < columns; ++j)
          design(k, j) = exact_basis(knots, static_cast<int>(j + first), 3, t[k + first]).get_d();
      const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(design).singularValues();
      const double condition = sigma(0) / sigma(sigma.size() - 1);
      std::printf("least squares, %s ends, %zu control points: %.1e (κ %.1e)\n", end_name, count, error, condition);
      EXPECT_LE(error, 32 * 0x1p-52 * std::max(condition, 1.0)) << count;
      worst_least_squares = std::max(worst_least_squares, error);
    }
    std::vector<double> knots{0, 0, 0};
    knots.insert(knots.end(), t.begin(), t.end());
    knots.insert(knots.end(), {t.back(), t.back(), t.back()});
    for (int k = -6; k <= 6; ++k) {
      SmoothingOptions options;
      options.smoothing = std::pow(10.0, k);
      options.ends = ends;
      const auto fit = fit_smoothing(head, t, options);
      ASSERT_TRUE(fit) << message_of(fit);
      const ExactFit exact = exact_fit(head, t, knots, 3, ends, mpq_class(*options.smoothing), true);
      const double error = largest_error(fit->curve.control_points(), exact.control_points) / scale;
      const double trace_error = std::abs(fit->effective_degrees_of_freedom - exact.trace.get_d());
      std::printf("smoothing, %s ends, λ = 1e%d: %.1e (tr H %.1e)\n", end_name, k, error, trace_error);
      worst_smoothing = std::max(worst_smoothing, error);
      worst_trace = std::max(worst_trace, trace_error);
    }
  }
  std::printf("worst: least squares %.1e, smoothing %.1e, tr H %.1e\n", worst_least_squares, worst_smoothing,
              worst_trace);
  EXPECT_LE(worst_smoothing, 1e-12);
  EXPECT_LE(worst_trace, 1e-11);
}

}  // namespace
}  // namespace casteljau

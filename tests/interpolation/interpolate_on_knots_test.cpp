// Interpolation and weighted least squares on given knots
// (interpolate_on_knots in spline_interpolation.hpp, fit_least_squares_on_knots
// in fit.hpp). References:
// - exact rational arithmetic (GMP): the collocation system (rows N_j(t_i) and
//   N_j^(k)(t_0), N_j^(k)(t_m)) and the weighted normal equations
//   (Σ w_i N_j(t_i) N_k(t_i)) built from the Cox–de Boor recursion in rationals
//   (tests/support/exact_basis.hpp) and solved by exact Gaussian elimination,
//   on dyadic knots, parameters and data (so every input is exact);
// - facts that hold whatever the algorithm: on interpolate_bspline's own knots
//   the result is interpolate_bspline's, unit weights on approximation_knots
//   give fit_least_squares, polynomials of degree <= p are reproduced;
// - the error messages for bad input (knot count, Schoenberg–Whitney, NaN and
//   decreasing knots, weights).

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/interpolation/fit.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "support/exact_basis.hpp"
#include "support/exact_linear.hpp"
#include "support/make.hpp"

namespace casteljau {
namespace {

using test::exact_basis;
using test::exact_basis_derivative;
using test::message_of;
using test::points_of;
using test::solve_exactly;
using Rational = test::RationalMatrix;

/// max |computed - exact| over all control point coordinates, relative to
/// max(1, max |exact|).
double relative_error(const PointArray& computed, const Rational& exact) {
  double error = 0.0, scale = 1.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    for (std::size_t k = 0; k < exact[i].size(); ++k) {
      const double e = exact[i][k].get_d();
      scale = std::max(scale, std::abs(e));
      error = std::max(error, std::abs(computed[i][k] - e));
    }
  }
  return error / scale;
}

/// The collocation system of interpolate_on_knots in rationals: one row per
/// point, one per derivative (any row order: the solution is the same).
Rational exact_interpolation(const std::vector<double>& knots, int p, const std::vector<double>& t,
                             const PointArray& points, const std::vector<EndDerivative>& derivatives) {
  const std::size_t n = knots.size() - static_cast<std::size_t>(p) - 1, d = static_cast<std::size_t>(points.dimension());
  Rational a, b;
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<mpq_class> row(n);
    for (std::size_t j = 0; j < n; ++j) row[j] = exact_basis(knots, static_cast<int>(j), p, t[i]);
    a.push_back(row);
    b.emplace_back(points[i].begin(), points[i].end());
  }
  for (const EndDerivative& e : derivatives) {
    const double u = e.at_end ? t.back() : t.front();
    std::vector<mpq_class> row(n);
    for (std::size_t j = 0; j < n; ++j) row[j] = exact_basis_derivative(knots, static_cast<int>(j), p, e.order, u);
    a.push_back(row);
    b.emplace_back(e.value.begin(), e.value.end());
  }
  EXPECT_EQ(a.size(), n);
  (void)d;
  return solve_exactly(a, b);
}

/// The weighted normal equations (Σ w_i N_j N_k) Q = Σ w_i N_j P_i in rationals (free ends).
Rational exact_weighted_fit(const std::vector<double>& knots, int p, const std::vector<double>& t,
                            const PointArray& points, const std::vector<double>& weights) {
  const std::size_t n = knots.size() - static_cast<std::size_t>(p) - 1, d = static_cast<std::size_t>(points.dimension());
  Rational a(n, std::vector<mpq_class>(n, 0)), b(n, std::vector<mpq_class>(d, 0));
  for (std::size_t i = 0; i < t.size(); ++i) {
    const mpq_class w = weights.empty() ? mpq_class(1) : mpq_class(weights[i]);
    std::vector<mpq_class> basis(n);
    for (std::size_t j = 0; j < n; ++j) basis[j] = exact_basis(knots, static_cast<int>(j), p, t[i]);
    for (std::size_t j = 0; j < n; ++j) {
      if (basis[j] == 0) continue;
      for (std::size_t k = 0; k < n; ++k) a[j][k] += w * basis[j] * basis[k];
      for (std::size_t c = 0; c < d; ++c) b[j][c] += w * basis[j] * mpq_class(points[i][c]);
    }
  }
  return solve_exactly(a, b);
}

// --- interpolate_on_knots: exact references ----------------------------------------------

TEST(InterpolateOnKnots, CubicOnGivenKnotsIsTheExactCollocationSolution) {
  // 7 points at dyadic parameters, interior knots where no averaging puts them.
  const std::vector<double> t = {0.0, 0.5, 1.25, 2.0, 2.5, 3.5, 4.0};
  const std::vector<double> knots = {0, 0, 0, 0, 0.75, 1.5, 3.0, 4, 4, 4, 4};
  const PointArray points = points_of(2, {0, 1, 1, 3, 2.5, -1, 4, 0.5, 3, 2, 1, -2.25, 0, 0});
  const auto curve = interpolate_on_knots(points, t, 3, knots);
  ASSERT_TRUE(curve) << message_of(curve);
  EXPECT_EQ(std::vector<double>(curve->knots().begin(), curve->knots().end()), knots);
  EXPECT_LE(relative_error(curve->control_points(), exact_interpolation(knots, 3, t, points, {})), 1e-14);
}

TEST(InterpolateOnKnots, QuarticWithEndDerivativesIsTheExactCollocationSolution) {
  // Orders 1 and 3 at the start, 2 at the end: 6 points + 3 derivatives = 9 control points.
  const std::vector<double> t = {-1.0, -0.25, 0.5, 1.0, 2.25, 3.0};
  const std::vector<double> knots = {-1, -1, -1, -1, -1, -0.5, 0.25, 1.5, 2.0, 3, 3, 3, 3, 3};
  const PointArray points = points_of(1, {2, -1, 0.5, 3, 1.25, -2});
  const std::vector<EndDerivative> derivatives = {
      {false, 1, {4.0}}, {true, 2, {-3.5}}, {false, 3, {12.0}}};
  const auto curve = interpolate_on_knots(points, t, 4, knots, derivatives);
  ASSERT_TRUE(curve) << message_of(curve);
  EXPECT_LE(relative_error(curve->control_points(), exact_interpolation(knots, 4, t, points, derivatives)), 1e-13);
}

TEST(InterpolateOnKnots, UnclampedKnotsAreAllowedWhenTheParametersSpanTheDomain) {
  // Quadratic knots continued past both ends: the domain [knots[2], knots[5]] = [0, 4].
  const std::vector<double> t = {0.0, 1.5, 2.5, 3.25, 4.0};
  const std::vector<double> knots = {-2, -1, 0, 1, 2.5, 4, 5, 6};
  const PointArray points = points_of(2, {1, 0, 2, 2, -1, 1.5, 0.5, -0.5, 3, 3});
  const auto curve = interpolate_on_knots(points, t, 2, knots);
  ASSERT_TRUE(curve) << message_of(curve);
  EXPECT_LE(relative_error(curve->control_points(), exact_interpolation(knots, 2, t, points, {})), 1e-14);
}

TEST(InterpolateOnKnots, LinearInterpolationOnTheParametersIsThePolyline) {
  const std::vector<double> t = {0.0, 1.0, 3.0, 4.0};
  const PointArray points = points_of(1, {1, 5, -2, 0});
  const auto curve = interpolate_on_knots(points, t, 1, {0, 0, 1, 3, 4, 4});
  ASSERT_TRUE(curve) << message_of(curve);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(curve->control_points()[i][0], points[i][0]);
}

// --- interpolate_on_knots: errors ----------------------------------------------------------

class InterpolateOnKnotsErrors : public ::testing::Test {
 protected:
  std::vector<double> t = {0, 1, 2, 3, 4, 5, 6, 7};
  PointArray points = points_of(1, {0, 1, 0, 1, 0, 1, 0, 1});
};

TEST_F(InterpolateOnKnotsErrors, AKnotCountThatDoesNotMatchTheConditions) {
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 2, 3, 4, 7, 7, 7, 7})),
            "11 knots given, 8 points and 0 end derivatives determine 8 control points of degree 3, which need 12 "
            "knots (control points + degree + 1)");
  const std::vector<EndDerivative> one = {{false, 1, {0.0}}};
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 2, 3, 4, 5, 7, 7, 7, 7}, one)),
            "12 knots given, 8 points and 1 end derivatives determine 9 control points of degree 3, which need 13 "
            "knots (control points + degree + 1)");
  const PointArray three = points_of(1, {0, 1, 0});
  EXPECT_EQ(message_of(interpolate_on_knots(three, std::vector<double>{0.0, 1.0, 2.0}, 3, {0, 0, 0, 0, 2, 2, 2})),
            "3 points and 0 end derivatives determine 3 control points, degree 3 needs at least 4");
}

TEST_F(InterpolateOnKnotsErrors, TheSchoenbergWhitneyConditionNamesTheParameterAndTheSupport) {
  // Four interior knots crowded into (2, 3): N_3's support [0, 2.8) misses t_3 = 3.
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 2.25, 2.5, 2.625, 2.75, 7, 7, 7, 7})),
            "parameter 3 (3) is not inside the support [0, 2.75) of basis function 3: the knots and parameters "
            "violate the Schoenberg–Whitney condition, no spline on these knots interpolates them");
  // Crowded to the right: N_4's support [4.25, 7) starts after t_4 = 4.
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 4.25, 4.5, 4.75, 5, 7, 7, 7, 7})),
            "parameter 4 (4) is not inside the support [4.25, 7) of basis function 4: the knots and parameters "
            "violate the Schoenberg–Whitney condition, no spline on these knots interpolates them");
}

TEST_F(InterpolateOnKnotsErrors, DerivativesTheSplineCannotMeetLeaveASingularSystem) {
  // One cubic piece: its third derivative is constant, so the rows of
  // C'''(t_0) and C'''(t_m) are the same.
  const std::vector<EndDerivative> third = {{false, 3, {1.0}}, {true, 3, {2.0}}};
  const auto bad = interpolate_on_knots(points_of(1, {0, 1}), std::vector<double>{0.0, 1.0}, 3,
                                        {0, 0, 0, 0, 1, 1, 1, 1}, third);
  EXPECT_NE(message_of(bad).find("singular"), std::string::npos) << message_of(bad);
}

TEST_F(InterpolateOnKnotsErrors, BadKnotsAndParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 3, 2, 4, 5, 7, 7, 7, 7})),
            "knot 5 (2) is smaller than knot 4 (3), knots must be non-decreasing");
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 2, nan, 4, 5, 7, 7, 7, 7})), "knot 5 is NaN");
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {-1, -1, -1, -1, 2, 3, 4, 5, 7, 7, 7, 7})),
            "parameter 0 (0) is not knot 3 (-1), the start of the knots' domain: the parameters must run from knot 3 "
            "to knot 8");
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 2, 3, 4, 5, 8, 8, 8, 8})),
            "parameter 7 (7) is not knot 8 (8), the end of the knots' domain: the parameters must run from knot 3 to "
            "knot 8");
  std::vector<double> backwards = t;
  std::swap(backwards[2], backwards[3]);
  EXPECT_NE(message_of(interpolate_on_knots(points, backwards, 3, {0, 0, 0, 0, 2, 3, 4, 5, 7, 7, 7, 7})).find(
                "parameters must increase strictly"),
            std::string::npos);
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 0, {0, 1, 2, 3, 4, 5, 6, 7, 7})),
            "degree 0 is outside 1.." + std::to_string(tolerances::kMaxBSplineDegree) + " for B-spline interpolation");
  const std::vector<EndDerivative> high = {{true, 4, {0.0}}};
  EXPECT_EQ(message_of(interpolate_on_knots(points, t, 3, {0, 0, 0, 0, 1, 2, 3, 4, 5, 7, 7, 7, 7}, high)),
            "end derivative 0 has order 4, orders must be in 1..3 for degree 3");
}

// --- interpolate_on_knots: properties -------------------------------------------------------

RC_GTEST_PROP(InterpolateOnKnots, OnInterpolateBsplinesKnotsItIsInterpolateBspline, ()) {
  const int p = *rc::gen::inRange(1, 8);
  const std::size_t at_start = static_cast<std::size_t>(*rc::gen::inRange(0, p));  // up to p - 1
  // At most p + 1 derivatives in all (interpolate_bspline's point count check
  // assumes it).
  const std::size_t at_end = static_cast<std::size_t>(*rc::gen::inRange(0, std::min(p, p + 2 - static_cast<int>(at_start))));
  const std::size_t count = *rc::gen::inRange<std::size_t>(std::max<std::size_t>(2, p + 1), 30);
  const int d = *rc::gen::inRange(1, 4);
  std::vector<double> t(count);
  double u = *rc::gen::inRange(-50, 50);
  for (double& v : t) v = (u += *rc::gen::inRange(1, 64) / 16.0);
  std::vector<double> coordinates(count * static_cast<std::size_t>(d));
  for (double& c : coordinates) c = *rc::gen::inRange(-1000, 1000) / 64.0;
  const PointArray points = points_of(d, coordinates);
  std::vector<EndDerivative> derivatives;
  for (std::size_t k = 0; k < at_start + at_end; ++k) {
    EndDerivative e;
    e.at_end = k >= at_start;
    e.order = static_cast<int>(e.at_end ? k - at_start : k) + 1;
    e.value.assign(static_cast<std::size_t>(d), *rc::gen::inRange(-100, 100) / 8.0);
    derivatives.push_back(e);
  }
  const auto reference = interpolate_bspline(points, t, p, derivatives);
  RC_PRE(reference.has_value());
  const std::vector<double> knots(reference->knots().begin(), reference->knots().end());
  const auto curve = interpolate_on_knots(points, t, p, knots, derivatives);
  RC_ASSERT(curve.has_value());
  RC_ASSERT(*curve == *reference);  // the same system through the same solver
}

RC_GTEST_PROP(InterpolateOnKnots, ReproducesPolynomialsOfItsDegree, ()) {
  // Random clamped knots that satisfy Schoenberg–Whitney (each interior knot
  // between the sites k apart), data and end derivatives from one polynomial.
  const int p = *rc::gen::inRange(1, 6);
  const std::size_t count = *rc::gen::inRange<std::size_t>(static_cast<std::size_t>(p) + 2, 20);
  std::vector<double> t(count);
  double u = 0.0;
  for (double& v : t) v = (u += *rc::gen::inRange(1, 32) / 8.0);
  const bool with_derivatives = p >= 2 && *rc::gen::arbitrary<bool>();
  std::vector<double> sites = t;
  if (with_derivatives) {
    sites.insert(sites.begin(), t.front());
    sites.push_back(t.back());
  }
  std::vector<double> knots(static_cast<std::size_t>(p) + 1, t.front());
  for (std::size_t j = 1; j + static_cast<std::size_t>(p) < sites.size(); ++j) {
    double sum = 0.0;
    for (std::size_t i = j; i < j + static_cast<std::size_t>(p); ++i) sum += sites[i];
    const double window = sites[j + static_cast<std::size_t>(p)] - sites[j];
    const double shifted = sum / p + (*rc::gen::inRange(-10, 11) / 100.0) * window;
    knots.push_back(std::clamp(std::max(shifted, knots.back()), t.front(), t.back()));
  }
  knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, t.back());
  RC_PRE(knots[static_cast<std::size_t>(p) + 1] > t.front() &&
         knots[knots.size() - static_cast<std::size_t>(p) - 2] < t.back());
  std::vector<double> coefficients(static_cast<std::size_t>(p) + 1);
  for (double& c : coefficients) c = *rc::gen::inRange(-8, 9) / 4.0;
  const double centre = (t.front() + t.back()) / 2, half = (t.back() - t.front()) / 2;
  const auto poly = [&](double x, int order) {  // d^order/dx^order of Σ c_i ((x - centre)/half)^i
    double sum = 0.0;
    for (std::size_t i = static_cast<std::size_t>(order); i < coefficients.size(); ++i) {
      double factor = coefficients[i];
      for (int k = 0; k < order; ++k) factor *= static_cast<double>(i - static_cast<std::size_t>(k)) / half;
      sum += factor * std::pow((x - centre) / half, static_cast<double>(i) - order);
    }
    return sum;
  };
  std::vector<double> values;
  for (double x : t) values.push_back(poly(x, 0));
  std::vector<EndDerivative> derivatives;
  if (with_derivatives) {
    derivatives.push_back({false, 1, {poly(t.front(), 1)}});
    derivatives.push_back({true, std::min(2, p), {poly(t.back(), std::min(2, p))}});
  }
  const auto curve = interpolate_on_knots(points_of(1, values), t, p, knots, derivatives);
  RC_PRE(curve.has_value());  // rounding may leave a degenerate span in rare draws
  for (int i = 0; i <= 20; ++i) {
    const double x = t.front() + (t.back() - t.front()) * i / 20.0;
    RC_ASSERT(std::abs(point_at(*curve, x)[0] - poly(x, 0)) <= 1e-9 * 8.0);
  }
}

// --- fit_least_squares_on_knots -------------------------------------------------------------

TEST(FitLeastSquaresOnKnots, WeightedFitIsTheExactNormalEquationsSolution) {
  std::vector<double> t, weights, coordinates;
  for (int i = 0; i <= 24; ++i) {
    const double x = i * 0.375;
    t.push_back(x);
    weights.push_back(i % 5 == 0 ? 0.0 : 0.25 * (1 + i % 3));
    coordinates.push_back(std::round(64 * std::sin(x)) / 64);
    coordinates.push_back(std::round(64 * std::cos(0.5 * x)) / 64);
  }
  const PointArray points = points_of(2, coordinates);
  // Clamped cubic and unclamped quadratic knots.
  const std::vector<double> clamped = {0, 0, 0, 0, 1.5, 2.75, 4.5, 6.25, 9, 9, 9, 9};
  const auto fit = fit_least_squares_on_knots(points, t, 3, clamped, weights);
  ASSERT_TRUE(fit) << message_of(fit);
  EXPECT_LE(relative_error(fit->curve.control_points(), exact_weighted_fit(clamped, 3, t, points, weights)), 1e-13);
  const std::vector<double> unclamped = {-1, -0.5, 0, 2, 3.5, 5, 7.5, 9, 9.5, 10};
  const auto open = fit_least_squares_on_knots(points, t, 2, unclamped, weights);
  ASSERT_TRUE(open) << message_of(open);
  EXPECT_LE(relative_error(open->curve.control_points(), exact_weighted_fit(unclamped, 2, t, points, weights)), 1e-13);
  const auto plain = fit_least_squares_on_knots(points, t, 3, clamped);
  ASSERT_TRUE(plain) << message_of(plain);
  EXPECT_LE(relative_error(plain->curve.control_points(), exact_weighted_fit(clamped, 3, t, points, {})), 1e-13);
  // The errors are unweighted distances at every point, zero-weight ones included.
  for (std::size_t i = 0; i < t.size(); ++i)
    EXPECT_NEAR(fit->errors[i], distance(point_at(fit->curve, t[i]), points[i]), 1e-14);
}

TEST(FitLeastSquaresOnKnots, UnitWeightsOnApproximationKnotsGiveFitLeastSquares) {
  std::vector<double> t, coordinates;
  for (int i = 0; i < 40; ++i) {
    t.push_back(i * 0.25 + 0.01 * (i % 3));
    coordinates.push_back(std::sin(t.back()));
  }
  const PointArray points = points_of(1, coordinates);
  const std::vector<double> ones(40, 1.0);
  for (int p = 1; p <= 5; ++p) {
    for (const FitEnds ends : {FitEnds::free, FitEnds::interpolated}) {
      const auto reference = fit_least_squares(points, t, p, 11, ends);
      ASSERT_TRUE(reference) << message_of(reference);
      const auto fit = fit_least_squares_on_knots(points, t, p, approximation_knots(t, p, 11), ones, ends);
      ASSERT_TRUE(fit) << message_of(fit);
      EXPECT_EQ(fit->curve, reference->curve);
      EXPECT_EQ(fit->errors, reference->errors);
    }
  }
}

RC_GTEST_PROP(FitLeastSquaresOnKnots, ReproducesPolynomialsForAnyPositiveWeights, ()) {
  const int p = *rc::gen::inRange(1, 6);
  const std::size_t count = *rc::gen::inRange<std::size_t>(static_cast<std::size_t>(p) + 10, 60);
  std::vector<double> t(count), weights(count), values(count);
  double u = 0.0;
  for (double& v : t) v = (u += *rc::gen::inRange(1, 16) / 8.0);
  for (double& w : weights) w = *rc::gen::inRange(1, 100) / 10.0;
  const std::size_t control = *rc::gen::inRange<std::size_t>(static_cast<std::size_t>(p) + 1, count / 2);
  std::vector<double> coefficients(static_cast<std::size_t>(p) + 1);
  for (double& c : coefficients) c = *rc::gen::inRange(-8, 9) / 4.0;
  const double centre = (t.front() + t.back()) / 2, half = (t.back() - t.front()) / 2;
  const auto poly = [&](double x) {
    double sum = 0.0;
    for (std::size_t i = coefficients.size(); i-- > 0;) sum = sum * ((x - centre) / half) + coefficients[i];
    return sum;
  };
  for (std::size_t i = 0; i < count; ++i) values[i] = poly(t[i]);
  const auto fit = fit_least_squares_on_knots(points_of(1, values), t, p, approximation_knots(t, p, control), weights);
  RC_ASSERT(fit.has_value());
  RC_ASSERT(fit->max_error <= 1e-10 * 8.0);
}

TEST(FitLeastSquaresOnKnots, BadInputNamesTheProblem) {
  std::vector<double> t, coordinates;
  for (int i = 0; i < 30; ++i) {
    t.push_back(i / 3.0);
    coordinates.push_back(std::cos(t.back()));
  }
  const PointArray points = points_of(1, coordinates);
  const std::vector<double> knots = {0, 0, 0, 0, 5, 29.0 / 3, 29.0 / 3, 29.0 / 3, 29.0 / 3};
  // Five knots between t_15 = 5 and t_16 = 5.33...: N_4's support [5.05, 5.25) holds no point.
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3,
                                                {0, 0, 0, 0, 5.05, 5.1, 5.15, 5.2, 5.25, 29.0 / 3, 29.0 / 3, 29.0 / 3,
                                                 29.0 / 3})),
            "no point is left for basis function 4 (support [5.05, 5.25)): the knots and "
            "parameters violate the Schoenberg–Whitney condition, the fit's normal equations are singular");
  // Zero weights on the right half leave the last basis function without a point.
  std::vector<double> half(30, 1.0);
  std::fill(half.begin() + 15, half.end(), 0.0);
  EXPECT_NE(message_of(fit_least_squares_on_knots(points, t, 3, knots, half)).find("Schoenberg"), std::string::npos);
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, knots, std::vector<double>(29, 1.0))),
            "29 weights for 30 points, a weighted fit needs one weight per point");
  std::vector<double> negative(30, 1.0);
  negative[3] = -1.0;
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, knots, negative)),
            "weight 3 is -1, weights must be >= 0");
  negative[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, knots, negative)), "weight 3 is NaN");
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, {1, 1, 1, 1, 5, 10, 10, 10, 10})),
            "parameter 0 (0) is outside the knots' domain [1, 10]");
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, {0, 0, 0, 0, 6, 5, 10, 10, 10, 10})),
            "knot 5 (5) is smaller than knot 4 (6), knots must be non-decreasing");
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, {0, 0, 0, 0, std::nan(""), 10, 10, 10, 10})),
            "knot 4 is NaN");
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, {0, 10})),
            "2 knots given, a B-spline of degree 3 needs at least 8 (degree + 1 control points)");
  EXPECT_EQ(message_of(fit_least_squares_on_knots(points, t, 3, {-1, 0, 0, 0, 5, 29.0 / 3, 29.0 / 3, 29.0 / 3, 29.0 / 3},
                                                {}, FitEnds::interpolated)),
            "a fit with interpolated ends needs knots clamped at the first and last parameters (0 and "
            "9.666666666666666, degree + 1 = 4 copies each)");
}

}  // namespace
}  // namespace casteljau

// Derivative and antiderivative curves and the integral of B-spline curves
// against exact rational references (tests/support/exact_basis.hpp): the
// exact derivatives of the curve, and the exact integral of its polynomial
// pieces (each piece recovered exactly from p+1 dyadic samples).
#include "casteljau/bspline/hodograph.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/core/tolerance.hpp"
#include "support/bspline_generators.hpp"
#include "support/exact.hpp"
#include "support/exact_basis.hpp"
#include "support/exact_bspline.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// The exact integral of the curve's full B-spline sum Σ_j P_j N_{j,p}(s)
/// (basis functions of the whole knot vector, zero outside [t_0, t_{n+p+1}])
/// from t_0 to u, u inside [t_0, t_{n+p+1}]. Each non-empty span's
/// polynomial is sampled exactly at p+1 interior dyadic points, its monomial
/// coefficients solved for in rationals and integrated exactly.
std::vector<mpq_class> exact_integral_from_first_knot(const BSplineCurve& curve, double u) {
  const auto t = curve.knots();
  const int p = curve.degree(), d = curve.dimension();
  int shift = 0;
  while ((1 << shift) < p + 2) ++shift;
  std::vector<mpq_class> total(static_cast<std::size_t>(d), 0);
  const mpq_class upper_limit(u);
  for (std::size_t i = 0; i + 1 < t.size() && t[i] < u; ++i) {
    if (t[i] == t[i + 1]) continue;
    const double h = (t[i + 1] - t[i]) / (1 << shift);  // exact: dyadic knots
    std::vector<mpq_class> nodes;
    std::vector<std::vector<mpq_class>> values;
    for (int j = 0; j <= p; ++j) {
      const double x = t[i] + (j + 1) * h;  // strictly inside the span
      nodes.emplace_back(x);
      // The full sum, not the curve's point (no division by the basis sum).
      std::vector<mpq_class> value(static_cast<std::size_t>(d), 0);
      for (std::size_t k = 0; k < curve.control_points().size(); ++k) {
        const mpq_class n = test::exact_basis(t, static_cast<int>(k), p, x);
        if (n == 0) continue;
        for (int c = 0; c < d; ++c) value[c] += n * mpq_class(curve.control_points()[k][c]);
      }
      values.push_back(value);
    }
    // Vandermonde system V a = values, Gauss–Jordan in rationals.
    const std::size_t m = nodes.size();
    std::vector<std::vector<mpq_class>> rows(m);
    for (std::size_t r = 0; r < m; ++r) {
      mpq_class power = 1;
      for (std::size_t k = 0; k < m; ++k) { rows[r].push_back(power); power *= nodes[r]; }
      for (int c = 0; c < d; ++c) rows[r].push_back(values[r][c]);
    }
    for (std::size_t col = 0; col < m; ++col) {
      std::size_t pivot = col;
      while (rows[pivot][col] == 0) ++pivot;
      std::swap(rows[pivot], rows[col]);
      for (std::size_t r = 0; r < m; ++r) {
        if (r == col || rows[r][col] == 0) continue;
        const mpq_class factor = rows[r][col] / rows[col][col];
        for (std::size_t k = col; k < rows[r].size(); ++k) rows[r][k] -= factor * rows[col][k];
      }
    }
    const mpq_class lower(t[i]);
    const mpq_class upper = u < t[i + 1] ? upper_limit : mpq_class(t[i + 1]);
    mpq_class lower_power = lower, upper_power = upper;
    for (std::size_t k = 0; k < m; ++k) {
      const mpq_class moment = (upper_power - lower_power) / static_cast<long>(k + 1);
      for (int c = 0; c < d; ++c) total[c] += rows[k][m + static_cast<std::size_t>(c)] / rows[k][k] * moment;
      upper_power *= upper;
      lower_power *= lower;
    }
  }
  return total;
}

double largest_control_coordinate(const BSplineCurve& curve) {
  return std::max(1.0, scale_of(curve.control_points()));
}

RC_GTEST_PROP(DerivativeCurve, EqualsTheExactDerivative, ()) {
  const auto curve = *test::bspline_curve({.max_degree = 6, .rational = test::Rational::never});
  const int k = *rc::gen::inRange(1, 4);
  const BSplineCurve derivative = derivative_curve(curve, k).value();
  RC_ASSERT(derivative.domain() == curve.domain());
  RC_ASSERT(derivative.degree() == std::max(0, curve.degree() - k));
  // The computed control points are exact up to a few roundings each, and
  // C^(k)(u) is a convex combination of them.
  const double tolerance = 1e-13 * k * largest_control_coordinate(derivative);
  for (int sample = 0; sample < 4; ++sample) {
    const double u = *test::parameter_in(curve);
    const auto exact = test::exact_bspline_derivative(curve, u, k);
    const auto computed = test::exact_bspline_point(derivative, u);
    for (int c = 0; c < curve.dimension(); ++c)
      RC_ASSERT(test::error_of(computed[c].get_d(), exact[c]) <= tolerance);
  }
  // Outside the domain both continue the end pieces.
  for (const double u : {curve.domain().lower - 0.25, curve.domain().upper + 0.25}) {
    const Point direct = derivative_at(curve, u, k);
    const Point via_curve = point_at(derivative, u);
    RC_ASSERT(distance(direct, via_curve) <= 1e-10 * std::max(1.0, scale_of(derivative.control_points())));
  }
}

// The exact hodograph of the test support (the W1/W2 benchmark's reference
// for derivatives) against the exact basis derivatives: two exact routes.
RC_GTEST_PROP(ExactHodograph, EqualsTheExactBasisDerivatives, ()) {
  const auto curve = *test::bspline_curve({.max_degree = 6, .rational = test::Rational::never});
  RC_PRE(curve.degree() >= 1);
  const test::ExactBSpline hodograph = test::ExactBSpline::of(curve).derivative();
  for (int sample = 0; sample < 4; ++sample) {
    const double u = *test::parameter_in(curve);
    RC_ASSERT(hodograph.point_at(mpq_class(u)) == test::exact_bspline_derivative(curve, u, 1));
  }
}

RC_GTEST_PROP(AntiderivativeCurve, IsTheExactIntegralFromTheFirstKnot, ()) {
  const auto curve =
      *test::bspline_curve({.max_degree = 5, .max_extra_points = 6, .rational = test::Rational::never});
  const BSplineCurve antiderivative = antiderivative_curve(curve).value();
  RC_ASSERT(antiderivative.degree() == curve.degree() + 1);
  RC_ASSERT(antiderivative.domain() == curve.domain());
  RC_ASSERT(antiderivative.control_points().size() == curve.control_points().size() + 1);
  const auto t = curve.knots();
  // Cumulative sums of size at most scale * (t_last - t_0), a few roundings each.
  const double tolerance = 1e-14 * t.size() * largest_control_coordinate(curve) * std::max(1.0, t.back() - t.front());
  for (int sample = 0; sample < 3; ++sample) {
    const double u = *test::parameter_in(curve);
    const auto exact = exact_integral_from_first_knot(curve, u);
    const auto computed = test::exact_bspline_point(antiderivative, u);
    const Point evaluated = point_at(antiderivative, u);
    for (int c = 0; c < curve.dimension(); ++c) {
      RC_ASSERT(test::error_of(computed[c].get_d(), exact[c]) <= tolerance);
      RC_ASSERT(test::error_of(evaluated[c], exact[c]) <= 4 * tolerance);
    }
  }
}

RC_GTEST_PROP(AntiderivativeCurve, ItsDerivativeIsTheCurve, ()) {
  const auto curve = *test::bspline_curve({.max_degree = 6, .rational = test::Rational::never, .allow_jumps = true});
  const int k = *rc::gen::inRange(1, 3);
  const BSplineCurve back = derivative_curve(antiderivative_curve(curve, k).value(), k).value();
  RC_ASSERT(back.degree() == curve.degree());
  RC_ASSERT(std::equal(back.knots().begin(), back.knots().end(), curve.knots().begin(), curve.knots().end()));
  const auto t = curve.knots();
  double narrowest = t.back() - t.front();
  for (std::size_t i = 0; i + static_cast<std::size_t>(curve.degree()) + 1 < t.size(); ++i)
    narrowest = std::min(narrowest, t[i + static_cast<std::size_t>(curve.degree()) + 1] - t[i]);
  // Differences of cumulative sums, divided by a knot span.
  const double tolerance = 1e-13 * largest_control_coordinate(curve) * (curve.degree() + k) * (t.back() - t.front()) /
                           narrowest * std::pow(16.0, k - 1);
  for (std::size_t i = 0; i < curve.control_points().size(); ++i)
    RC_ASSERT(distance(back.control_points()[i], curve.control_points()[i]) <= tolerance);
}

RC_GTEST_PROP(Integral, IsAdditiveAndChangesSignWithItsLimits, ()) {
  const auto curve = *test::bspline_curve({.max_degree = 6, .rational = test::Rational::never});
  const double a = *test::parameter_in(curve), b = *test::parameter_in(curve), c = *test::parameter_in(curve);
  const Point ab = integral(curve, a, b).value(), bc = integral(curve, b, c).value(), ac = integral(curve, a, c).value();
  const Point ba = integral(curve, b, a).value();
  const auto t = curve.knots();
  const double tolerance = 1e-13 * largest_control_coordinate(curve) * std::max(1.0, t.back() - t.front());
  for (int k = 0; k < curve.dimension(); ++k) {
    RC_ASSERT(std::abs(ab[k] + bc[k] - ac[k]) <= tolerance);
    RC_ASSERT(ab[k] == -ba[k]);
  }
  const Point empty = integral(curve, a, a).value();
  for (double v : empty) RC_ASSERT(v == 0.0);
}

TEST(Integral, EqualsTheExactIntegralOverTheDomain) {
  // Clamped: ∫_{t_p}^u C is the full sum's integral from t_0 = t_p.
  const BSplineCurve curve = test::book_example_5_1();
  for (const auto& [a, b] : std::vector<std::pair<double, double>>{{0, 5}, {0.5, 3.25}, {1, 2}, {4.125, 4.875}}) {
    const auto from_a = exact_integral_from_first_knot(curve, a);
    const auto from_b = exact_integral_from_first_knot(curve, b);
    const Point computed = integral(curve, a, b).value();
    for (int c = 0; c < 2; ++c) EXPECT_LE(test::error_of(computed[c], from_b[c] - from_a[c]), 1e-13) << a << " " << b;
  }
}

TEST(Integral, OfAPolylineIsTheTrapezoidSum) {
  const auto line = BSplineCurve::make(1, {0, 0, 1, 2, 2}, PointArray::make({{0, 0}, {2, 4}, {6, 0}}).value()).value();
  EXPECT_EQ(integral(line, 0, 2).value(), (Point{5, 4}));   // (0+2)/2 + (2+6)/2, (0+4)/2 + (4+0)/2
  EXPECT_EQ(integral(line, 2, 0).value(), (Point{-5, -4}));
  // Outside the domain the end segments continue: ∫_{-1}^0 (2u, 4u) du = (-1, -2).
  EXPECT_EQ(integral(line, -1, 0).value(), (Point{-1, -2}));
}

TEST(DerivativeCurve, OfAPolylineIsItsSegmentsSlopes) {
  const auto line = BSplineCurve::make(1, {0, 0, 1, 3, 3}, PointArray::make({{0, 0}, {2, 4}, {6, 0}}).value()).value();
  const BSplineCurve slopes = derivative_curve(line).value();
  EXPECT_EQ(slopes.degree(), 0);
  EXPECT_EQ(std::vector<double>(slopes.knots().begin(), slopes.knots().end()), (std::vector<double>{0, 1, 3}));
  EXPECT_EQ(slopes.control_points(), PointArray::make({{2, 4}, {2, -2}}).value());
}

TEST(DerivativeCurve, DropsTheKnotsOfEmptyBasisFunctions) {
  // Degree 2 with a triple knot at 1: the curve jumps there. t_1..t_7 has
  // the triple knot, too many for degree 1: one copy and one (identically
  // zero) control point go, and the pieces' derivatives remain.
  const auto curve = BSplineCurve::make(2, {0, 0, 0, 1, 1, 1, 2, 2, 2},
                                        PointArray::make({{0, 0}, {1, 2}, {2, 1}, {5, 5}, {6, 3}, {8, 8}}).value())
                         .value();
  const BSplineCurve derivative = derivative_curve(curve).value();
  EXPECT_EQ(std::vector<double>(derivative.knots().begin(), derivative.knots().end()),
            (std::vector<double>{0, 0, 1, 1, 2, 2}));
  ASSERT_EQ(derivative.control_points().size(), 4u);
  for (const double u : {0.0, 0.25, 0.999, 1.0, 1.5, 2.0}) {
    const auto exact = test::exact_bspline_derivative(curve, u, 1);
    const Point computed = point_at(derivative, u);
    for (int c = 0; c < 2; ++c) EXPECT_LE(test::error_of(computed[c], exact[c]), 1e-14) << u;
  }
  // The antiderivative is continuous across the jump.
  const BSplineCurve antiderivative = antiderivative_curve(curve).value();
  EXPECT_LE(distance(point_at(antiderivative, 1.0), point_at(antiderivative, std::nextafter(1.0, 0.0))), 1e-14 * 16);
}

TEST(DerivativeCurve, AboveTheDegreeIsTheZeroCurveAndOrderZeroTheCurve) {
  const BSplineCurve curve = test::book_example_5_1();
  const BSplineCurve zero = derivative_curve(curve, 4).value();
  EXPECT_EQ(zero.degree(), 0);
  EXPECT_EQ(zero.domain(), curve.domain());
  EXPECT_EQ(zero.control_points(), PointArray::zeros(2, 1));
  EXPECT_EQ(derivative_curve(curve, 0).value(), curve);
  EXPECT_EQ(antiderivative_curve(curve, 0).value(), curve);
  // The third derivative is piecewise constant: degree 0 on t_3 .. t_8.
  const BSplineCurve third = derivative_curve(curve, 3).value();
  EXPECT_EQ(std::vector<double>(third.knots().begin(), third.knots().end()), (std::vector<double>{0, 1, 2, 3, 4, 5}));
}

TEST(DerivativeCurve, RefusesRationalCurvesAndNegativeOrders) {
  const auto nurbs = BSplineCurve::make(2, {0, 0, 0, 1, 1, 1}, PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(),
                                        {1, std::sqrt(0.5), 1})
                         .value();
  for (const auto& result : {derivative_curve(nurbs), antiderivative_curve(nurbs)}) {
    ASSERT_FALSE(result);
    EXPECT_NE(result.error().message.find("rational"), std::string::npos) << result.error().message;
  }
  EXPECT_FALSE(integral(nurbs, 0, 1));
  const BSplineCurve curve = test::book_example_5_1();
  EXPECT_FALSE(derivative_curve(curve, -1));
  EXPECT_FALSE(antiderivative_curve(curve, -2));
  EXPECT_FALSE(integral(curve, 0, std::nan("")));
  EXPECT_FALSE(integral(curve, -INFINITY, 1));
  EXPECT_FALSE(antiderivative_curve(curve, tolerances::kMaxBSplineDegree));
}

}  // namespace
}  // namespace casteljau

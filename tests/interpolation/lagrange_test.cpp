// Barycentric Lagrange interpolation against the Lagrange formula in exact
// rational arithmetic, polynomial reproduction, the weights' closed forms
// (Berrut & Trefethen 2004 §5), Runge's function on equispaced and
// Chebyshev nodes (scipy's numbers and the theory), the Bézier conversion.
#include "casteljau/interpolation/lagrange.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/interpolation/tolerance.hpp"
#include "support/exact.hpp"

namespace casteljau {
namespace {

/// Σ_j f_j Π_{k≠j} (t − x_k)/(x_j − x_k) (coordinate k of the values), exactly.
mpq_class exact_lagrange(std::span<const double> nodes, const PointArray& values, int k, double t) {
  mpq_class sum = 0;
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    mpq_class term(values[j][static_cast<std::size_t>(k)]);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (i != j) term *= (mpq_class(t) - mpq_class(nodes[i])) / (mpq_class(nodes[j]) - mpq_class(nodes[i]));
    sum += term;
  }
  return sum;
}

/// Strictly increasing dyadic nodes k/16 with steps 1/16..1/2, starting in [−1, 0].
rc::Gen<std::vector<double>> dyadic_nodes(int count) {
  return rc::gen::exec([count] {
    std::vector<double> nodes{*rc::gen::inRange(-16, 1) / 16.0};
    for (int i = 1; i < count; ++i) nodes.push_back(nodes.back() + *rc::gen::inRange(1, 9) / 16.0);
    return nodes;
  });
}

RC_GTEST_PROP(Lagrange, BarycentricEqualsTheExactLagrangeFormula, ()) {
  const int count = *rc::gen::inRange(2, 9);
  const int d = *rc::gen::inRange(1, 4);
  const auto nodes = *dyadic_nodes(count);
  const auto coordinates = *rc::gen::container<std::vector<double>>(
      static_cast<std::size_t>(count * d), rc::gen::map(rc::gen::inRange(-100000, 100001), [](int i) { return i * 1e-3; }));
  const PointArray values = PointArray::make(d, coordinates).value();
  const auto interpolant = interpolate_lagrange(values, nodes).value();
  const double scale = std::max(1.0, scale_of(values));
  for (int j = 0; j <= 16; ++j) {
    const double t = nodes.front() + (nodes.back() - nodes.front()) * j / 16.0;
    const Point p = point_at(interpolant, t);
    for (int k = 0; k < d; ++k) {
      const mpq_class exact = exact_lagrange(nodes, values, k, t);
      RC_ASSERT(test::error_of(p[k], exact) <= 1e-13 * std::max(scale, std::abs(exact.get_d())));
    }
  }
}

/// A polynomial with coefficients i/8 and degree <= 6: at nodes k/16 in
/// [−2, 2] its values are exact doubles (numerators below 2^40).
struct ExactPolynomial {
  std::vector<double> coefficients;
  mpq_class operator()(const mpq_class& t) const {
    mpq_class value = 0;
    for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it) value = value * t + *it;
    return value;
  }
};

RC_GTEST_PROP(Lagrange, ReproducesPolynomialsExactlyUpToRounding, ()) {
  const int degree = *rc::gen::inRange(0, 7);
  const int count = degree + 1 + *rc::gen::inRange(0, 3);
  ExactPolynomial polynomial{*rc::gen::container<std::vector<double>>(
      static_cast<std::size_t>(degree) + 1, rc::gen::map(rc::gen::inRange(-32, 33), [](int i) { return i / 8.0; }))};
  const auto nodes = *dyadic_nodes(std::max(count, 2));
  std::vector<double> values;
  for (double x : nodes) {
    values.push_back(polynomial(mpq_class(x)).get_d());
    RC_ASSERT(mpq_class(values.back()) == polynomial(mpq_class(x)));  // the data are exact
  }
  const PointArray points = PointArray::make(1, values).value();
  const auto interpolant = interpolate_lagrange(points, nodes).value();
  const auto bezier = to_bezier(interpolant).value();
  const double scale = std::max(1.0, scale_of(points));
  for (int j = 0; j <= 32; ++j) {
    const double s = j / 32.0;
    const double t = nodes.front() + (nodes.back() - nodes.front()) * s;
    const mpq_class exact = polynomial(mpq_class(t));
    RC_ASSERT(test::error_of(point_at(interpolant, t)[0], exact) <= 1e-13 * scale);
    // The Bézier form, at the same s (t − t_0 = s (t_n − t_0) exactly here).
    RC_ASSERT(test::error_of(point_at(bezier, s)[0], exact) <= 1e-12 * scale);
  }
}

TEST(Lagrange, ReproducesPolynomialsOnChebyshevNodes) {
  const ExactPolynomial polynomial{{0.5, -1.25, 3, 0.125, -2, 0.75}};  // degree 5
  for (std::size_t count : {6u, 11u, 21u}) {
    const auto nodes = chebyshev_parameters(count, {-2, 3}).value();
    std::vector<double> values;
    for (double x : nodes) values.push_back(polynomial(mpq_class(x)).get_d());
    const auto interpolant = interpolate_lagrange(PointArray::make(1, values).value(), nodes).value();
    // The closed-form weights (−1)^j δ_j were chosen.
    EXPECT_EQ(interpolant.weights.front(), 0.5);
    EXPECT_EQ(interpolant.weights[1], -1.0);
    EXPECT_EQ(std::abs(interpolant.weights.back()), 0.5);
    const double scale = scale_of(PointArray::make(1, values).value());
    for (int j = 0; j <= 50; ++j) {
      const double t = -2 + 5 * j / 50.0;
      EXPECT_LE(test::error_of(point_at(interpolant, t)[0], polynomial(mpq_class(t))), 1e-13 * scale)
          << count << " nodes, t " << t;
    }
  }
}

TEST(Lagrange, ProductWeightsMatchTheEquispacedClosedFormWithoutOverflow) {
  // Equispaced nodes: w_j ∝ (−1)^j C(n, j) (Berrut & Trefethen eq. 5.1). At
  // n = 1000 the plain products reach 1e-2000 and underflow; the scaled
  // weights are (−1)^(j − n/2) C(n, j) / C(n, n/2).
  const int n = 1000;
  std::vector<double> nodes(n + 1);
  for (int j = 0; j <= n; ++j) nodes[static_cast<std::size_t>(j)] = j;  // exact, spacing 1
  const auto interpolant = interpolate_lagrange(PointArray::zeros(1, n + 1), nodes).value();
  for (int j = 0; j <= n; ++j) {
    const double log_ratio = std::lgamma(n + 1.0) - std::lgamma(j + 1.0) - std::lgamma(n - j + 1.0) -
                             (std::lgamma(n + 1.0) - 2 * std::lgamma(n / 2 + 1.0));
    const double expected = ((j - n / 2) % 2 == 0 ? 1.0 : -1.0) * std::exp(log_ratio);
    EXPECT_NEAR(interpolant.weights[static_cast<std::size_t>(j)], expected, 1e-10 * std::abs(expected) + 1e-300)
        << "j = " << j;
  }
}

TEST(Lagrange, ExactAtTheNodesAndBatchEqualsScalar) {
  const auto nodes = chebyshev_parameters(9, {0, 4}).value();
  std::vector<double> coordinates;
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    coordinates.push_back(std::sin(nodes[j]));
    coordinates.push_back(std::cos(3 * nodes[j]) + 0.1 * static_cast<double>(j));
  }
  const PointArray values = PointArray::make(2, coordinates).value();
  const auto interpolant = interpolate_lagrange(values, nodes).value();
  EXPECT_EQ(interpolant.domain(), (Interval{0, 4}));
  std::vector<double> ts(nodes);
  for (int j = 0; j <= 40; ++j) ts.push_back(4.0 * j / 40.0 - 0.25);  // a little outside too
  std::vector<double> out(ts.size() * 2);
  points_at(interpolant, ts, out);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Point p = point_at(interpolant, ts[i]);
    EXPECT_EQ(p[0], out[2 * i]);
    EXPECT_EQ(p[1], out[2 * i + 1]);
    if (i < nodes.size()) {
      EXPECT_EQ(p[0], values[i][0]);
      EXPECT_EQ(p[1], values[i][1]);
    }
  }
  // Next to a node the value tends to the node's value.
  const Point near = point_at(interpolant, std::nextafter(nodes[3], 10.0));
  EXPECT_NEAR(near[0], values[3][0], 1e-13);
}

TEST(Lagrange, ChebyshevParametersAreSymmetricWithExactEnds) {
  const auto unit = chebyshev_parameters(21, {-1, 1}).value();
  ASSERT_EQ(unit.size(), 21u);
  for (int j = 0; j <= 20; ++j) {
    EXPECT_NEAR(unit[static_cast<std::size_t>(j)], -std::cos(j * std::numbers::pi / 20), 1e-15);
    EXPECT_EQ(unit[static_cast<std::size_t>(j)], -unit[static_cast<std::size_t>(20 - j)]);
  }
  const auto shifted = chebyshev_parameters(7, {2, 5}).value();
  EXPECT_EQ(shifted.front(), 2.0);
  EXPECT_EQ(shifted.back(), 5.0);
  EXPECT_EQ(shifted[3], 3.5);
  EXPECT_TRUE(std::is_sorted(shifted.begin(), shifted.end()));
}

double runge(double x) { return 1.0 / (1.0 + 25.0 * x * x); }

/// max |p(x) − f(x)| over 20001 equispaced x in [−1, 1].
double runge_error(const std::vector<double>& nodes) {
  std::vector<double> values;
  for (double x : nodes) values.push_back(runge(x));
  const auto interpolant = interpolate_lagrange(PointArray::make(1, values).value(), nodes).value();
  std::vector<double> xs(20001), ps(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = -1.0 + static_cast<double>(i) * (2.0 / 20000.0);
  xs.back() = 1.0;
  points_at(interpolant, xs, ps);
  double error = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) error = std::max(error, std::abs(ps[i] - runge(xs[i])));
  return error;
}

std::vector<double> equispaced(int n) {
  std::vector<double> nodes(static_cast<std::size_t>(n) + 1);
  for (int j = 0; j <= n; ++j) nodes[static_cast<std::size_t>(j)] = -1.0 + j * (2.0 / n);
  nodes.back() = 1.0;
  return nodes;
}

// Runge's example (seed 001 problem P1). Reference: scipy 1.10.1
// BarycentricInterpolator on numpy.linspace(-1, 1, n+1) and -cos(pi j/n),
// max error on numpy.linspace(-1, 1, 20001):
//   n             10         20          30          40
//   equispaced    1.91566    59.8223     2388.28     104667.7
//   Chebyshev     0.132197   0.0177378   0.00242579  0.000339877
// Theory (Trefethen, ATAP ch. 8): on Chebyshev points the error decays like
// ρ^(−n), ρ = 1/5 + √(1 + 1/25) ≈ 1.2198 (the Bernstein ellipse through the
// poles ±i/5), so each 10 more nodes divide it by ρ^10 ≈ 7.29.
TEST(Lagrange, RungeGrowsOnEquispacedNodesAndDecaysOnChebyshevNodes) {
  const double equispaced_reference[] = {1.9156588027848283, 59.82230871075007, 2388.2809716157244,
                                         104667.73403802408};
  const double chebyshev_reference[] = {0.13219742331070383, 0.017737824286446824, 0.002425789426788727,
                                        0.00033987749989372595};
  const double rho = 0.2 + std::sqrt(1.04);
  double previous_equispaced = 0, previous_chebyshev = 0;
  for (int i = 0; i < 4; ++i) {
    const int n = 10 * (i + 1);
    const double e = runge_error(equispaced(n));
    const double c = runge_error(chebyshev_parameters(static_cast<std::size_t>(n) + 1, {-1, 1}).value());
    // Equispaced interpolation has a condition number near the Lebesgue
    // constant (1e10 at n = 40): two correct programs differ by ~1e-6 there.
    EXPECT_NEAR(e, equispaced_reference[i], 1e-5 * equispaced_reference[i]) << "n = " << n;
    EXPECT_NEAR(c, chebyshev_reference[i], 1e-6 * chebyshev_reference[i]) << "n = " << n;
    if (i > 0) {
      EXPECT_GT(e, 10 * previous_equispaced) << "n = " << n;
      const double decay = c / previous_chebyshev;
      EXPECT_GT(decay, 0.5 * std::pow(rho, -10)) << "n = " << n;
      EXPECT_LT(decay, 2.0 * std::pow(rho, -10)) << "n = " << n;
    }
    previous_equispaced = e;
    previous_chebyshev = c;
  }
  EXPECT_LT(previous_chebyshev, 5e-4);  // n = 40
}

/// max |Bézier(s) − p(t)| over 401 points, relative to max |p(t)| there.
double bezier_conversion_error(const BarycentricInterpolant& interpolant) {
  const auto bezier = to_bezier(interpolant).value();
  const Interval domain = interpolant.domain();
  double error = 0, size = 0;
  for (int j = 0; j <= 400; ++j) {
    const double s = j / 400.0;
    const double p = point_at(interpolant, domain.lerp(s))[0];
    error = std::max(error, std::abs(point_at(bezier, s)[0] - p));
    size = std::max(size, std::abs(p));
  }
  return error / size;
}

// The measurements quoted in lagrange.hpp and tolerance.hpp.
TEST(Lagrange, BezierConversionConditioning) {
  // Measured (g++ 12, x86-64): Chebyshev 2.7e-15, 3.3e-13, 3.0e-11, 4.6e-9;
  // equispaced 8.7e-15, 4.9e-13, 4.3e-10, 2.5e-7 (n = 10, 20, 30, 40).
  const double chebyshev_bound[] = {1e-14, 1e-12, 1e-10, 1e-8};
  const double equispaced_bound[] = {1e-13, 1e-11, 1e-8, 1e-5};
  for (int i = 0; i < 4; ++i) {
    const int n = 10 * (i + 1);
    if (n > tolerances::kMaxLagrangeBezierDegree) break;
    const auto nodes = chebyshev_parameters(static_cast<std::size_t>(n) + 1, {-1, 1}).value();
    std::vector<double> values;
    for (double x : nodes) values.push_back(runge(x));
    const auto interpolant = interpolate_lagrange(PointArray::make(1, values).value(), nodes).value();
    const double error = bezier_conversion_error(interpolant);
    std::printf("Runge, Chebyshev n = %d: Bézier conversion error %.3g\n", n, error);
    EXPECT_LT(error, chebyshev_bound[i]) << "n = " << n;
    std::vector<double> uniform_values;
    for (double x : equispaced(n)) uniform_values.push_back(runge(x));
    const double uniform_error =
        bezier_conversion_error(interpolate_lagrange(PointArray::make(1, uniform_values).value(), equispaced(n)).value());
    std::printf("Runge, equispaced n = %d: Bézier conversion error %.3g\n", n, uniform_error);
    EXPECT_LT(uniform_error, equispaced_bound[i]) << "n = " << n;
  }
  const auto nodes = chebyshev_parameters(tolerances::kMaxLagrangeBezierDegree + 2, {-1, 1}).value();
  const auto too_high = to_bezier(interpolate_lagrange(PointArray::zeros(1, nodes.size()), nodes).value());
  ASSERT_FALSE(too_high);
  EXPECT_NE(too_high.error().message.find("refused above degree"), std::string::npos) << too_high.error().message;
}

TEST(Lagrange, RefusesBadInput) {
  const PointArray three = PointArray::make(2, {0, 0, 1, 0, 1, 1}).value();
  auto e = interpolate_lagrange(PointArray::make(2, {0, 0}).value(), std::vector<double>{0});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "Lagrange interpolation needs at least 2 points, got 1");
  // One point more than the highest degree allows: a limit, named with the degree.
  const std::size_t too_many = static_cast<std::size_t>(tolerances::kMaxLagrangeDegree) + 2;
  std::vector<double> many(too_many);
  for (std::size_t i = 0; i < too_many; ++i) many[i] = static_cast<double>(i);
  e = interpolate_lagrange(PointArray::make(1, many).value(), many);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().kind, ErrorKind::limit);
  EXPECT_EQ(e.error().message, "Lagrange interpolation of " + std::to_string(too_many) +
                                   " points is above the limit of " + std::to_string(too_many - 1) + " (degree " +
                                   std::to_string(tolerances::kMaxLagrangeDegree) + ")");
  e = interpolate_lagrange(three, std::vector<double>{0, 1});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "Lagrange interpolation needs one parameter per point: 3 points, 2 parameters");
  e = interpolate_lagrange(three, std::vector<double>{0, 1, 1});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message,
            "parameters must increase strictly: parameter 2 is 1, parameter 1 is 1");
  e = interpolate_lagrange(three, std::vector<double>{0, std::nan(""), 1});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "parameter 1 is NaN");
  e = interpolate_lagrange(PointArray::from_trusted(2, {0, 0, 1, 0, 1, std::nan("")}), std::vector<double>{0, 1, 2});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "coordinate 1 of point 2 is NaN");
  e = interpolate_lagrange(PointArray::make(1, {0, 1}).value(), std::vector<double>{-1e308, 1e308});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "parameter 0 is -1e+308, outside [-1e+100, 1e+100], the range of knots");
  auto c = chebyshev_parameters(1);
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().message, "Chebyshev parameters need a count of at least 2, got 1");
  c = chebyshev_parameters(5, {1, 1});
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().message, "Chebyshev parameters need a finite interval with lower < upper, got [1, 1]");
  EXPECT_FALSE(chebyshev_parameters(5, {0, std::numeric_limits<double>::infinity()}));
  EXPECT_FALSE(chebyshev_parameters(static_cast<std::size_t>(tolerances::kMaxLagrangeDegree) + 2));
}

}  // namespace
}  // namespace casteljau

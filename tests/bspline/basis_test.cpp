// Basis functions against the Cox–de Boor definition in exact rational
// arithmetic, the span search at the ends, and partition of unity.
#include <gtest/gtest.h>
#include <gmpxx.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "../support/exact_basis.hpp"

namespace casteljau {
namespace {

using test::exact_basis;

TEST(FindSpan, IsRightAtTheEndsAndAtRepeatedKnots) {
  const std::vector<double> knots{0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1};  // p = 3, n = 6
  EXPECT_EQ(find_span(knots, 3, 0.0), 3);
  EXPECT_EQ(find_span(knots, 3, 0.1), 3);
  EXPECT_EQ(find_span(knots, 3, 0.25), 4);
  EXPECT_EQ(find_span(knots, 3, 0.5), 6);  // the non-empty span after the double knot
  EXPECT_EQ(find_span(knots, 3, 0.75), 6);
  // The classic bug: u = 1 must give span 6 (not 7..10, where every N is 0).
  EXPECT_EQ(find_span(knots, 3, 1.0), 6);
  // Outside the domain: the end spans (extrapolation), NaN included.
  EXPECT_EQ(find_span(knots, 3, -5.0), 3);
  EXPECT_EQ(find_span(knots, 3, 7.0), 6);
  EXPECT_EQ(find_span(knots, 3, std::nan("")), 3);
}

TEST(FindSpan, SpansOfOneUlpAreOrdinarySpans) {
  const double a = 0.3;
  const double b = std::nextafter(a, 1.0);
  const std::vector<double> knots{0, 0, 0, a, b, 1, 1, 1};  // p = 2, n = 4
  EXPECT_EQ(find_span(knots, 2, a), 3);
  EXPECT_EQ(find_span(knots, 2, b), 4);
  std::vector<double> values(3);
  for (double u : {a, b, std::nextafter(a, 0.0)}) {
    basis_functions(knots, 2, find_span(knots, 2, u), u, values);
    double sum = 0;
    for (double v : values) {
      EXPECT_TRUE(std::isfinite(v));
      EXPECT_GE(v, 0.0);
      sum += v;
    }
    EXPECT_NEAR(sum, 1.0, 4e-16);
  }
}

TEST(BasisFunctions, EqualTheExactRecursion) {
  // Degrees 0..5 on knots with a repeated interior knot, at sample points,
  // knots and both ends, against exact rationals.
  const std::vector<std::vector<double>> vectors{
      {0, 1, 2, 3, 4, 5, 6, 7, 8, 9},
      {0, 0, 0, 0.1, 0.35, 0.35, 0.6, 1, 1, 1},
      {-2, -2, -2, -2, -1.5, -0.25, -0.25, -0.25, 1, 3, 3, 3, 3},
      {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1},
  };
  for (const auto& knots : vectors) {
    for (int p = 0; p <= 5; ++p) {
      const int n = static_cast<int>(knots.size()) - p - 2;
      if (n < p || !validate_knots(knots, p, static_cast<std::size_t>(n + 1))) continue;
      const double lo = knots[p], hi = knots[n + 1];
      std::vector<double> us;
      for (int k = 0; k <= 40; ++k) us.push_back(lo + (hi - lo) * k / 40.0);
      for (int i = p; i <= n + 1; ++i) us.push_back(knots[i]);
      std::vector<double> values(static_cast<std::size_t>(p) + 1);
      for (double u : us) {
        const int span = find_span(knots, p, u);
        basis_functions(knots, p, span, u, values);
        for (int i = 0; i <= n; ++i) {
          const double computed = (i >= span - p && i <= span) ? values[i - span + p] : 0.0;
          const mpq_class exact = exact_basis(knots, i, p, u);
          EXPECT_LE(std::abs(computed - exact.get_d()), 8e-16)
              << "p=" << p << " i=" << i << " u=" << u;
          EXPECT_LE(std::abs(basis_function(knots, p, i, u) - exact.get_d()), 8e-16);
        }
      }
    }
  }
}

TEST(BasisFunction, FollowsTheDefinitionOutsideTheDomainToo) {
  // Uniform degree-2 knots: the domain is [2, 5], the functions live on [0, 7].
  const std::vector<double> knots{0, 1, 2, 3, 4, 5, 6, 7};
  for (int k = 0; k <= 70; ++k) {
    const double u = k / 10.0;
    for (int i = 0; i <= 4; ++i) {
      const double exact = exact_basis(knots, i, 2, u).get_d();
      EXPECT_LE(std::abs(basis_function(knots, 2, i, u) - exact), 8e-16) << "i=" << i << " u=" << u;
    }
  }
  // N_{0,1} on 0 1 2 ...: the hat u on [0, 1] (0.06, not an extrapolated piece).
  EXPECT_NEAR(basis_function(std::vector<double>{0, 1, 2, 3, 4}, 1, 0, 0.06), 0.06, 1e-16);
  EXPECT_EQ(basis_function(knots, 2, 0, -1.0), 0.0);
  EXPECT_EQ(basis_function(knots, 2, 4, 7.5), 0.0);
}

TEST(BasisFunctionDerivatives, EqualExactDerivativesOfThePieces) {
  // On a span the basis functions are polynomials; their derivatives follow
  // from the exact recursion by the derivative formula (The NURBS Book eq.
  // 2.7): N'_{i,p} = p/(t_{i+p}-t_i) N_{i,p-1} - p/(t_{i+p+1}-t_{i+1}) N_{i+1,p-1},
  // applied k times in exact arithmetic.
  const std::vector<double> knots{0, 0, 0, 0, 0.2, 0.45, 0.45, 0.7, 1, 1, 1, 1};
  const int p = 3;
  const int n = static_cast<int>(knots.size()) - p - 2;
  const int orders = 4;
  std::vector<double> out((orders + 1) * (p + 1));
  for (double u : {0.0, 0.05, 0.2, 0.3, 0.45, 0.5, 0.7, 0.99, 1.0}) {
    const int span = find_span(knots, p, u);
    basis_function_derivatives(knots, p, span, u, orders, out);
    for (int k = 0; k <= orders; ++k) {
      for (int r = 0; r <= p; ++r) {
        const int i = span - p + r;
        ASSERT_LE(i, n);
        const double exact = test::exact_basis_derivative(knots, i, p, k, u).get_d();
        EXPECT_LE(std::abs(out[k * (p + 1) + r] - exact), 1e-12 * std::max(1.0, std::abs(exact)))
            << "k=" << k << " i=" << i << " u=" << u;
      }
    }
  }
}

RC_GTEST_PROP(BasisFunctions, PartitionOfUnityAndNonNegativity, ()) {
  const int p = *rc::gen::inRange(0, 8);
  const int n = p + *rc::gen::inRange(0, 12);
  // Random non-decreasing knots with repeats, multiplicity capped at p+1.
  std::vector<double> knots{*rc::gen::inRange(-50, 50) * 0.5};
  int run = 1;
  while (static_cast<int>(knots.size()) < n + p + 2) {
    double step = *rc::gen::inRange(0, 4) * 0.25;
    if (step == 0.0 && run == p + 1) step = 0.25;
    run = step == 0.0 ? run + 1 : 1;
    knots.push_back(knots.back() + step);
  }
  RC_PRE(validate_knots(knots, p, static_cast<std::size_t>(n + 1)).has_value());
  const double f = *rc::gen::inRange(0, 1001) / 1000.0;
  const double u = knots[p] + f * (knots[n + 1] - knots[p]);
  std::vector<double> values(static_cast<std::size_t>(p) + 1);
  basis_functions(knots, p, find_span(knots, p, u), u, values);
  double sum = 0;
  for (double v : values) {
    RC_ASSERT(v >= -1e-15);
    RC_ASSERT(v <= 1.0 + 1e-15);
    sum += v;
  }
  RC_ASSERT(std::abs(sum - 1.0) <= 4e-15);
}

}  // namespace
}  // namespace casteljau

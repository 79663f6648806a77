// Bernstein basis: reference values from exact dyadic arithmetic (GMP) and the
// seed corrections table (shared/docs/seeds.md).
#include "casteljau/bezier/bernstein.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "support/exact.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

TEST(Binomial, ExactWhileBelowTwoToThe53) {
  for (int n = 0; n <= 56; ++n)
    for (int k = 0; k <= n; ++k) {
      mpz_class c;
      mpz_bin_uiui(c.get_mpz_t(), n, k);
      EXPECT_EQ(binomial(n, k), c.get_d()) << "C(" << n << "," << k << ")";
    }
  EXPECT_EQ(binomial(5, -1), 0.0);
  EXPECT_EQ(binomial(5, 6), 0.0);
}

TEST(Binomial, OverflowsToInfinityNearDegree1030) {
  EXPECT_TRUE(std::isfinite(binomial(1000, 500)));
  EXPECT_TRUE(std::isinf(binomial(1100, 550)));
}

TEST(Bernstein, AllValuesMatchExactArithmetic) {
  std::vector<double> values(61);
  for (int n : {1, 2, 3, 5, 10, 20, 40, 60})
    for (double t : {0.0, 1e-3, 0.1, 1.0 / 3.0, 0.5, 0.77, 0.999, 1.0}) {
      bernstein_all(n, t, values);
      for (int k = 0; k <= n; ++k) {
        const test::Dyadic exact = test::exact_bernstein(n, k, t);
        // Each value is a sum of positive terms built in n steps: relative error <= 2n ulps.
        EXPECT_LE(test::error_of(values[k], exact), 2.0 * n * 1.2e-16 * std::max(exact.approximate(), 1e-300))
            << "B_{" << n << "," << k << "}(" << t << ")";
        EXPECT_NEAR(bernstein(n, k, t), exact.approximate(), 1e-15 * std::max(1.0, n / 10.0));
      }
    }
}

TEST(Bernstein, SeedCorrectionDegreeFour) {
  // seeds.md: seed 001 prints B_3 = -3u^4 + 4u^3; correct is 4u^3(1-u) = -4u^4 + 4u^3.
  for (double u : {0.1, 0.25, 0.5, 0.9}) EXPECT_NEAR(bernstein(4, 3, u), -4 * std::pow(u, 4) + 4 * std::pow(u, 3), 1e-15);
}

TEST(Bernstein, LargeDegreeStaysFiniteAndAccurate) {
  const double b = bernstein(2000, 1000, 0.5);
  EXPECT_TRUE(std::isfinite(b));
  std::vector<double> all(2001);
  bernstein_all(2000, 0.5, all);
  EXPECT_NEAR(b, all[1000], 1e-12 * all[1000]);
  EXPECT_NEAR(b, test::exact_bernstein(2000, 1000, 0.5).approximate(), 3 * 2000 * 1.2e-16 * b);
}

RC_GTEST_PROP(Bernstein, PartitionOfUnityAndPositivity, ()) {
  const int n = *rc::gen::inRange(0, 300);
  const double t = *test::unit_parameter();
  std::vector<double> values(n + 1);
  bernstein_all(n, t, values);
  double sum = 0.0;
  for (double v : values) {
    RC_ASSERT(v >= 0.0);
    sum += v;
  }
  RC_ASSERT(std::abs(sum - 1.0) <= (n + 1) * 4e-16);
}

TEST(BernsteinDerivatives, MatchDifferentiatedExactPolynomials) {
  // d/dt B_{n,k} = n (B_{n-1,k-1} - B_{n-1,k}), exactly; order r by repetition.
  std::vector<double> values(13);
  for (int n : {1, 3, 6, 12})
    for (int r = 0; r <= n + 1; ++r)
      for (double t : {0.0, 0.3, 0.5, 1.0}) {
        bernstein_derivatives(n, t, r, values);
        for (int k = 0; k <= n; ++k) {
          // Exact r-th derivative: n!/(n-r)! sum_i (-1)^(r-i) C(r,i) B_{n-r,k-i}.
          mpq_class exact = 0;
          if (r <= n) {
            mpz_class falling = 1;
            for (int i = 0; i < r; ++i) falling *= n - i;
            for (int i = 0; i <= r; ++i) {
              if (k - i < 0 || k - i > n - r) continue;
              mpz_class c;
              mpz_bin_uiui(c.get_mpz_t(), r, i);
              const mpq_class term = c * test::exact_bernstein(n - r, k - i, t).rational();
              exact += ((r - i) % 2 == 0) ? term : mpq_class(-term);
            }
            exact *= falling;
          }
          EXPECT_LE(test::error_of(values[k], exact), 1e-13 * std::pow(2.0 * n, r) + 1e-15)
              << "n=" << n << " r=" << r << " k=" << k << " t=" << t;
        }
      }
}

TEST(BezierBasisPolynomial, SeedCubicCorrected) {
  // seeds.md: f_1 = u^3 - 3u^2 + 3u (printed u^3 - 3u^2 + u), f_2 = 3u^2 - 2u^3, f_3 = u^3.
  for (double u : {0.0, 0.2, 0.5, 0.8, 1.0}) {
    EXPECT_DOUBLE_EQ(bezier_basis_polynomial(3, 0, u), 1.0);
    EXPECT_NEAR(bezier_basis_polynomial(3, 1, u), u * u * u - 3 * u * u + 3 * u, 1e-15);
    EXPECT_NEAR(bezier_basis_polynomial(3, 2, u), 3 * u * u - 2 * u * u * u, 1e-15);
    EXPECT_NEAR(bezier_basis_polynomial(3, 3, u), u * u * u, 1e-15);
  }
}

}  // namespace
}  // namespace casteljau

#pragma once
// Exact reference arithmetic for tests. Every double is a dyadic rational
// m * 2^e, and de Casteljau, Bernstein sums and hodographs only add and
// multiply, so they can be computed EXACTLY in dyadic arithmetic on GMP
// integers (no gcd, unlike mpq_class, so degree 200 stays fast). Results are
// compared without rounding: the error of a double x is |x - exact| computed
// exactly, then rounded once for reporting.

#include <gmpxx.h>

#include <cassert>
#include <cmath>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"

namespace casteljau::test {

/// m * 2^e with m an arbitrary-precision integer: exact for every double.
struct Dyadic {
  mpz_class mantissa = 0;
  long exponent = 0;

  static Dyadic of(double x) {
    assert(std::isfinite(x));
    int e = 0;
    const double m = std::frexp(x, &e);  // x = m 2^e, |m| in [0.5, 1)
    Dyadic d;
    d.mantissa = mpz_class(std::ldexp(m, 53));  // exact: 53-bit integer
    d.exponent = e - 53;
    return d;
  }
  static Dyadic integer(long v) { return Dyadic{mpz_class(v), 0}; }

  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) {
    return Dyadic{a.mantissa * b.mantissa, a.exponent + b.exponent};
  }
  friend Dyadic operator+(const Dyadic& a, const Dyadic& b) {
    if (a.exponent == b.exponent) return Dyadic{a.mantissa + b.mantissa, a.exponent};
    if (a.exponent > b.exponent) {
      mpz_class shifted = a.mantissa;
      mpz_mul_2exp(shifted.get_mpz_t(), shifted.get_mpz_t(), a.exponent - b.exponent);
      return Dyadic{shifted + b.mantissa, b.exponent};
    }
    return b + a;
  }
  friend Dyadic operator-(const Dyadic& a) { return Dyadic{-a.mantissa, a.exponent}; }
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return a + (-b); }

  /// The exact value as a rational.
  mpq_class rational() const {
    mpq_class q(mantissa);
    if (exponent >= 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), exponent);
    else mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), -exponent);
    return q;
  }
  /// Nearest-ish double (for reporting only; truncation error < 1 ulp).
  double approximate() const {
    long e = 0;
    const double m = mpz_get_d_2exp(&e, mantissa.get_mpz_t());
    return std::ldexp(m, static_cast<int>(e + exponent));
  }
};

/// |computed - exact| rounded once to double.
inline double error_of(double computed, const Dyadic& exact) {
  return std::abs((Dyadic::of(computed) - exact).approximate());
}
inline double error_of(double computed, const mpq_class& exact) {
  const mpq_class diff = mpq_class(computed) - exact;
  return std::abs(diff.get_d());
}

/// Exact de Casteljau of a polynomial curve (any dimension) at a double t.
inline std::vector<Dyadic> exact_point(const BezierCurve& curve, double t) {
  assert(!curve.is_rational());
  const int n = curve.degree(), d = curve.dimension();
  const Dyadic tt = Dyadic::of(t), s = Dyadic::integer(1) - tt;
  std::vector<Dyadic> rows;
  for (double c : curve.control_points().coordinates()) rows.push_back(Dyadic::of(c));
  for (int r = 1; r <= n; ++r)
    for (int i = 0; i <= n - r; ++i)
      for (int j = 0; j < d; ++j) rows[i * d + j] = s * rows[i * d + j] + tt * rows[(i + 1) * d + j];
  rows.resize(d);
  return rows;
}

/// Exact point of a rational (or polynomial) curve as rationals:
/// sum w_k P_k B_k / sum w_k B_k, the homogeneous de Casteljau done exactly.
inline std::vector<mpq_class> exact_rational_point(const BezierCurve& curve, double t) {
  const int n = curve.degree(), d = curve.dimension();
  const Dyadic tt = Dyadic::of(t), s = Dyadic::integer(1) - tt;
  std::vector<Dyadic> rows;
  for (int i = 0; i <= n; ++i) {
    const Dyadic w = Dyadic::of(curve.is_rational() ? curve.weights()[i] : 1.0);
    for (int j = 0; j < d; ++j) rows.push_back(w * Dyadic::of(curve.control_points()[i][j]));
    rows.push_back(w);
  }
  const int width = d + 1;
  for (int r = 1; r <= n; ++r)
    for (int i = 0; i <= n - r; ++i)
      for (int j = 0; j < width; ++j) rows[i * width + j] = s * rows[i * width + j] + tt * rows[(i + 1) * width + j];
  std::vector<mpq_class> point;
  const mpq_class w = rows[d].rational();
  for (int j = 0; j < d; ++j) point.push_back(rows[j].rational() / w);
  return point;
}

/// Exact k-th derivative of a polynomial curve: n!/(n-k)! times de Casteljau
/// of the k-th forward differences, all exact.
inline std::vector<Dyadic> exact_derivative(const BezierCurve& curve, double t, int k) {
  assert(!curve.is_rational());
  const int n = curve.degree(), d = curve.dimension();
  if (k > n) return std::vector<Dyadic>(d, Dyadic::integer(0));
  std::vector<Dyadic> rows;
  for (double c : curve.control_points().coordinates()) rows.push_back(Dyadic::of(c));
  for (int r = 1; r <= k; ++r)
    for (int i = 0; i <= n - r; ++i)
      for (int j = 0; j < d; ++j) rows[i * d + j] = rows[(i + 1) * d + j] - rows[i * d + j];
  const Dyadic tt = Dyadic::of(t), s = Dyadic::integer(1) - tt;
  for (int r = 1; r <= n - k; ++r)
    for (int i = 0; i <= n - k - r; ++i)
      for (int j = 0; j < d; ++j) rows[i * d + j] = s * rows[i * d + j] + tt * rows[(i + 1) * d + j];
  long falling = 1;
  for (int i = 0; i < k; ++i) falling *= n - i;
  rows.resize(d);
  for (auto& c : rows) c = Dyadic::integer(falling) * c;
  return rows;
}

/// Exact B_{n,k}(t) = C(n,k) t^k (1-t)^(n-k).
inline Dyadic exact_bernstein(int n, int k, double t) {
  mpz_class c;
  mpz_bin_uiui(c.get_mpz_t(), n, k);
  const Dyadic tt = Dyadic::of(t), s = Dyadic::integer(1) - tt;
  Dyadic value{c, 0};
  for (int i = 0; i < k; ++i) value = value * tt;
  for (int i = 0; i < n - k; ++i) value = value * s;
  return value;
}

}  // namespace casteljau::test

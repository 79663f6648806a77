#pragma once
// The natural spline of order q in the seed's truncated-power form (seed 001,
// problem P2; Schoenberg 1964), solved EXACTLY in GMP rationals:
//   s(x) = sum_{j<q} a_j x^j + sum_{i=0..m} d_i (x - x_i)_+^(2q-1) / (2q-1)!,
//   s(x_i) = y_i (i = 0..m),   sum_i d_i x_i^k = 0 (k = 0..q-1).
// The side conditions make s a polynomial of degree q-1 beyond x_m (and it is
// one before x_0 by construction), which is what the natural end conditions
// s^(j)(x_0) = s^(j)(x_m) = 0, j = q..2q-2, say. Independent of the library:
// dense Gaussian elimination on the m+1+q unknowns, for small sets only.

#include <gmpxx.h>

#include <cassert>
#include <vector>

namespace casteljau::test {

struct ExactNaturalSpline {
  int order = 0;                  // q
  std::vector<mpq_class> nodes;   // x_0 < ... < x_m
  std::vector<mpq_class> a;       // polynomial part, a_0..a_{q-1}
  std::vector<mpq_class> d;       // truncated-power coefficients d_0..d_m

  /// Solves the (m+1+q) x (m+1+q) system exactly. Asserts it is regular
  /// (true for m+1 >= q distinct nodes).
  static ExactNaturalSpline solve(int q, const std::vector<mpq_class>& x, const std::vector<mpq_class>& y) {
    assert(q >= 1 && x.size() == y.size() && x.size() >= static_cast<std::size_t>(q));
    const std::size_t points = x.size(), unknowns = points + static_cast<std::size_t>(q);
    const int e = 2 * q - 1;
    const mpq_class e_factorial = factorial(e);
    std::vector<std::vector<mpq_class>> rows(unknowns, std::vector<mpq_class>(unknowns + 1, 0));
    for (std::size_t i = 0; i < points; ++i) {
      for (int j = 0; j < q; ++j) rows[i][static_cast<std::size_t>(j)] = power(x[i], j);
      for (std::size_t k = 0; k < points; ++k)
        if (x[i] > x[k]) rows[i][static_cast<std::size_t>(q) + k] = power(x[i] - x[k], e) / e_factorial;
      rows[i][unknowns] = y[i];
    }
    for (int k = 0; k < q; ++k)
      for (std::size_t i = 0; i < points; ++i) rows[points + static_cast<std::size_t>(k)][static_cast<std::size_t>(q) + i] = power(x[i], k);
    // Gauss–Jordan with any non-zero pivot: exact arithmetic needs no more.
    for (std::size_t c = 0; c < unknowns; ++c) {
      std::size_t pivot = c;
      while (pivot < unknowns && rows[pivot][c] == 0) ++pivot;
      assert(pivot < unknowns);
      std::swap(rows[c], rows[pivot]);
      const mpq_class inverse = 1 / rows[c][c];
      for (auto& v : rows[c]) v *= inverse;
      for (std::size_t r = 0; r < unknowns; ++r) {
        if (r == c || rows[r][c] == 0) continue;
        const mpq_class f = rows[r][c];
        for (std::size_t k = c; k <= unknowns; ++k) rows[r][k] -= f * rows[c][k];
      }
    }
    ExactNaturalSpline s;
    s.order = q;
    s.nodes = x;
    for (int j = 0; j < q; ++j) s.a.push_back(rows[static_cast<std::size_t>(j)][unknowns]);
    for (std::size_t i = 0; i < points; ++i) s.d.push_back(rows[static_cast<std::size_t>(q) + i][unknowns]);
    return s;
  }

  /// s^(r)(x) exactly, 0 <= r <= 2q-2 (below 2q-1 every term is continuous,
  /// so the value at a node is unambiguous).
  mpq_class derivative(const mpq_class& x, int r) const {
    assert(r >= 0 && r <= 2 * order - 2);
    mpq_class value = 0;
    for (int j = r; j < order; ++j) value += a[static_cast<std::size_t>(j)] * falling(j, r) * power(x, j - r);
    const int e = 2 * order - 1 - r;
    const mpq_class e_factorial = factorial(e);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (x > nodes[i]) value += d[i] * power(x - nodes[i], e) / e_factorial;
    return value;
  }
  mpq_class value(const mpq_class& x) const { return derivative(x, 0); }

  static mpq_class power(const mpq_class& base, int exponent) {
    mpq_class result = 1;
    for (int i = 0; i < exponent; ++i) result *= base;
    return result;
  }
  static mpq_class factorial(int n) {
    mpq_class result = 1;
    for (int i = 2; i <= n; ++i) result *= i;
    return result;
  }
  /// j (j-1) ... (j-r+1).
  static mpq_class falling(int j, int r) {
    mpq_class result = 1;
    for (int i = 0; i < r; ++i) result *= j - i;
    return result;
  }
};

}  // namespace casteljau::test

#include "casteljau/bezier/bernstein.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>

#include "casteljau/core/precondition.hpp"

namespace casteljau {

namespace {

/// C(n, k) computed: exact in 64-bit integers while they fit, then the seed
/// notebook's float product.
double computed_binomial(int n, int k) {
  k = std::min(k, n - k);
  // Integers while they fit: C(n, i+1) = C(n, i) (n - i) / (i + 1) is exact in
  // 64 bits as long as the product does not overflow.
  std::uint64_t exact = 1;
  int i = 0;
  for (; i < k; ++i) {
    std::uint64_t product = 0;
    if (__builtin_mul_overflow(exact, static_cast<std::uint64_t>(n - i), &product)) break;
    exact = product / static_cast<std::uint64_t>(i + 1);
  }
  double p = static_cast<double>(exact);
  for (; i < k; ++i) p = p * (n - i) / (i + 1);  // beyond 2^64: the seed notebook's float product
  return p;
}

/// Rows 0..kTableRows - 1 of Pascal's triangle, computed once (the same
/// values as computed_binomial, bit for bit): products of Bernstein
/// polynomials (bernstein_product, the intersection and closest-point
/// polynomials) ask for C(n, k) in their inner loops, where the loop above
/// cost 7 % of W8.
constexpr int kTableRows = 64;

const std::array<double, kTableRows*(kTableRows + 1) / 2>& binomial_table() {
  static const auto table = [] {
    std::array<double, kTableRows*(kTableRows + 1) / 2> rows{};
    for (int n = 0; n < kTableRows; ++n)
      for (int k = 0; k <= n; ++k) rows[static_cast<std::size_t>(n * (n + 1) / 2 + k)] = computed_binomial(n, k);
    return rows;
  }();
  return table;
}

}  // namespace

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  if (n < kTableRows) return binomial_table()[static_cast<std::size_t>(n * (n + 1) / 2 + k)];
  return computed_binomial(n, k);
}

double bernstein(int n, int k, double t) {
  if (k < 0 || k > n) return 0.0;
  // C(n,k) t^k (1-t)^(n-k) as one running product of the factors t (n-a)/(a+1)
  // (a < k) and (1-t), taking a (1-t) whenever the value exceeds 1: it stays
  // near 1 until the end, so it neither overflows nor underflows early, and
  // each of its n factors adds one or two roundings (relative error ~ 3n ulps).
  const double s = 1.0 - t;
  double value = 1.0;
  int a = 0, b = 0;
  while (a < k || b < n - k) {
    if (b < n - k && (std::abs(value) >= 1.0 || a == k)) {
      value *= s;
      ++b;
    } else {
      value *= t * (n - a) / (a + 1);
      ++a;
    }
  }
  return value;
}

void bernstein_all(int n, double t, std::span<double> out) {
  detail::require(n >= 0 && out.size() >= static_cast<std::size_t>(n) + 1, "bernstein_all",
                  "n must be >= 0 and out must hold n + 1 values");
  const double s = 1.0 - t;
  out[0] = 1.0;
  for (int j = 1; j <= n; ++j) {
    double saved = 0.0;
    for (int k = 0; k < j; ++k) {
      const double temp = out[k];
      out[k] = saved + s * temp;
      saved = t * temp;
    }
    out[j] = saved;
  }
}

void bernstein_derivatives(int n, double t, int order, std::span<double> out) {
  detail::require(n >= 0 && order >= 0 && out.size() >= static_cast<std::size_t>(n) + 1, "bernstein_derivatives",
                  "n and order must be >= 0 and out must hold n + 1 values");
  std::fill(out.begin(), out.begin() + n + 1, 0.0);
  if (order > n) return;
  const int m = n - order;
  bernstein_all(m, t, out);
  // Raise from degree m to n: d/dt B_{j,k} = j (B_{j-1,k-1} - B_{j-1,k}).
  for (int j = m + 1; j <= n; ++j) {
    out[j] = 0.0;
    for (int k = j; k >= 0; --k) {
      const double left = (k > 0) ? out[k - 1] : 0.0;
      const double right = (k < j) ? out[k] : 0.0;
      out[k] = j * (left - right);
    }
  }
}

double bezier_basis_polynomial(int n, int i, double t) {
  if (i <= 0) return 1.0;
  if (i > n) return 0.0;
  // Sum the tail B_{n,i..n}: all terms positive on [0,1], no cancellation.
  double sum = 0.0;
  for (int k = i; k <= n; ++k) sum += bernstein(n, k, t);
  return sum;
}

}  // namespace casteljau

#include "casteljau/bezier/bernstein.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace casteljau {

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double p = 1.0;
  for (int i = 0; i < k; ++i) p = p * (n - i) / (i + 1);  // seed 004's binom, same order
  return p;
}

double bernstein(int n, int k, double t) {
  if (k < 0 || k > n) return 0.0;
  const double c = binomial(n, k);
  if (std::isfinite(c)) return c * std::pow(t, k) * std::pow(1.0 - t, n - k);
  // C(n,k) overflows: work with logarithms (t in (0,1) only; the ends are 0 here).
  if (t <= 0.0 || t >= 1.0) return (t <= 0.0) ? (k == 0 ? 1.0 : 0.0) : (k == n ? 1.0 : 0.0);
  const double log_c = std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
  return std::exp(log_c + k * std::log(t) + (n - k) * std::log1p(-t));
}

void bernstein_all(int n, double t, std::span<double> out) {
  assert(n >= 0 && out.size() >= static_cast<std::size_t>(n) + 1);
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
  assert(n >= 0 && order >= 0 && out.size() >= static_cast<std::size_t>(n) + 1);
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

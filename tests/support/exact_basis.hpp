#pragma once
// Exact B-spline references in rational arithmetic (GMP mpq_class): the
// Cox–de Boor recursion exactly as defined (seed 001 §1.2.3, The NURBS Book
// eq. 2.5), with the degree-0 functions half-open and the last non-empty
// span closed at the end of the domain (the convention of find_span), and
// curve points as exact sums of basis functions times control points.
// Independent of the library's algorithms (no span search, no de Boor).

#include <gmpxx.h>

#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"

namespace casteljau::test {

/// Index of the last span t_i < t_{i+1} with i <= n.
inline int last_nonempty_span(std::span<const double> knots, int p) {
  int i = static_cast<int>(knots.size()) - p - 2;
  while (knots[i] == knots[i + 1]) --i;
  return i;
}

/// N_{i,p}(u) exactly for u in the domain [t_p, t_{n+1}] of a curve of
/// degree p with n+1 = knots.size() - p - 1 control points. At the end of the
/// domain, the degree-0 function of the last non-empty span is 1 (the domain
/// is closed there, as find_span closes it); elsewhere they are half-open.
inline mpq_class exact_basis(std::span<const double> knots, int i, int p, double u, int last_span = -1) {
  if (last_span < 0) last_span = last_nonempty_span(knots, p);
  if (p == 0) {
    if (u == knots[last_span + 1]) return i == last_span ? 1 : 0;
    return (knots[i] <= u && u < knots[i + 1]) ? 1 : 0;
  }
  const mpq_class x(u);
  mpq_class value = 0;
  const mpq_class ti(knots[i]), tip(knots[i + p]), ti1(knots[i + 1]), tip1(knots[i + p + 1]);
  if (tip != ti) value += (x - ti) / (tip - ti) * exact_basis(knots, i, p - 1, u, last_span);
  if (tip1 != ti1) value += (tip1 - x) / (tip1 - ti1) * exact_basis(knots, i + 1, p - 1, u, last_span);
  return value;
}

/// C(u) exactly: sum N_i P_i, divided by sum N_i w_i for a NURBS curve.
inline std::vector<mpq_class> exact_bspline_point(const BSplineCurve& curve, double u) {
  const int d = curve.dimension();
  std::vector<mpq_class> numerator(static_cast<std::size_t>(d), 0);
  mpq_class denominator = 0;
  for (std::size_t i = 0; i < curve.control_points().size(); ++i) {
    const mpq_class n = exact_basis(curve.knots(), static_cast<int>(i), curve.degree(), u);
    if (n == 0) continue;
    const mpq_class w = curve.is_rational() ? mpq_class(curve.weights()[i]) : mpq_class(1);
    for (int k = 0; k < d; ++k) numerator[k] += n * w * mpq_class(curve.control_points()[i][k]);
    denominator += n * w;
  }
  for (auto& c : numerator) c /= denominator;
  return numerator;
}

}  // namespace casteljau::test

namespace casteljau::test {

/// The k-th derivative of N_{i,p} at u exactly, by The NURBS Book eq. 2.7
/// applied k times: N'_{i,p} = p/(t_{i+p}-t_i) N_{i,p-1} - p/(t_{i+p+1}-t_{i+1}) N_{i+1,p-1}.
inline mpq_class exact_basis_derivative(std::span<const double> knots, int i, int p, int k, double u,
                                        int last_span = -1) {
  if (last_span < 0) last_span = last_nonempty_span(knots, p);
  if (k == 0) return exact_basis(knots, i, p, u, last_span);
  if (p == 0) return 0;
  mpq_class value = 0;
  const mpq_class ti(knots[i]), tip(knots[i + p]), ti1(knots[i + 1]), tip1(knots[i + p + 1]);
  if (tip != ti) value += mpq_class(p) / (tip - ti) * exact_basis_derivative(knots, i, p - 1, k - 1, u, last_span);
  if (tip1 != ti1) value -= mpq_class(p) / (tip1 - ti1) * exact_basis_derivative(knots, i + 1, p - 1, k - 1, u, last_span);
  return value;
}

/// C^(k)(u) exactly. NURBS: the homogeneous derivatives A^(j), w^(j) exactly,
/// then Leibniz's rule solved for C^(k) (The NURBS Book eq. 4.8) in rationals.
inline std::vector<mpq_class> exact_bspline_derivative(const BSplineCurve& curve, double u, int k) {
  const int d = curve.dimension();
  std::vector<std::vector<mpq_class>> a(static_cast<std::size_t>(k) + 1, std::vector<mpq_class>(d, 0));
  std::vector<mpq_class> w(static_cast<std::size_t>(k) + 1, 0);
  for (int j = 0; j <= k; ++j) {
    for (std::size_t i = 0; i < curve.control_points().size(); ++i) {
      const mpq_class n = exact_basis_derivative(curve.knots(), static_cast<int>(i), curve.degree(), j, u);
      if (n == 0) continue;
      const mpq_class wi = curve.is_rational() ? mpq_class(curve.weights()[i]) : mpq_class(1);
      for (int c = 0; c < d; ++c) a[j][c] += n * wi * mpq_class(curve.control_points()[i][c]);
      w[j] += n * wi;
    }
  }
  std::vector<std::vector<mpq_class>> c(static_cast<std::size_t>(k) + 1, std::vector<mpq_class>(d, 0));
  for (int order = 0; order <= k; ++order) {
    for (int coordinate = 0; coordinate < d; ++coordinate) {
      mpq_class v = a[order][coordinate];
      mpz_class binomial = 1;
      for (int j = 1; j <= order; ++j) {
        binomial = binomial * (order - j + 1) / j;
        v -= mpq_class(binomial) * w[j] * c[order - j][coordinate];
      }
      c[order][coordinate] = v / w[0];
    }
  }
  return c[k];
}

}  // namespace casteljau::test

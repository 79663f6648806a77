#pragma once
// Exact references for tensor-product surfaces in GMP rationals: points and
// partial derivatives of B-spline, NURBS and Bézier surfaces from the
// definition S = sum_i sum_j N_i(u) N_j(v) w_ij P_ij / sum N_i N_j w_ij
// (The NURBS Book eqs. 3.11, 4.15), the basis functions and their
// derivatives from the exact Cox–de Boor recursion of exact_basis.hpp, and
// for NURBS the Leibniz rule solved for S^(k,l) in rationals (eq. 4.20).
// Independent of the library's surface code: no span search, no tensor
// contraction order, no de Casteljau; small surfaces only.
#include <gmpxx.h>

#include <vector>

#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "support/exact_basis.hpp"

namespace casteljau::test {

/// All exact partial derivatives S^(k,l)(u, v), k <= K, l <= L: result[k][l][c].
inline std::vector<std::vector<std::vector<mpq_class>>> exact_surface_derivatives(const BSplineSurface& s, double u,
                                                                                  double v, int K, int L) {
  const int d = s.dimension();
  const ControlNet& net = s.control_net();
  const int rows = static_cast<int>(net.rows()), columns = static_cast<int>(net.columns());
  // Basis derivatives N_i^(k)(u), N_j^(l)(v).
  std::vector<std::vector<mpq_class>> nu(K + 1, std::vector<mpq_class>(rows)), nv(L + 1, std::vector<mpq_class>(columns));
  for (int k = 0; k <= K; ++k)
    for (int i = 0; i < rows; ++i) nu[k][i] = exact_basis_derivative(s.knots_u(), i, s.degree_u(), k, u);
  for (int l = 0; l <= L; ++l)
    for (int j = 0; j < columns; ++j) nv[l][j] = exact_basis_derivative(s.knots_v(), j, s.degree_v(), l, v);
  // Homogeneous derivatives A^(k,l) (width d) and w^(k,l).
  std::vector<std::vector<std::vector<mpq_class>>> a(K + 1, std::vector<std::vector<mpq_class>>(L + 1, std::vector<mpq_class>(d, 0)));
  std::vector<std::vector<mpq_class>> w(K + 1, std::vector<mpq_class>(L + 1, 0));
  for (int k = 0; k <= K; ++k)
    for (int l = 0; l <= L; ++l)
      for (int i = 0; i < rows; ++i) {
        if (nu[k][i] == 0) continue;
        for (int j = 0; j < columns; ++j) {
          if (nv[l][j] == 0) continue;
          const mpq_class weight = s.is_rational() ? mpq_class(s.weights()[i * columns + j]) : mpq_class(1);
          const mpq_class factor = nu[k][i] * nv[l][j] * weight;
          for (int c = 0; c < d; ++c) a[k][l][c] += factor * mpq_class(net(i, j)[c]);
          w[k][l] += factor;
        }
      }
  auto binomial = [](int n, int r) {
    mpz_class b = 1;
    for (int x = 1; x <= r; ++x) b = b * (n - r + x) / x;
    return mpq_class(b);
  };
  std::vector<std::vector<std::vector<mpq_class>>> out = a;
  for (int k = 0; k <= K; ++k)
    for (int l = 0; l <= L; ++l)
      for (int c = 0; c < d; ++c) {
        mpq_class value = a[k][l][c];
        for (int i = 0; i <= k; ++i)
          for (int j = 0; j <= l; ++j) {
            if (i == 0 && j == 0) continue;
            value -= binomial(k, i) * binomial(l, j) * w[i][j] * out[k - i][l - j][c];
          }
        out[k][l][c] = value / w[0][0];
      }
  return out;
}

/// S(u, v) exactly.
inline std::vector<mpq_class> exact_surface_point(const BSplineSurface& s, double u, double v) {
  return exact_surface_derivatives(s, u, v, 0, 0)[0][0];
}

/// A Bézier patch's point exactly: the Bernstein polynomials are the
/// B-splines on 0^(n+1) 1^(n+1) (The NURBS Book §2.3), so the exact
/// Cox–de Boor sum above on those knots is the exact Bernstein sum.
inline std::vector<mpq_class> exact_surface_point(const BezierSurface& s, double u, double v) {
  return exact_surface_point(to_bspline_surface(s), u, v);
}

/// The largest |computed - exact| over the coordinates, relative to `scale`.
inline double relative_error(std::span<const double> computed, const std::vector<mpq_class>& exact, double scale) {
  double worst = 0.0;
  for (std::size_t c = 0; c < exact.size(); ++c) {
    const mpq_class diff = mpq_class(computed[c]) - exact[c];
    worst = std::max(worst, std::abs(diff.get_d()) / scale);
  }
  return worst;
}

}  // namespace casteljau::test

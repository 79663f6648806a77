#pragma once
// The Bernstein basis B_{n,k}(t) = C(n,k) t^k (1-t)^(n-k), k = 0..n
// (seed 000, 001, 004): a partition of unity, positive on (0,1), and a basis
// of the polynomials of degree <= n.

#include <span>

namespace casteljau {

/// Binomial coefficient C(n, k) as a double: C(n, i+1) = C(n, i) (n-i)/(i+1)
/// in 64-bit integers while they fit (so exact whenever C(n,k) < 2^53, e.g.
/// every n <= 56), then in doubles like the seed notebook's `binom`.
/// +inf once it overflows (n >= 1030 near k = n/2). 0 for k < 0 or k > n.
double binomial(int n, int k);

/// One Bernstein polynomial B_{n,k}(t) = C(n,k) t^k (1-t)^(n-k), as a single
/// running product of its n factors ordered to stay near 1, so it is finite and
/// accurate (relative error about 3n ulps) at any degree, where C(n,k) alone
/// would overflow. O(n). Any finite t (outside [0,1] it extrapolates).
double bernstein(int n, int k, double t);

/// All n+1 values B_{n,0}(t) .. B_{n,n}(t) into `out` (size n+1), by the
/// triangular recurrence B_{j,k} = (1-t) B_{j-1,k} + t B_{j-1,k-1}
/// (The NURBS Book, A1.3 AllBernstein). O(n^2), no heap, no binomials, so no
/// overflow at any degree; for t in [0,1] every step is a convex combination.
void bernstein_all(int n, double t, std::span<double> out);

/// The r-th derivatives d^r/dt^r B_{n,k}(t), k = 0..n, into `out` (size n+1),
/// from B'_{n,k} = n (B_{n-1,k-1} - B_{n-1,k}) applied r times to the basis of
/// degree n - r (The NURBS Book, eq. 1.10 / 2.9). Zero for r > n. O(n^2), no heap.
void bernstein_derivatives(int n, double t, int order, std::span<double> out);

/// Bézier's own basis (seed 001 "polynômes de Bézier", seed 003 vector form):
/// f_0 = 1 and f_i(t) = sum_{k >= i} B_{n,k}(t) = 1 - sum_{k < i} B_{n,k}(t),
/// so that P(t) = sum_i f_i(t) V_i with V_0 = P_0, V_i = P_i - P_{i-1}.
/// For n = 3: f_1 = t^3 - 3t^2 + 3t, f_2 = 3t^2 - 2t^3, f_3 = t^3 (seed 001 misprints f_1).
double bezier_basis_polynomial(int n, int i, double t);

}  // namespace casteljau

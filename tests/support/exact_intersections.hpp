#pragma once
// Exact reference for the intersections of plane polynomial Bézier curves, in
// rational arithmetic (GMP), independent of the library: it depends only on
// gmpxx and the standard library. Slow and simple on purpose; it is the oracle
// the double-precision intersection code is tested against.
//
// Method (every step exact):
//  1. Both curves go to the power basis. Their intersections are the common
//     zeros of P(s,t) = x_a(s) - x_b(t) and Q(s,t) = y_a(s) - y_b(t); a
//     curve's self-intersections those of the divided differences
//     (x(s) - x(t))/(s - t), (y(s) - y(t))/(s - t).
//  2. The variable t is eliminated with the Sylvester resultant
//     R(s) = res_t(P, Q) (Sederberg, "Implicit representation of parametric
//     curves and surfaces", 1984; Sederberg & Nishita, "Curve intersection
//     using Bézier clipping", 1990, for the use in intersection). The
//     determinant, a polynomial in s, is computed by evaluation at integer
//     points (fraction-free Bareiss elimination, Bareiss 1968) and exact Newton
//     interpolation through deg + 1 points, the degree bounded by the entries'
//     degrees. The first subresultant S_1(s, t) = S11(s) t + S10(s) is
//     computed the same way (Collins 1967; Basu, Pollack & Roy, "Algorithms in
//     Real Algebraic Geometry", ch. 8).
//  3. R is split into square-free factors (Yun 1976, over Z with primitive
//     gcds) and the real roots of its square-free part are isolated with
//     Descartes' rule of signs in the Bernstein basis and exact de Casteljau
//     bisection (Collins & Akritas 1976; Mourrain, Rouillier & Roy 2005), then
//     refined by bisection to the requested width. A root that is rational
//     with a denominator below 2^(bits/2) is found exactly: after refinement
//     the simplest rational of the interval is tried.
//  4. Pairing. The s-roots (of res_t) and t-roots (of res_s) in [0,1] give
//     candidate pairs. A pair is rejected when the interval evaluation of P or
//     Q on its box excludes 0. A pair is accepted only with a proof: in a
//     projection u = s + lambda t (lambda = 0, then the b side u = t, then
//     sheared ones lambda = 1, -1, 2, ...), a root u0 of the resultant with
//     S11(u0) != 0 has exactly one common zero above it (the gcd of the two
//     polynomials at u0 has degree 1), w = -S10(u0)/S11(u0); its interval
//     enclosure is refined until it lies in the isolating neighbourhoods of
//     one s-root and one t-root, which it then equals.
//  5. Multiplicity. When the leading coefficients in the eliminated variable
//     are constants, res(u) = c prod (u - u_p)^{I_p} over all complex common
//     zeros p, I_p their intersection multiplicities (Fulton, "Algebraic
//     Curves", ch. 3 and 5; Cox, Little & O'Shea, "Using Algebraic Geometry",
//     ch. 3). So the multiplicity of u0 as a root of res equals I_p when p is
//     the only common zero above u0, which is what step 4 proves. The a-side
//     and the b-side multiplicities are cross-checked (each >= I_p, equal when
//     that side is unique), and I_p = 1 is cross-checked against the Jacobian
//     of (P, Q) (nonzero iff I_p = 1).
//
// What "multiplicity" means: the intersection multiplicity, at the pair of
// parameters (s, t), of the branch of curve a through a(s) and the branch of
// curve b through b(t). Transversal crossing: 1; contact of order k (tangent
// with k - 1 equal derivatives of the graphs): k; a line through a cusp: 2,
// along the cusp's tangent: 3. A point the curves pass through several times
// gives one ExactIntersection per pair of parameters, each with its own
// multiplicity. It equals the root multiplicity of res_t(P, Q) at s when no
// other (complex) common zero projects to the same s.
//
// Kinds: transversal iff multiplicity == 1 (a'(s) x b'(t) != 0); tangent
// otherwise (parallel tangents, or a cusp/stationary point of either curve);
// overlap for a shared sub-arc.
//
// Overlaps (the curves share their whole algebraic curve, R identically 0):
// both parametrizations must be proper (each point of the curve traced by one
// parameter except at finitely many points); then b(t) = a(alpha t + beta)
// with rational alpha, beta, found exactly, and the shared arc has rational
// end parameters. A curve that traces part of itself twice (e.g. a cubic with
// collinear control points folding back, or any degree >= 2 parametrization
// of a line) is rejected with std::invalid_argument in that case only. Points
// where the two arcs cross at a double point of the common curve are reported
// as point intersections. When the arcs of the same curve just touch (a's end
// is b's start), the point is reported as a tangent intersection with
// multiplicity kSharedComponent (0: infinite contact).
//
// Rejected with std::invalid_argument (these asserts hold in release builds
// too): a curve with no control point or whose control points are all equal
// (a point); an improper parametrization where an overlap or a
// self-intersection needs a proper one; a common point where both curves are
// stationary (a' = b' = 0, cusp on cusp) at irrational parameters, which no
// projection can certify.
//
// Self-intersections: pairs s < t in [0,1] with a(s) = a(t). A cusp
// (a'(s) = 0) is not a self-intersection and is not reported. A curve with
// collinear control points has none, unless it turns back on its line inside
// (0,1): then it overlaps itself, rejected with std::invalid_argument.

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace casteljau::test {

/// A polynomial plane Bézier curve on [0,1]: degree points.size() - 1.
struct ExactBezier {
  std::vector<std::array<mpq_class, 2>> points;
};

/// One intersection of two curves (or of a curve with itself).
struct ExactIntersection {
  enum class Kind { transversal, tangent, overlap };
  /// The multiplicity of a point where the two curves belong to one algebraic
  /// curve (infinite contact), and of every overlap.
  static constexpr int kSharedComponent = 0;

  Kind kind = Kind::transversal;
  /// Point: isolating intervals of the exact parameters (lower == upper when
  /// the parameter is rational and found exactly), width <= 2^-bits.
  /// Overlap: the exact end parameters of the shared sub-arcs, lower <= upper.
  mpq_class a_lower, a_upper, b_lower, b_upper;
  /// Point: the intersection multiplicity (see the top of this file).
  /// Overlap: kSharedComponent.
  int multiplicity = 1;
  /// Overlap only: b runs backwards (a_lower meets b_upper).
  bool reversed = false;
};

namespace exact_intersection_detail {

using Q = mpq_class;
using Z = mpz_class;
using ZPoly = std::vector<Z>;               // low to high, trimmed; zero = {}
using QPoly = std::vector<Q>;
using ZBi = std::vector<std::vector<Z>>;    // A[i][j]: coefficient of u^i w^j

[[noreturn]] inline void fail(const std::string& what) {
  throw std::invalid_argument("exact_intersections: " + what);
}
inline void check(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("exact_intersections internal check failed: ") + what);
}

/// n / d in canonical form (mpq_class(n, d) does not reduce, and every mpq
/// operation requires reduced operands).
inline Q ratio(const Z& n, const Z& d) {
  Q q(n, d);
  q.canonicalize();
  return q;
}

inline int sign(const Z& z) { return sgn(z); }
inline int sign(const Q& q) { return sgn(q); }

// ---------------------------------------------------------------- univariate
template <class P> void trim(P& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}
template <class P> int degree(const P& p) { return static_cast<int>(p.size()) - 1; }

inline ZPoly derivative(const ZPoly& p) {
  ZPoly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<unsigned long>(i));
  trim(d);
  return d;
}
inline QPoly derivative(const QPoly& p) {
  QPoly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<unsigned long>(i));
  trim(d);
  return d;
}
inline ZPoly sub(ZPoly a, const ZPoly& b) {
  if (a.size() < b.size()) a.resize(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) a[i] -= b[i];
  trim(a);
  return a;
}

/// Divides by the (positive) gcd of the coefficients: signs are kept.
inline ZPoly primitive(ZPoly p) {
  trim(p);
  Z g = 0;
  for (const Z& c : p) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
  if (g > 1)
    for (Z& c : p) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
  return p;
}
/// Primitive with a positive leading coefficient (same roots).
inline ZPoly normalized(ZPoly p) {
  p = primitive(std::move(p));
  if (!p.empty() && p.back() < 0)
    for (Z& c : p) c = -c;
  return p;
}
/// The integer polynomial with the roots of a rational one.
inline ZPoly integer_multiple(const QPoly& p) {
  Z l = 1;
  for (const Q& c : p) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  ZPoly z;
  for (const Q& c : p) z.push_back(c.get_num() * (l / c.get_den()));
  return primitive(z);
}

/// A positive multiple of (a mod b): the pseudo-remainder with |lc(b)|.
inline ZPoly positive_remainder(ZPoly a, const ZPoly& b) {
  const int db = degree(b);
  check(db >= 0, "division by zero polynomial");
  const Z lb = abs(b.back());
  const int sb = sign(b.back());
  trim(a);
  while (degree(a) >= db) {
    const int shift = degree(a) - db;
    const Z lead = a.back();
    for (Z& c : a) c *= lb;
    for (int i = 0; i <= db; ++i) a[i + shift] -= sb * lead * b[i];
    trim(a);
    a = primitive(std::move(a));
  }
  return a;
}
inline ZPoly gcd(ZPoly a, ZPoly b) {
  a = normalized(std::move(a));
  b = normalized(std::move(b));
  while (!b.empty()) {
    ZPoly r = normalized(positive_remainder(a, b));
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}
/// a / b when b divides a in Q[x] and b is primitive: the quotient is in Z[x].
inline ZPoly exact_quotient(ZPoly a, const ZPoly& b) {
  const int db = degree(b);
  check(db >= 0, "exact division by zero");
  trim(a);
  if (degree(a) < db) {
    check(a.empty(), "inexact polynomial division");
    return {};
  }
  ZPoly q(a.size() - db);
  for (int k = degree(a) - db; k >= 0; --k) {
    Z c = a[k + db];
    check(mpz_divisible_p(c.get_mpz_t(), b.back().get_mpz_t()) != 0, "inexact polynomial division");
    mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), b.back().get_mpz_t());
    q[k] = c;
    for (int i = 0; i <= db; ++i) a[k + i] -= c * b[i];
  }
  trim(a);
  check(a.empty(), "inexact polynomial division");
  trim(q);
  return q;
}

/// Square-free factorization (Yun 1976): f = c * prod_k factors[k]^(k+1).
inline std::vector<ZPoly> yun(const ZPoly& f0) {
  std::vector<ZPoly> factors;
  ZPoly f = normalized(f0);
  if (degree(f) <= 0) return factors;
  const ZPoly fp = derivative(f);
  const ZPoly a0 = gcd(f, fp);
  ZPoly b = exact_quotient(f, a0);
  ZPoly c = exact_quotient(fp, a0);
  ZPoly d = sub(c, derivative(b));
  while (degree(b) > 0) {
    const ZPoly a = gcd(b, d);
    factors.push_back(a);
    b = exact_quotient(b, a);
    c = exact_quotient(d, a);
    d = sub(c, derivative(b));
  }
  return factors;
}

/// Sign of p(x) for a rational x, with integers only (homogeneous Horner).
inline int sign_at(const ZPoly& p, const Q& x) {
  if (p.empty()) return 0;
  const Z& n = x.get_num();
  const Z& d = x.get_den();
  Z acc = p.back(), dpow = 1;
  for (int i = degree(p) - 1; i >= 0; --i) {
    dpow *= d;
    acc = acc * n + p[i] * dpow;
  }
  return sign(acc);
}
inline Q value_at(const ZPoly& p, const Q& x) {
  Q acc = 0;
  for (int i = degree(p); i >= 0; --i) acc = acc * x + p[i];
  return acc;
}

// ---------------------------------------------------- rational intervals
struct Ival {
  Q lo, hi;
  static Ival point(const Q& q) { return {q, q}; }
  bool contains_zero() const { return lo <= 0 && hi >= 0; }
  bool is_point() const { return lo == hi; }
  Q width() const { return hi - lo; }
};
inline Ival operator+(const Ival& a, const Ival& b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Ival operator-(const Ival& a, const Ival& b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline Ival operator-(const Ival& a) { return {-a.hi, -a.lo}; }
inline Ival operator*(const Ival& a, const Ival& b) {
  if (a.is_point() && b.is_point()) return Ival::point(a.lo * b.lo);
  const Q p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
inline Ival scale(const Ival& a, const Q& c) {
  return c >= 0 ? Ival{a.lo * c, a.hi * c} : Ival{a.hi * c, a.lo * c};
}
inline Ival divide(const Ival& a, const Ival& b) {
  check(!b.contains_zero(), "interval division by an interval containing 0");
  return a * Ival{1 / b.hi, 1 / b.lo};
}
inline bool disjoint(const Ival& a, const Ival& b) { return a.hi < b.lo || b.hi < a.lo; }

inline Ival eval(const ZPoly& p, const Ival& x) {
  Ival acc = Ival::point(0);
  for (int i = degree(p); i >= 0; --i) acc = acc * x + Ival::point(Q(p[i]));
  return acc;
}
/// Interval value of a bivariate polynomial A[i][j] s^i t^j on a box.
inline Ival eval(const ZBi& A, const Ival& s, const Ival& t) {
  std::size_t nj = 0;
  for (const auto& row : A) nj = std::max(nj, row.size());
  Ival acc = Ival::point(0);
  for (int j = static_cast<int>(nj) - 1; j >= 0; --j) {
    Ival column = Ival::point(0);
    for (int i = static_cast<int>(A.size()) - 1; i >= 0; --i)
      column = column * s + Ival::point(Q(j < static_cast<int>(A[i].size()) ? A[i][j] : Z(0)));
    acc = acc * t + column;
  }
  return acc;
}

// -------------------------------------------------------------- bivariate
inline ZBi bi_zero(int n) { return ZBi(n + 1, std::vector<Z>(n + 1, Z(0))); }
inline int bi_size(const ZBi& A) { return static_cast<int>(A.size()); }
inline bool bi_is_zero(const ZBi& A) {
  for (const auto& r : A)
    for (const Z& c : r)
      if (c != 0) return false;
  return true;
}
inline ZBi bi_mul(const ZBi& A, const ZBi& B) {
  const int n = bi_size(A) + bi_size(B) - 2;
  ZBi C = bi_zero(std::max(n, 0));
  for (int i = 0; i < bi_size(A); ++i)
    for (int j = 0; j < static_cast<int>(A[i].size()); ++j) {
      if (A[i][j] == 0) continue;
      for (int k = 0; k < bi_size(B); ++k)
        for (int l = 0; l < static_cast<int>(B[k].size()); ++l)
          if (B[k][l] != 0) C[i + k][j + l] += A[i][j] * B[k][l];
    }
  return C;
}
/// A(c00 u + c01 w, c10 u + c11 w).
inline ZBi bi_substitute(const ZBi& A, const Z c[2][2]) {
  const int n = bi_size(A) - 1;
  ZBi L1 = bi_zero(1), L2 = bi_zero(1);
  L1[1][0] = c[0][0];
  L1[0][1] = c[0][1];
  L2[1][0] = c[1][0];
  L2[0][1] = c[1][1];
  std::vector<ZBi> p1{bi_zero(0)}, p2{bi_zero(0)};
  p1[0][0][0] = 1;
  p2[0][0][0] = 1;
  for (int k = 1; k <= n; ++k) {
    p1.push_back(bi_mul(p1.back(), L1));
    p2.push_back(bi_mul(p2.back(), L2));
  }
  ZBi out = bi_zero(std::max(n, 0));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < static_cast<int>(A[i].size()); ++j) {
      if (A[i][j] == 0) continue;
      const ZBi term = bi_mul(p1[i], p2[j]);
      for (int k = 0; k < bi_size(term); ++k)
        for (int l = 0; l < static_cast<int>(term[k].size()); ++l)
          if (k <= n && l <= n) out[k][l] += A[i][j] * term[k][l];
          else check(term[k][l] == 0, "substitution degree");
    }
  return out;
}
inline ZBi bi_derivative(const ZBi& A, bool in_first) {
  const int n = bi_size(A) - 1;
  ZBi D = bi_zero(std::max(n, 0));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < static_cast<int>(A[i].size()); ++j) {
      if (A[i][j] == 0) continue;
      if (in_first && i > 0) D[i - 1][j] += A[i][j] * i;
      if (!in_first && j > 0) D[i][j - 1] += A[i][j] * j;
    }
  return D;
}
/// The coefficient of w^j as a polynomial in u.
inline ZPoly bi_column(const ZBi& A, int j) {
  ZPoly p;
  for (int i = 0; i < bi_size(A); ++i) p.push_back(j < static_cast<int>(A[i].size()) ? A[i][j] : Z(0));
  trim(p);
  return p;
}
inline int bi_w_degree(const ZBi& A) {
  int d = -1;
  for (const auto& r : A)
    for (int j = 0; j < static_cast<int>(r.size()); ++j)
      if (r[j] != 0) d = std::max(d, j);
  return d;
}
inline int bi_total_degree(const ZBi& A) {
  int d = -1;
  for (int i = 0; i < bi_size(A); ++i)
    for (int j = 0; j < static_cast<int>(A[i].size()); ++j)
      if (A[i][j] != 0) d = std::max(d, i + j);
  return d;
}
/// Scale to coprime integers (a nonzero constant factor changes no zero).
inline ZBi bi_from_rational(const std::vector<std::vector<Q>>& A) {
  Z l = 1;
  for (const auto& r : A)
    for (const Q& c : r) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  ZBi out;
  Z g = 0;
  for (const auto& r : A) {
    out.emplace_back();
    for (const Q& c : r) {
      out.back().push_back(c.get_num() * (l / c.get_den()));
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), out.back().back().get_mpz_t());
    }
  }
  if (g > 1)
    for (auto& r : out)
      for (Z& c : r) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
  return out;
}

// ------------------------------------------------ determinants of polynomial matrices
/// Fraction-free Gaussian elimination (Bareiss 1968): the exact determinant.
inline Z bareiss(std::vector<std::vector<Z>> M) {
  const int n = static_cast<int>(M.size());
  if (n == 0) return 1;
  int sgn_ = 1;
  Z prev = 1;
  for (int k = 0; k < n - 1; ++k) {
    if (M[k][k] == 0) {
      int p = k + 1;
      while (p < n && M[p][k] == 0) ++p;
      if (p == n) return 0;
      std::swap(M[k], M[p]);
      sgn_ = -sgn_;
    }
    for (int i = k + 1; i < n; ++i) {
      for (int j = k + 1; j < n; ++j) {
        M[i][j] = M[i][j] * M[k][k] - M[i][k] * M[k][j];
        mpz_divexact(M[i][j].get_mpz_t(), M[i][j].get_mpz_t(), prev.get_mpz_t());
      }
    }
    prev = M[k][k];
  }
  return sgn_ * M[n - 1][n - 1];
}

using PolyMatrix = std::vector<std::vector<ZPoly>>;

/// det(M(u)) as a polynomial: evaluation at deg + 1 integer points, exact
/// Newton interpolation. deg is bounded by the smaller of the sums over rows
/// and over columns of the entries' largest degrees (each Leibniz term takes
/// one entry per row and per column).
inline ZPoly determinant_polynomial(const PolyMatrix& M) {
  const int n = static_cast<int>(M.size());
  if (n == 0) return ZPoly{Z(1)};
  long row_bound = 0, column_bound = 0;
  for (int r = 0; r < n; ++r) {
    int d = 0;
    for (int c = 0; c < n; ++c) d = std::max(d, degree(M[r][c]));
    row_bound += d;
  }
  for (int c = 0; c < n; ++c) {
    int d = 0;
    for (int r = 0; r < n; ++r) d = std::max(d, degree(M[r][c]));
    column_bound += d;
  }
  const long D = std::min(row_bound, column_bound);
  std::vector<Q> xs, ys;
  std::vector<std::vector<Z>> E(n, std::vector<Z>(n));
  for (long k = 0; k <= D; ++k) {
    const Z x = k - D / 2;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        Z acc = 0;
        for (int i = degree(M[r][c]); i >= 0; --i) acc = acc * x + M[r][c][i];
        E[r][c] = acc;
      }
    xs.push_back(Q(x));
    ys.push_back(Q(bareiss(E)));
  }
  // Newton divided differences, then the monomial coefficients.
  const int m = static_cast<int>(xs.size());
  std::vector<Q> dd = ys;
  for (int j = 1; j < m; ++j)
    for (int i = m - 1; i >= j; --i) dd[i] = (dd[i] - dd[i - 1]) / (xs[i] - xs[i - j]);
  QPoly p{dd[m - 1]};
  for (int i = m - 2; i >= 0; --i) {
    QPoly next(p.size() + 1, Q(0));
    for (std::size_t k = 0; k < p.size(); ++k) {
      next[k + 1] += p[k];
      next[k] -= p[k] * xs[i];
    }
    next[0] += dd[i];
    p = std::move(next);
  }
  ZPoly z;
  for (const Q& c : p) {
    check(c.get_den() == 1, "resultant with a non-integer coefficient");
    z.push_back(c.get_num());
  }
  trim(z);
  return z;
}

/// res_w(F, G) and the first subresultant S_1 = s11 w + s10 (when it certifies
/// a unique common zero; see the top of the file).
struct Elimination {
  ZPoly res;
  bool has_s1 = false;
  ZPoly s11, s10;
};

inline Elimination eliminate(const ZBi& F, const ZBi& G) {
  Elimination e;
  const int m = bi_w_degree(F), n = bi_w_degree(G);
  if (m < 0 || n < 0) return e;  // a zero polynomial: res = 0
  std::vector<ZPoly> f, g;
  for (int j = 0; j <= m; ++j) f.push_back(bi_column(F, j));
  for (int j = 0; j <= n; ++j) g.push_back(bi_column(G, j));
  const bool f_const_lc = degree(f[m]) == 0, g_const_lc = degree(g[n]) == 0;
  // The specialization and multiplicity theorems need a constant leading
  // coefficient; every system built here has both, or one polynomial free of w.
  check((m == 0 || f_const_lc) && (n == 0 || g_const_lc), "leading coefficient depends on the other variable");
  check(m + n > 0, "both polynomials free of the eliminated variable");
  auto coefficient_row = [](const std::vector<ZPoly>& p, int deg, int shift, int width, int top) {
    // the coefficients of w^shift p over the powers top, top-1, ..., top-width+1
    std::vector<ZPoly> row(width);
    for (int c = 0; c < width; ++c) {
      const int power = top - c - shift;
      if (power >= 0 && power <= deg) row[c] = p[power];
    }
    return row;
  };
  PolyMatrix S;
  for (int r = n - 1; r >= 0; --r) S.push_back(coefficient_row(f, m, r, m + n, m + n - 1));
  for (int r = m - 1; r >= 0; --r) S.push_back(coefficient_row(g, n, r, m + n, m + n - 1));
  e.res = determinant_polynomial(S);
  if (n == 1 && g_const_lc) {
    e.has_s1 = true;
    e.s11 = g[1];
    e.s10 = g[0];
  } else if (m == 1 && f_const_lc) {
    e.has_s1 = true;
    e.s11 = f[1];
    e.s10 = f[0];
  } else if (n == 1 && m == 0) {  // F free of w, G linear with varying lc
    e.has_s1 = true;
    e.s11 = g[1];
    e.s10 = g[0];
  } else if (m == 1 && n == 0) {
    e.has_s1 = true;
    e.s11 = f[1];
    e.s10 = f[0];
  } else if (m >= 2 && n >= 2) {
    const int width = m + n - 1;  // powers m+n-2 .. 0
    PolyMatrix T;
    for (int r = n - 2; r >= 0; --r) T.push_back(coefficient_row(f, m, r, width, m + n - 2));
    for (int r = m - 2; r >= 0; --r) T.push_back(coefficient_row(g, n, r, width, m + n - 2));
    const int size = m + n - 2;
    PolyMatrix A(size), B(size);
    for (int r = 0; r < size; ++r) {
      A[r].assign(T[r].begin(), T[r].begin() + size);  // powers m+n-2 .. 1
      B[r].assign(T[r].begin(), T[r].begin() + size - 1);
      B[r].push_back(T[r][width - 1]);  // power 0 instead of 1
    }
    e.has_s1 = true;
    e.s11 = determinant_polynomial(A);
    e.s10 = determinant_polynomial(B);
  }
  return e;
}

// --------------------------------------------------------- real roots
/// One real root of a square-free polynomial g.
struct Root {
  Q lo, hi;      // enclosure: the root is in (lo, hi), or equals lo == hi
  Q nlo, nhi;    // isolating neighbourhood: the only root of g in (nlo, nhi)
  int sign_lo = 0;  // sign of g on (lo, root), for bisection
  int piece = 0;    // index of the domain piece (breaks[piece], breaks[piece+1]]
  bool exact() const { return lo == hi; }
  Ival interval() const { return {lo, hi}; }
};

using Bern = std::vector<Z>;

inline int variations(const Bern& b) {
  int v = 0, last = 0;
  for (const Z& c : b) {
    const int s = sign(c);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}
/// Bernstein coefficients (up to a positive factor) of g on [lo, hi].
inline Bern bernstein_on(const ZPoly& g, const Q& lo, const Q& hi) {
  const int d = degree(g);
  QPoly h;  // g(lo + (hi - lo) y)
  const Q w = hi - lo;
  for (int i = d; i >= 0; --i) {
    QPoly next(h.size() + 1, Q(0));
    for (std::size_t k = 0; k < h.size(); ++k) {
      next[k] += h[k] * lo;
      next[k + 1] += h[k] * w;
    }
    next[0] += g[i];
    h = std::move(next);
  }
  h.resize(d + 1, Q(0));
  std::vector<Z> binom(d + 1);
  for (int k = 0; k <= d; ++k) mpz_bin_uiui(binom[k].get_mpz_t(), d, k);
  QPoly b(d + 1, Q(0));
  for (int i = 0; i <= d; ++i) {
    Z ci = 1;  // C(i, k)
    for (int k = 0; k <= i; ++k) {
      b[i] += h[k] * ratio(ci, binom[k]);
      ci = ci * (i - k) / (k + 1);
    }
  }
  Z l = 1;
  for (const Q& c : b) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  Bern out;
  for (const Q& c : b) out.push_back(c.get_num() * (l / c.get_den()));
  return out;
}
/// Exact de Casteljau at 1/2 on integers (both halves scaled by 2^d).
inline void split_half(const Bern& b, Bern& left, Bern& right) {
  const int d = static_cast<int>(b.size()) - 1;
  Bern work = b;
  left.assign(d + 1, Z(0));
  right.assign(d + 1, Z(0));
  left[0] = work[0] << d;
  right[d] = work[d] << d;
  for (int r = 1; r <= d; ++r) {
    for (int i = 0; i <= d - r; ++i) work[i] += work[i + 1];
    left[r] = work[0] << (d - r);
    right[d - r] = work[d - r] << (d - r);
  }
  auto reduce = [](Bern& v) {
    Z g = 0;
    for (const Z& c : v) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    if (g > 1)
      for (Z& c : v) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
  };
  reduce(left);
  reduce(right);
}
inline int first_sign(const Bern& b) {
  for (const Z& c : b)
    if (c != 0) return sign(c);
  return 0;
}

/// Roots of g in the open interval (lo, hi), by Descartes' rule on Bernstein
/// coefficients (zeros at the ends are ignored: they are roots at lo or hi,
/// recorded separately, and dropping them keeps the count of the quotient).
inline void descartes(const Bern& b, const Q& lo, const Q& hi, int piece, std::vector<Root>& out, int depth = 0) {
  const int v = variations(b);
  if (v == 0) return;
  if (v == 1) {
    Root r;
    r.lo = r.nlo = lo;
    r.hi = r.nhi = hi;
    r.sign_lo = first_sign(b);
    r.piece = piece;
    out.push_back(r);
    return;
  }
  check(depth < 4000, "root isolation did not terminate (polynomial not square-free?)");
  const Q m = (lo + hi) / 2;
  Bern left, right;
  split_half(b, left, right);
  descartes(left, lo, m, piece, out, depth + 1);
  if (right[0] == 0) {
    Root r;
    r.lo = r.hi = m;
    r.piece = piece;
    out.push_back(r);
  }
  descartes(right, m, hi, piece, out, depth + 1);
}

struct RealRoots {
  ZPoly g;                 // square-free, primitive
  std::vector<Q> breaks;   // domain pieces (breaks[k], breaks[k+1]]
  std::vector<Root> roots; // increasing
};

inline void bisect(const ZPoly& g, Root& r) {
  if (r.exact()) return;
  const Q m = (r.lo + r.hi) / 2;
  const int s = sign_at(g, m);
  if (s == 0) r.lo = r.hi = m;
  else if (s == r.sign_lo) r.lo = m;
  else r.hi = m;
}
/// The simplest rational (smallest denominator) in [lo, hi], lo <= hi.
inline Q simplest_between(Q lo, Q hi) {
  Z c;
  mpz_cdiv_q(c.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());  // ceil(lo)
  if (Q(c) <= hi) {
    // integers in range: the one closest to zero
    Z f;
    mpz_fdiv_q(f.get_mpz_t(), hi.get_num_mpz_t(), hi.get_den_mpz_t());
    if (c <= 0 && f >= 0) return Q(0);
    return c > 0 ? Q(c) : Q(f);
  }
  Z fl;
  mpz_fdiv_q(fl.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  const Q frac = simplest_between(1 / (hi - fl), 1 / (lo - fl));
  return Q(fl) + 1 / frac;
}
/// Refines to width <= width; then a rational root of small denominator is
/// recognized exactly (the simplest rational of the enclosure is tried).
inline void refine_to(const ZPoly& g, Root& r, const Q& width) {
  while (!r.exact() && r.hi - r.lo > width) bisect(g, r);
  if (!r.exact()) {
    const Q q = simplest_between(r.lo, r.hi);
    if (q > r.lo && q < r.hi && sign_at(g, q) == 0) r.lo = r.hi = q;
  }
}

/// Isolates the real roots of the square-free g in [breaks.front(), breaks.back()].
inline RealRoots isolate(const ZPoly& g, std::vector<Q> breaks) {
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  RealRoots rr;
  rr.g = g;
  rr.breaks = breaks;
  if (degree(g) <= 0) return rr;
  for (std::size_t k = 0; k < breaks.size(); ++k) {
    if (k > 0) descartes(bernstein_on(g, breaks[k - 1], breaks[k]), breaks[k - 1], breaks[k], static_cast<int>(k) - 1, rr.roots);
    if (sign_at(g, breaks[k]) == 0) {
      Root r;
      r.lo = r.hi = breaks[k];
      r.piece = k == 0 ? -1 : static_cast<int>(k) - 1;
      rr.roots.push_back(r);
    }
  }
  // Neighbourhoods of exact roots: (r - delta, r + delta) free of other roots.
  for (Root& r : rr.roots) {
    if (!r.exact()) continue;
    Q delta = 1;
    for (int it = 0;; ++it) {
      check(it < 4000, "neighbourhood of an exact root");
      const Bern left = bernstein_on(g, r.lo - delta, r.lo), right = bernstein_on(g, r.lo, r.lo + delta);
      if (variations(left) == 0 && variations(right) == 0) break;
      delta /= 2;
    }
    r.nlo = r.lo - delta;
    r.nhi = r.lo + delta;
  }
  return rr;
}

/// Does h (a divisor of the square-free g) vanish at the root r of g?
inline bool vanishes_at(const ZPoly& h, const ZPoly& g, Root& r) {
  if (h.empty()) return true;
  if (degree(h) == 0) return false;
  if (r.exact()) return sign_at(h, r.lo) == 0;
  // Two points strictly inside the neighbourhood on either side of the root:
  // no root of g there, so h is nonzero at both and changes sign iff h(root) = 0.
  for (int it = 0; !(r.lo > r.nlo && r.hi < r.nhi); ++it) {
    check(it < 100000, "vanishing test");
    bisect(g, r);
    if (r.exact()) return sign_at(h, r.lo) == 0;
  }
  return sign_at(h, r.lo) != sign_at(h, r.hi);
}

// ---------------------------------------------------------------- projections
/// Elimination of w after the change of coordinates (u, w) = M (s, t).
struct Projection {
  Z m[2][2];    // (u, w) = m (s, t)
  Z inv[2][2];  // (s, t) = inv (u, w)
  ZBi F, G;
  Elimination e;
  std::vector<ZPoly> factors;  // res = c prod factors[k]^(k+1)
  RealRoots rr;
  ZPoly psc_gcd;               // gcd(s11, g): s11 vanishes at a root of g iff this does
  std::vector<int> multiplicity_cache, unique_cache;
  std::vector<std::optional<std::pair<int, int>>> point_cache;
  std::vector<bool> point_known;

  int multiplicity(int k) {
    if (multiplicity_cache[k] > 0) return multiplicity_cache[k];
    for (std::size_t f = 0; f < factors.size(); ++f)
      if (vanishes_at(factors[f], rr.g, rr.roots[k])) return multiplicity_cache[k] = static_cast<int>(f) + 1;
    check(false, "root of the square-free part in no square-free factor");
    return 0;
  }
  /// Exactly one common zero (complex) lies above the root k.
  bool unique(int k) {
    if (unique_cache[k] >= 0) return unique_cache[k] == 1;
    const bool u = e.has_s1 && !vanishes_at(psc_gcd, rr.g, rr.roots[k]);
    unique_cache[k] = u ? 1 : 0;
    return u;
  }
};

inline Projection make_projection(const ZBi& P, const ZBi& Qp, int kind, long lambda, std::vector<Q> breaks) {
  // kind 0: u = s, w = t; kind 1: u = t, w = s; kind 2: u = s + lambda t, w = t.
  Projection pr;
  for (auto& r : pr.m)
    for (auto& c : r) c = 0;
  for (auto& r : pr.inv)
    for (auto& c : r) c = 0;
  if (kind == 0) {
    pr.m[0][0] = pr.m[1][1] = pr.inv[0][0] = pr.inv[1][1] = 1;
  } else if (kind == 1) {
    pr.m[0][1] = pr.m[1][0] = pr.inv[0][1] = pr.inv[1][0] = 1;
  } else {
    pr.m[0][0] = pr.m[1][1] = pr.inv[0][0] = pr.inv[1][1] = 1;
    pr.m[0][1] = lambda;
    pr.inv[0][1] = -lambda;
  }
  pr.F = kind == 0 ? P : bi_substitute(P, pr.inv);
  pr.G = kind == 0 ? Qp : bi_substitute(Qp, pr.inv);
  pr.e = eliminate(pr.F, pr.G);
  if (pr.e.res.empty()) return pr;
  pr.factors = yun(pr.e.res);
  ZPoly g{Z(1)};
  for (const ZPoly& f : pr.factors) {
    ZPoly prod(g.size() + f.size() - 1, Z(0));
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = 0; j < f.size(); ++j) prod[i + j] += g[i] * f[j];
    g = normalized(prod);
  }
  pr.rr = isolate(g, std::move(breaks));
  if (pr.e.has_s1) pr.psc_gcd = gcd(pr.e.s11, g);
  const std::size_t n = pr.rr.roots.size();
  pr.multiplicity_cache.assign(n, 0);
  pr.unique_cache.assign(n, -1);
  pr.point_cache.assign(n, std::nullopt);
  pr.point_known.assign(n, false);
  return pr;
}

/// A common zero of P and Q: root indices into the s-roots and t-roots.
struct Zero {
  int i = 0, j = 0, multiplicity = 0;
};

struct ZeroSearch {
  const ZBi& P;
  const ZBi& Qp;
  Ival I, J;
  bool symmetric;
  std::vector<Projection> projections;  // [0] a side, [1] b side, then sheared
  std::vector<bool> in_I, in_J;

  std::vector<Root>& S() { return projections[0].rr.roots; }
  std::vector<Root>& T() { return projections[1].rr.roots; }
  const ZPoly& gS() { return projections[0].rr.g; }
  const ZPoly& gT() { return projections[1].rr.g; }

  static bool member(const Root& r, const RealRoots& rr, const Ival& X) {
    if (r.exact()) return X.lo <= r.lo && r.lo <= X.hi;
    if (r.piece < 0) return false;
    return X.lo <= rr.breaks[r.piece] && rr.breaks[r.piece + 1] <= X.hi;
  }

  /// The root (index) of T whose neighbourhood holds the t-interval, or -1.
  static int holder(const std::vector<Root>& roots, const Ival& x) {
    for (std::size_t k = 0; k < roots.size(); ++k)
      if (roots[k].nlo < x.lo && x.hi < roots[k].nhi) return static_cast<int>(k);
    return -1;
  }

  /// The unique common zero above root k of projection p: (s-root, t-root)
  /// indices, or nullopt when it is outside I x J.
  std::optional<std::pair<int, int>> certified_point(int p, int k) {
    Projection& pr = projections[p];
    if (pr.point_known[k]) return pr.point_cache[k];
    Root& r = pr.rr.roots[k];
    std::optional<std::pair<int, int>> result;
    for (int it = 0;; ++it) {
      check(it < 100000, "certified point did not converge");
      const Ival U = r.interval();
      const Ival d = eval(pr.e.s11, U);
      if (d.contains_zero()) {
        check(!r.exact(), "S11 vanishes at a root called unique");
        bisect(pr.rr.g, r);
        continue;
      }
      const Ival W = -divide(eval(pr.e.s10, U), d);
      const Ival s = scale(U, Q(pr.inv[0][0])) + scale(W, Q(pr.inv[0][1]));
      const Ival t = scale(U, Q(pr.inv[1][0])) + scale(W, Q(pr.inv[1][1]));
      if (disjoint(s, I) || disjoint(t, J)) break;
      const int i = holder(S(), s), j = holder(T(), t);
      if (i >= 0 && j >= 0) {
        result = std::make_pair(i, j);
        break;
      }
      check(!r.exact(), "exact point outside every neighbourhood");
      bisect(pr.rr.g, r);
    }
    pr.point_known[k] = true;
    pr.point_cache[k] = result;
    return result;
  }

  /// The root of projection p at u(s_i, t_j) if (i, j) is a zero; -1 when no
  /// root of projection p can be there (then (i, j) is not a zero).
  int locate(int p, int i, int j) {
    if (p == 0) return i;
    if (p == 1) return j;
    Projection& pr = projections[p];
    for (int it = 0;; ++it) {
      check(it < 100000, "locating a candidate in a projection");
      const Ival U = scale(S()[i].interval(), Q(pr.m[0][0])) + scale(T()[j].interval(), Q(pr.m[0][1]));
      std::vector<int> inside;
      bool undecided = false;
      for (std::size_t k = 0; k < pr.rr.roots.size(); ++k) {
        Root& r = pr.rr.roots[k];
        if (r.exact()) {
          if (U.lo <= r.lo && r.lo <= U.hi) inside.push_back(static_cast<int>(k));
        } else if (r.hi <= U.lo || r.lo >= U.hi) {
        } else if (r.lo >= U.lo && r.hi <= U.hi) {
          inside.push_back(static_cast<int>(k));
        } else {
          undecided = true;
          bisect(pr.rr.g, r);
        }
      }
      if (undecided) continue;
      if (inside.empty()) return -1;
      if (inside.size() == 1) return inside[0];
      bisect(gS(), S()[i]);
      bisect(gT(), T()[j]);
    }
  }

  bool excluded(int i, int j) {
    const Ival s = S()[i].interval(), t = T()[j].interval();
    return !eval(P, s, t).contains_zero() || !eval(Qp, s, t).contains_zero();
  }

  std::optional<std::vector<Zero>> run(std::vector<Q> breaks_s, std::vector<Q> breaks_t) {
    projections.push_back(make_projection(P, Qp, 0, 0, breaks_s));
    if (projections[0].e.res.empty()) return std::nullopt;
    if (symmetric) {
      Projection mirror = projections[0];
      for (auto& r : mirror.m)
        for (auto& c : r) c = 0;
      for (auto& r : mirror.inv)
        for (auto& c : r) c = 0;
      mirror.m[0][1] = mirror.m[1][0] = mirror.inv[0][1] = mirror.inv[1][0] = 1;
      projections.push_back(std::move(mirror));
    } else {
      projections.push_back(make_projection(P, Qp, 1, 0, breaks_t));
      check(!projections[1].e.res.empty(), "one resultant zero, the other not");
    }
    for (const Root& r : S()) in_I.push_back(member(r, projections[0].rr, I));
    for (const Root& r : T()) in_J.push_back(member(r, projections[1].rr, J));

    // 0 unknown, 1 zero, 2 not a zero
    std::vector<std::pair<int, int>> candidates;
    for (std::size_t i = 0; i < S().size(); ++i)
      for (std::size_t j = 0; j < T().size(); ++j)
        if (in_I[i] && in_J[j] && !(symmetric && i == j)) candidates.emplace_back(int(i), int(j));
    std::vector<int> state(candidates.size(), 0), mult(candidates.size(), 0);

    for (int level : {12, 32}) {
      const Q width(Z(1), Z(1) << level);
      for (std::size_t i = 0; i < S().size(); ++i)
        if (in_I[i]) refine_to(gS(), S()[i], width);
      for (std::size_t j = 0; j < T().size(); ++j)
        if (in_J[j]) refine_to(gT(), T()[j], width);
      for (std::size_t c = 0; c < candidates.size(); ++c)
        if (state[c] == 0 && excluded(candidates[c].first, candidates[c].second)) state[c] = 2;
    }

    auto unknown = [&] { return std::count(state.begin(), state.end(), 0); };
    const int total = std::max(1, degree(projections[0].e.res));
    const int max_projections = total + 2;
    long lambda = 0;
    for (int p = 0; unknown() > 0 && p < max_projections; ++p) {
      if (p >= 2) {
        // next shear whose leading coefficients stay constant
        std::optional<Projection> next;
        while (!next) {
          lambda = lambda > 0 ? -lambda : -lambda + 1;
          check(lambda < 10000, "no usable shear");
          Z inv[2][2] = {{Z(1), Z(-lambda)}, {Z(0), Z(1)}};
          const ZBi F = bi_substitute(P, inv), G = bi_substitute(Qp, inv);
          if (degree(bi_column(F, bi_w_degree(F))) != 0 || degree(bi_column(G, bi_w_degree(G))) != 0) continue;
          Ival Ds{breaks_s.front(), breaks_s.back()}, Dt{breaks_t.front(), breaks_t.back()};
          const Ival U = Ds + scale(Dt, Q(lambda));
          next = make_projection(P, Qp, 2, lambda, {U.lo - 1, U.hi + 1});
        }
        check(!next->e.res.empty(), "sheared resultant vanishes");
        projections.push_back(std::move(*next));
        p = static_cast<int>(projections.size()) - 1;
      }
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        if (state[c] != 0) continue;
        const auto [i, j] = candidates[c];
        const int k = locate(p, i, j);
        if (k < 0) {
          state[c] = 2;
          continue;
        }
        if (!projections[p].unique(k)) continue;
        const auto point = certified_point(p, k);
        if (point && point->first == i && point->second == j) {
          state[c] = 1;
          mult[c] = projections[p].multiplicity(k);
        } else {
          state[c] = 2;
        }
      }
    }
    // Last resorts: deeper exclusion; exact evaluation at rational parameters,
    // with the multiplicity the least over more projections than there are
    // common zeros (one of them then sees the point alone).
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (state[c] != 0) continue;
      const auto [i, j] = candidates[c];
      for (int it = 0; it < 2000 && state[c] == 0; ++it) {
        if (S()[i].exact() && T()[j].exact()) break;
        bisect(gS(), S()[i]);
        bisect(gT(), T()[j]);
        if (excluded(i, j)) state[c] = 2;
      }
      if (state[c] != 0) continue;
      if (!(S()[i].exact() && T()[j].exact()))
        fail("a common point where both curves are stationary, at irrational parameters: unsupported");
      if (excluded(i, j)) {
        state[c] = 2;
        continue;
      }
      check(static_cast<int>(projections.size()) >= max_projections, "too few projections for the fallback");
      int best = std::numeric_limits<int>::max();
      for (int p = 0; p < static_cast<int>(projections.size()); ++p) {
        const int k = locate(p, i, j);
        check(k >= 0, "zero without a root in a projection");
        best = std::min(best, projections[p].multiplicity(k));
      }
      state[c] = 1;
      mult[c] = best;
    }
    std::vector<Zero> zeros;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (state[c] != 1) continue;
      const auto [i, j] = candidates[c];
      // Cross-check with both resultants: each side's multiplicity counts
      // every common zero above the root, so it is >= this one, with equality
      // when this zero is alone above it.
      const int ma = projections[0].multiplicity(i), mb = projections[1].multiplicity(j);
      check(ma >= mult[c] && mb >= mult[c], "a-side or b-side multiplicity below the certified one");
      if (projections[0].unique(i)) check(ma == mult[c], "a-side multiplicity differs");
      if (projections[1].unique(j)) check(mb == mult[c], "b-side multiplicity differs");
      zeros.push_back(Zero{i, j, mult[c]});
    }
    return zeros;
  }
};

/// Jacobian check: multiplicity 1 iff det d(P,Q)/d(s,t) != 0 at the zero.
inline void check_jacobian(const ZBi& P, const ZBi& Qp, const ZPoly& gs, Root& s, const ZPoly& gt, Root& t,
                           int multiplicity) {
  const ZBi Ps = bi_derivative(P, true), Pt = bi_derivative(P, false);
  const ZBi Qs = bi_derivative(Qp, true), Qt = bi_derivative(Qp, false);
  for (int it = 0;; ++it) {
    const Ival S = s.interval(), T = t.interval();
    const Ival j = eval(Ps, S, T) * eval(Qt, S, T) - eval(Pt, S, T) * eval(Qs, S, T);
    if (multiplicity >= 2) {
      check(j.contains_zero(), "tangent intersection with a nonzero Jacobian");
      return;
    }
    if (!j.contains_zero()) return;
    check(!(s.exact() && t.exact()) && it < 100000, "transversal intersection with a zero Jacobian");
    bisect(gs, s);
    bisect(gt, t);
  }
}

// ------------------------------------------------------------ curves
inline QPoly power_coordinate(const ExactBezier& c, int k) {
  const int n = static_cast<int>(c.points.size()) - 1;
  QPoly p(n + 1, Q(0));
  for (int i = 0; i <= n; ++i) {
    Z bi;
    mpz_bin_uiui(bi.get_mpz_t(), n, i);
    for (int j = i; j <= n; ++j) {
      Z bj;
      mpz_bin_uiui(bj.get_mpz_t(), n - i, j - i);
      const Q term = c.points[i][k] * Q(bi * bj);
      if ((j - i) % 2 == 0) p[j] += term;
      else p[j] -= term;
    }
  }
  trim(p);
  return p;
}
inline void validate(const ExactBezier& c, const char* which) {
  if (c.points.size() < 2) fail(std::string("curve ") + which + " needs at least 2 control points");
  for (const auto& p : c.points)
    if (p != c.points.front()) return;
  fail(std::string("curve ") + which + " is a point (all control points equal)");
}
inline std::vector<std::vector<Q>> q_zero(int n) { return std::vector<std::vector<Q>>(n + 1, std::vector<Q>(n + 1, Q(0))); }

/// x_a(s) - x_b(t) as a bivariate polynomial (t eliminated first).
inline ZBi separated(const QPoly& fa, const QPoly& fb) {
  const int n = std::max({degree(fa), degree(fb), 0});
  auto A = q_zero(n);
  for (int i = 0; i <= degree(fa); ++i) A[i][0] += fa[i];
  for (int j = 0; j <= degree(fb); ++j) A[0][j] -= fb[j];
  return bi_from_rational(A);
}
/// (f(s) - f(t)) / (s - t) = sum_k f_k sum_{i+j=k-1} s^i t^j.
inline ZBi divided_difference(const QPoly& f) {
  const int n = std::max(degree(f) - 1, 0);
  auto A = q_zero(n);
  for (int k = 1; k <= degree(f); ++k)
    for (int i = 0; i <= k - 1; ++i) A[i][k - 1 - i] += f[k];
  return bi_from_rational(A);
}

/// Proper parametrization: almost every point traced by one parameter.
inline bool proper(const QPoly& x, const QPoly& y) {
  const ZBi dx = divided_difference(x), dy = divided_difference(y);
  const bool zx = degree(x) <= 0, zy = degree(y) <= 0;
  if (zx) return degree(y) == 1;
  if (zy) return degree(x) == 1;
  if (bi_w_degree(dx) <= 0 || bi_w_degree(dy) <= 0) return true;  // a line of degree 1 in one coordinate
  return !eliminate(dx, dy).res.empty();
}

/// For a curve whose control points are collinear: whether it turns back on
/// its line inside (0,1) (the coordinate along the line has a root of odd
/// multiplicity of its derivative there); nullopt when not collinear.
inline std::optional<bool> line_folds_back(const ExactBezier& c) {
  const auto& p = c.points;
  std::size_t k = 1;
  while (k < p.size() && p[k] == p[0]) ++k;
  if (k == p.size()) return std::nullopt;
  const Q dx = p[k][0] - p[0][0], dy = p[k][1] - p[0][1];
  for (const auto& q : p)
    if ((q[0] - p[0][0]) * dy - (q[1] - p[0][1]) * dx != 0) return std::nullopt;
  QPoly u = power_coordinate(c, 0), uy = power_coordinate(c, 1);
  u.resize(std::max(u.size(), uy.size()), Q(0));
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = u[i] * dx + (i < uy.size() ? uy[i] : Q(0)) * dy;
  trim(u);
  const std::vector<ZPoly> factors = yun(integer_multiple(derivative(u)));
  for (std::size_t f = 0; f < factors.size(); f += 2) {  // multiplicities 1, 3, 5, ...
    const RealRoots rr = isolate(factors[f], {Q(0), Q(1)});
    for (const Root& r : rr.roots)
      if (r.exact() ? (r.lo > 0 && r.lo < 1) : r.piece == 0) return true;
  }
  return false;
}

inline QPoly compose_affine(const QPoly& f, const Q& alpha, const Q& beta) {
  QPoly out;  // f(alpha t + beta)
  for (int i = degree(f); i >= 0; --i) {
    QPoly next(out.size() + 1, Q(0));
    for (std::size_t k = 0; k < out.size(); ++k) {
      next[k] += out[k] * beta;
      next[k + 1] += out[k] * alpha;
    }
    next[0] += f[i];
    out = std::move(next);
  }
  trim(out);
  return out;
}
/// A rational r with r^n = q, if there is one (r >= 0 when n is even).
inline std::optional<Q> rational_root(const Q& q, int n) {
  if (q < 0 && n % 2 == 0) return std::nullopt;
  Z num = abs(q.get_num()), rn, rd;
  const Z& den = q.get_den();
  if (mpz_root(rn.get_mpz_t(), num.get_mpz_t(), n) == 0) return std::nullopt;
  if (mpz_root(rd.get_mpz_t(), den.get_mpz_t(), n) == 0) return std::nullopt;
  Q r(rn, rd);
  r.canonicalize();
  return q < 0 ? Q(-r) : r;
}

inline Q width_for(int bits) { return Q(Z(1), Z(1) << bits); }

inline std::vector<Q> breaks_around(const std::vector<Ival>& intervals) {
  std::vector<Q> b;
  Q lo = intervals[0].lo, hi = intervals[0].hi;
  for (const Ival& x : intervals) {
    b.push_back(x.lo);
    b.push_back(x.hi);
    lo = std::min(lo, x.lo);
    hi = std::max(hi, x.hi);
  }
  b.push_back(lo - 1);
  b.push_back(hi + 1);
  return b;
}

inline void sort_intersections(std::vector<ExactIntersection>& v) {
  std::sort(v.begin(), v.end(), [](const ExactIntersection& x, const ExactIntersection& y) {
    if (x.a_lower != y.a_lower) return x.a_lower < y.a_lower;
    if (x.a_upper != y.a_upper) return x.a_upper < y.a_upper;
    return x.b_lower < y.b_lower;
  });
}

/// Common zeros in I x J of two bivariate polynomials, refined; nullopt when
/// they share a factor. In symmetric mode (P(s,t) = P(t,s), same for Q) the
/// diagonal s = t is skipped.
struct PointZero {
  Root s, t;
  int multiplicity;
  int i, j;  // indices of the s-root and t-root (same list in symmetric mode)
};
inline std::optional<std::vector<PointZero>> common_zeros(const ZBi& P, const ZBi& Qp, const Ival& I, const Ival& J,
                                                          bool symmetric, const Q& s_width, const Q& t_width) {
  ZeroSearch search{P, Qp, I, J, symmetric, {}, {}, {}};
  std::vector<Q> bs = symmetric ? breaks_around({I, J}) : breaks_around({I});
  std::vector<Q> bt = symmetric ? bs : breaks_around({J});
  std::sort(bs.begin(), bs.end());
  std::sort(bt.begin(), bt.end());
  auto zeros = search.run(bs, bt);
  if (!zeros) return std::nullopt;
  std::vector<PointZero> out;
  for (const Zero& z : *zeros) {
    Root& s = search.S()[z.i];
    Root& t = search.T()[z.j];
    refine_to(search.gS(), s, s_width);
    refine_to(search.gT(), t, t_width);
    check_jacobian(P, Qp, search.gS(), s, search.gT(), t, z.multiplicity);
    refine_to(search.gS(), s, s_width);
    refine_to(search.gT(), t, t_width);
    out.push_back(PointZero{s, t, z.multiplicity, z.i, z.j});
  }
  return out;
}

inline ExactIntersection point_intersection(const Ival& s, const Ival& t, int multiplicity) {
  ExactIntersection x;
  x.kind = multiplicity == 1 ? ExactIntersection::Kind::transversal : ExactIntersection::Kind::tangent;
  x.a_lower = s.lo;
  x.a_upper = s.hi;
  x.b_lower = t.lo;
  x.b_upper = t.hi;
  x.multiplicity = multiplicity;
  return x;
}

}  // namespace exact_intersection_detail

/// The exact point of a curve at a rational parameter (de Casteljau).
inline std::array<mpq_class, 2> exact_bezier_point(const ExactBezier& c, const mpq_class& t) {
  auto rows = c.points;
  const mpq_class s = 1 - t;
  for (std::size_t r = 1; r < rows.size(); ++r)
    for (std::size_t i = 0; i + r < rows.size(); ++i)
      for (int k = 0; k < 2; ++k) rows[i][k] = s * rows[i][k] + t * rows[i + 1][k];
  return rows.front();
}

/// The curve c(alpha u + beta) for u in [0,1], same degree, exact: the
/// sub-curve on [t0, t1] is exact_reparametrized(c, t1 - t0, t0), the reversed
/// curve exact_reparametrized(c, -1, 1).
inline ExactBezier exact_reparametrized(const ExactBezier& c, const mpq_class& alpha, const mpq_class& beta) {
  using namespace exact_intersection_detail;
  const int n = static_cast<int>(c.points.size()) - 1;
  ExactBezier out;
  out.points.resize(n + 1);
  for (int k = 0; k < 2; ++k) {
    QPoly p = compose_affine(power_coordinate(c, k), alpha, beta);
    p.resize(n + 1, Q(0));
    // power to Bernstein: b_i = sum_{j <= i} C(i,j)/C(n,j) p_j
    for (int i = 0; i <= n; ++i) {
      Q b = 0;
      for (int j = 0; j <= i; ++j) {
        Z cij, cnj;
        mpz_bin_uiui(cij.get_mpz_t(), i, j);
        mpz_bin_uiui(cnj.get_mpz_t(), n, j);
        b += p[j] * ratio(cij, cnj);
      }
      b.canonicalize();
      out.points[i][k] = b;
    }
  }
  return out;
}
inline ExactBezier exact_subcurve(const ExactBezier& c, const mpq_class& t0, const mpq_class& t1) {
  return exact_reparametrized(c, t1 - t0, t0);
}
inline ExactBezier exact_reversed(const ExactBezier& c) { return ExactBezier{{c.points.rbegin(), c.points.rend()}}; }
/// Degree elevation by one (Farin, "Curves and Surfaces for CAGD", 6.1).
inline ExactBezier exact_elevated(const ExactBezier& c) {
  const int n = static_cast<int>(c.points.size()) - 1;
  ExactBezier out;
  out.points.resize(n + 2);
  out.points[0] = c.points[0];
  out.points[n + 1] = c.points[n];
  for (int i = 1; i <= n; ++i)
    for (int k = 0; k < 2; ++k)
      out.points[i][k] = exact_intersection_detail::ratio(i, n + 1) * c.points[i - 1][k] +
                         exact_intersection_detail::ratio(n + 1 - i, n + 1) * c.points[i][k];
  return out;
}

/// Every intersection of a and b with both parameters in [0,1] (ends
/// included), sorted by a. Point parameters are isolated to width <= 2^-bits.
inline std::vector<ExactIntersection> exact_intersections(const ExactBezier& a, const ExactBezier& b, int bits = 80) {
  using namespace exact_intersection_detail;
  validate(a, "a");
  validate(b, "b");
  const QPoly xa = power_coordinate(a, 0), ya = power_coordinate(a, 1);
  const QPoly xb = power_coordinate(b, 0), yb = power_coordinate(b, 1);
  const ZBi P = separated(xa, xb), Qp = separated(ya, yb);
  const Ival unit{Q(0), Q(1)};
  std::vector<ExactIntersection> out;
  // Both x constant (two vertical segments) or both y constant: one equation
  // is free of both variables.
  const bool px = bi_total_degree(P) <= 0, py = bi_total_degree(Qp) <= 0;
  if ((px && bi_is_zero(P) == false) || (py && bi_is_zero(Qp) == false)) return out;  // parallel, distinct
  std::optional<std::vector<PointZero>> zeros;
  if (!px && !py) zeros = common_zeros(P, Qp, unit, unit, false, width_for(bits), width_for(bits));
  if (zeros) {
    for (const PointZero& z : *zeros) out.push_back(point_intersection(z.s.interval(), z.t.interval(), z.multiplicity));
    sort_intersections(out);
    return out;
  }
  // The curves lie on one algebraic curve: b(t) = a(alpha t + beta).
  if (!proper(xa, ya) || !proper(xb, yb))
    fail("the curves share a component and one of them traces part of it twice (improper parametrization)");
  const int n = std::max(degree(xa), degree(ya));
  check(std::max(degree(xb), degree(yb)) == n, "shared component with different degrees");
  const int k = degree(xa) == n ? 0 : 1;
  const QPoly& fa = k == 0 ? xa : ya;
  const QPoly& fb = k == 0 ? xb : yb;
  check(degree(fb) == n, "shared component: coordinate degrees differ");
  std::optional<std::pair<Q, Q>> phi;
  const auto root = rational_root(fb[n] / fa[n], n);
  check(root.has_value(), "shared component without a rational reparametrization");
  for (const Q& alpha : {*root, Q(-*root)}) {
    if (alpha == 0) continue;
    Q a_pow = 1;
    for (int i = 0; i < n - 1; ++i) a_pow *= alpha;
    const Q beta = (fb[n - 1] - fa[n - 1] * a_pow) / (n * fa[n] * a_pow);
    if (compose_affine(xa, alpha, beta) == xb && compose_affine(ya, alpha, beta) == yb) {
      phi = std::make_pair(alpha, beta);
      break;
    }
  }
  check(phi.has_value(), "shared component: no affine reparametrization");
  const Q alpha = phi->first, beta = phi->second;
  const Q end = alpha + beta;
  const Ival J{std::min(beta, end), std::max(beta, end)};  // b's arc in a's parameter
  const Q lo = std::max(Q(0), J.lo), hi = std::min(Q(1), J.hi);
  auto to_b = [&](const Q& s) { return Q((s - beta) / alpha); };
  if (lo < hi) {
    ExactIntersection x;
    x.kind = ExactIntersection::Kind::overlap;
    x.a_lower = lo;
    x.a_upper = hi;
    x.b_lower = std::min(to_b(lo), to_b(hi));
    x.b_upper = std::max(to_b(lo), to_b(hi));
    x.multiplicity = ExactIntersection::kSharedComponent;
    x.reversed = alpha < 0;
    out.push_back(x);
  } else if (lo == hi) {
    out.push_back(point_intersection(Ival::point(lo), Ival::point(to_b(lo)), ExactIntersection::kSharedComponent));
    out.back().kind = ExactIntersection::Kind::tangent;
  }
  // Crossings of the two arcs at double points of the curve: a(s) = a(s'),
  // s != s', s in [0,1], s' in J.
  const ZBi dx = divided_difference(xa), dy = divided_difference(ya);
  if (bi_total_degree(dx) > 0 && bi_total_degree(dy) > 0) {
    const Q abs_alpha = alpha < 0 ? Q(-alpha) : alpha;
    const Q t_width = width_for(bits) * std::min(Q(1), abs_alpha);
    const auto crossings = common_zeros(dx, dy, unit, J, true, width_for(bits), t_width);
    check(crossings.has_value(), "proper curve with a vanishing self-intersection resultant");
    for (const PointZero& z : *crossings) {
      const Ival t = scale(z.t.interval() - Ival::point(beta), 1 / alpha);
      out.push_back(point_intersection(z.s.interval(), t, z.multiplicity));
    }
  }
  sort_intersections(out);
  return out;
}

/// Every pair s < t in [0,1] with a(s) = a(t) (as a_lower..a_upper and
/// b_lower..b_upper), sorted by s; cusps are not reported.
inline std::vector<ExactIntersection> exact_self_intersections(const ExactBezier& a, int bits = 80) {
  using namespace exact_intersection_detail;
  validate(a, "a");
  const QPoly x = power_coordinate(a, 0), y = power_coordinate(a, 1);
  if (const auto folds = line_folds_back(a)) {
    if (*folds) fail("the curve runs along a line and turns back on it (it overlaps itself)");
    return {};
  }
  if (!proper(x, y)) fail("the curve traces part of itself twice (improper parametrization)");
  std::vector<ExactIntersection> out;
  const ZBi dx = divided_difference(x), dy = divided_difference(y);
  if (bi_total_degree(dx) <= 0 || bi_total_degree(dy) <= 0) return out;  // a nonzero constant: a line
  const Ival unit{Q(0), Q(1)};
  const auto zeros = common_zeros(dx, dy, unit, unit, true, width_for(bits), width_for(bits));
  check(zeros.has_value(), "proper curve with a vanishing self-intersection resultant");
  for (const PointZero& z : *zeros)
    if (z.i < z.j)  // s < t: the roots are listed in increasing order
      out.push_back(point_intersection(z.s.interval(), z.t.interval(), z.multiplicity));
  sort_intersections(out);
  return out;
}

/// The double nearest to q (ties to even).
inline double nearest_double(const mpq_class& q) {
  const double d = q.get_d();  // truncated toward zero
  double best = d;
  mpq_class best_error = abs(q - mpq_class(d));
  for (double c : {std::nextafter(d, HUGE_VAL), std::nextafter(d, -HUGE_VAL)}) {
    if (!std::isfinite(c)) continue;
    const mpq_class e = abs(q - mpq_class(c));
    if (e < best_error) {
      best = c;
      best_error = e;
    } else if (e == best_error) {
      std::uint64_t bits_c, bits_b;
      std::memcpy(&bits_c, &c, 8);
      std::memcpy(&bits_b, &best, 8);
      if ((bits_c & 1) == 0 && (bits_b & 1) == 1) best = c;
    }
  }
  return best;
}
/// The double estimate of an exact parameter: its interval's midpoint, rounded.
inline double exact_estimate(const mpq_class& lower, const mpq_class& upper) {
  return nearest_double(mpq_class((lower + upper) / 2));
}

/// How many doubles x is away from the nearest double that rounds a point of
/// [lower, upper]: 0 when x is the double nearest to some point of the interval.
inline double ulps_from(const mpq_class& lower, const mpq_class& upper, double x) {
  auto key = [](double v) {
    std::int64_t i;
    std::memcpy(&i, &v, 8);
    return i < 0 ? -(i & std::numeric_limits<std::int64_t>::max()) : i;
  };
  const double lo = nearest_double(lower), hi = nearest_double(upper);
  if (x >= lo && x <= hi) return 0.0;
  const std::int64_t kx = key(x), kf = key(x < lo ? lo : hi);
  if ((kx >= 0) == (kf >= 0)) return static_cast<double>(kx > kf ? kx - kf : kf - kx);
  return static_cast<double>(kx) - static_cast<double>(kf) < 0 ? static_cast<double>(kf) - static_cast<double>(kx)
                                                                : static_cast<double>(kx) - static_cast<double>(kf);
}

}  // namespace casteljau::test

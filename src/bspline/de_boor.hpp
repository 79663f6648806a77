#pragma once
// De Boor's algorithm as every B-spline point evaluator runs it: point_at,
// de_boor_net and the batch kernels of points_at.cpp call these functions
// (or, in the SIMD lanes, perform the same operations in the same order), so
// their results agree bit for bit. Internal to src/bspline.
//
// The arithmetic (The NURBS Book §5.3, eq. 5.11, on the span k of u):
//   a_{r,j} = (u - t_{k-p+j}) * (1 / (t_{k+1+j-r} - t_{k-p+j})),  j = p..r
//   P^r_j   = lerp_step(P^{r-1}_{j-1}, P^r_j, 1 - a, a)
// The reciprocal is what makes the batch fast: it depends only on the knots,
// so a sorted batch computes it once per span and each parameter then pays a
// subtraction and a multiplication instead of a division (a division costs
// 8-16 times a multiplication in SIMD lanes). It rounds twice instead of
// once, which moves a by at most one more unit in the last place. Two cases
// are fixed so that the result is what exact division gives:
//  - u == t_upper gives a = 1 exactly (d * RN(1/d) can round to 1 - 2^-53),
//    so a clamped curve still returns P_n exactly at the end of its domain;
//    u == t_lower gives a = 0 without help (0 * anything finite).
//  - a knot difference below 2^-1024 (subnormal knots only) has no finite
//    reciprocal: there the division is used.

#include <cmath>
#include <cstddef>
#include <span>

#include "../bezier/de_casteljau.hpp"

namespace casteljau::detail {

/// b - a c: rounded once (one fused multiply-add) where the target has FMA,
/// twice without; the same choice in every kernel of one build. Written out
/// because g++ contracts a*b+c in C++ even in ISO mode, and might otherwise
/// fuse the two statements in one kernel and not in another.
inline double subtract_product(double b, double a, double c) {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  return std::fma(-a, c, b);
#else
  const double product = a * c;
  return b - product;
#endif
}

/// The de Boor coefficient a = (u - lower) / (upper - lower) as casteljau
/// computes it, given reciprocal = 1 / (upper - lower) (see above).
inline double de_boor_alpha(double u, double lower, double upper, double reciprocal) {
  if (u == upper) return 1.0;
  if (std::isinf(reciprocal)) return (u - lower) / (upper - lower);
  return (u - lower) * reciprocal;
}

/// Rounds r = first..last of de Boor's algorithm, in place on rows[0..p]
/// (`width` doubles each, the control rows P_{k-p}..P_k of span k): row j
/// becomes lerp_step(row j-1, row j, 1 - a, a) for j = p down to r. After
/// rounds 1..p, row p holds the point.
inline void de_boor_rounds(std::span<const double> knots, int p, int span, double u, int first, int last,
                           double* rows, int width) {
  for (int r = first; r <= last; ++r) {
    for (int j = p; j >= r; --j) {
      const double lower = knots[static_cast<std::size_t>(span - p + j)];
      const double upper = knots[static_cast<std::size_t>(span + 1 + j - r)];
      const double a = de_boor_alpha(u, lower, upper, 1.0 / (upper - lower));
      const double s = 1.0 - a;
      double* row = rows + static_cast<std::ptrdiff_t>(j) * width;
      const double* previous = row - width;
      for (int k = 0; k < width; ++k) row[k] = lerp_step(previous[k], row[k], s, a);
    }
  }
}

/// The point and the first derivative from one de Boor triangle: after
/// rounds 1..p-1 the two rows Q_0 = rows[p-1], Q_1 = rows[p] give
///   A(u)  = lerp_step(Q_0, Q_1, 1 - a, a)            (the last round)
///   A'(u) = (Q_1 - Q_0) * (p * 1/(t_{k+1} - t_k))
/// (the derivative of a B-spline from its blossom: A'(u) = p (b(u^{p-1},
/// t_{k+1}) - b(u^{p-1}, t_k)) / (t_{k+1} - t_k); The NURBS Book §3.3
/// states it as the derivative's control points). For a NURBS curve the rows
/// are homogeneous and C = A/w, C' = (A' - w' C) / w (The NURBS Book eq.
/// 4.8). Degree 0: A' = 0. Writes d coordinates to point and derivative;
/// the rows are overwritten.
inline void de_boor_point_and_derivative(std::span<const double> knots, int p, int span, double u,
                                         double* rows, int d, bool rational, double* point,
                                         double* derivative) {
  const int width = rational ? d + 1 : d;
  if (p == 0) {
    for (int k = 0; k < d; ++k) {
      point[k] = rational ? rows[k] / rows[d] : rows[k];
      derivative[k] = 0.0;
    }
    return;
  }
  de_boor_rounds(knots, p, span, u, 1, p - 1, rows, width);
  const double lower = knots[static_cast<std::size_t>(span)];
  const double upper = knots[static_cast<std::size_t>(span + 1)];
  const double reciprocal = 1.0 / (upper - lower);
  const double a = de_boor_alpha(u, lower, upper, reciprocal);
  const double s = 1.0 - a;
  const double factor = static_cast<double>(p) * reciprocal;
  const double* q0 = rows + static_cast<std::ptrdiff_t>(p - 1) * width;
  const double* q1 = q0 + width;
  if (!rational) {
    for (int k = 0; k < d; ++k) {
      point[k] = lerp_step(q0[k], q1[k], s, a);
      derivative[k] = (q1[k] - q0[k]) * factor;
    }
    return;
  }
  const double w = lerp_step(q0[d], q1[d], s, a);
  const double w_prime = (q1[d] - q0[d]) * factor;
  for (int k = 0; k < d; ++k) {
    const double c = lerp_step(q0[k], q1[k], s, a) / w;
    const double slope = (q1[k] - q0[k]) * factor;
    point[k] = c;
    derivative[k] = subtract_product(slope, w_prime, c) / w;
  }
}

}  // namespace casteljau::detail

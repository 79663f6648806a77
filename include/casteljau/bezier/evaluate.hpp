#pragma once
// Points and derivatives of Bézier curves.
//
// Parameters: a Bézier curve's domain is [0,1]. Every function here accepts
// any finite t and, outside [0,1], evaluates the same polynomial (or rational
// function): it extrapolates, it does not clamp. Front ends (CLI, Python)
// refuse parameters outside the domain before calling these, or call
// points_at_within, which checks them as it evaluates.

#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

/// C(t) by de Casteljau's algorithm: n rounds of convex combinations
/// P^r_i = (1-t) P^{r-1}_i + t P^{r-1}_{i+1} (seed 004 §3; Farin, "Curves and
/// Surfaces for CAGD", §3.1). Rational curves run it on the homogeneous points.
/// O(n^2 d); no heap up to degree tolerances::kMaxStackDegree.
Point point_at(const BezierCurve& curve, double t);
/// The same point written into `out` (dimension() values, checked in every
/// build): no allocation, the same arithmetic, so the same value bit for bit.
void point_at(const BezierCurve& curve, double t, std::span<double> out);

/// C(t) by the direct sum sum_k C(n,k) t^k (1-t)^(n-k) P_k, exactly as the seed
/// notebook's `bezier0` computes it (float binomials, powers). Kept to show
/// where it breaks: the binomials overflow to inf near n = 1030 and the sum
/// becomes inf or NaN. Below that it is as accurate as de Casteljau in double
/// (measured at n = 200: 6e-15 of the scale for both; the seed's "vanishing"
/// degree-200 curve is a property of the curve, not of rounding). O(n^2).
Point point_at_bernstein_sum(const BezierCurve& curve, double t);

/// Batch evaluation: out[i*d .. i*d+d) = C(ts[i]) for every i, with the same
/// arithmetic as point_at (so the same accuracy, bit for bit), parameters in
/// any order. Requires out.size() == ts.size() * dimension(). Never allocates
/// up to degree tolerances::kMaxStackDegree (one workspace per call above it).
void points_at(const BezierCurve& curve, std::span<const double> ts, std::span<double> out);

/// The k-th derivative C^(k)(t), k >= 0. Polynomial curves: de Casteljau on
/// the k-th hodograph n!/(n-k)! Delta^k P_i. Rational curves: homogeneous
/// derivatives A^(j), w^(j) combined by C^(k) = (A^(k) - sum_{j=1..k} C(k,j)
/// w^(j) C^(k-j)) / w (The NURBS Book, eq. 4.8, A4.2). Zero for k > n (polynomial).
Point derivative_at(const BezierCurve& curve, double t, int order);

/// C(t), C'(t), ..., C^(max_order)(t) in one pass (same formulas as derivative_at).
std::vector<Point> derivatives_up_to(const BezierCurve& curve, double t, int max_order);

/// points_at for parameters from outside, checked as they are evaluated: it
/// stops at the first parameter outside `allowed` (NaN is outside every
/// interval) and returns its index, ts.size() when all are inside (the
/// B-spline's points_at_within, same contract). Each block of parameters is
/// checked just before the kernel reads it, while it is in cache. After a
/// stop the rows of `out` past the index are unspecified. Never allocates.
std::size_t points_at_within(const BezierCurve& curve, std::span<const double> ts, Interval allowed,
                             std::span<double> out);

/// Batch k-th derivatives: out[i*d ..] = derivative_at(curve, ts[i], order)
/// to rounding. Polynomial curves: the batch kernel on the k-th derivative
/// curve (one allocation per call, for it); rational ones: A4.2 per
/// parameter, without allocating up to degree kMaxStackDegree.
void derivatives_at(const BezierCurve& curve, std::span<const double> ts, int order, std::span<double> out);

/// Batch points and first derivatives: points[i*d ..] = C(ts[i]) (as points_at)
/// and derivatives[i*d ..] = C'(ts[i]) (as derivatives_at). Both of size ts.size() * d.
void points_and_derivatives_at(const BezierCurve& curve, std::span<const double> ts, std::span<double> points,
                               std::span<double> derivatives);

/// The k-th derivative curve (the hodograph) of a polynomial curve: the
/// Bézier curve of degree n-k whose control points are n!/(n-k)! Delta^k P_i
/// (Farin §4.3). For k > n, the zero curve of degree 0. Refuses rational
/// curves (their derivative is not a Bézier curve of that form) and k < 0.
/// The same verb as the B-spline's derivative_curve (bspline/hodograph.hpp).
Expected<BezierCurve> derivative_curve(const BezierCurve& curve, int order = 1);

/// {0, 1}: a Bézier curve is one polynomial piece.
std::vector<double> breakpoints(const BezierCurve& curve);

}  // namespace casteljau

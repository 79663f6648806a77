#pragma once
// Points and derivatives of Bézier curves.
//
// Parameters: a Bézier curve's domain is [0,1]. Every function here accepts
// any finite t and, outside [0,1], evaluates the same polynomial (or rational
// function): it extrapolates, it does not clamp. Front ends (CLI, Python)
// refuse parameters outside the domain before calling these.

#include <span>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"

namespace casteljau {

/// C(t) by de Casteljau's algorithm: n rounds of convex combinations
/// P^r_i = (1-t) P^{r-1}_i + t P^{r-1}_{i+1} (seed 004 §3; Farin, "Curves and
/// Surfaces for CAGD", §3.1). Rational curves run it on the homogeneous points.
/// O(n^2 d); no heap up to degree tolerances::kMaxStackDegree.
Point point_at(const BezierCurve& curve, double t);

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
std::vector<Point> derivatives_at(const BezierCurve& curve, double t, int max_order);

/// The k-th hodograph of a polynomial curve: the Bézier curve of degree n-k
/// whose control points are n!/(n-k)! Delta^k P_i (Farin §4.3). For k > n, the
/// zero curve of degree 0. Refuses rational curves (their derivative is not a
/// Bézier curve of that form).
Expected<BezierCurve> hodograph(const BezierCurve& curve, int order = 1);

/// Unit tangent C'(t)/|C'(t)|. Where C'(t) vanishes (a repeated end control
/// point, a cusp), the direction of the first derivative that does not vanish
/// (relative to the curve's scale, tolerances::kVanishingDerivative): the
/// one-sided limit of the tangent, toward increasing t. The zero vector
/// for a curve that is a single point.
Point unit_tangent_at(const BezierCurve& curve, double t);

/// Unit principal normal: the part of C'' orthogonal to the tangent,
/// normalised (points toward the centre of curvature). Where the curvature is
/// zero it is undefined; then in the plane the left normal (tangent turned by
/// +90 degrees), in other dimensions the zero vector. d = 1: always zero.
Point unit_normal_at(const BezierCurve& curve, double t);

/// Curvature kappa = sqrt(|C'|^2 |C''|^2 - (C'.C'')^2) / |C'|^3 (any d; in the
/// plane this is |C' x C''| / |C'|^3, unsigned). +inf where C' = 0 and C'' != 0
/// (a cusp), 0 where both vanish.
double curvature_at(const BezierCurve& curve, double t);

/// Signed curvature of a plane curve, (C' x C'') / |C'|^3: positive when the
/// curve turns left. Requires dimension() == 2.
double signed_curvature_at(const BezierCurve& curve, double t);

}  // namespace casteljau

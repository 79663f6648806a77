#pragma once
// Points and derivatives of B-spline and NURBS curves.
//
// Parameters: the domain is [t_p, t_{n+1}] (BSplineCurve::domain()). Like the
// Bézier functions, these accept any finite u and extrapolate outside the
// domain (the first or last polynomial piece continued); front ends refuse
// parameters outside the domain before calling them. At the end of the
// domain the last non-empty span is used (find_span), so a clamped curve
// interpolates its last control point exactly.

#include <span>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"

namespace casteljau {

/// C(u) by de Boor's algorithm: p rounds of convex combinations
/// P^r_j = (1 - a) P^{r-1}_{j-1} + a P^{r-1}_j, a = (u - t_j) * (1/(t_{j+p+1-r} - t_j))
/// on the span of u (The NURBS Book §5.3, eq. 5.11; span by A2.1). The
/// reciprocal form rounds a at most one ulp away from the quotient and lets
/// the batch kernels reuse it per span (src/bspline/de_boor.hpp); a = 1
/// exactly at u = t_{j+p+1-r}, so a clamped curve gives P_0 and P_n exactly
/// at the ends of its domain. NURBS curves run it on the homogeneous points
/// and divide (A4.1). O(p^2 d); no heap up to degree tolerances::kMaxStackDegree.
Point point_at(const BSplineCurve& curve, double u);
/// The same point written into `out` (dimension() values, checked in every build), without allocating.
void point_at(const BSplineCurve& curve, double u, std::span<double> out);

/// C(u) as sum N_{i,p}(u) P_i from the basis functions (The NURBS Book A3.1,
/// A4.1): the independent half of the differential pair with point_at.
Point point_at_basis_sum(const BSplineCurve& curve, double u);

/// The k-th derivative C^(k)(u), k >= 0. Order 1 comes from the same de Boor
/// triangle as the point, C' = p (Q_1 - Q_0) / (t_{k+1} - t_k) from its last
/// two rows (The NURBS Book §3.3), so it equals the batch kernels bit for bit;
/// orders 2 and up from the basis derivatives (A3.2). NURBS: the homogeneous
/// derivatives combined by C^(k) = (A^(k) - sum_{j=1..k} C(k,j) w^(j) C^(k-j)) / w (A4.2).
/// Zero for k > p on a polynomial curve. At a knot, the derivative of the
/// span to the right (the left one at the end of the domain).
Point derivative_at(const BSplineCurve& curve, double u, int order);

/// C(u), C'(u), ..., C^(max_order)(u) in one pass (same formulas as derivative_at).
std::vector<Point> derivatives_up_to(const BSplineCurve& curve, double u, int max_order);

/// The distinct knots inside the domain, both ends included, increasing: the
/// parameters where the curve may be less smooth (its Bézier pieces' breakpoints).
std::vector<double> breakpoints(const BSplineCurve& curve);

/// Batch evaluation: out[i*d .. i*d+d) = C(us[i]) for every i, parameters in
/// any order (sorted runs are fastest). Writes into the caller's storage and
/// never allocates up to degree tolerances::kMaxStackDegree.
/// Requires out.size() == us.size() * dimension().
void points_at(const BSplineCurve& curve, std::span<const double> us, std::span<double> out);

/// points_at for parameters from outside, checked as they are evaluated: it
/// stops at the first parameter outside `allowed` (NaN is outside every
/// interval; pass [-DBL_MAX, DBL_MAX] to refuse only NaN and infinities) and
/// returns its index, or us.size() when every parameter is inside. Each SIMD
/// block is compared with `allowed` on the values the kernel loads anyway, so
/// a front end pays about nothing for the check, where a separate pass over
/// the parameters cost W1 a fifth of its throughput. After a stop, the rows
/// of `out` are unspecified. Never allocates (as points_at).
std::size_t points_at_within(const BSplineCurve& curve, std::span<const double> us, Interval allowed,
                             std::span<double> out);

/// Batch points and first derivatives: points[i*d ..] = C(us[i]) and
/// derivatives[i*d ..] = C'(us[i]). Requires both sizes us.size() * dimension().
void points_and_derivatives_at(const BSplineCurve& curve, std::span<const double> us,
                               std::span<double> points, std::span<double> derivatives);

/// Batch k-th derivatives: out[i*d ..] = C^(k)(us[i]), the same values as
/// derivative_at (order 1 by the batch kernel, orders 0 and >= 2 by the
/// scalar functions per parameter).
void derivatives_at(const BSplineCurve& curve, std::span<const double> us, int order,
                    std::span<double> out);

/// De Boor's algorithm at u as data, for figures and the playground:
/// level r = 0..p holds the p+1-r points P^r_j (level 0: the control points
/// P_{span-p}..P_span of the span; level p: the single point C(u), projected
/// for a NURBS curve). Levels are stored projected (Cartesian) points.
struct DeBoorNet {
  double parameter = 0.0;
  int span = 0;
  std::vector<PointArray> levels;
};

/// The de Boor net of the curve at u (The NURBS Book §5.3, fig. 5.11).
DeBoorNet de_boor_net(const BSplineCurve& curve, double u);

}  // namespace casteljau

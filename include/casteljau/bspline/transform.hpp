#pragma once
// Exact rewritings of a B-spline curve that keep its shape: reversal,
// another parameter interval, clamped ends, splitting at a parameter.

#include <utility>

#include "casteljau/bezier/affine.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

/// The same curve traversed backwards on the same domain [a, b]:
/// C_r(u) = C(a + b - u), with knots t'_i = a + b - t_{n+p+1-i} and the
/// control points (and weights) in reverse order (The NURBS Book §6.1 on
/// reversing a curve's direction). The domain ends map exactly to each
/// other. O(n d).
BSplineCurve reversed(const BSplineCurve& curve);

/// The same curve on the domain `domain` = [c, d]: the knots are mapped by
/// the increasing affine map t -> c + (t - a)(d - c)/(b - a) (the ends of
/// the old domain exactly to c and d), the control points are kept, so
/// C_new(c + (u - a)(d - c)/(b - a)) = C(u) and the k-th derivatives scale
/// by ((b - a)/(d - c))^k (The NURBS Book §6.1, linear reparameterization).
/// O(n). Errors: an interval that is not finite or has lower >= upper, ends
/// beyond tolerances::kMaxKnot, a span shrunk below tolerances::kMinKnotSpan.
Expected<BSplineCurve> reparameterized(const BSplineCurve& curve, Interval domain);

/// The same curve with clamped knots on its domain: both ends inserted to
/// multiplicity p (The NURBS Book A5.4), the control points and knots
/// outside the domain dropped, and the end knots given multiplicity p+1, so
/// that the curve starts at its first control point and ends at its last.
/// A clamped curve comes back equal. O(n w + p^2 w).
BSplineCurve clamped(const BSplineCurve& curve);

/// The two parts of the curve at u: the first on [a, u], the second on
/// [u, b], both clamped, each the original curve restricted (u inserted to
/// multiplicity p by A5.4, then the knots and control points cut there;
/// The NURBS Book §5.3, "splitting a curve"). Their shared end point is the
/// control point at the cut, C(u) up to rounding (both parts start from
/// the same row); at a knot of multiplicity p+1 (a jump) the first part
/// ends at the left limit and the second starts at the right one.
/// O(n w + p^2 w). Errors: u not finite or not strictly inside the domain,
/// u closer than tolerances::kMinKnotSpan to a knot without being one.
Expected<std::pair<BSplineCurve, BSplineCurve>> split_at(const BSplineCurve& curve, double u);

/// The curve restricted to [u0, u1] (t_p <= u0 < u1 <= t_{n+1}), clamped,
/// on the same parameters: both ends inserted to multiplicity p (A5.4), the
/// knots and control points outside dropped (The NURBS Book §5.3). Errors as
/// for every curve kind (core/parameter_checks.hpp): not finite, outside the
/// domain, u0 >= u1; and an end closer than tolerances::kMinKnotSpan to a knot
/// without being one.
Expected<BSplineCurve> segment(const BSplineCurve& curve, double u0, double u1);

/// The curve with every control point mapped by x -> A x + b (weights and
/// knots unchanged): its image, as B-splines are affinely invariant (The
/// NURBS Book §3.2, property P3.3). Errors: the map's dimension differs from
/// the curve's, or a mapped point leaves the valid coordinates.
Expected<BSplineCurve> transformed(const BSplineCurve& curve, const AffineMap& map);

}  // namespace casteljau

#pragma once
// Derivatives and integrals of polynomial B-spline curves as B-spline curves:
// the derivative curve (hodograph) C^(k), the antiderivative A with A' = C,
// and the definite integral. scipy's BSpline.derivative, .antiderivative and
// .integrate (FITPACK's splder/splantider conventions) in the Python module
// are built on these.
//
// Only polynomial curves: the derivative of a NURBS curve is a rational
// function of twice the degree (The NURBS Book §4.3, eq. 4.8), not a NURBS
// curve on the same knots, and its integral is not a rational curve at all,
// so rational curves are refused with an Error.

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// The k-th derivative C^(k) as a B-spline curve, by The NURBS Book eq. 3.8
/// (A3.3) applied k times: the derivative of a curve of degree p >= 1 has
/// degree p - 1, the knots t_1 .. t_{n+p} (the first and last dropped) and
/// the n control points Q_i = p (P_{i+1} - P_i) / (t_{i+p+1} - t_{i+1}),
/// i = 0..n-1 (computed in that order, as FITPACK's splder). The domain is
/// unchanged and the end pieces extrapolate like the curve's. Where
/// t_{i+p+1} = t_{i+1} (a knot of multiplicity p+1 in t_1..t_{n+p}: the
/// curve may jump there) the basis function of Q_i is identically zero: it
/// is dropped with one copy of the knot, so the result is the piecewise
/// derivative on a valid knot vector (scipy's splder raises instead).
/// k = 0 returns the curve; k > p returns the zero curve: degree 0, knots
/// (t_p, t_{n+1}) and one control point at the origin (the domain kept).
/// Errors: k < 0, a rational curve. O(k n d).
Expected<BSplineCurve> derivative_curve(const BSplineCurve& curve, int order = 1);

/// The k-th antiderivative, applied k times: the curve A of degree p + 1 on
/// the knots t_0, t_0 .. t_{n+p+1}, t_{n+p+1} (each end once more) with the
/// n+2 control points Q_0 = 0, Q_{i+1} = (Σ_{j<=i} P_j (t_{j+p+1} - t_j)) / (p+1),
/// i = 0..n (the integral of a B-spline series, de Boor, A Practical Guide
/// to Splines, ch. X: ∫ N_{j,p} = (t_{j+p+1} - t_j)/(p+1) over its support;
/// summed, then divided, in the order of FITPACK's splantider).
/// A' = C on the domain and A(u) = ∫_{t_0}^u Σ_j P_j N_{j,p}(s) ds with the
/// basis functions of the whole knot vector (zero outside [t_0, t_{n+p+1}]),
/// so for a clamped curve A(u) = ∫_{t_p}^u C and A(t_p) = 0. The domain is
/// unchanged; outside it A extrapolates the integral of C's extrapolated
/// end pieces. k = 0 returns the curve.
/// Errors: k < 0, a rational curve, a degree p + k above
/// tolerances::kMaxBSplineDegree or more than tolerances::kMaxControlPoints
/// control points. O(k n d).
Expected<BSplineCurve> antiderivative_curve(const BSplineCurve& curve, int order = 1);

/// ∫_a^b C(u) du (a d-vector), as A(b) - A(a) with A = antiderivative_curve
/// (the same route as scipy's BSpline.integrate with extrapolate=True):
/// a and b may lie anywhere, the curve's end pieces continued outside the
/// domain, and b < a gives the negated integral. Errors: a or b not finite,
/// a rational curve. O(n d + p^2 d).
Expected<Point> integral(const BSplineCurve& curve, double a, double b);

}  // namespace casteljau

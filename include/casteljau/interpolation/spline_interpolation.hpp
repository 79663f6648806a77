#pragma once
// Interpolation of points P_0..P_m at parameter values t_0 < ... < t_m by
// B-splines: the C² cubic spline with its four classic end conditions, and
// B-splines of any degree on averaged knots (The NURBS Book §9.2). Each is one
// banded linear system solved in O(m p²) time and O(m p) memory; the d
// coordinates share the factorization.

#include <span>
#include <string_view>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// What closes the cubic spline's system at its two ends (de Boor, A Practical
/// Guide to Splines, ch. IV; the names of scipy's CubicSpline bc_type).
enum class EndCondition {
  natural,     ///< C''(t_0) = C''(t_m) = 0 (knots at every t_i)
  clamped,     ///< C'(t_0), C'(t_m) given (knots at every t_i)
  not_a_knot,  ///< C''' continuous at t_1 and t_{m-1}: knots at t_0, t_2..t_{m-2}, t_m
  periodic,    ///< closed: C, C', C'' equal at t_0 and t_{m+1} (the closing parameter)
};

/// "natural", "clamped", "not-a-knot", "periodic".
std::string_view name_of(EndCondition condition) noexcept;

/// Reads a name of name_of (also "not_a_knot"); the error lists the names.
Expected<EndCondition> end_condition_from_name(std::string_view name);

/// The end condition and, for `clamped`, the end derivatives C'(t_0) and
/// C'(t_m) with respect to the parameter (d coordinates each; for a function
/// y(x) the tangent (1, y'(x))).
struct CubicEnds {
  EndCondition condition = EndCondition::not_a_knot;
  Point start_tangent;  ///< clamped only
  Point end_tangent;    ///< clamped only
};

/// The C² cubic B-spline through the points: C(t_i) = P_i, with `ends`
/// closing the system. The result equals scipy's
/// make_interp_spline(t, P, k=3, bc_type=...) and CubicSpline(t, P, bc_type=...)
/// (same knots, same control points up to rounding).
/// - natural, clamped: knots t_0⁴, t_1..t_{m-1}, t_m⁴ (m+3 control points);
/// - not-a-knot: knots t_0⁴, t_2..t_{m-2}, t_m⁴ (m+1 control points);
///   needs at least 4 points;
/// - periodic: `parameters` has m+2 values, the last for the closing step back
///   to P_0; the result is make_periodic-like: closed, C² at the seam, its
///   domain [t_0, t_{m+1}].
/// Errors: fewer points than the condition needs (2, 2, 4, 3), parameters not
/// strictly increasing or of the wrong count, non-finite values, tangents of
/// the wrong dimension. O(m d) time and memory.
Expected<BSplineCurve> interpolate_cubic(const PointArray& points, std::span<const double> parameters,
                                         const CubicEnds& ends);

/// A derivative the interpolant must take at one end of its domain.
struct EndDerivative {
  bool at_end = false;  ///< false: at t_0; true: at t_m
  int order = 1;        ///< k >= 1, at most the degree
  Point value;          ///< C^(k)(t), d coordinates
};

/// The B-spline of degree p (1 <= p <= m + number of derivatives) through the
/// points, clamped at t_0 and t_m, on knots that average the parameters
/// (The NURBS Book eq. 9.8, Algorithm A9.1). With k_0 derivatives prescribed
/// at t_0 and k_m at t_m (§9.2.2), the averaged sequence is
///   s = (t_0 repeated k_0 + 1 times, t_1, ..., t_{m-1}, t_m repeated k_m + 1 times),
/// n + 1 = m + 1 + k_0 + k_m control points, and the interior knots are
/// u_{j+p} = (s_j + ... + s_{j+p-1}) / p for j = 1..n-p: one more control
/// point and one more averaged knot per derivative (with one first derivative
/// at each end this is the book's eq. 9.22). Rows of the system: C(t_0), the
/// start derivatives, C(t_1)..C(t_{m-1}), the end derivatives, C(t_m).
/// Errors as for interpolate_cubic; a derivative order outside 1..p, given
/// twice at one end, or more than p - 1 derivatives at one end (p of them
/// would make the first averaged knot t_0 again); a system that the given
/// derivative orders leave singular. O(m p² d).
Expected<BSplineCurve> interpolate_bspline(const PointArray& points, std::span<const double> parameters,
                                           int degree, std::span<const EndDerivative> derivatives = {});

/// The B-spline of degree p on the given knots through the points, by
/// collocation (The NURBS Book §9.2.1 eq. 9.10 and §9.2.2; de Boor, A
/// Practical Guide to Splines, ch. XIII): C(t_i) = P_i and the prescribed end
/// derivatives at t_0 and t_m, n + 1 = m + 1 + (number of derivatives)
/// control points, so knots.size() must be n + p + 2. This is scipy's
/// make_interp_spline(t, P, k=p, t=knots, bc_type=...) (same coefficients up
/// to rounding). The knots pass validate_knots, and the parameters must span
/// the domain exactly: t_0 = knots[p], t_m = knots[n+1] (the knots need not
/// be clamped). The Schoenberg–Whitney condition is checked row by row in
/// the solver's row order (C(t_0), start derivatives, C(t_1)..C(t_{m-1}),
/// end derivatives, C(t_m)): the row of parameter i must not vanish on basis
/// function j, its column ("parameter 3 (0.5) is not inside the support
/// [0.6, 0.9) of basis function 3"; derivative rows always meet it, t_0 and
/// t_m being the domain's ends). Errors also: degree outside
/// 1..tolerances::kMaxBSplineDegree, fewer than 2 points, a knot count that
/// does not match, parameters not finite or not strictly increasing,
/// derivatives as for interpolate_bspline (an order outside 1..p, or one
/// order twice at one end; up to p derivatives at each end are allowed), a
/// system that is singular anyway. O(m p² d).
Expected<BSplineCurve> interpolate_on_knots(const PointArray& points, std::span<const double> parameters,
                                            int degree, std::vector<double> knots,
                                            std::span<const EndDerivative> derivatives = {});

}  // namespace casteljau

#pragma once
// Cubic Hermite interpolation: Ferguson's cubic from two end points and two
// end tangents (seed 001, "courbes de Ferguson"), and the piecewise cubic
// through P_0..P_m with a prescribed tangent at every point (the parametric
// form of scipy's CubicHermiteSpline).

#include <initializer_list>
#include <span>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/closure.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// Ferguson's cubic (seed 001): the cubic C on [0,1] with C(0) = P0,
/// C'(0) = T0, C(1) = P1, C'(1) = T1, in Bézier form with control points
/// P0, P0 + T0/3, P1 − T1/3, P1 (since C'(0) = 3(b1 − b0), C'(1) = 3(b3 − b2);
/// Farin, "Curves and Surfaces for CAGD", §7.1). O(d).
/// Errors: the four vectors of different dimensions or empty, a NaN or
/// infinite coordinate ("coordinate 1 of the end tangent is NaN").
Expected<BezierCurve> ferguson_curve(std::span<const double> start, std::span<const double> start_tangent,
                                     std::span<const double> end, std::span<const double> end_tangent);
/// The same with the four vectors written in braces: ferguson_curve({0, 0}, {1, 0}, {1, 1}, {0, 1}).
inline Expected<BezierCurve> ferguson_curve(std::initializer_list<double> start,
                                            std::initializer_list<double> start_tangent,
                                            std::initializer_list<double> end,
                                            std::initializer_list<double> end_tangent) {
  return ferguson_curve(std::span<const double>(start.begin(), start.size()),
                        std::span<const double>(start_tangent.begin(), start_tangent.size()),
                        std::span<const double>(end.begin(), end.size()),
                        std::span<const double>(end_tangent.begin(), end_tangent.size()));
}

/// The C¹ piecewise cubic with C(t_i) = P_i and C'(t_i) = T_i (derivative
/// with respect to the parameter t, as scipy's CubicHermiteSpline takes dydx),
/// as a cubic B-spline with knots t_0⁴, t_1², ..., t_{m-1}², t_m⁴ and
/// control points P_0, Q_0, R_0, Q_1, R_1, ..., R_{m-1}, P_m, where on
/// [t_i, t_{i+1}] (h_i = t_{i+1} − t_i) the Bézier points are
/// P_i, Q_i = P_i + h_i T_i / 3, R_i = P_{i+1} − h_i T_{i+1} / 3, P_{i+1}
/// (Farin §7.1; a double knot of a cubic leaves C¹, The NURBS Book §2.3, and
/// the dropped joint P_i = (h_i R_{i−1} + h_{i−1} Q_i)/(h_{i−1} + h_i) is the
/// one C¹ implies). Domain [t_0, t_m].
/// `Closure::closed`: one more segment from P_m back to P_0 with the tangent T_0 at
/// its end, so `parameters` has m+2 values (t_{m+1} for the return to P_0)
/// and the curve is C¹ across the seam at t_0 ≡ t_{m+1}; domain [t_0, t_{m+1}].
/// Errors: fewer than 2 points (3 when closed), tangents not one per point or
/// of another dimension, parameters of the wrong count, not finite or not
/// strictly increasing, a NaN or infinite coordinate, a closed set whose last
/// point repeats the first (drop it: without_closing_duplicate). O(m d).
Expected<BSplineCurve> interpolate_hermite(const PointArray& points, const PointArray& tangents,
                                           std::span<const double> parameters, Closure closure = Closure::open);

}  // namespace casteljau

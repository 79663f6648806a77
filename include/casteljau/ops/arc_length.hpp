#pragma once
// Arc length of any curve kind (CurveView), its inverse and equal-arc-length
// sampling, to a requested absolute accuracy.
//
// L(a, b) = integral over [a, b] of |C'(u)| du, computed piece by piece on the
// curve's Bézier pieces (to_bezier_pieces) by adaptive Gauss–Kronrod
// quadrature (the 7-point Gauss rule inside the 15-point Kronrod rule,
// Piessens et al., QUADPACK, 1983, qk15): an interval is accepted when
// |K15 - G7| is within its share of the tolerance, else it is halved. For the
// smooth speed of a Bézier piece |K15 - G7| bounds the error of K15 by orders
// of magnitude (K15 is exact for polynomials of degree 22, G7 for degree 13),
// so the request is met, not only estimated: tests/ops/arc_length_test.cpp
// measures it on exact cases (lines, the parabola, the NURBS circle and arcs,
// the ellipse against scipy) at every accuracy from 1e-1 to 1e-13 of the size.
// Where the speed vanishes (a cusp, a repeated control point) the halving
// concentrates the intervals there. The speed of a rational piece comes from
// its homogeneous form, C' = (A' w - A w') / w^2 (The NURBS Book eq. 4.7).
// A rational piece whose weights differ by more than 16 in standard form
// (weights 1, 1e20, 1 run the whole curve but its corner within 1e-20 of the
// parameter's ends, where 15 nodes never look) is first halved into parts of
// balanced weights, each integrated in its own Möbius parameter; where a
// part lies closer to a piece's end than doubles can resolve (within 1e-16
// of 1), parameter_at_length answers with the nearest parameter doubles hold.

#include <cstddef>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// The length of the whole curve, within tolerance.distance (absolute).
/// Errors: a tolerance not finite or <= 0, or below
/// tolerances::kMinArcLengthRelativeTolerance x size_of(curve) (what double
/// precision can promise); more than tolerances::kMaxArcLengthIntervals
/// quadrature intervals needed.
Expected<double> arc_length(CurveView curve, Tolerance tolerance);

/// The length of the curve between the parameters range.lower <= range.upper,
/// both inside the domain (errors name them), within tolerance (as above).
Expected<double> arc_length(CurveView curve, Interval range, Tolerance tolerance);

/// The inverse: the parameter u at which the length from the start of the
/// domain is `length`, so that |L(lower, u) - length| <= tolerance.distance.
/// `length` must lie in [0, L] (L the curve's length; up to the tolerance
/// beyond L is taken as L). Where the curve stands still (a stretch of zero
/// speed) any parameter of the stretch is an answer; the first is not
/// promised. Errors as arc_length, and a length outside [0, L].
Expected<double> parameter_at_length(CurveView curve, double length, Tolerance tolerance);

/// `count` >= 2 parameters whose points are equally spaced along the curve:
/// u_0 = lower, u_{count-1} = upper, L(lower, u_i) = i L / (count - 1) within
/// the tolerance. Increasing (non-decreasing where the curve stands still).
/// Errors as arc_length, and count < 2 or above tolerances::kMaxInputValues.
Expected<std::vector<double>> equal_arc_length_parameters(CurveView curve, std::size_t count, Tolerance tolerance);

/// The accuracy front ends use when none is asked for:
/// tolerances::kDefaultArcLengthRelativeTolerance x size_of(curve), or 1 for
/// a curve that is a single point (size 0, length exactly 0).
Tolerance default_arc_length_tolerance(CurveView curve);

}  // namespace casteljau

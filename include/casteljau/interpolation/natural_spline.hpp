#pragma once
// Natural splines of order q (seed 001, problem P2; de Boor, A Practical
// Guide to Splines, ch. XIII; Schoenberg 1964): among all functions through
// (t_i, P_i) with a square-integrable q-th derivative, the one minimizing
// ∫ ‖s^(q)‖² is a spline of degree 2q − 1, C^(2q−2) at the nodes, with
// s^(j)(t_0) = s^(j)(t_m) = 0 for j = q..2q−2 (it continues as a polynomial of
// degree q − 1 outside [t_0, t_m]). q = 1 is the polyline, q = 2 the natural
// cubic spline, q = 3 the natural quintic.

#include <span>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// The natural spline of order q >= 1 through the points at strictly
/// increasing `parameters`, as a clamped B-spline of degree 2q − 1 on
/// [t_0, t_m] with a simple knot at each interior t_i. Computed in the
/// B-spline basis (a banded system), never in the ill-conditioned
/// truncated-power basis of the seed. Needs at least max(q, 2) points (with
/// exactly q points it is the polynomial of degree q − 1 through them);
/// q at most tolerances::kMaxNaturalSplineOrder.
/// O(m q² d).
Expected<BSplineCurve> interpolate_natural(const PointArray& points, std::span<const double> parameters,
                                           int order);

}  // namespace casteljau

#pragma once
// Seed 000 §2: a C¹ curve through P_0..P_m made of cubic Bézier pieces, with
// a free parameter α that sets the length of the tangents.

#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/core/closure.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// Seed 000's C¹ interpolant: piece i (on [i, i+1]) has control points
/// P_i, Q_i, R_i, P_{i+1} with
///   Q_i = P_i + (P_{i+1} − P_{i−1})/(3α),  i = 1..m−1;   Q_0 = P_0 + 2(P_1 − P_0)/(3α);
///   R_i = P_{i+1} − (P_{i+2} − P_i)/(3α),  i = 0..m−2;   R_{m−1} = P_m − 2(P_m − P_{m−1})/(3α).
/// At every joint P_{i+1} − R_i = Q_{i+1} − P_{i+1} = (P_{i+2} − P_i)/(3α), so
/// the pieces meet with equal first derivatives (P_{i+2} − P_i)/α: C¹ in the
/// global parameter (R_i, P_{i+1}, Q_{i+1} collinear, P_{i+1} the midpoint).
/// α = 2 gives the uniform Catmull–Rom tangents (P_{i+1} − P_{i−1})/2, and at
/// the ends the one-sided P_1 − P_0 (interpolate_catmull_rom on 0, 1, ..., m).
/// `Closure::closed`: the natural cyclic extension (not in the seed): indices mod m+1,
/// so Q_i, R_i use the cyclic neighbours for every i and one more piece
/// P_m, Q_m, R_m, P_0 closes the curve C¹ at P_0; m+1 pieces, domain [0, m+1].
/// Errors: fewer than 2 points (3 when closed), α not finite or <= 0, a NaN
/// coordinate, a closed set whose last point repeats the first (within
/// tolerances::kJointRelativeGap of the scale: drop it, without_closing_duplicate). O(m d).
Expected<PiecewiseBezierCurve> interpolate_c1_bezier(const PointArray& points, double alpha = 1.0,
                                                     Closure closure = Closure::open);

}  // namespace casteljau

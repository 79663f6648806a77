#pragma once
// Catmull–Rom splines with any parameter values: uniform, chord-length or
// centripetal (Yuksel, Schaefer & Keyser, "Parameterization and applications
// of Catmull–Rom curves", CAD 43(7), 2011). Each segment [t_i, t_{i+1}] is
// the Barry–Goldman pyramid over P_{i−1}, P_i, P_{i+1}, P_{i+2} (Barry &
// Goldman, SIGGRAPH 1988): a cubic that interpolates P_i and P_{i+1}, whose
// tangent at t_i is the derivative there of the quadratic through
// (t_{i−1}, P_{i−1}), (t_i, P_i), (t_{i+1}, P_{i+1}). So the whole curve is
// the cubic Hermite interpolant with those tangents (hermite.hpp).

#include <span>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/closure.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// The Catmull–Rom spline through P_0..P_m at `parameters` (from
/// parameter_values: uniform, chord or centripetal), as a C¹ cubic B-spline
/// with double interior knots on [t_0, t_m] (interpolate_hermite) with the
/// Barry–Goldman tangents
///   T_i = (P_i − P_{i−1})/h_{i−1} − (P_{i+1} − P_{i−1})/(h_{i−1} + h_i) + (P_{i+1} − P_i)/h_i
///       = (h_i d_{i−1} + h_{i−1} d_i)/(h_{i−1} + h_i),  d_i = (P_{i+1} − P_i)/h_i, h_i = t_{i+1} − t_i
/// (Yuksel et al. 2011, eq. 2 differentiated; equal to the pyramid's derivative).
/// Open ends: the missing neighbour is the reflected phantom point
/// P_{−1} = 2P_0 − P_1 at t_{−1} = 2t_0 − t_1 (likewise after P_m), which
/// gives the one-sided difference T_0 = d_0, T_m = d_{m−1}; it is consistent
/// with every parameterization (the phantom step has the length of the first
/// step) and makes the uniform spline equal seed 000's c1-bezier with α = 2,
/// ends included. `Closure::closed`: the neighbours are cyclic and `parameters` has
/// m+2 values (t_{m+1} for the return to P_0); domain [t_0, t_{m+1}], C¹
/// across the seam. The centripetal spline has no cusp or self-intersection
/// inside a segment (Yuksel et al., §4). Errors: fewer than 2 points (3 when
/// closed), parameters of the wrong count, not finite or not strictly
/// increasing, a NaN coordinate, a closed set repeating its first point. O(m d).
Expected<BSplineCurve> interpolate_catmull_rom(const PointArray& points, std::span<const double> parameters,
                                               Closure closure = Closure::open);

}  // namespace casteljau

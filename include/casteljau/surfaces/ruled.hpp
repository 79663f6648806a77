#pragma once
// Ruled surfaces: the straight segments joining corresponding points of two
// curves (The NURBS Book §10.3 "ruled surfaces", and §10.4; Farin ch. 22).
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The ruled surface S(u,v) = (1 - v) C0(u) + v C1(u) on [0,1] x [0,1]
/// between `first` (v = 0) and `second` (v = 1). Both curves are first
/// brought to the domain [0, 1] and made compatible (surfaces/
/// compatible_curves.hpp make_compatible: same degree p by elevation, same
/// knots by refinement), so u is each curve's own parameter mapped linearly
/// to [0, 1]: S(u, 0) = C0(a0 + u (b0 - a0)), S(u, 1) = C1(a1 + u (b1 - a1)).
/// The surface has degree (p, 1), knots_v = 0 0 1 1, and row i of its net is
/// (P0_i, P1_i). For NURBS curves the net carries the curves' weights: the
/// rulings are still the straight segments C0(u) C1(u), but v runs along
/// them linearly only where the two weights agree (the homogeneous form is
/// linear in v). Exact up to the rounding of elevation and refinement.
/// O(n p^2 d). Errors: curves of different dimensions ("curve 1 has 2
/// coordinates, curve 0 has 3; ..."), and the size limits of elevation and
/// refinement.
Expected<BSplineSurface> ruled_surface(const BSplineCurve& first, const BSplineCurve& second);

}  // namespace casteljau

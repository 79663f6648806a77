#pragma once
// Iso-parametric curves of B-spline, NURBS and Bézier surfaces: the surface
// with one parameter fixed is a curve of the other direction's degree and
// knots, whose control points are the surface seen along the fixed direction
// (a curve of whole rows) evaluated at the fixed value (The NURBS Book §3.4,
// eq. 3.14 and §4.4 for NURBS: on the homogeneous net, then projected).
#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The curve of the free parameter with `fixed` held at `value`: for fixed =
/// Direction::u the curve v -> S(value, v) (degree q, knots t), for fixed =
/// Direction::v the curve u -> S(u, value) (degree p, knots s). Control
/// point j is sum_i N_{i,p}(value) P_ij (homogeneous for NURBS, so the curve
/// is rational with weights sum_i N_i w_ij), by de Boor's algorithm on the
/// rows (A3.1 through the curve's point_at). O(p^2 N / n).
/// Errors: value not finite or outside the domain of `fixed` ("the
/// iso-curve parameter u = 7.5 is outside the domain [0, 4]").
Expected<BSplineCurve> iso_curve(const BSplineSurface& surface, Direction fixed, double value);

/// The same for a Bézier patch, value in [0, 1]: de Casteljau on the rows
/// (The NURBS Book A1.7's first stage). O(n^2 N / n).
Expected<BezierCurve> iso_curve(const BezierSurface& surface, Direction fixed, double value);

}  // namespace casteljau

#pragma once
// Degree elevation of B-spline, NURBS and Bézier surfaces in one direction:
// the curve algorithm (bspline/degree.hpp, bezier/degree.hpp) run once on the
// surface seen as a curve whose control points are whole rows of the
// homogeneous net (The NURBS Book §5.5: "elevate each row or column").
#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The same surface with degree raised by `times` in `direction` (The NURBS
/// Book §5.5, through the curve's elevate_degree: Bézier pieces elevated,
/// then the interior knots removed back to multiplicity m + times, so the
/// continuity is unchanged). The result is clamped in that direction (an
/// unclamped direction is clamped at its domain ends first); NURBS surfaces
/// elevate their homogeneous net. O(N (p + times)^2).
/// Errors (naming the direction): times < 0, a degree above
/// tolerances::kMaxBSplineDegree, more than tolerances::kMaxControlPoints
/// points. times = 0 returns the surface unchanged.
Expected<BSplineSurface> elevate_degree(const BSplineSurface& surface, Direction direction, int times = 1);

/// The same Bézier patch with degree n + times in `direction`: Q_i =
/// (i/(n+1)) P_{i-1} + (1 - i/(n+1)) P_i on every row or column, `times`
/// times (Farin §5.1 / The NURBS Book eq. 5.36 through the curve's
/// elevate_degree; rational patches on the homogeneous net). O(times n N).
/// Errors: times < 0, a degree above tolerances::kMaxBezierDegree, more
/// than tolerances::kMaxControlPoints points.
Expected<BezierSurface> elevate_degree(const BezierSurface& surface, Direction direction, int times = 1);

}  // namespace casteljau

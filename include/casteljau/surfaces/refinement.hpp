#pragma once
// Knot insertion and refinement of B-spline and NURBS surfaces in one
// direction (The NURBS Book §5.2, A5.3 for insertion, A5.5 for
// refinement): the curve algorithms of bspline/knot_insertion.hpp run once
// on the surface seen as a curve whose control points are whole rows of the
// homogeneous net (all columns at once), so the surface, its domain and its
// parameterization do not change.
#include <span>

#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The surface with `value` inserted `times` times into the knots of
/// `direction` (Boehm's algorithm on every row or column: The NURBS Book
/// A5.3, through the curve's insert_knot). Exact up to rounding: each new
/// control point is a convex combination of old ones (homogeneous for NURBS).
/// O(times p N) for N control points. Errors (naming the direction): value
/// not finite or outside that domain, times < 0, a multiplicity above
/// degree + 1, more than tolerances::kMaxControlPoints points. times = 0
/// returns the surface unchanged.
Expected<BSplineSurface> insert_knot(const BSplineSurface& surface, Direction direction, double value,
                                     int times = 1);

/// The surface with every value of `new_knots` inserted in `direction` (any
/// order, repeats inserted that many times): knot refinement, The NURBS Book
/// A5.5 (A5.4 on every row or column). Errors as insert_knot, naming the
/// offending entry.
Expected<BSplineSurface> refine_knots(const BSplineSurface& surface, Direction direction,
                                      std::span<const double> new_knots);

/// The same surface with clamped knots in `direction`: both ends of that
/// domain inserted up to multiplicity degree + 1 and the knots and rows
/// outside it dropped (the curve's clamped, bspline/transform.hpp, on every
/// row or column; The NURBS Book A5.4). Same domain, same parameterization;
/// a surface already clamped there comes back equal. For readers that take
/// only clamped knots (IGES and STEP in CAD systems).
BSplineSurface clamped(const BSplineSurface& surface, Direction direction);

}  // namespace casteljau

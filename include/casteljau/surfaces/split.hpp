#pragma once
// Splitting B-spline, NURBS and Bézier surfaces along one direction: the
// curve's split_at (bspline/transform.hpp, bezier/split.hpp) run once on the
// surface seen as a curve whose control points are whole rows of the
// homogeneous net.
#include <utility>

#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The two parts of the surface at `value` of `direction`: the first on
/// [lower, value], the second on [value, upper] (the other direction
/// unchanged), both clamped in `direction`; each equals the original
/// surface restricted (value inserted to multiplicity p in every row or
/// column, The NURBS Book §5.3 / A5.3, then the net cut there). Their shared
/// boundary is the same row of control points in both. O(N p).
/// Errors (naming the direction): value not finite or not strictly inside the domain.
Expected<std::pair<BSplineSurface, BSplineSurface>> split_at(const BSplineSurface& surface, Direction direction,
                                                             double value);

/// The two halves of a Bézier patch at t of `direction`: S on [0,t] and on
/// [t,1] in that direction, each reparameterised to [0,1] (de Casteljau's
/// subdivision on every row or column, Farin §3.2 through the curve's
/// split_at; rational patches in homogeneous form). O(n N).
/// Errors: t not finite or not strictly inside (0, 1).
Expected<std::pair<BezierSurface, BezierSurface>> split_at(const BezierSurface& surface, Direction direction,
                                                           double t);

}  // namespace casteljau

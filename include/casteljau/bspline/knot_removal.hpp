#pragma once
// Knot removal (The NURBS Book §5.4, A5.8; Tiller 1992): the inverse of knot
// insertion. A knot is exactly removable only where the curve is smoother
// than its knots say; otherwise removal approximates, and is accepted only
// while a guaranteed bound on the change of the curve stays within the
// caller's tolerance.

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {

/// A curve after knot removal and what the removal cost.
struct KnotRemoval {
  /// The curve with the removable knots removed (the input when none was).
  BSplineCurve curve;
  /// How many knots were removed (0 when none was removable within the tolerance).
  int removed = 0;
  /// Guaranteed: max over the domain of |C(u) - C_new(u)| is at most this
  /// (up to the rounding of the computation, about 1e-15 of the scale), and
  /// it is at most the tolerance. The sum over the removal steps of each
  /// step's bound: the distance delta between the two ways of computing the
  /// middle control point (A5.8's test), which bounds the control-point
  /// change after re-insertion and so the curve change (convex hull); for a
  /// NURBS curve delta (1 + R) / w_min, R the largest |C(u)| and w_min the
  /// smallest weight (The NURBS Book eq. 5.30 read as a bound).
  double error_bound = 0.0;
};

/// Removes the interior knot u up to `times` times, one copy after the
/// other, stopping at the first copy whose removal would take the
/// accumulated error bound above tolerance.distance (The NURBS Book A5.8).
/// NURBS curves work on their homogeneous points (a removal that would make
/// a weight <= 0 is refused as not removable). O(times p w) plus one copy of
/// the curve.
/// Errors: u not finite or not a knot strictly inside the domain, times < 0
/// or above u's multiplicity, a tolerance not finite or <= 0.
Expected<KnotRemoval> remove_knot(const BSplineCurve& curve, double u, int times, Tolerance tolerance);

/// Removes every removable interior knot, distinct values from left to
/// right, each as many times as the remaining tolerance allows (what
/// from_bezier_pieces needs to get the smoothness back). The total bound is
/// at most tolerance.distance. O(n p^2 w) (the curve is streamed through a
/// buffer, so each removal shifts O(p) points, not the whole tail).
/// Errors: a tolerance not finite or <= 0.
Expected<KnotRemoval> remove_knots(const BSplineCurve& curve, Tolerance tolerance);

}  // namespace casteljau

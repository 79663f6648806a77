#pragma once
// Changing the degree of a B-spline curve: elevation (exact: the same curve)
// and reduction (approximate, within a tolerance, with a guaranteed bound).
// Both go through the Bézier pieces (The NURBS Book §5.5: decompose, change
// each piece's degree, recompose, remove the knots that are not needed).

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {

/// The same curve written with degree p + times: each Bézier piece is
/// elevated (Farin §5.1), the pieces are joined with knots of multiplicity
/// p + times, and each interior knot is then removed exactly back to its
/// multiplicity m + times (the continuity C^(p-m) is unchanged by
/// elevation). This is the three-step method of The NURBS Book §5.5; A5.9
/// does the same in one sweep. The result is clamped (an unclamped curve is
/// clamped at its domain ends first) and NURBS curves elevate their
/// homogeneous points. O(n (p + times)^2 w).
/// Errors: times < 0, a degree above tolerances::kMaxBSplineDegree or more
/// than tolerances::kMaxControlPoints control points. times = 0 returns the
/// curve unchanged.
Expected<BSplineCurve> elevate_degree(const BSplineCurve& curve, int times = 1);

/// A B-spline of degree p - 1 within a tolerance of a curve of degree p.
struct BSplineDegreeReduction {
  /// The curve of degree p - 1 (same domain, clamped).
  BSplineCurve curve;
  /// Guaranteed: max over the domain of |C(u) - R(u)| is at most this, and
  /// it is at most the tolerance. The largest of the pieces' bounds
  /// (DegreeReduction::error_bound) plus the bound of the knot removals that
  /// follow.
  double error_bound = 0.0;
};

/// Degree reduction within tolerance.distance: each Bézier piece is reduced
/// by constrained least squares keeping its end points (bezier/degree.hpp,
/// Eck 1995), so the pieces still join; they are recomposed with knots of
/// multiplicity p - 1 and then remove_knots spends the rest of the tolerance
/// on getting the smoothness back. (The NURBS Book A5.11 reduces piece by
/// piece with a different, bound-based test; this keeps one reduction
/// method for Bézier and B-spline curves.) O(n p^3) for the small normal
/// equations of each piece.
/// Errors: a tolerance not finite or <= 0, degree below 2, a rational curve
/// (as for Bézier curves), a piece that cannot be reduced within the
/// tolerance (the message names the piece and the error it would need).
Expected<BSplineDegreeReduction> reduce_degree(const BSplineCurve& curve, Tolerance tolerance);

}  // namespace casteljau

#pragma once
// A B-spline curve as Bézier pieces and back (The NURBS Book §5.4, A5.6).
// Each non-empty span [u_i, u_{i+1}] of a degree-p B-spline is a Bézier
// curve of degree p; inserting every knot of the domain until its
// multiplicity is p exposes the Bézier control points.

#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// Bézier pieces of one curve with their parameter intervals: piece i covers
/// [breakpoints[i], breakpoints[i+1]] and is evaluated there at the local
/// parameter (u - breakpoints[i]) / (breakpoints[i+1] - breakpoints[i]).
struct BezierPieces {
  /// b_0 < b_1 < ... < b_m, one more than the pieces.
  std::vector<double> breakpoints;
  /// The m pieces, each on [0,1] in its own parameter.
  std::vector<BezierCurve> pieces;
  friend bool operator==(const BezierPieces&, const BezierPieces&) = default;
};

/// The Bézier pieces of the curve on its domain, one per non-empty span, each
/// of degree p and rational when the curve is (The NURBS Book A5.6: every
/// distinct knot of the domain, its two ends included, raised to
/// multiplicity p by the refinement A5.4, which also clamps unclamped ends;
/// the piece of span k is then Q_{k-p}..Q_k). Exact up to rounding:
/// O(n p^2 w), w = d (+1 if rational). Knots of multiplicity p+1 inside the
/// domain (a jump) give pieces that do not meet.
BezierPieces to_bezier_pieces(const BSplineCurve& curve);

/// A Bézier curve as its one piece on [0, 1].
BezierPieces to_bezier_pieces(const BezierCurve& curve);

/// The pieces of a piecewise Bézier curve of model JSON (piece i on [i, i+1]).
BezierPieces to_bezier_pieces(const PiecewiseBezierCurve& curve);

/// The pieces as a piecewise Bézier curve of model JSON (piece i on [i, i+1]:
/// the shape is kept, the parameterization becomes uniform per piece).
PiecewiseBezierCurve to_piecewise_bezier(const BezierPieces& pieces);

/// The B-spline with the same pieces: pieces of lower degree are elevated to
/// the highest degree p (Farin §5.1), the joints become knots of
/// multiplicity p (C^0 in general; The NURBS Book §5.4 read backwards), and
/// the start of piece i+1 replaces the end of piece i. Rational pieces give a
/// NURBS curve: each piece's weights are rescaled (which does not change a
/// rational Bézier curve) so that they agree at the joints. For degree 0 the
/// knots are the breakpoints (a piecewise constant curve). O(m p w) plus the
/// elevations. Removing the knots again where the pieces join smoothly is
/// remove_knots' job (knot_removal.hpp).
/// Errors (the pieces may come from a file): no piece, breakpoints not one
/// more than the pieces, not finite or not increasing, pieces of different
/// dimensions, consecutive pieces that do not meet within
/// tolerances::kJointRelativeGap of their scale (the message names the joint
/// and the gap), more than tolerances::kMaxControlPoints control points.
Expected<BSplineCurve> from_bezier_pieces(const BezierPieces& pieces);

}  // namespace casteljau

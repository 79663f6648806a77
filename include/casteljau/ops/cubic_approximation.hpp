#pragma once
// Cubic Bézier pieces within a distance of any curve: what SVG, PostScript,
// PDF and font formats can hold. Polynomial pieces of degree <= 3 are kept
// exactly; higher degrees and rational pieces (conics: arcs, circles) are
// replaced by cubic Hermite interpolants of their end points and end
// derivatives, halved until each is certified within the tolerance.

#include <cstddef>

#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// The cubics, and how far from the curve they are known to be.
struct CubicApproximation {
  PiecewiseBezierCurve curve;         ///< pieces of degree <= 3, polynomial, in the curve's order
  double deviation_bound = 0.0;       ///< the largest certified bound (0 when every piece was kept)
  std::size_t approximated_pieces = 0;  ///< the curve's Bézier pieces that were replaced
};

/// Cubic pieces C_j such that |C(t) - C_j(s)| <= tolerance.distance at
/// corresponding parameters, hence every point of each within the tolerance
/// of the other curve (the Hausdorff distance is at most the parametric one).
/// Each piece (to_bezier_pieces) of degree <= 3 and polynomial is copied bit
/// for bit. Any other piece B, with derivatives B' on [0,1]: the cubic H with
/// H(0) = B(0), H(1) = B(1), H'(0) = B'(0), H'(1) = B'(1) (Farin §7.1,
/// Hermite form), the error O(h^4) as B is halved (split_at 1/2, exact up to
/// rounding). Certified, not sampled: for polynomial B of degree n, the
/// control points of B - H (H elevated to n) bound |B - H| (convex hull); for
/// rational B = P / W, the coefficients of P - W H (degree n + 3, Bernstein
/// products, Farin §5.8) divided by the smallest weight, since W >= min w_i.
/// The tolerance is met minus the flattening rounding allowance
/// (tolerances::kFlattenRoundingAllowance, the same arithmetic). End points
/// are the piece's own, so joints stay joints. Errors: tolerance not finite
/// and > 0 or below what double precision certifies (as flatten), more than
/// tolerances::kMaxSubdivisionDepth halvings, more than
/// tolerances::kMaxControlPoints control points.
Expected<CubicApproximation> approximate_by_cubics(CurveView curve, Tolerance tolerance);

}  // namespace casteljau

#pragma once
// Flattening: a polyline whose vertices lie on the curve and that stays within
// a distance tolerance of it, guaranteed (not estimated). Used to draw every
// curve casteljau renders, and for CNC output (G1 moves). Method and proof:
// docs/flattening.md.

#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {

/// Polyline vertices on a curve, with the parameter of each vertex.
struct Polyline {
  PointArray points;               ///< vertices, in order; first and last the curve's ends
  std::vector<double> parameters;  ///< parameter of each vertex, increasing over the domain
};

/// A polyline through points of the curve, vertex i = point_at(curve, t_i)
/// bit for bit, 0 = t_0 < t_1 < ... < t_m = 1, such that every point of the
/// curve between two consecutive vertices lies within tolerance.distance of
/// the segment joining them, and every point of that segment within
/// tolerance.distance of the curve (Hausdorff distance <= tolerance).
/// Each segment is certified by chord_deviation_bound (which cannot
/// underestimate) against the tolerance minus a rounding allowance
/// (tolerances::kFlattenRoundingAllowance), and the count stays close to the
/// optimum (greedy furthest reach). Plane polynomial curves of degree <= 3:
/// breakpoints proposed all at once to equalise the deviations (an additive
/// measure, sqrt of the deviation), certified in SIMD batches, greedy steps
/// only where a proposal fails or falls short (inflections, cusps); about 1-3
/// O(1) bound evaluations per segment. Other curves: greedy furthest reach,
/// about 2.5 O(n^2 d) bound evaluations per segment. Any degree, dimension,
/// rational curves, cusps, loops, zero-length curves. See docs/flattening.md.
/// Errors: tolerance not finite or <= 0; tolerance below what double precision
/// can certify for this curve (kFlattenSmallestToleranceFactor x allowance);
/// more than tolerances::kMaxFlattenSegments segments.
Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance);

/// Any curve kind (CurveView): its Bézier pieces (to_bezier_pieces) each
/// flattened as above within the tolerance and joined, the vertex at a joint
/// once; the parameters are the curve's own (piece i's t mapped to
/// [b_i, b_{i+1}]), from domain().lower to domain().upper. Where pieces do
/// not meet (a knot of multiplicity p+1) both end points are kept, so the jump
/// shows as one segment that is not within the tolerance. Errors as above,
/// the piece named ("piece 3: ..."); kMaxFlattenSegments counts all pieces.
Expected<Polyline> flatten(CurveView curve, Tolerance tolerance);

/// flatten() with a caller's cap on the segment count (<= the library's
/// tolerances::kMaxFlattenSegments in practice): an error, not a truncated
/// polyline, when more would be needed. For budgets (a plotter's buffer) and tests.
Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance, long max_segments);

/// The number of segments flatten() produces for this curve and tolerance
/// (same errors), without building the polyline.
Expected<long> flatten_segment_count(const BezierCurve& curve, Tolerance tolerance);

/// A certified upper bound on the distance from the curve to the chord
/// [C(0), C(1)]: the largest distance from a control point to that segment
/// (the curve lies in the convex hull of its control points, weights > 0, and
/// the distance to a segment is a convex function). O(n d).
double control_polygon_flatness(const BezierCurve& curve);

/// A certified upper bound (up to rounding, far below
/// tolerances::kFlattenRoundingAllowance x scale) on the largest distance from
/// a point of C restricted to [t0, t1] (0 <= t0 < t1 <= 1) to the segment
/// [C(t0), C(t1)]. Plane polynomial curves of degree <= 3: the exact maximum
/// of the signed distance to the chord's line (a cubic in t, maximised at
/// the roots of a quadratic), combined with the largest overshoot beyond the
/// chord's ends as sqrt(F^2 + O^2) when the curve runs past them. Otherwise:
/// the largest distance from the control points of the piece (up to degree
/// 16: of its two halves, split at its middle) to the segment (convex hull
/// property). O(1) or O(n^2 d).
double chord_deviation_bound(const BezierCurve& curve, double t0, double t1);

}  // namespace casteljau

#pragma once
// Flattening: a polyline whose vertices lie on the curve and that stays within
// a distance tolerance of it, guaranteed (not estimated). Used to draw every
// curve casteljau renders, and for CNC output (G1 moves).

#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {

/// Polyline vertices on a curve, with the parameter of each vertex.
struct Polyline {
  PointArray points;               ///< vertices, in order; first C(0), last C(1)
  std::vector<double> parameters;  ///< t of each vertex, increasing from 0 to 1
};

/// A polyline through points of the curve such that every point of the curve
/// between two consecutive vertices lies within tolerance.distance of the
/// segment joining them (Hausdorff distance from curve to polyline <= tolerance).
/// Each piece's deviation is certified by a bound that cannot underestimate
/// (the control-polygon / convex hull bound, or the exact maximum of the
/// signed distance for degree <= 3; see docs/flattening.md), and the pieces
/// are chosen to keep the segment count close to the optimum.
/// Errors: tolerance not finite and > 0; more than tolerances::kMaxFlattenSegments segments.
Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance);

/// The number of segments flatten() produces for this curve and tolerance.
Expected<long> flatten_segment_count(const BezierCurve& curve, Tolerance tolerance);

/// A certified upper bound on the distance from the curve to the chord
/// [C(0), C(1)]: the largest distance from a control point to that segment
/// (the curve lies in the convex hull of its control points, weights > 0).
double control_polygon_flatness(const BezierCurve& curve);

}  // namespace casteljau

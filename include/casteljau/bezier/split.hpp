#pragma once
// Subdivision of Bézier curves (seed 004 §3.3): the two sides of the de
// Casteljau triangle at t are the control polygons of C on [0,t] and [t,1].

#include <utility>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// The two halves of C at t in (0, 1): left is C on [0,t], right is C on
/// [t,1], each reparameterised to [0,1]. The shared end point is bit for bit
/// point_at(C, t) (same operations). Rational curves split in homogeneous
/// form. Farin §3.2; O(n^2 d). Errors (as for every curve kind,
/// core/parameter_checks.hpp): t not finite or not strictly inside (0, 1).
Expected<std::pair<BezierCurve, BezierCurve>> split_at(const BezierCurve& curve, double t);

/// C restricted to [t0, t1] (0 <= t0 < t1 <= 1) and reparameterised to
/// [0,1]. Two subdivisions. O(n^2 d). Errors as for every curve kind: not
/// finite, outside [0, 1], t0 >= t1.
Expected<BezierCurve> segment(const BezierCurve& curve, double t0, double t1);

/// What only a Bézier curve can do: the same polynomial (or rational
/// function) on any finite [t0, t1], inside or outside [0, 1], reparameterised
/// to [0, 1] (blossoming, Farin §3.4; t0 > t1 gives the reversed piece, t0 =
/// t1 the point repeated). Outside [0, 1] a rational curve's weights may reach
/// zero or below: callers with outside parameters check them (Python's
/// extrapolate=True does). The kernel of split_at and segment.
BezierCurve extended_segment(const BezierCurve& curve, double t0, double t1);

/// The same curve traversed backwards: control points (and weights) reversed.
BezierCurve reversed(const BezierCurve& curve);

/// Recursive subdivision r times at t (seed 004's `bezier(Ps, r, t)`): the
/// 2^r + 1 end points of the 2^r pieces, all on the curve, in order. For
/// t = 1/2 they are C(i / 2^r). r = 10 gives 1025 points. Refuses r < 0 and
/// r > tolerances::kMaxSubdivisionDepth (a huge size) and t outside (0,1).
Expected<PointArray> subdivide_recursive(const BezierCurve& curve, int depth, double t = 0.5);

}  // namespace casteljau

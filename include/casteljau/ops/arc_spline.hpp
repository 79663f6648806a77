#pragma once
// Arc splines: a plane curve of any kind approximated by a G1 chain of
// circular arcs and line segments (biarcs), what machine controllers move
// along (G2/G3, G1). The distance between the chain and the curve is
// certified by a bound, not sampled. Method and proof: docs/cnc.md.

#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// A circular arc or a line segment of the plane from `start` to `end`,
/// stored as DXF's LWPOLYLINE stores it: bulge = tan(sweep / 4), where the
/// sweep is the signed angle the arc turns through (positive counterclockwise).
/// Bulge 0 is the segment, |bulge| = 1 a half circle, |bulge| > 1 more than
/// half a circle; a whole circle has no bulge (two arcs make one).
struct ArcSegment {
  Vec2 start{};
  Vec2 end{};
  double bulge = 0.0;
};

/// The signed angle an arc turns through, 4 atan(bulge), in (-2 pi, 2 pi) (0 for a segment).
double sweep_of(const ArcSegment& arc);
/// The signed curvature 2 sin(sweep / 2) / |end - start| (0 for a segment;
/// positive when the arc turns left, counterclockwise).
double curvature_of(const ArcSegment& arc);
/// The centre of an arc (requires bulge != 0).
Vec2 center_of(const ArcSegment& arc);
/// The radius |end - start| (1 + bulge^2) / (4 |bulge|) of an arc (requires bulge != 0).
double radius_of(const ArcSegment& arc);
/// Its length: radius x |sweep| for an arc, |end - start| for a segment.
double length_of(const ArcSegment& arc);
/// The point a fraction f in [0, 1] of the way along it (equal angles of an
/// arc, equal lengths of a segment): start at 0, end at 1.
Vec2 point_along(const ArcSegment& arc, double fraction);
/// The unit tangent (direction of travel) a fraction f of the way along it.
Vec2 tangent_along(const ArcSegment& arc, double fraction);

/// An arc spline and what is known of it.
struct ArcSpline {
  /// The arcs and segments in the curve's order; each starts where the
  /// previous ends (bit for bit), the first at the curve's start and the last
  /// at its end (bit for bit). Consecutive elements share their tangent
  /// (within rounding) except where the curve itself has a corner.
  std::vector<ArcSegment> segments;
  /// The curve's parameter at each segment's start and at the last end
  /// (segments.size() + 1 values, increasing): segment i approximates the
  /// curve over [parameters[i], parameters[i + 1]].
  std::vector<double> parameters;
  /// The largest certified bound of the Hausdorff distance between a segment
  /// and its stretch of curve (including the rounding allowance): <= the tolerance.
  double deviation_bound = 0.0;
};

/// A G1 chain of arcs and segments within tolerance.distance of a plane
/// curve of any kind (Hausdorff distance: every point of the chain within it
/// of the curve and every point of the curve within it of the chain),
/// certified per element (docs/cnc.md, "The certificate"). The chain breaks
/// only where the curve does: at cusps and corners. Between them, from the
/// start, the longest stretch one certified biarc covers (bisection on its
/// end), the biarc matching the stretch's end points and end tangents with
/// equal tangent lengths (Bolton, "Biarc curves", CAD 7, 1975); the error of
/// a biarc is O(h^3) (Meek & Walton, J. Comput. Appl. Math. 59, 1995), so the
/// count grows as O(tolerance^(-1/3)) and the greedy reach keeps it near the
/// fewest. Consecutive elements on one circle (or one line) are joined and
/// the join certified again: a circular arc of a NURBS conic becomes one
/// arc, a whole circle two. An arc straight within rounding (sagitta at most
/// tolerances::kArcStraightSagitta x the curve's size) is a segment.
/// Errors: a curve that is not plane ("arc fitting needs a plane curve, this
/// one lives in R^3"); a tolerance not finite and > 0, or below what double
/// precision certifies (tolerances::kFlattenSmallestToleranceFactor x the
/// rounding allowance of the curve's size); a curve that jumps (a knot of
/// multiplicity p + 1 whose pieces do not meet); a curve of zero length (a
/// point); more than tolerances::kMaxFlattenSegments segments.
Expected<ArcSpline> fit_arcs(CurveView curve, Tolerance tolerance);

}  // namespace casteljau

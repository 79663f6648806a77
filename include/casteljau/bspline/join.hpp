#pragma once
// Joining two B-spline curves end to start into one curve.

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/continuity.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// The joined curve and how well the two parts meet.
struct JoinResult {
  /// first then second, on [first's lower, first's upper + second's length].
  BSplineCurve curve;
  /// The continuity measured at the joint (continuity_at): C^k and G^1.
  Continuity continuity;
  /// The parameter of the joint in the joined curve (the end of the first domain).
  double joint = 0.0;
  /// Distance between the end of the first curve and the start of the
  /// second; the joined curve passes through their midpoint.
  double gap = 0.0;
};

/// `first` followed by `second`: the degrees are made equal by elevating
/// the lower one (elevate_degree), both are clamped at the joint, the
/// second's domain is shifted to start where the first's ends (its length is
/// kept), and the joint becomes a knot of multiplicity p with the midpoint
/// of the two end points as control point (The NURBS Book §5.3 read
/// backwards: the inverse of split_at). NURBS (either curve rational): the
/// second's weights are scaled so that both weights agree at the joint.
/// Join a split curve back and the shape is the original's; the knot at the
/// joint can then be removed with remove_knot. O((n_1 + n_2) p^2 w).
/// Errors: different dimensions, the end of the first and the start of the
/// second farther apart than tolerances::kJointRelativeGap of the curves'
/// scale (the message gives both points and the gap), an elevation beyond
/// the limits of elevate_degree.
Expected<JoinResult> join(const BSplineCurve& first, const BSplineCurve& second);

}  // namespace casteljau

#pragma once
// The bspline layer's own tolerances: continuity at knots
// (core/tolerance.hpp says why each layer keeps its tolerances beside its code).

namespace casteljau::tolerances {

/// Relative agreement under which the left and right k-th derivatives at a
/// knot count as equal when measuring continuity (continuity_at_knots, join).
/// Each side is computed by the basis derivatives of its own span, with a
/// rounding error of about p^k ulps of the derivative scale
/// s (p/h)^k (s the control points' scale, h the shorter adjacent span);
/// 1e-9 of that scale is far above the noise for degrees up to 10 and far
/// below a real jump. Unit: fraction of the derivative scale.
inline constexpr double kContinuityRelative = 1e-9;

/// Angle, in radians, under which the unit tangents on both sides of a knot
/// count as the same direction (G^1). 1e-7 rad is about sqrt of the rounding
/// of a normalized difference of two O(1) tangents (1e-14 relative): what
/// a tangent computed to ~1e-14 can certify.
inline constexpr double kTangentAngle = 1e-7;

}  // namespace casteljau::tolerances

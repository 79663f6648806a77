#pragma once
// Internal to src/ops: distances to and between straight segments in R^d,
// the bounds flatten.cpp and intersection.cpp put on Bézier pieces through
// their chords (a piece lies in its control points' hull, so within the
// largest distance of a control point from its chord segment).
#include <span>

namespace casteljau::detail {

/// Distance from point p to the segment [a, b] (any dimension; a == b allowed).
double distance_to_segment(std::span<const double> p, std::span<const double> a, std::span<const double> b);

/// Distance between the segments [p0, p1] and [q0, q1] (any dimension; either
/// may be a point): the closest points of the two lines, clamped to the
/// segments (Ericson, Real-Time Collision Detection, 5.1.9). Coordinates are
/// taken relative to p0 and divided by the largest difference, so that
/// coordinates up to the largest double do not overflow the squares; NaN
/// when a coordinate is not finite.
double distance_between_segments(std::span<const double> p0, std::span<const double> p1, std::span<const double> q0,
                                 std::span<const double> q1);

}  // namespace casteljau::detail

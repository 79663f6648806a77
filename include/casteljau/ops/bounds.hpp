#pragma once
// The tight axis-aligned bounding box of any curve kind: not the control
// polygon's box (which may be far larger), but the box of the curve itself,
// from its end points and the parameters where a coordinate's derivative
// vanishes (the roots of each coordinate of the hodograph, found in
// Bernstein form by bezier/bernstein_roots.hpp; for a rational piece the
// roots of the numerator A_j' w - A_j w' of (A_j / w)').

#include "casteljau/core/point_array.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// An axis-aligned box: lower[j] <= x_j <= upper[j].
struct Box {
  Point lower;
  Point upper;
};

/// The smallest box holding every point of the curve on its domain, to the
/// accuracy of the extreme points' parameters (full double precision for
/// simple extrema; a coordinate's extreme at a double root of its
/// derivative, an inflection on the axis, to about 1e-8 in the parameter,
/// which changes the coordinate by far less). O(pieces x d x n^2 log).
Box bounding_box(CurveView curve);

/// bounding_box widened on every side by `margin` and by what rounding may
/// have cut off its extremes (tolerances::kBoxRoundingMargin x its diagonal
/// plus its largest |coordinate|): a box no point of the curve, nor any
/// point within `margin` of it, lies outside, for pruning (closest points
/// and intersections among many curves).
Box pruning_box(CurveView curve, double margin);

}  // namespace casteljau

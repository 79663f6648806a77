#pragma once
// Bézier's original "pantin vectoriel" (seed 003 §1; seed 001 "polynômes de
// Bézier"): P(t) = sum_i f_i(t) V_i with V_0 = P_0 (a point) and
// V_i = P_i - P_{i-1} (the polygon's sides as vectors), f_i from bernstein.hpp.

#include "casteljau/bezier/bezier_curve.hpp"

namespace casteljau {

/// V_0 = P_0, V_i = P_i - P_{i-1}: the vector form of a control polygon.
PointArray to_vector_form(const PointArray& control_points);

/// The inverse: P_0 = V_0, P_i = P_{i-1} + V_i (a running sum).
PointArray from_vector_form(const PointArray& vectors);

/// P(t) = sum_i f_i(t) V_i, computed in Bézier's basis (for teaching and as a
/// differential check against point_at; not the evaluator to use).
Point point_at_vector_form(const PointArray& vectors, double t);

}  // namespace casteljau

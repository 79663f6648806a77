#pragma once
// Changing the degree of a Bézier curve: elevation (exact, the same curve) and
// reduction (least squares, with the error it makes), and the seed 003
// demonstration that repeating a control point pulls the curve toward it.

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// The same curve written with degree n + times: Q_i = (i/(n+1)) P_{i-1} +
/// (1 - i/(n+1)) P_i, applied `times` times (Farin §5.1; The NURBS Book eq.
/// 5.36). Rational curves elevate their homogeneous points. times >= 0.
BezierCurve elevate_degree(const BezierCurve& curve, int times = 1);

/// How reduce_degree should treat the end points.
struct DegreeReductionOptions {
  /// Keep C(0) and C(1) exactly (the constrained least-squares problem), so
  /// that reduced pieces still join; otherwise the plain L2-best curve.
  bool keep_end_points = true;
};

/// A reduced curve and the error it makes against the original.
struct DegreeReduction {
  BezierCurve curve;
  /// Guaranteed: max |C(t) - R(t)| over [0,1] is at most this (the largest
  /// control-point difference after elevating R back to degree n, by the
  /// convex hull property of the difference curve).
  double error_bound;
  /// max |C(t) - R(t)| sampled at 1025 evenly spaced parameters (<= error_bound).
  double sampled_error;
};

/// The curve R of degree n - 1 closest to C in the L2 norm
/// integral_0^1 |C(t) - R(t)|^2 dt (optionally with the same end points), by
/// the normal equations with the Bernstein Gram matrix
/// G_ij = C(m,i) C(m,j) / ((2m+1) C(2m, i+j)) (Eck, "Least squares degree
/// reduction of Bézier curves", CAD 27(11), 1995), solved by Eigen's LDLT.
/// Errors: degree 0 (nothing to reduce), a rational curve (not supported:
/// elevate or approximate its polynomial pieces instead).
Expected<DegreeReduction> reduce_degree(const BezierCurve& curve,
                                        DegreeReductionOptions options = {});

/// Seed 003, fig. 4 b): the curve whose control polygon repeats P_index
/// `extra` more times (P_0..P_index, P_index x extra, ..., P_n): degree
/// n + extra, same polygon, the curve pulled toward P_index. Not an elevation:
/// a different curve. Requires 0 <= index <= n and extra >= 0.
BezierCurve repeat_control_point(const BezierCurve& curve, int index, int extra);

}  // namespace casteljau

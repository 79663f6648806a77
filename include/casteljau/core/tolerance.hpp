#pragma once
// The tolerances every layer shares, with their unit and their reason (style
// rule 6): the Tolerance callers pass to approximate operations, the rounding
// and scale floors relative comparisons use, the ranges of valid model
// numbers and the size limits of a model. Exact operations take no
// tolerance; approximate ones require a Tolerance from the caller.
// Comparisons are relative to the data's scale (scale_of), never
// numeric_limits::epsilon() used as an absolute.
//
// A tolerance that only one layer uses lives beside that layer's code, in
// casteljau/<layer>/tolerance.hpp (bezier, bspline, nurbs, interpolation,
// ops, io, render), so that changing it rebuilds that layer and those above
// it, not the whole library; the namespace is casteljau::tolerances in all.

#include <cstddef>

namespace casteljau {

/// A distance in model units that an approximate operation must stay within
/// (flattening, degree reduction checks, later fitting and tessellation).
/// Must be finite and > 0; operations assert it.
struct Tolerance {
  double distance = 0.0;
};

namespace tolerances {

// --- Rounding, scale and kernels ---------------------------------------------

/// Relative rounding unit used when a bound has to absorb floating-point
/// error: a few ulps of double (2^-52 = 2.2e-16) for the handful of
/// operations behind one control point of a subdivided curve.
inline constexpr double kRoundingSlack = 8.0 * 2.220446049250313e-16;

/// The smallest scale a relative comparison divides by or multiplies with
/// (max(scale, kScaleFloor)): data whose scale is 0 (every point at the
/// origin, a zero derivative) then compares absolutely instead of dividing
/// by zero. 1e-300 lies below any coordinate that matters and above the
/// subnormal range, where a quotient by it would overflow. Unit: model units.
inline constexpr double kScaleFloor = 1e-300;

/// Relative size, against the control points' scale, below which a derivative
/// is treated as vanishing when looking for a tangent direction. A derivative
/// of a curve whose control points are O(s) is computed with an absolute error
/// of about n * 1e-16 * s per order; 1e-12 sits well above that noise for
/// degrees up to a few hundred and well below any real tangent.
inline constexpr double kVanishingDerivative = 1e-12;

/// Largest gap allowed where two curves or Bézier pieces are joined end to
/// start (join, from_bezier_pieces), relative to the larger of their scales
/// (scale_of of the control points, at least kScaleFloor so that curves at
/// the origin compare absolutely). Pieces produced by casteljau (decomposition,
/// splitting) meet to a few ulps, about 1e-15 relative; 1e-9 accepts data
/// rounded to 9 significant digits (files, other programs) and refuses any
/// visible gap. Unit: fraction of the scale.
inline constexpr double kJointRelativeGap = 1e-9;

/// Degree up to which kernels keep their de Casteljau triangle on the stack.
/// Beyond it, a batch call allocates one workspace for the whole call.
inline constexpr int kMaxStackDegree = 255;

// --- Valid model numbers (core/model_numbers.hpp) -----------------------------
// The ranges every make() accepts, chosen so that a valid curve or surface
// never fails to evaluate: its points and first derivatives are finite
// everywhere on its domain. They share out double's exponent range (up to
// DBL_MAX = 1.8e308). The first derivative of a degree-p B-spline or NURBS
// curve is computed from its de Boor triangle as (Q1 - Q0) (p / h) on rows
// (w P, w), h the width of the span, then C' = (A' - w' C) / w (The NURBS
// Book eq. 4.8), so
//   |C'| <= 4 p (w_max / w_min) M / h,   intermediates <= 4 p w_max M / h,
// M the largest coordinate. With p <= kMaxBSplineDegree (1e4), weights in
// [kMinWeight, kMaxWeight] (a ratio up to 1e100), M <= kMaxCoordinate and
// h >= kMinKnotSpan: |C'| <= 4e4 * 1e100 * 1e100 / 1e-100 = 4e304, and the
// intermediates stay below 4e254. A Bézier curve is the case h = 1, each
// partial derivative of a surface the case of its direction's degree and
// spans. Orders >= 2 grow like (2p/h)^k M: finite for any ordinary data, but
// at the corners of these ranges they can overflow to +-inf, as can products
// of two first derivatives (normals, curvature), which must be scaled first.
// Coordinates below kScaleFloor, subnormals included, are valid (they
// evaluate to finite values; relative comparisons treat them as scale 0).

/// Largest absolute coordinate of a control point (and of the points,
/// tangents, conic centres and radii the constructions take). 1e100: a third
/// of the exponent range (see above), far beyond any geometry (the
/// observable universe is 1e27 m), and squares of coordinate differences
/// (squared distances, dot and cross products of chords: <= 4e200 d) stay
/// finite. Unit: model units.
inline constexpr double kMaxCoordinate = 1e100;

/// Largest absolute knot, and parameter value of interpolation and fitting
/// (parameters become knots). 1e100 keeps sums and differences of knots
/// finite (the domain's width, midpoints (a + b) / 2, reversal's
/// (a + b) - t), and the width of a knot vector at most 2e200 times its
/// narrowest span, so that a parameter normalized to [0, 1] (Coons
/// boundaries, tessellation cells) still has normal-number spans (>= 5e-201).
/// Unit: parameter units.
inline constexpr double kMaxKnot = 1e100;

/// Narrowest non-empty knot span t_{i+1} - t_i > 0, and the closest two
/// parameters of interpolation and fitting may be. 1e-100: its reciprocal
/// (1e100) and p times it are representable with room for the coordinate
/// and weight ranges (see above); spans of a subnormal width (5e-324,
/// 1e-310) have no finite reciprocal at all. Spans of one ulp of ordinary
/// knots (1 and nextafter(1, 2): 2.2e-16) are far above it. Unit: parameter
/// units.
inline constexpr double kMinKnotSpan = 1e-100;

/// Smallest and largest weight of a NURBS (rational) curve or surface. The
/// ratio of any two weights is then at most 1e100 (no separate ratio bound
/// is needed, see above), and w P stays within 1e150. Weights that matter
/// in design lie within 1e-3..1e3; a weight of 1e-320 is positive but
/// subnormal, and 1/w overflows. Dimensionless.
inline constexpr double kMinWeight = 1e-50;
inline constexpr double kMaxWeight = 1e50;

// --- Size limits for untrusted input -----------------------------------------
// "Huge sizes" are refused with a clear error instead of exhausting memory or
// running for hours. The limits of one layer's own inputs live in its header.

/// Highest degree of one Bézier curve accepted from outside (BezierCurve::make).
/// Evaluation costs O(n^2) per point: at n = 10^4 that is already 10^8
/// operations per point (tens of milliseconds), and no design needs more: long
/// point sets are interpolated or split into pieces, not made one polynomial.
inline constexpr int kMaxBezierDegree = 10'000;

/// Highest degree of one B-spline or NURBS curve accepted from outside
/// (BSplineCurve::make). The same bound as a Bézier curve's, so that every
/// Bézier curve converts (to_bspline); evaluation is O(p^2) per point and the
/// basis derivatives (basis_function_derivatives) take (p+1)^2 doubles.
inline constexpr int kMaxBSplineDegree = kMaxBezierDegree;

/// Most control points in one model (all pieces together), and most points
/// in one CSV point set. 10^7 points in 3D are 240 MB as doubles and about
/// 1 GB as parsed JSON: beyond any drawing or machining need, still inside
/// memory.
inline constexpr std::size_t kMaxControlPoints = 10'000'000;

/// Most values in one input file: JSON values (numbers, arrays, objects,
/// strings...) of a model JSON text, numbers of a CSV file. Exactly what
/// kMaxControlPoints points in 3D with weights need in JSON (10^7 point
/// arrays + 3*10^7 coordinates + 10^7 weights). A parsed JSON document takes
/// about 16 bytes per value and a CSV table 8 bytes per number, so this caps
/// their memory near 1 GB whatever the shape of the file.
inline constexpr std::size_t kMaxInputValues = 50'000'000;

/// Highest derivative order the front ends accept. A polynomial curve's
/// derivatives of order > n vanish, and n!/(n-k)! overflows a double once
/// k > 170 for any n, so larger orders only make sense as zeros; rational
/// derivatives cost O(k^2) per point (NURBS Book A4.2). 1000 keeps every
/// request cheap.
inline constexpr int kMaxDerivativeOrder = 1000;

/// Highest total order k + l of a surface partial derivative d^(k+l)S/du^k dv^l
/// the front ends accept. A NURBS surface's derivative needs every lower pair
/// (NURBS Book A4.4): O(k^2 l^2) point operations, 50^4 ≈ 6e6 at k = l = 50,
/// while k = l = 300 already took 28 s. Polynomial derivatives above the
/// degree vanish, so the limit costs nothing real.
inline constexpr int kMaxSurfaceDerivativeOrder = 100;

}  // namespace tolerances
}  // namespace casteljau

#pragma once
// The interpolation layer's own tolerances and limits: fitting, GCV, Lagrange
// and natural splines (core/tolerance.hpp says why each layer keeps its
// tolerances beside its code).

namespace casteljau::tolerances {

// --- Fitting (interpolation/fit.hpp) -----------------------------------------

/// Smallest pivot D_i = R_ii² of a fit's system A = RᵀR = G + λΩ (R from
/// its rotations), relative to the diagonal entry A_ii (the squared norm of
/// column i), below which the system counts as singular (dimensionless):
/// D_i / A_ii >= 1 / cond(A). A ratio under 1e-13 (cond(R) above 3e6 in that
/// column) means the data do not determine the control points (too few
/// parameters in some knot span, λ = 0 with more control points than points);
/// the seed's head fitted with as many control points as points (cond(R) =
/// 3.0e6, so 1 / cond(A) = 1.1e-13) still passes.
inline constexpr double kFitSingularPivot = 1e-13;

/// The range of λ that GCV searches, in decades around the scale
/// λ₀ = tr(BᵀB) / tr(Ω) where data term and penalty weigh alike: from
/// λ₀ 10^-10 (the fit all but interpolates: 1 − tr H/(m+1) is at the level
/// of rounding and GCV is noise) to λ₀ 10^6 (heavily smoothed, nearly the
/// least-squares straight line: tr H = 3.3 effective degrees of freedom on
/// the 102 points of examples/noisy.csv, where the line has 2 and GCV's
/// choice 12.3; the line itself is only the limit λ → ∞).
inline constexpr double kGcvSearchDecadesBelow = 10.0;
inline constexpr double kGcvSearchDecadesAbove = 6.0;

/// Step of the GCV grid over log10 λ, in decades: 2 values per decade find
/// the basin of the minimum (GCV changes smoothly over a fraction of a decade
/// and its minima are broad; 4 per decade chose the same λ on every test and
/// scipy cross-check); Brent's method then refines within it.
inline constexpr double kGcvGridStepDecades = 0.5;

/// How far beyond an edge of the range the grid goes on while GCV keeps
/// falling there, in decades: data smooth at the range's scale (scipy's gcvspl
/// test: 100 points of sin x + noise, the minimum at λ₀ 10^7.3).
inline constexpr double kGcvSearchDecadesBeyond = 10.0;

/// Width of the final bracket of log10 λ, in decades: 1e-6 decades is a
/// relative change of 2.3e-6 in λ, far below any visible change of the
/// curve; Brent's method (parabolic steps) reaches it in about a dozen GCV
/// evaluations from the grid's bracket, at most kGcvBrentEvaluations.
inline constexpr double kGcvRefinementDecades = 1e-6;
inline constexpr int kGcvBrentEvaluations = 60;

/// Smallest n − tr H (residual degrees of freedom) at which GCV is trusted.
/// Near interpolation GCV = n RSS / (n − tr H)² is 0/0: both factors come
/// from cancellation, and rounding made it spuriously small (4e-4 against
/// its true limit 0.035 on 41 noisy points over x in [0, 6]). A thousandth
/// of a degree of freedom is far from any fit GCV should choose. Unit:
/// degrees of freedom.
inline constexpr double kGcvNearInterpolation = 1e-3;

// --- Size limits (interpolation/lagrange.hpp, interpolation/natural_spline.hpp) ---

/// Highest degree of a Lagrange (barycentric) interpolant, and so at most
/// kMaxLagrangeDegree + 1 nodes (interpolate_lagrange, chebyshev_parameters).
/// The weights cost O(n^2) operations: 10^8 at this bound, a fraction of a
/// second; evaluation is O(n) per point. On Chebyshev nodes the barycentric
/// form stays accurate at this degree (Berrut & Trefethen 2004 §7).
inline constexpr int kMaxLagrangeDegree = 10'000;

/// Highest degree of a Lagrange interpolant converted to a Bézier curve
/// (to_bezier in interpolation/lagrange.hpp). The conversion solves a
/// Bernstein-Vandermonde system whose condition number grows like 2^n;
/// measured on Runge's function, the Bézier curve misses the interpolant by
/// 3e-11 (n = 30) and 5e-9 (n = 40) of its size on Chebyshev nodes, 4e-10
/// and 3e-7 on equispaced ones (tests/interpolation/lagrange_test.cpp),
/// about 100x more per 10 degrees. Above 40 the Bézier form would no longer
/// represent the polynomial to single-precision accuracy: refused.
inline constexpr int kMaxLagrangeBezierDegree = 40;

/// Highest order q accepted by interpolate_natural (degree 2q - 1). The
/// natural end conditions are derivatives of orders q..2q-2 at the ends,
/// whose basis values grow like (2q-1)!/(q-1)! / h^j; past q = 8 (degree 15,
/// derivatives up to order 14) the collocation system loses most of double
/// precision on ordinary data, and no use of natural splines needs more
/// (q = 2, 3 are the common ones). Dimensionless.
inline constexpr int kMaxNaturalSplineOrder = 8;

}  // namespace casteljau::tolerances

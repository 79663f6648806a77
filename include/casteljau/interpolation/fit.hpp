#pragma once
// Approximation of points P_0..P_m at parameter values t_0 < ... < t_m by a
// B-spline curve C (not through every point): least squares with a fixed
// number of control points (The NURBS Book §9.4.1), smoothing with the
// penalty λ ∫ ‖C''‖² and λ chosen by generalized cross-validation (Craven &
// Wahba 1979), and least squares refined until a tolerance is met.
//
// Every fit is one banded least-squares problem (half-bandwidth p) in the
// unknown control points, solved by Givens rotations into a banded R, row by
// row as FITPACK does (Dierckx 1993), in O(m p² + n p d): its error grows with
// the design matrix's condition number, not its square as the normal
// equations' would (issue 43); the d coordinates share the rotations. "Error" everywhere below is the
// distance ‖C(t_i) − P_i‖ at the point's own parameter: an upper bound of the
// distance from P_i to the curve (the parameters are not re-projected).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {

/// Whether a fit passes through the first and last points exactly
/// (C(t_0) = P_0, C(t_m) = P_m: The NURBS Book eq. 9.63–9.67) or treats them
/// like the others (scipy's make_lsq_spline, make_smoothing_spline).
enum class FitEnds { interpolated, free };

/// A fitted curve with what it achieved.
struct BSplineFit {
  BSplineCurve curve;            ///< clamped, domain [t_0, t_m]
  std::vector<double> errors;    ///< ‖C(t_i) − P_i‖ for every point
  double max_error = 0.0;        ///< max_i errors[i]
  std::size_t worst_point = 0;   ///< an i where errors[i] = max_error
  double rms_error = 0.0;        ///< sqrt(Σ errors[i]² / (m+1))
  double smoothing = 0.0;        ///< λ of the penalty (0 for plain least squares)
  /// Effective degrees of freedom: the trace of the hat matrix H (fitted
  /// points = H · data points, per coordinate); the number of control points
  /// for plain least squares, falling towards 2 (a straight line) as λ → ∞.
  double effective_degrees_of_freedom = 0.0;
  /// GCV(λ) = (Σ ‖C(t_i) − P_i‖² / (m+1)) / (1 − tr H / (m+1))² (Craven &
  /// Wahba 1979, eq. 1.3; summed over the coordinates). For one coordinate
  /// it is the score scipy's make_smoothing_spline minimizes. NaN when
  /// tr H = m+1 (the fit interpolates).
  double gcv_score = 0.0;
  bool smoothing_from_gcv = false;  ///< λ was chosen by minimizing GCV
};

/// The knots of a least-squares fit with n+1 control points of degree p to
/// parameters t_0..t_m (The NURBS Book eq. 9.68–9.69): p+1 copies of t_0 and
/// t_m and, for j = 1..n−p, with d = (m+1)/(n−p+1), i = ⌊j d⌋, α = j d − i,
/// the interior knot (1 − α) t_{i−1} + α t_i. Every knot span then contains
/// a parameter, so the normal equations are positive definite
/// (Schoenberg–Whitney). Requires p >= 1, p+1 <= n+1 <= m+1 and increasing
/// parameters (asserted). O(n + p).
std::vector<double> approximation_knots(std::span<const double> parameters, int degree,
                                        std::size_t control_point_count);

/// The least-squares B-spline of degree p with n+1 = `control_point_count`
/// control points on approximation_knots: minimizes Σ ‖C(t_i) − P_i‖² over
/// all control points (FitEnds::free) or over Q_1..Q_{n−1} with Q_0 = P_0,
/// Q_n = P_m (FitEnds::interpolated: The NURBS Book §9.4.1, Algorithm A9.7's
/// system). With n = m it interpolates; polynomial data of degree <= p is
/// reproduced exactly (up to rounding). Errors: degree outside
/// 1..tolerances::kMaxBSplineDegree, fewer than p+1 points or control points,
/// more control points than points, a parameter count that differs from the
/// point count, parameters not finite or not strictly increasing, non-finite
/// coordinates. O(m p² + m p d) time, O(m p) memory.
Expected<BSplineFit> fit_least_squares(const PointArray& points, std::span<const double> parameters, int degree,
                                       std::size_t control_point_count, FitEnds ends = FitEnds::interpolated);

/// The weighted least-squares B-spline of degree p on the given knots
/// (The NURBS Book §9.4.1 with the weights of §9.4.4; de Boor, A Practical
/// Guide to Splines, ch. XIV): minimizes Σ w_i ‖C(t_i) − P_i‖² over all n+1 =
/// knots.size() − p − 1 control points (FitEnds::free: scipy's
/// make_lsq_spline(t, P, knots, k=p, w=√w), whose weights multiply the
/// residual before squaring), or over Q_1..Q_{n−1} with Q_0 = P_0 and
/// Q_n = P_m (FitEnds::interpolated, which needs knots clamped at t_0 and
/// t_m). `weights` empty means all 1; otherwise one finite w_i >= 0 per point
/// (a zero weight leaves the point out). The knots pass validate_knots and
/// every parameter lies in the domain [knots[p], knots[n+1]] (the knots need
/// not be clamped). The Schoenberg–Whitney condition (an increasing choice
/// of points of positive weight, one inside the support of each free basis
/// function) is checked, and its error names the first basis function left
/// without a point and its support. Other errors: those of
/// fit_least_squares (degree, counts, non-finite or non-increasing input).
/// The result's errors are unweighted distances. O(m p² + m p d) time,
/// O(m p) memory.
Expected<BSplineFit> fit_least_squares_on_knots(const PointArray& points, std::span<const double> parameters,
                                                int degree, std::vector<double> knots,
                                                std::span<const double> weights = {}, FitEnds ends = FitEnds::free);

/// What a smoothing fit is asked for.
struct SmoothingOptions {
  int degree = 3;  ///< p >= 2 (∫ ‖C''‖² needs C'' to be a function)
  /// n+1 control points on approximation_knots (a penalized least-squares
  /// spline), or 0: a simple knot at every interior parameter, m+p control
  /// points; with p = 3 that is the cubic smoothing spline itself (Reinsch
  /// 1967), the minimizer over all C¹ functions with square-integrable C''.
  std::size_t control_point_count = 0;
  /// λ >= 0; empty: the λ minimizing GCV (see fit_smoothing).
  std::optional<double> smoothing;
  FitEnds ends = FitEnds::free;
  /// Empty (all 1), or one w_i >= 0 per point multiplying its squared
  /// residual (scipy's make_smoothing_spline w, not squared).
  std::vector<double> weights;
};

/// The B-spline minimizing Σ w_i ‖C(t_i) − P_i‖² + λ ∫_{t_0}^{t_m} ‖C''(u)‖² du
/// (w_i = 1 without weights).
/// The penalty's Gram matrix Ω_jk = ∫ N_j'' N_k'' is exact (Gauss–Legendre
/// with p−1 nodes per knot span, Ω = Σ_q r_q r_qᵀ): the rows √λ r_q are
/// rotated in beside the data's, so the penalized problem is least squares
/// too, never the normal equations (BᵀB + λΩ) Q = BᵀP. λ has scipy's meaning: with p = 3, knots at every parameter
/// and free ends, the result equals make_smoothing_spline(t, y, lam=λ) for
/// each coordinate. The effective degrees of freedom tr H = tr((BᵀB + λΩ)⁻¹
/// BᵀB) (plus 2 for interpolated ends) come from the band of the inverse
/// (Hutchinson & de Hoog 1985), O(n p²). Without λ, GCV(λ) is minimized over
/// log λ: a grid (tolerances::kGcvGridStepDecades) from λ₀ 10^-kGcvSearchDecadesBelow
/// to λ₀ 10^kGcvSearchDecadesAbove around the scale λ₀ = tr(BᵀB) / tr(Ω),
/// extended beyond the top while GCV falls there (kGcvSearchDecadesBeyond),
/// then Brent's method around the best grid point (the global minimum on the
/// grid when GCV has several local ones, an interior one before the bottom
/// edge, where GCV may fall towards interpolation's 0/0). The λ chosen is
/// BSplineFit::smoothing. Errors: those of
/// fit_least_squares, degree below 2, λ negative or not finite, λ = 0 with
/// more control points than points, a singular system.
/// A λ that leaves the system singular is named too large (λ tr Ω
/// swamps tr(BᵀB): the data are lost in rounding) or too small (it cannot
/// determine more control points than points), with the range GCV searches.
/// The data's rows are rotated once, O(m p²); each λ merges R's rows with the
/// penalty's, O(n p²); about 100 values of λ for GCV, each reported to
/// `progress` (the fraction of the search's evaluations done).
Expected<BSplineFit> fit_smoothing(const PointArray& points, std::span<const double> parameters,
                                   const SmoothingOptions& options, Progress progress = {});

/// Least squares refined until every error ‖C(t_i) − P_i‖ is at most
/// `tolerance.distance`: start from p+1 control points (one Bézier piece) and
/// repeatedly split every knot span that holds a point with an error above
/// the tolerance, at the middle of its points (between the two middle
/// parameters, so both halves keep points and the normal equations stay
/// positive definite; checked by the Schoenberg–Whitney condition), worst
/// spans first. Ends as in fit_least_squares. Errors: those of
/// fit_least_squares, a tolerance that is not finite and > 0, and "not
/// reached" (naming the error achieved and the control point count) when no
/// span can be split any more: every offending span holds a single point or
/// the control points reached the number of points.
/// O(m p² d) per round; the rounds roughly halve the offending spans. After
/// each round `progress` hears the share of points within the tolerance (the
/// largest so far; 1 when done).
Expected<BSplineFit> fit_to_tolerance(const PointArray& points, std::span<const double> parameters, int degree,
                                      Tolerance tolerance, FitEnds ends = FitEnds::interpolated,
                                      Progress progress = {});

}  // namespace casteljau

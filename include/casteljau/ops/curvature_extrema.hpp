#pragma once
// Where the curvature of a curve of any kind is extreme, and where it is
// infinite (cusps): the points a designer looks at on a curvature comb, the
// sharpest turns a machine must slow down for.
//
// On each Bézier piece the curve is written with P = W X' - W' X (X the
// homogeneous coordinates w x, W the weight; P = C' for a polynomial piece,
// P = W^2 C' in general) and its curvature is kappa = W^2 (P x P') / |P|^3
// (do Carmo §1-5 for kappa = |C' x C''| / |C'|^3; the W factors cancel as in
// Farin §13.2). Every factor is a polynomial built in Bernstein form by
// products (Farin §5.8), so the critical points are the roots of one
// polynomial per piece, found by bernstein_roots (exact isolation, not
// sampling):
// - in the plane, with F = W^2 (P x P') (a scalar) and G = |P|^2,
//   dkappa/dt has the sign of N = F' G - 3 F (P . P');
// - in R^d, d >= 3, with H = W^4 (G |P'|^2 - (P . P')^2) = W^4 |P x P'|^2
//   (Lagrange's identity), d(kappa^2)/dt has the sign of N = H' G - 6 H (P . P').
// A cusp is a point where P vanishes and the tangent turns back: P . P' has a
// simple root there (|P|^2 touches zero quadratically).

#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// A local extremum of the curvature magnitude |kappa|.
struct CurvatureExtremum {
  double parameter = 0.0;
  /// The curvature there: signed in the plane (positive turning left, as
  /// signed_curvature_at), kappa >= 0 in R^3 and beyond (curvature_at).
  double curvature = 0.0;
  /// True where |kappa| is a local maximum (the sharpest point around), false
  /// where it is a local minimum (the flattest).
  bool maximum = false;
};

/// The local extrema of |kappa| inside the domain, by increasing parameter:
/// the odd roots of N (see above) on each piece, and a junction of pieces
/// where the curvature is continuous (tolerances::kCurvatureContinuity) and
/// N changes sign across it. Not reported: the ends of the domain; a
/// junction where the curvature jumps (a C^1 curve's knots: breakpoints()
/// says where); the zeros of the curvature in the plane (inflection_parameters
/// gives them: |kappa| is least there, the signed curvature is not extreme);
/// cusps (cusp_parameters); a piece of constant curvature (a line, a circular
/// arc: N vanishes within tolerances::kConstantCurvature of its terms), which
/// has none. Parameters to about 1e-12 of a piece's span (simple roots to the
/// last bits); curvatures from curvature_at / signed_curvature_at there.
/// Error: a curve in R^1 ("curvature extrema need a curve in R^2 or more,
/// this one lives in R^1").
Expected<std::vector<CurvatureExtremum>> curvature_extrema(CurveView curve);

/// The parameters of the cusps inside the domain, increasing: inside a piece,
/// a point where the velocity vanishes (below tolerances::kVanishingDerivative
/// of its scale, at a root of P . P') and the velocities on both sides
/// (tolerances::kCuspSide of the piece away) point opposite ways: the tangent
/// turns back, as (t^2, t^3) at 0 (a stationary point on a smooth arc, as
/// (t^3, t^5), is not a cusp); at a junction of pieces, a point where the tangent arriving and the
/// tangent leaving (one-sided limits, unit_tangent_at) are opposite within
/// tolerances::kTangentAngle. The ends of the domain are not cusps.
/// Error: a curve in R^1 (as curvature_extrema).
Expected<std::vector<double>> cusp_parameters(CurveView curve);

}  // namespace casteljau

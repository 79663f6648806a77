#pragma once
// The differential geometry of a curve, written once on CurveView and so
// available on every curve kind: unit tangent, principal normal, binormal,
// curvature (signed in the plane), torsion and the Frenet frame, all from
// the derivatives at one parameter (do Carmo, "Differential Geometry of
// Curves and Surfaces", §1-5; Farin §10.2 for the Bézier formulas).
//
// At a knot or junction the derivatives are those of the span or piece to
// the right (the left one at the end of the domain), as derivative_at gives.

#include "casteljau/core/point_array.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// Unit tangent C'(u)/|C'(u)|. Where C'(u) vanishes (a repeated end control
/// point, a cusp), the direction of the first derivative that does not vanish
/// (relative to the curve's scale, tolerances::kVanishingDerivative): the
/// one-sided limit of the tangent from inside the domain. The zero vector for
/// a curve that is a single point.
Point unit_tangent_at(CurveView curve, double u);

/// Unit principal normal: the part of C'' orthogonal to the tangent,
/// normalised (toward the centre of curvature). Where the curvature is zero
/// it is undefined; then in the plane the left normal (tangent turned by +90
/// degrees), in other dimensions the zero vector. d = 1: always zero.
Point unit_normal_at(CurveView curve, double u);

/// Unit binormal T x N of a space curve (requires dimension() == 3); the zero
/// vector where the normal is undefined.
Point binormal_at(CurveView curve, double u);

/// Curvature kappa = sqrt(|C'|^2 |C''|^2 - (C'.C'')^2) / |C'|^3 (any d; in the
/// plane |C' x C''| / |C'|^3, unsigned). +inf where C' = 0 and C'' != 0 (a
/// cusp), 0 where both vanish.
double curvature_at(CurveView curve, double u);

/// Signed curvature of a plane curve, (C' x C'') / |C'|^3: positive when the
/// curve turns left. Requires dimension() == 2.
double signed_curvature_at(CurveView curve, double u);

/// Torsion of a space curve, tau = (C' x C'') . C''' / |C' x C''|^2 (requires
/// dimension() == 3); 0 where the curvature vanishes (the osculating plane is
/// undefined there and a straight or planar piece does not twist).
double torsion_at(CurveView curve, double u);

/// The Frenet frame at u with curvature and torsion, from one evaluation of
/// C', C'', C''' (binormal and torsion zero unless d == 3).
struct FrenetFrame {
  Point tangent;
  Point normal;
  Point binormal;
  double curvature = 0.0;
  double torsion = 0.0;
};

/// unit_tangent_at, unit_normal_at, binormal_at, curvature_at and torsion_at
/// at once (the same values; binormal empty and torsion 0 unless d == 3).
FrenetFrame frenet_frame_at(CurveView curve, double u);

}  // namespace casteljau

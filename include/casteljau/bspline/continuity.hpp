#pragma once
// Continuity of a B-spline curve at its knots: what the knots predict and
// what the curve actually achieves. Seed 001 says "a knot of multiplicity m
// lowers the continuity by m"; precisely (The NURBS Book §2.2, P2.5 and §3.2),
// a degree-p curve is C^(p-m) at a knot of multiplicity m (C^(-1): a jump
// at m = p+1), and may be smoother when its control points happen to allow
// it (such knots are removable: knot_removal.hpp).

#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"

namespace casteljau {

/// The continuity measured at one parameter.
struct Continuity {
  /// The highest k <= p such that the derivatives of orders 0..k from the
  /// left and from the right agree within tolerances::kContinuityRelative of
  /// their scale (the larger of their norms and the rounding scale
  /// sum_r |N^(k)_r| max |P|); -1 when the curve jumps. p means "as smooth as
  /// a polynomial piece of degree p can tell" (all derivatives agree). For a
  /// NURBS curve this is the continuity of the homogeneous curve (w C, w),
  /// which implies the same continuity of C.
  int parametric = -1;
  /// G^1: the curve is continuous and its unit tangents on both sides agree
  /// within tolerances::kTangentAngle radians (true whenever parametric >= 1
  /// and the tangent does not vanish; false when a tangent vanishes).
  bool tangent = false;
  friend bool operator==(const Continuity&, const Continuity&) = default;
};

/// One distinct interior knot: its value, multiplicity m, the continuity
/// p - m the knots predict and the continuity measured there.
struct KnotContinuity {
  /// The knot value u.
  double value = 0.0;
  /// m, how many knots equal u.
  int multiplicity = 0;
  /// p - m: what the knots guarantee (-1: a jump is allowed).
  int predicted = 0;
  /// What the curve achieves at u (>= predicted).
  Continuity measured;
  friend bool operator==(const KnotContinuity&, const KnotContinuity&) = default;
};

/// The derivatives at u from the left (basis functions of the span that ends
/// at u) and from the right (the span that starts at u) compared order by
/// order (The NURBS Book A2.3 on each span). u strictly inside the domain
/// (asserted: callers loop over knots or a checked joint). Away from a knot
/// both sides are one polynomial and the result is p. O(p^2 w).
Continuity continuity_at(const BSplineCurve& curve, double u);

/// continuity_at for every distinct knot strictly inside the domain, in
/// increasing order. The measured order is never below the predicted one
/// for a valid curve (up to the tolerance). O(k p^2 w) for k distinct knots.
std::vector<KnotContinuity> continuity_at_knots(const BSplineCurve& curve);

}  // namespace casteljau

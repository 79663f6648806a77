#pragma once
// Knot insertion and refinement: the same curve written on more knots
// (The NURBS Book §5.2). Exact up to rounding: every new control point is a
// convex combination of old ones (Boehm 1980), so the shape, the domain and
// the parameterization do not change.
//
// Failures: a knot outside the domain, a non-finite knot, a negative count or
// a multiplicity above p+1 come from the caller's data (a CLI user can ask
// for them), so they are Expected errors, not assertions.

#include <span>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// The curve with u inserted `times` times (Boehm's algorithm; The NURBS Book
/// A5.1, computed by the refinement kernel A5.4 with X = (u, ..., u), which
/// also reaches multiplicity p+1 where A5.1 stops at p). NURBS curves insert
/// into their homogeneous points. O(n w + times p w), w = d (+1 if rational).
/// Errors: u not finite, u outside the domain [t_p, t_{n+1}], times < 0, a
/// resulting multiplicity above p+1 (at a clamped end u already has p+1),
/// more than tolerances::kMaxControlPoints control points, u closer than
/// tolerances::kMinKnotSpan to a knot without being one (check_added_knot_spans:
/// the new span's derivatives would overflow). times = 0 gives the curve unchanged.
Expected<BSplineCurve> insert_knot(const BSplineCurve& curve, double u, int times = 1);

/// The curve with every knot of `new_knots` inserted (any order; a value
/// repeated k times is inserted k times): knot refinement, The NURBS Book
/// A5.4, O((n + r) w + r p w) for r new knots. Errors as insert_knot, naming
/// the offending entry ("new knot 3 (7.5) is outside the domain [0, 4]").
Expected<BSplineCurve> refine_knots(const BSplineCurve& curve, std::span<const double> new_knots);

}  // namespace casteljau

#pragma once
// Compatible curves: several B-spline (NURBS) curves rewritten, each without
// changing its shape, on one domain with one degree and one knot vector, so
// that their control points correspond one to one. Ruled surfaces, skinning
// and the B-spline form of Coons patches need them (The NURBS Book §10.3,
// "compatibility"; Piegl & Tiller 1996).
#include <span>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// The curves made compatible (The NURBS Book §10.3):
///  1. one dimension: refused otherwise ("curve 2 has 3 coordinates, curve 0
///     has 2; compatible curves need one dimension");
///  2. one domain [0, 1]: each curve is clamped (bspline/transform.hpp
///     clamped) and reparameterized linearly to [0, 1], so C_new(u) =
///     C(a + u (b - a)) (this is the parameter the ruled and skinned surfaces
///     use in u);
///  3. one degree: each elevated to the highest (bspline/degree.hpp
///     elevate_degree, exact);
///  4. one knot vector: every knot value of any curve, with the highest
///     multiplicity it has in any curve, inserted where missing
///     (bspline/knot_insertion.hpp refine_knots, exact). Knots are compared
///     exactly: values that differ by one ulp stay two knots (a short span,
///     still the same curves).
/// Rational curves stay rational; when some curves are NURBS, the
/// polynomial ones get weights 1 (the same curve) so that all carry weights.
/// Each returned curve is the input curve reparameterized to [0, 1], up to
/// the rounding of elevation and refinement (about 1e-15 of the scale).
/// Cost O(sum n_k p^2 d) for the elevations plus the refinements.
/// Errors: no curve, different dimensions, the size limits of elevation and
/// refinement (tolerances::kMaxBSplineDegree, kMaxControlPoints).
Expected<std::vector<BSplineCurve>> make_compatible(std::span<const BSplineCurve> curves);

}  // namespace casteljau

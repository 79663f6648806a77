#pragma once
// Internal to src/bspline: the control points an exact B-spline algorithm
// works on ("rows"), and the knot refinement kernel shared by insertion,
// decomposition, splitting and joining.
//
// Rational curves run the polynomial algorithms on their homogeneous points
// (w_i P_i, w_i) (The NURBS Book §4.2), so every kernel here sees a flat
// row-major block of `width` doubles per control point and never needs to
// know whether the curve is rational.

#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"

namespace casteljau::detail {

/// A curve's control points as rows: homogeneous (width d+1) for a NURBS
/// curve, Cartesian (width d) for a polynomial one.
struct CurveRows {
  int degree = 0;
  bool rational = false;
  int width = 0;
  std::vector<double> knots;
  std::vector<double> rows;

  std::size_t count() const { return rows.size() / static_cast<std::size_t>(width); }
  double* row(std::size_t i) { return rows.data() + i * static_cast<std::size_t>(width); }
  const double* row(std::size_t i) const { return rows.data() + i * static_cast<std::size_t>(width); }
};

/// The rows of `curve` (homogeneous when rational).
inline CurveRows rows_of(const BSplineCurve& curve) {
  CurveRows r;
  r.degree = curve.degree();
  r.rational = curve.is_rational();
  r.knots.assign(curve.knots().begin(), curve.knots().end());
  const PointArray points = r.rational ? homogeneous_points(curve) : curve.control_points();
  r.width = points.dimension();
  r.rows.assign(points.coordinates().begin(), points.coordinates().end());
  return r;
}

/// The curve whose (homogeneous when rational) control points are the rows.
inline BSplineCurve curve_of(CurveRows r) {
  PointArray points = PointArray::from_trusted(r.width, std::move(r.rows));
  if (r.rational) return from_homogeneous(r.degree, std::move(r.knots), points);
  return BSplineCurve::from_trusted(r.degree, std::move(r.knots), std::move(points));
}

/// How many knots equal `value` (knots sorted; exact comparison).
int multiplicity_count(std::span<const double> knots, double value);

/// Inserts the knots `sorted_new_knots` (non-decreasing, inside the domain,
/// no resulting multiplicity above p+1) into the rows: The NURBS Book A5.4.
/// O((n + r) w + r p w) for r new knots; two allocations (the results).
CurveRows refine(const CurveRows& curve, std::span<const double> sorted_new_knots);

/// The multiplicities each distinct knot value in [lower, upper] lacks to
/// reach `target` (values repeated in the result, sorted): what refine needs
/// to expose Bézier pieces (target p) on a sub-domain.
std::vector<double> knots_missing_for(std::span<const double> knots, double lower, double upper, int target);

/// The curve restricted to [lower, upper] (t_p <= lower < upper <= t_{n+1}),
/// with clamped ends: both ends inserted to multiplicity p, the control
/// points and knots outside dropped. Exact up to rounding.
CurveRows restrict_to(const CurveRows& curve, double lower, double upper);

/// Removes up to `times` copies of the interior knot whose last index is
/// `last_index` (multiplicity `multiplicity`) in place (The NURBS Book A5.8),
/// while error_bound + the step's bound stays <= budget; adds each step's
/// bound to error_bound. `radius` is the largest |C(u)| of the curve before
/// any removal, `min_weight` a lower bound of the weights (1 for polynomial
/// curves), lowered as new weights appear. Only rows up to last_index + 1 and
/// knots up to last_index + p + 1 are read; rows and knots after them shift
/// left. Returns how many copies were removed. Budget +infinity forces the
/// removal (for knots known to be removable, e.g. after degree elevation).
/// `scratch` is reused storage (resized to 2p+2 rows): no allocation per knot.
int remove_in_place(CurveRows& curve, int last_index, int multiplicity, int times, double budget,
                    double radius, double& min_weight, double& error_bound, std::vector<double>& scratch);

/// Removes counts[k] copies (at most) of the k-th distinct knot value strictly
/// inside the domain, left to right, within the budget as remove_in_place
/// does; the curve streams through a buffer so each removal moves O(p) rows.
/// Returns the new rows; adds to `removed` and `error_bound`.
CurveRows remove_interior(const CurveRows& source, std::span<const int> counts, double budget, double radius,
                          double& min_weight, int& removed, double& error_bound);

}  // namespace casteljau::detail

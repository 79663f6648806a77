// Degree elevation and reduction of B-spline curves through their Bézier
// pieces (The NURBS Book §5.5).
#include "casteljau/bspline/degree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/bezier/degree.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "working_rows.hpp"

namespace casteljau {
namespace {

using detail::number_text;

/// Joins Bézier pieces of one degree q (already elevated or reduced) into
/// rows: joints where the original curve jumps (multiplicity p+1) keep both
/// end points and get q+1 knots, the others q knots and one shared point.
detail::CurveRows assemble(const std::vector<BezierCurve>& pieces, const std::vector<double>& breaks,
                           const std::vector<bool>& jumps, int q, bool rational) {
  detail::CurveRows out;
  out.degree = q;
  out.rational = rational;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const PointArray points = rational ? homogeneous_points(pieces[i]) : pieces[i].control_points();
    out.width = points.dimension();
    const bool jump = i > 0 && jumps[i];
    const std::size_t first = (i == 0 || jump) ? 0 : 1;
    const auto all = points.coordinates();
    out.rows.insert(out.rows.end(), all.begin() + static_cast<std::ptrdiff_t>(first * out.width), all.end());
    const int copies = (i == 0 || jump) ? q + 1 : q;
    out.knots.insert(out.knots.end(), static_cast<std::size_t>(copies), breaks[i]);
  }
  out.knots.insert(out.knots.end(), static_cast<std::size_t>(q + 1), breaks.back());
  return out;
}

/// Which joints of the pieces are jumps (knot multiplicity p+1) and, for the
/// others, the original multiplicity m.
void joint_multiplicities(const BSplineCurve& curve, const std::vector<double>& breaks, std::vector<bool>& jumps,
                          std::vector<int>& multiplicities) {
  jumps.assign(breaks.size(), false);
  multiplicities.assign(breaks.size(), 0);
  for (std::size_t i = 1; i + 1 < breaks.size(); ++i) {
    multiplicities[i] = detail::multiplicity_count(curve.knots(), breaks[i]);
    jumps[i] = multiplicities[i] > curve.degree();
  }
}

}  // namespace

Expected<BSplineCurve> elevate_degree(const BSplineCurve& curve, int times) {
  const int p = curve.degree();
  if (times < 0) return Error{"the degree cannot be elevated " + std::to_string(times) + " times, it must be >= 0"};
  if (times > tolerances::kMaxBSplineDegree - p)
    return Error{"elevating degree " + std::to_string(p) + " by " + std::to_string(times) + " is above the limit " +
                 std::to_string(tolerances::kMaxBSplineDegree), ErrorKind::limit};
  if (times == 0) return curve;
  const BezierPieces pieces = to_bezier_pieces(curve);
  const int q = p + times;
  const double count = static_cast<double>(pieces.pieces.size()) * (q + 1);
  if (count > static_cast<double>(tolerances::kMaxControlPoints))
    return Error{"elevating to degree " + std::to_string(q) + " would give more than " +
                 std::to_string(tolerances::kMaxControlPoints) + " control points", ErrorKind::limit};
  std::vector<BezierCurve> elevated;
  elevated.reserve(pieces.pieces.size());
  for (const BezierCurve& piece : pieces.pieces) elevated.push_back(elevate_degree(piece, times));
  std::vector<bool> jumps;
  std::vector<int> multiplicities;
  joint_multiplicities(curve, pieces.breakpoints, jumps, multiplicities);
  const detail::CurveRows joined = assemble(elevated, pieces.breakpoints, jumps, q, curve.is_rational());
  // Joint i has multiplicity q now and needs m + times: remove p - m copies,
  // which are exactly removable (same curve), so the removal is forced.
  std::vector<int> counts;
  for (std::size_t i = 1; i + 1 < pieces.breakpoints.size(); ++i)
    counts.push_back(jumps[i] ? 0 : p - multiplicities[i]);
  double min_weight = 0.0, bound = 0.0;
  int removed = 0;
  min_weight = curve.is_rational() ? *std::min_element(curve.weights().begin(), curve.weights().end()) : 1.0;
  detail::CurveRows rows = detail::remove_interior(joined, counts, std::numeric_limits<double>::infinity(), 0.0,
                                                   min_weight, removed, bound);
  return detail::curve_of(std::move(rows));
}

Expected<BSplineDegreeReduction> reduce_degree(const BSplineCurve& curve, Tolerance tolerance) {
  if (!std::isfinite(tolerance.distance) || !(tolerance.distance > 0.0))
    return Error{"the degree reduction tolerance is " + number_text(tolerance.distance) +
                 ", it must be finite and > 0"};
  const int p = curve.degree();
  if (p < 2) return Error{"a B-spline of degree " + std::to_string(p) + " cannot be reduced, the degree must be >= 2"};
  if (curve.is_rational()) return Error{"degree reduction of rational B-spline (NURBS) curves is not supported"};
  const BezierPieces pieces = to_bezier_pieces(curve);
  std::vector<BezierCurve> reduced;
  reduced.reserve(pieces.pieces.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < pieces.pieces.size(); ++i) {
    auto r = reduce_degree(pieces.pieces[i]);
    if (!r) return r.error();
    if (!(r->error_bound <= tolerance.distance))
      return Error{"degree " + std::to_string(p) + " cannot be reduced within " + number_text(tolerance.distance) +
                   ": piece " + std::to_string(i) + " on [" + number_text(pieces.breakpoints[i]) + ", " +
                   number_text(pieces.breakpoints[i + 1]) + "] would be off by up to " + number_text(r->error_bound)};
    worst = std::max(worst, r->error_bound);
    reduced.push_back(std::move(r->curve));
  }
  std::vector<bool> jumps;
  std::vector<int> multiplicities;
  joint_multiplicities(curve, pieces.breakpoints, jumps, multiplicities);
  const detail::CurveRows joined = assemble(reduced, pieces.breakpoints, jumps, p - 1, false);
  // The pieces are disjoint in u, so the reduction error is their largest;
  // the knot removals then spend what is left of the tolerance.
  std::vector<int> counts(pieces.breakpoints.size() >= 2 ? pieces.breakpoints.size() - 2 : 0, p);
  double radius = 0.0, min_weight = 1.0, bound = worst;
  int removed = 0;
  detail::CurveRows rows =
      detail::remove_interior(joined, counts, tolerance.distance, radius, min_weight, removed, bound);
  return BSplineDegreeReduction{detail::curve_of(std::move(rows)), bound};
}

}  // namespace casteljau

// Decomposition of a B-spline into Bézier pieces and the way back
// (The NURBS Book §5.4, A5.6 by way of the refinement A5.4).
#include "casteljau/bspline/bezier_pieces.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "casteljau/bezier/degree.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "working_rows.hpp"

namespace casteljau {

using detail::number_text;

BezierPieces to_bezier_pieces(const BSplineCurve& curve) {
  const detail::CurveRows rows = detail::rows_of(curve);
  const Interval domain = curve.domain();
  const int p = curve.degree();
  const std::vector<double> missing = detail::knots_missing_for(rows.knots, domain.lower, domain.upper, p);
  const detail::CurveRows refined = detail::refine(rows, missing);
  const auto& t = refined.knots;
  const int n = static_cast<int>(refined.count()) - 1;
  BezierPieces out;
  for (int k = p; k <= n; ++k) {
    if (!(t[k] < t[k + 1])) continue;
    // Span k: its p knots on each side are t_k and t_{k+1} (multiplicity >= p
    // now), so its Bézier points are the blossoms Q_{k-p+j} = b(t_k^(p-j), t_{k+1}^j).
    std::vector<double> piece(refined.row(k - p), refined.row(k) + refined.width);
    PointArray points = PointArray::from_trusted(refined.width, std::move(piece));
    out.pieces.push_back(refined.rational ? from_homogeneous(points) : BezierCurve::from_trusted(std::move(points)));
    if (out.breakpoints.empty()) out.breakpoints.push_back(t[k]);
    out.breakpoints.push_back(t[k + 1]);
  }
  return out;
}

BezierPieces to_bezier_pieces(const BezierCurve& curve) { return {{0.0, 1.0}, {curve}}; }

BezierPieces to_bezier_pieces(const PiecewiseBezierCurve& curve) {
  return {breakpoints(curve), curve.pieces()};
}

PiecewiseBezierCurve to_piecewise_bezier(const BezierPieces& pieces) {
  return PiecewiseBezierCurve::make(pieces.pieces).value();
}

Expected<BSplineCurve> from_bezier_pieces(const BezierPieces& input) {
  const auto& pieces = input.pieces;
  const auto& breaks = input.breakpoints;
  const std::size_t m = pieces.size();
  if (m == 0) return Error{"no Bézier piece to make a B-spline from"};
  if (breaks.size() != m + 1)
    return Error{std::to_string(breaks.size()) + " breakpoints for " + std::to_string(m) +
                 " pieces, there must be one more breakpoint than pieces"};
  for (std::size_t i = 0; i <= m; ++i) {
    if (auto ok = check_finite(breaks[i], "breakpoint " + std::to_string(i)); !ok) return ok.error();
    if (i > 0 && !(breaks[i - 1] < breaks[i]))
      return Error{"breakpoint " + std::to_string(i) + " (" + number_text(breaks[i]) + ") is not above breakpoint " +
                   std::to_string(i - 1) + " (" + number_text(breaks[i - 1]) + "), breakpoints must increase"};
  }
  const int d = pieces[0].dimension();
  int p = 0;
  bool rational = false;
  double scale = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    if (pieces[i].dimension() != d)
      return Error{"piece " + std::to_string(i) + " has dimension " + std::to_string(pieces[i].dimension()) +
                   ", piece 0 has " + std::to_string(d)};
    p = std::max(p, pieces[i].degree());
    rational = rational || pieces[i].is_rational();
    scale = std::max(scale, scale_of(pieces[i].control_points()));
  }
  const std::size_t count = p == 0 ? m : m * static_cast<std::size_t>(p) + 1;
  if (count > tolerances::kMaxControlPoints)
    return Error{"the B-spline of these pieces would have " + std::to_string(count) + " control points, above " +
                 std::to_string(tolerances::kMaxControlPoints)};

  const int width = rational ? d + 1 : d;
  std::vector<double> rows;
  rows.reserve(count * static_cast<std::size_t>(width));
  std::vector<double> knots;
  knots.reserve(count + static_cast<std::size_t>(p) + 1);
  const double allowed_gap = tolerances::kJointRelativeGap * std::max(scale, tolerances::kScaleFloor);
  std::vector<double> previous_end(static_cast<std::size_t>(d));  // Cartesian end of the previous piece
  double previous_weight = 1.0;
  for (std::size_t i = 0; i < m; ++i) {
    const BezierCurve piece = elevate_degree(pieces[i], p - pieces[i].degree());
    const PointArray& points = piece.control_points();
    const auto weight = [&](int k) { return piece.is_rational() ? piece.weights()[k] : 1.0; };
    // Scaling every weight of a rational Bézier curve by one factor keeps the curve;
    // it makes the shared control point carry one weight on both sides.
    const double factor = (i == 0 || p == 0) ? 1.0 : previous_weight / weight(0);
    if (i > 0 && p > 0) {
      const double gap = distance(previous_end, points[0]);
      if (!(gap <= allowed_gap))
        return Error{"piece " + std::to_string(i) + " starts " + number_text(gap) + " away from the end of piece " +
                     std::to_string(i - 1) + " (more than " + number_text(allowed_gap) +
                     "), consecutive pieces must meet"};
    }
    const int first = (i == 0 || p == 0) ? 0 : 1;  // the start of piece i replaces the end of piece i-1
    for (int k = first; k <= p; ++k) {
      const double w = weight(k) * factor;
      for (double c : points[k]) rows.push_back(rational ? c * w : c);
      if (rational) rows.push_back(w);
    }
    std::copy(points[p].begin(), points[p].end(), previous_end.begin());
    previous_weight = weight(p) * factor;
    const int copies = i == 0 ? p + 1 : std::max(p, 1);
    knots.insert(knots.end(), static_cast<std::size_t>(copies), breaks[i]);
  }
  knots.insert(knots.end(), static_cast<std::size_t>(p + 1), breaks[m]);
  detail::CurveRows out;
  out.degree = p;
  out.rational = rational;
  out.width = width;
  out.knots = std::move(knots);
  out.rows = std::move(rows);
  return detail::curve_of(std::move(out));
}

}  // namespace casteljau

// Joining two B-spline curves (the inverse of split_at).
#include "casteljau/bspline/join.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "casteljau/bspline/degree.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "working_rows.hpp"

namespace casteljau {
namespace {

using detail::number_text;

std::string point_text(std::span<const double> point) {
  std::string text = "(";
  for (std::size_t i = 0; i < point.size(); ++i) text += (i ? ", " : "") + number_text(point[i]);
  return text + ")";
}

/// Rows of the curve, homogeneous when `rational` (weight 1 for a polynomial curve).
std::vector<double> rows_in(const BSplineCurve& curve, bool rational) {
  const PointArray points = rational ? homogeneous_points(curve) : curve.control_points();
  return {points.coordinates().begin(), points.coordinates().end()};
}

}  // namespace

Expected<JoinResult> join(const BSplineCurve& first_input, const BSplineCurve& second_input) {
  if (first_input.dimension() != second_input.dimension())
    return Error{"cannot join a curve of dimension " + std::to_string(first_input.dimension()) +
                 " to one of dimension " + std::to_string(second_input.dimension())};
  const int p = std::max(first_input.degree(), second_input.degree());
  auto first_elevated = elevate_degree(first_input, p - first_input.degree());
  if (!first_elevated) return first_elevated.error();
  auto second_elevated = elevate_degree(second_input, p - second_input.degree());
  if (!second_elevated) return second_elevated.error();
  const BSplineCurve a = clamped(*first_elevated), b = clamped(*second_elevated);
  const std::size_t na = a.control_points().size(), nb = b.control_points().size();
  if (na + nb - 1 > tolerances::kMaxControlPoints)
    return Error{"the joined curve would have more than " + std::to_string(tolerances::kMaxControlPoints) +
                 " control points", ErrorKind::limit};

  // Clamped: the first curve ends at its last control point, the second starts at its first.
  const auto end = a.control_points()[na - 1];
  const auto start = b.control_points()[0];
  const double gap = distance(end, start);
  const double scale = std::max({scale_of(a.control_points()), scale_of(b.control_points()), tolerances::kScaleFloor});
  const double allowed = tolerances::kJointRelativeGap * scale;
  if (!(gap <= allowed))
    return Error{"the curves do not meet: the first ends at " + point_text(end) + ", the second starts at " +
                 point_text(start) + ", a gap of " + number_text(gap) + " (more than " + number_text(allowed) +
                 " allowed at their scale)"};

  const double joint = a.domain().upper;
  const double shift = joint - b.domain().lower;
  const bool rational = a.is_rational() || b.is_rational();
  detail::CurveRows out;
  out.degree = p;
  out.rational = rational;
  out.width = a.dimension() + (rational ? 1 : 0);
  const int w = out.width, d = a.dimension();

  out.knots.assign(a.knots().begin(), a.knots().end() - 1);  // ends with p copies of the joint
  for (std::size_t i = static_cast<std::size_t>(p) + 1; i < b.knots().size(); ++i) {
    const double t = b.knots()[i] + shift;
    if (!std::isfinite(t)) return Error{"the second curve's knots overflow once shifted to start at " + number_text(joint)};
    out.knots.push_back(std::max(t, joint));  // rounding must not put a knot before the joint
  }

  out.rows = rows_in(a, rational);
  std::vector<double> second = rows_in(b, rational);
  // Scaling all homogeneous points of a NURBS curve keeps the curve: make the
  // weights agree at the joint.
  const double factor = rational ? out.rows[na * w - 1] / second[static_cast<std::size_t>(w - 1)] : 1.0;
  for (double& x : second) x *= factor;
  // The joint control point: the midpoint of the two ends (in Cartesian
  // terms; both carry the same weight now).
  double* joint_row = out.rows.data() + (na - 1) * static_cast<std::size_t>(w);
  for (int c = 0; c < d; ++c) joint_row[c] = 0.5 * (joint_row[c] + second[static_cast<std::size_t>(c)]);
  out.rows.insert(out.rows.end(), second.begin() + w, second.end());

  JoinResult result{detail::curve_of(std::move(out)), {}, joint, gap};
  result.continuity = continuity_at(result.curve, joint);
  return result;
}

}  // namespace casteljau

// B-spline interpolation: the C² cubic spline with its end conditions and
// any-degree interpolation on averaged knots (The NURBS Book §9.2).
#include "casteljau/interpolation/spline_interpolation.hpp"

#include <algorithm>
#include <optional>
#include <cmath>
#include <string>

#include "../core/number_text.hpp"
#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/tolerance.hpp"
#include "collocation.hpp"
#include "cubic_sweep.hpp"

namespace casteljau {

namespace {

/// p+1 copies of t_0, the interior knots, p+1 copies of t_m.
std::vector<double> clamped_knots(int degree, double start, std::span<const double> interior, double end) {
  std::vector<double> knots;
  knots.reserve(interior.size() + 2 * static_cast<std::size_t>(degree) + 2);
  knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, start);
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, end);
  return knots;
}

Status check_vector(std::span<const double> value, int dimension, const std::string& what) {
  if (value.size() != static_cast<std::size_t>(dimension)) {
    return Error{what + " has " + std::to_string(value.size()) + " coordinates, the points have " +
                 std::to_string(dimension)};
  }
  for (std::size_t k = 0; k < value.size(); ++k) {
    if (!std::isfinite(value[k])) {
      return Error{"coordinate " + std::to_string(k) + " of " + what + " is " +
                   (std::isnan(value[k]) ? "NaN" : "infinite")};
    }
  }
  return {};
}

/// Checks the end derivatives of interpolate_bspline / interpolate_on_knots:
/// orders in 1..p, no order twice at one end, values of the points'
/// dimension and finite. Counts them per end.
/// The degree range both B-spline interpolators accept.
Status check_interpolation_degree(int p) {
  if (p < 1 || p > tolerances::kMaxBSplineDegree) {
    return Error{"degree " + std::to_string(p) + " is outside 1.." + std::to_string(tolerances::kMaxBSplineDegree) +
                 " for B-spline interpolation"};
  }
  return {};
}

Status check_end_derivatives(std::span<const EndDerivative> derivatives, int p, int dimension, std::size_t& at_start,
                             std::size_t& at_end) {
  at_start = at_end = 0;
  for (std::size_t i = 0; i < derivatives.size(); ++i) {
    const EndDerivative& e = derivatives[i];
    const std::string what = "end derivative " + std::to_string(i);
    if (e.order < 1 || e.order > p) {
      return Error{what + " has order " + std::to_string(e.order) + ", orders must be in 1.." + std::to_string(p) +
                   " for degree " + std::to_string(p)};
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (derivatives[j].at_end == e.at_end && derivatives[j].order == e.order) {
        return Error{what + " repeats the order-" + std::to_string(e.order) + " derivative at the " +
                     (e.at_end ? "end" : "start") + " (end derivative " + std::to_string(j) + ")"};
      }
    }
    if (auto ok = check_vector(e.value, dimension, what); !ok) return ok.error();
    ++(e.at_end ? at_end : at_start);
  }
  return {};
}

/// The knots of a closed spline of degree p through M points at the M + 1
/// parameters t_0..t_M (t_M closes the curve): t_0..t_M with the steps
/// continued cyclically on both sides (u_{j+M} = u_j + T, T = t_M - t_0).
std::vector<double> periodic_interpolation_knots(std::span<const double> parameters, std::size_t degree) {
  const std::size_t count = parameters.size() - 1;
  const double period = parameters[count] - parameters[0];
  std::vector<double> knots(count + 2 * degree + 1);
  std::copy(parameters.begin(), parameters.end(), knots.begin() + static_cast<std::ptrdiff_t>(degree));
  for (std::size_t i = 0; i < degree; ++i) {
    knots[i] = parameters[count - degree + i] - period;
    knots[count + degree + 1 + i] = parameters[1 + i] + period;
  }
  return knots;
}

/// The closed cubic: periodic knots extended by the parameter steps taken
/// cyclically (u_{j+M} = u_j + T, T = t_M - t_0), so every span of the closed
/// curve keeps its own parameter step, as scipy's periodic knots do.
Expected<BSplineCurve> interpolate_periodic(const PointArray& points, std::span<const double> parameters, int p) {
  const std::size_t degree = static_cast<std::size_t>(p);
  auto knots = periodic_interpolation_knots(parameters, degree);
  auto distinct = detail::solve_periodic_collocation(p, knots, points);
  if (!distinct) return distinct.error();
  PointArray control_points = std::move(*distinct);
  for (std::size_t j = 0; j < degree; ++j) {
    const std::vector<double> wrapped(control_points[j].begin(), control_points[j].end());
    control_points.push_back(wrapped);
  }
  return BSplineCurve::from_trusted(p, std::move(knots), std::move(control_points));
}

/// True when the values are finite and strictly increasing.
bool strictly_increasing(std::span<const double> values) {
  double previous = -HUGE_VAL;
  for (const double value : values) {
    if (!(value > previous) || !std::isfinite(value)) return false;
    previous = value;
  }
  return true;
}

/// The fast path of interpolate_cubic (cubic_sweep.hpp) for valid input of
/// at least kSweepMinimumPoints points: one pass to check the parameters,
/// one to write the knots, one sweep for the control points. An empty
/// result means "take the general path", which checks everything and names
/// any problem (NaN points, for instance, show only as a failed sweep).
std::optional<BSplineCurve> sweep_cubic(const PointArray& points, std::span<const double> parameters,
                                        const CubicEnds& ends) {
  const std::size_t count = points.size();
  const std::size_t d = static_cast<std::size_t>(points.dimension());
  if (count < detail::kSweepMinimumPoints) return std::nullopt;
  const std::size_t m = count - 1;
  const std::size_t expected = ends.condition == EndCondition::periodic ? count + 1 : count;
  if (parameters.size() != expected || !strictly_increasing(parameters)) return std::nullopt;
  std::vector<double> knots;
  switch (ends.condition) {
    case EndCondition::natural:
    case EndCondition::clamped:
      if (ends.condition == EndCondition::clamped &&
          (ends.start_tangent.size() != d || ends.end_tangent.size() != d))
        return std::nullopt;
      knots = clamped_knots(3, parameters.front(), parameters.subspan(1, m - 1), parameters.back());
      break;
    case EndCondition::not_a_knot:
      knots = clamped_knots(3, parameters.front(), parameters.subspan(2, m - 3), parameters.back());
      break;
    case EndCondition::periodic:
      knots = periodic_interpolation_knots(parameters, 3);
      break;
  }
  const std::size_t rows = knots.size() - 4;
  std::vector<double> control(rows * d);
  const bool solved = ends.condition == EndCondition::periodic ? detail::sweep_cubic_periodic(knots, points, control)
                      : ends.condition == EndCondition::not_a_knot
                          ? detail::sweep_cubic_not_a_knot(knots, parameters, points, control)
                          : detail::sweep_cubic_at_knots(knots, points, ends, control);
  if (!solved) return std::nullopt;
  return BSplineCurve::from_trusted(3, std::move(knots), PointArray::from_trusted(static_cast<int>(d), std::move(control)));
}

}  // namespace

std::string_view name_of(EndCondition condition) noexcept {
  switch (condition) {
    case EndCondition::natural: return "natural";
    case EndCondition::clamped: return "clamped";
    case EndCondition::not_a_knot: return "not-a-knot";
    case EndCondition::periodic: return "periodic";
  }
  return "natural";
}

Expected<EndCondition> end_condition_from_name(std::string_view name) {
  for (EndCondition c : {EndCondition::natural, EndCondition::clamped, EndCondition::not_a_knot, EndCondition::periodic})
    if (name == name_of(c)) return c;
  if (name == "not_a_knot") return EndCondition::not_a_knot;
  return Error{"unknown end condition '" + std::string(name) +
               "', expected natural, clamped, not-a-knot or periodic"};
}

Expected<BSplineCurve> interpolate_cubic(const PointArray& points, std::span<const double> parameters,
                                         const CubicEnds& ends) {
  constexpr int p = 3;
  const std::size_t m1 = points.size();  // m + 1
  if (auto swept = sweep_cubic(points, parameters, ends)) return std::move(*swept);
  const std::string method = "cubic interpolation with " + std::string(name_of(ends.condition)) + " ends";
  switch (ends.condition) {
    case EndCondition::periodic: {
      if (auto ok = detail::check_interpolation_input(points, parameters, m1 + 1, 3, method); !ok) return ok.error();
      return interpolate_periodic(points, parameters, p);
    }
    case EndCondition::not_a_knot: {
      if (auto ok = detail::check_interpolation_input(points, parameters, m1, 4, method); !ok) return ok.error();
      // The knots t_1 and t_{m-1} are left out, so the cubic pieces on both
      // sides of them are one polynomial: C''' is continuous there.
      auto knots = clamped_knots(p, parameters.front(), parameters.subspan(2, m1 - 4), parameters.back());
      auto control = detail::solve_collocation(p, knots, parameters, points, {});
      if (!control) return control.error();
      return BSplineCurve::from_trusted(p, std::move(knots), std::move(*control));
    }
    case EndCondition::natural:
    case EndCondition::clamped: {
      if (auto ok = detail::check_interpolation_input(points, parameters, m1, 2, method); !ok) return ok.error();
      const bool clamped = ends.condition == EndCondition::clamped;
      detail::EndConstraint constraints[2];
      if (clamped) {
        if (auto ok = check_vector(ends.start_tangent, points.dimension(), "the start tangent"); !ok) return ok.error();
        if (auto ok = check_vector(ends.end_tangent, points.dimension(), "the end tangent"); !ok) return ok.error();
        constraints[0] = {false, 1, ends.start_tangent};
        constraints[1] = {true, 1, ends.end_tangent};
      } else {
        constraints[0] = {false, 2, {}};
        constraints[1] = {true, 2, {}};
      }
      auto knots = clamped_knots(p, parameters.front(), parameters.subspan(1, m1 - 2), parameters.back());
      auto control = detail::solve_collocation(p, knots, parameters, points, constraints);
      if (!control) return control.error();
      return BSplineCurve::from_trusted(p, std::move(knots), std::move(*control));
    }
  }
  return Error{"unknown end condition"};
}

Expected<BSplineCurve> interpolate_bspline(const PointArray& points, std::span<const double> parameters, int degree,
                                           std::span<const EndDerivative> derivatives) {
  const int p = degree;
  if (auto ok = check_interpolation_degree(p); !ok) return ok.error();
  const std::size_t m1 = points.size();
  // Each end takes at most p - 1 derivatives: p of them would make the first
  // averaged interior knot equal t_0 (multiplicity p + 2).
  std::size_t at_start = 0, at_end = 0;
  if (auto ok = check_end_derivatives(derivatives, p, points.dimension(), at_start, at_end); !ok) return ok.error();
  if (std::max(at_start, at_end) > static_cast<std::size_t>(p - 1)) {
    return Error{std::to_string(std::max(at_start, at_end)) + " derivatives at the " +
                 (at_end > at_start ? "end" : "start") + ", degree " + std::to_string(p) + " takes at most " +
                 std::to_string(p - 1) + " at each end"};
  }
  // Signed: with more derivatives than p + 1 the difference is negative (and
  // 2 points are then enough), which an unsigned subtraction would wrap.
  const auto needed = static_cast<std::size_t>(
      std::max<long long>(2, static_cast<long long>(p) + 1 - static_cast<long long>(derivatives.size())));
  const std::string method =
      "degree-" + std::to_string(p) + " B-spline interpolation" +
      (derivatives.empty() ? std::string()
                           : " with " + std::to_string(derivatives.size()) + " end derivative" +
                                 (derivatives.size() == 1 ? "" : "s"));
  if (auto ok = detail::check_interpolation_input(points, parameters, m1, needed, method); !ok) return ok.error();

  // Sites with t_0 repeated once per start derivative and t_m once per end
  // derivative, then knots averaging p consecutive sites (eq. 9.8; with one
  // first derivative at each end this is eq. 9.22 of §9.2.2).
  std::vector<double> sites;
  sites.reserve(m1 + derivatives.size());
  sites.insert(sites.end(), at_start + 1, parameters.front());
  sites.insert(sites.end(), parameters.begin() + 1, parameters.end() - 1);
  sites.insert(sites.end(), at_end + 1, parameters.back());
  const std::size_t unknowns = sites.size();
  const std::size_t interior_count = unknowns - static_cast<std::size_t>(p) - 1;
  std::vector<double> interior(interior_count);
  for (std::size_t j = 1; j <= interior_count; ++j) {
    double sum = 0.0;
    for (std::size_t i = j; i < j + static_cast<std::size_t>(p); ++i) sum += sites[i];
    // Rounding may carry an average of sites next to t_m just past it.
    interior[j - 1] = std::clamp(sum / p, parameters.front(), parameters.back());
  }
  auto knots = clamped_knots(p, parameters.front(), interior, parameters.back());
  std::vector<detail::EndConstraint> constraints;
  for (const EndDerivative& e : derivatives) constraints.push_back({e.at_end, e.order, e.value});
  auto control = detail::solve_collocation(p, knots, parameters, points, constraints);
  if (!control) return control.error();
  return BSplineCurve::from_trusted(p, std::move(knots), std::move(*control));
}

Expected<BSplineCurve> interpolate_on_knots(const PointArray& points, std::span<const double> parameters, int degree,
                                            std::vector<double> knots, std::span<const EndDerivative> derivatives) {
  using detail::number_text;
  const int p = degree;
  if (auto ok = check_interpolation_degree(p); !ok) return ok.error();
  const std::size_t m1 = points.size();
  std::size_t at_start = 0, at_end = 0;
  if (auto ok = check_end_derivatives(derivatives, p, points.dimension(), at_start, at_end); !ok) return ok.error();
  const std::string method = "degree-" + std::to_string(p) + " interpolation on given knots";
  if (auto ok = detail::check_interpolation_input(points, parameters, m1, 2, method); !ok) return ok.error();

  // One control point per condition: n + 1 = (m + 1) + derivatives.
  const std::size_t unknowns = m1 + derivatives.size();
  const std::size_t width = static_cast<std::size_t>(p) + 1;
  const std::string conditions = std::to_string(m1) + " points and " + std::to_string(derivatives.size()) +
                                 " end derivatives";
  if (unknowns < width) {
    return Error{conditions + " determine " + std::to_string(unknowns) + " control points, degree " +
                 std::to_string(p) + " needs at least " + std::to_string(width)};
  }
  if (knots.size() != unknowns + width) {
    return Error{std::to_string(knots.size()) + " knots given, " + conditions + " determine " +
                 std::to_string(unknowns) + " control points of degree " + std::to_string(p) + ", which need " +
                 std::to_string(unknowns + width) + " knots (control points + degree + 1)"};
  }
  if (auto ok = validate_knots(knots, p, unknowns); !ok) return ok.error();
  const std::size_t first = static_cast<std::size_t>(p), last = unknowns;  // the domain [knots[p], knots[n+1]]
  if (parameters.front() != knots[first] || parameters.back() != knots[last]) {
    const bool at_first = parameters.front() != knots[first];
    const std::size_t i = at_first ? 0 : m1 - 1;
    const std::size_t k = at_first ? first : last;
    return Error{"parameter " + std::to_string(i) + " (" + number_text(parameters[i]) + ") is not knot " +
                 std::to_string(k) + " (" + number_text(knots[k]) + "), the " + (at_first ? "start" : "end") +
                 " of the knots' domain: the parameters must run from knot " + std::to_string(first) +
                 " to knot " + std::to_string(last)};
  }

  // Schoenberg–Whitney: the point rows in the solver's order (C(t_0), the
  // start derivatives, the interior points, the end derivatives, C(t_m)) take
  // the basis functions left by the derivative rows. A derivative row needs
  // t_0 (t_m) in the closed support of N_j, which holds for every j it takes
  // (j <= p at the start, so knots[j] <= knots[p] = t_0 <= knots[j+p+1];
  // alike at the end): only point rows can fail.
  std::vector<std::size_t> columns;
  columns.reserve(m1);
  for (std::size_t j = 0; j < unknowns; ++j) {
    const bool derivative_row = (j >= 1 && j <= at_start) || (j + 1 < unknowns && j + 1 + at_end >= unknowns);
    if (!derivative_row) columns.push_back(j);
  }
  if (const auto gap = detail::schoenberg_whitney_gap(knots, p, columns, parameters)) {
    return detail::schoenberg_whitney_error(knots, p, parameters, *gap, 0, false,
                                            "no spline on these knots interpolates them");
  }

  std::vector<detail::EndConstraint> constraints;
  constraints.reserve(derivatives.size());
  for (const EndDerivative& e : derivatives) constraints.push_back({e.at_end, e.order, e.value});
  auto control = detail::solve_collocation(p, knots, parameters, points, constraints);
  if (!control) return control.error();
  return BSplineCurve::from_trusted(p, std::move(knots), std::move(*control));
}

}  // namespace casteljau

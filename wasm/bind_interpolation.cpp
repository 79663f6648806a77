// The playground's interpolation views (seed 000's head and car, seed 001's
// Runge and natural splines): C¹ Bézier interpolation with its α, Catmull–Rom,
// the C² cubic with each end condition, Lagrange on uniform or Chebyshev
// nodes, and natural splines of order q. Points cross as flat xy arrays.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/core/closure.hpp"
#include "casteljau/interpolation/c1_bezier.hpp"
#include "casteljau/interpolation/catmull_rom.hpp"
#include "casteljau/interpolation/lagrange.hpp"
#include "casteljau/interpolation/natural_spline.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "curve_values.hpp"
#include "js_values.hpp"

namespace casteljau::wasm {
namespace {

using emscripten::val;

Closure closure_of(bool closed) { return closed ? Closure::closed : Closure::open; }

val curve_or_error(const auto& result) {
  return value_or_error(result, [](const auto& curve) { return description_of(curve); });
}

/// The parameters t_i of the data points: "uniform", "chord-length" or "centripetal";
/// closed: one more value for the step back to the first point.
val parameters_of(const val& flat_points, const std::string& kind, bool closed) {
  const auto points = points_of(flat_points, 2, "data points");
  if (!points) return error_value(points.error());
  const auto parameterization = parameterization_from_name(kind);
  if (!parameterization) return error_value(parameterization.error());
  return value_or_error(parameter_values(*points, *parameterization, closure_of(closed)),
                        [](const std::vector<double>& ts) { return float64_array(ts); });
}

/// Seed 000's C¹ Bézier interpolation (one cubic per step, Q_i and R_i inside) as a piecewise curve.
val c1_bezier(const val& flat_points, double alpha, bool closed) {
  const auto points = points_of(flat_points, 2, "data points");
  if (!points) return error_value(points.error());
  return curve_or_error(interpolate_c1_bezier(*points, alpha, closure_of(closed)));
}

/// The Catmull–Rom spline at the given parameterization, as a B-spline.
val catmull_rom(const val& flat_points, const std::string& kind, bool closed) {
  const auto points = points_of(flat_points, 2, "data points");
  if (!points) return error_value(points.error());
  const auto parameterization = parameterization_from_name(kind);
  if (!parameterization) return error_value(parameterization.error());
  const auto ts = parameter_values(*points, *parameterization, closure_of(closed));
  if (!ts) return error_value(ts.error());
  return curve_or_error(interpolate_catmull_rom(*points, *ts, closure_of(closed)));
}

/// The C² cubic spline with an end condition ("natural", "not-a-knot",
/// "periodic", or "clamped" with the one-sided differences as end tangents).
val cubic(const val& flat_points, const std::string& condition, const std::string& kind) {
  const auto points = points_of(flat_points, 2, "data points");
  if (!points) return error_value(points.error());
  const auto ends_condition = end_condition_from_name(condition);
  if (!ends_condition) return error_value(ends_condition.error());
  const auto parameterization = parameterization_from_name(kind);
  if (!parameterization) return error_value(parameterization.error());
  const bool periodic = *ends_condition == EndCondition::periodic;
  const auto ts = parameter_values(*points, *parameterization, closure_of(periodic));
  if (!ts) return error_value(ts.error());
  CubicEnds ends{*ends_condition, {}, {}};
  if (*ends_condition == EndCondition::clamped) {
    // The chord of each end step divided by its parameter step: the tangent
    // the data suggests (a demanding user drags the points, not the tangents).
    const std::size_t m = points->size() - 1;
    for (int c = 0; c < 2; ++c) {
      ends.start_tangent.push_back(((*points)[1][c] - (*points)[0][c]) / ((*ts)[1] - (*ts)[0]));
      ends.end_tangent.push_back(((*points)[m][c] - (*points)[m - 1][c]) / ((*ts)[m] - (*ts)[m - 1]));
    }
  }
  return curve_or_error(interpolate_cubic(*points, *ts, ends));
}

/// count Chebyshev points of the second kind on [lower, upper].
val chebyshev(int count, double lower, double upper) {
  if (count < 2) return error_value(Error{"Chebyshev nodes: count must be at least 2"});
  return value_or_error(chebyshev_parameters(static_cast<std::size_t>(count), Interval{lower, upper}),
                        [](const std::vector<double>& ts) { return float64_array(ts); });
}

/// The Lagrange interpolant through the points at `parameters`, evaluated at ts (barycentric form).
val lagrange_points(const val& flat_points, const val& parameters, const val& at) {
  const auto points = points_of(flat_points, 2, "data points");
  if (!points) return error_value(points.error());
  const std::vector<double> nodes = numbers_of(parameters);
  return value_or_error(interpolate_lagrange(*points, nodes), [&](const BarycentricInterpolant& interpolant) {
    const std::vector<double> ts = numbers_of(at);
    std::vector<double> out(ts.size() * 2);
    points_at(interpolant, ts, out);
    return float64_array(out);
  });
}

/// The natural spline of order q (degree 2q − 1) through the points at `parameters`.
val natural(const val& flat_points, const val& parameters, int order) {
  const auto points = points_of(flat_points, 2, "data points");
  if (!points) return error_value(points.error());
  const std::vector<double> ts = numbers_of(parameters);
  return curve_or_error(interpolate_natural(*points, ts, order));
}

}  // namespace
}  // namespace casteljau::wasm

EMSCRIPTEN_BINDINGS(casteljau_interpolation) {
  using namespace casteljau::wasm;
  emscripten::function("parameterValues", &parameters_of);
  emscripten::function("interpolateC1Bezier", &c1_bezier);
  emscripten::function("interpolateCatmullRom", &catmull_rom);
  emscripten::function("interpolateCubic", &cubic);
  emscripten::function("chebyshevParameters", &chebyshev);
  emscripten::function("lagrangePoints", &lagrange_points);
  emscripten::function("interpolateNatural", &natural);
}

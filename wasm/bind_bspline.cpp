// The playground's B-spline and NURBS views (seeds 001, 003, 004): the basis
// functions under the curve, knot insertion, de Boor's construction, the
// exact NURBS circle and the seed's cubic semicircle beside it.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_insertion.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "curve_values.hpp"
#include "js_values.hpp"

namespace casteljau::wasm {
namespace {

using emscripten::val;

Expected<BSplineCurve> bspline_argument(const val& description) {
  auto curve = curve_of(description);
  if (!curve) return curve.error();
  if (auto* bspline = std::get_if<BSplineCurve>(&*curve)) return std::move(*bspline);
  return Error{"this view needs a B-spline (kind \"bspline\")"};
}

/// N_{i,p}(u_j) for i = first..last (rows) of the n+1 = count functions and
/// every u_j (columns), zero outside each function's support (basis_function:
/// the figure over all knots). A range, so that a page with 1,000 control
/// points draws the few functions near the chosen one in O(range).
val bspline_basis(int degree, const val& knot_values, int count, int first, int last, const val& parameters) {
  const std::vector<double> knots = numbers_of(knot_values);
  if (count < 1) return error_value(Error{"a B-spline basis needs at least one function"});
  if (const Status valid = validate_knots(knots, degree, static_cast<std::size_t>(count)); !valid) {
    return error_value(valid.error());
  }
  if (first < 0 || last >= count || first > last) {
    return error_value(Error{"basis functions: the range must lie within 0.." + std::to_string(count - 1)});
  }
  const std::vector<double> us = numbers_of(parameters);
  std::vector<double> out(static_cast<std::size_t>(last - first + 1) * us.size());
  for (int i = first; i <= last; ++i) {
    for (std::size_t j = 0; j < us.size(); ++j) out[(i - first) * us.size() + j] = basis_function(knots, degree, i, us[j]);
  }
  return float64_array(out);
}

/// The same curve with the knot u inserted `times` times (Boehm).
val knot_inserted(const val& description, double u, int times) {
  const auto curve = bspline_argument(description);
  if (!curve) return error_value(curve.error());
  return value_or_error(insert_knot(*curve, u, times),
                        [](const BSplineCurve& refined) { return description_of(refined); });
}

/// {span, levels: [level 0, ..., level p]}: de Boor's construction at u.
val de_boor(const val& description, double u) {
  const auto curve = bspline_argument(description);
  if (!curve) return error_value(curve.error());
  const Interval domain = curve->domain();
  if (!(u >= domain.lower && u <= domain.upper)) {
    return error_value(Error{"de Boor's construction: u must lie in the domain"});
  }
  const DeBoorNet net = de_boor_net(*curve, u);
  val levels = val::array();
  for (const PointArray& level : net.levels) levels.call<void>("push", float64_array(level.coordinates()));
  val out = val::object();
  out.set("span", net.span);
  out.set("levels", levels);
  return out;
}

/// The exact circle as a rational quadratic B-spline (nine control points).
val circle(double center_x, double center_y, double radius) {
  return value_or_error(make_circle(center_x, center_y, radius),
                        [](const BSplineCurve& curve) { return description_of(curve); });
}

/// Seed 003's semicircle of radius 3: exact (NURBS) and its cubic Bézier approximation.
val seed_semicircles() {
  val out = val::object();
  out.set("exact", description_of(seed_semicircle()));
  out.set("cubic", description_of(seed_semicircle_cubic()));
  return out;
}

/// Clamped uniform knots for `count` control points of `degree` on [0, 1].
val clamped_knots(int degree, int count) {
  if (degree < 1 || count < degree + 1) {
    return error_value(Error{"clamped knots need degree >= 1 and at least degree + 1 control points"});
  }
  return float64_array(clamped_uniform_knots(degree, static_cast<std::size_t>(count)));
}

}  // namespace
}  // namespace casteljau::wasm

EMSCRIPTEN_BINDINGS(casteljau_bspline) {
  using namespace casteljau::wasm;
  emscripten::function("bsplineBasis", &bspline_basis);
  emscripten::function("insertKnot", &knot_inserted);
  emscripten::function("deBoorConstruction", &de_boor);
  emscripten::function("circle", &circle);
  emscripten::function("seedSemicircles", &seed_semicircles);
  emscripten::function("clampedUniformKnots", &clamped_knots);
}

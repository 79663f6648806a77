// The playground's Bézier views (seeds 000, 001, 003, 004): the Bernstein
// basis, the seed notebook's direct sum beside de Casteljau, every level of
// the construction, splitting, degree elevation and Bézier's vector form.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/construction.hpp"
#include "casteljau/bezier/degree.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bezier/vector_form.hpp"
#include "curve_values.hpp"
#include "js_values.hpp"

namespace casteljau::wasm {
namespace {

using emscripten::val;

// The largest degree the page may ask the basis for: beyond it a row of
// binomials overflows double (C(1030, 515) > 1.8e308), and the views stop
// well before (the direct-sum comparison goes to 1100 on purpose).
constexpr int kMaxPlaygroundDegree = 4000;

Expected<BezierCurve> bezier_argument(const val& description) {
  auto curve = curve_of(description);
  if (!curve) return curve.error();
  if (auto* bezier = std::get_if<BezierCurve>(&*curve)) return std::move(*bezier);
  return Error{"this view needs a Bézier curve (kind \"bezier\")"};
}

/// B_{n,k}(t_j) for k = 0..n (rows) and every t_j (columns): (n+1) x m values.
val bernstein_basis(int degree, const val& parameters) {
  if (degree < 0 || degree > kMaxPlaygroundDegree) {
    return error_value(Error{"degree must be in 0.." + std::to_string(kMaxPlaygroundDegree)});
  }
  const std::vector<double> ts = numbers_of(parameters);
  const std::size_t rows = static_cast<std::size_t>(degree) + 1;
  std::vector<double> column(rows), out(rows * ts.size());
  for (std::size_t j = 0; j < ts.size(); ++j) {
    bernstein_all(degree, ts[j], column);
    for (std::size_t k = 0; k < rows; ++k) out[k * ts.size() + j] = column[k];
  }
  return float64_array(out);
}

/// The points at ts by the seed notebook's direct sum (float binomials, powers).
val bernstein_sum_points(const val& description, const val& parameters) {
  const auto curve = bezier_argument(description);
  if (!curve) return error_value(curve.error());
  std::vector<double> out;
  for (double t : numbers_of(parameters)) {
    const Point p = point_at_bernstein_sum(*curve, t);
    out.insert(out.end(), p.begin(), p.end());
  }
  return float64_array(out);
}

/// [level 0, ..., level n]: every polygon of de Casteljau's construction at t (flat).
val construction(const val& description, double t) {
  const auto curve = bezier_argument(description);
  if (!curve) return error_value(curve.error());
  val out = val::array();
  for (const PointArray& level : casteljau_construction(*curve, t)) {
    out.call<void>("push", float64_array(level.coordinates()));
  }
  return out;
}

/// [left, right]: the two halves at t, as curve descriptions.
val split(const val& description, double t) {
  const auto curve = bezier_argument(description);
  if (!curve) return error_value(curve.error());
  return value_or_error(split_at(*curve, t), [](const std::pair<BezierCurve, BezierCurve>& halves) {
    val out = val::array();
    out.call<void>("push", description_of(halves.first));
    out.call<void>("push", description_of(halves.second));
    return out;
  });
}

/// The same curve with degree n + 1.
val elevated(const val& description) {
  const auto curve = bezier_argument(description);
  if (!curve) return error_value(curve.error());
  return description_of(elevate_degree(*curve));
}

/// {vectors: V_0 = P_0, V_i = P_i - P_{i-1}; factors: f_i(t)} (Bézier's own form).
val vector_form(const val& description, double t) {
  const auto curve = bezier_argument(description);
  if (!curve) return error_value(curve.error());
  std::vector<double> factors;
  for (int i = 0; i <= curve->degree(); ++i) factors.push_back(bezier_basis_polynomial(curve->degree(), i, t));
  const PointArray vectors = to_vector_form(curve->control_points());
  val out = val::object();
  out.set("vectors", float64_array(vectors.coordinates()));
  out.set("factors", float64_array(factors));
  return out;
}

}  // namespace
}  // namespace casteljau::wasm

EMSCRIPTEN_BINDINGS(casteljau_bezier) {
  using namespace casteljau::wasm;
  emscripten::function("bernsteinBasis", &bernstein_basis);
  emscripten::function("bernsteinSumPoints", &bernstein_sum_points);
  emscripten::function("casteljauConstruction", &construction);
  emscripten::function("splitAt", &split);
  emscripten::function("elevateDegree", &elevated);
  emscripten::function("vectorForm", &vector_form);
}

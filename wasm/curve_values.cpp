#include "curve_values.hpp"

#include <emscripten/val.h>

#include <string>
#include <utility>
#include <vector>

#include "js_values.hpp"

namespace casteljau::wasm {

using emscripten::val;

namespace {

int dimension_of(const val& description) {
  const val dimension = description["dimension"];
  return dimension.isNumber() ? dimension.as<int>() : 2;
}

std::vector<double> weights_of(const val& description) {
  const val weights = description["weights"];
  if (weights.isUndefined() || weights.isNull()) return {};
  return numbers_of(weights);
}

Expected<BezierCurve> bezier_of(const val& description, int dimension, const std::string& what) {
  auto control = points_of(description["control"], dimension, what + "control points");
  if (!control) return control.error();
  return BezierCurve::make(std::move(*control), weights_of(description));
}

void set_weights(val& out, std::span<const double> weights) {
  if (!weights.empty()) out.set("weights", float64_array(weights));
}

}  // namespace

Expected<AnyCurve> curve_of(const val& description) {
  if (description.isNull() || description.typeOf().as<std::string>() != "object") {
    return Error{"curve: expected an object with a kind"};
  }
  const int dimension = dimension_of(description);
  if (dimension < 1 || dimension > 3) return Error{"curve: dimension must be 1, 2 or 3"};
  const std::string kind = description["kind"].isString() ? description["kind"].as<std::string>() : "";
  if (kind == "bezier") {
    auto curve = bezier_of(description, dimension, "");
    if (!curve) return curve.error();
    return AnyCurve(std::move(*curve));
  }
  if (kind == "piecewise") {
    const val pieces = description["pieces"];
    if (!pieces.isArray()) return Error{"piecewise curve: pieces must be an array"};
    std::vector<BezierCurve> beziers;
    const int count = pieces["length"].as<int>();
    for (int i = 0; i < count; ++i) {
      auto piece = bezier_of(pieces[i], dimension, "piece " + std::to_string(i) + ": ");
      if (!piece) return piece.error();
      beziers.push_back(std::move(*piece));
    }
    auto curve = PiecewiseBezierCurve::make(std::move(beziers));
    if (!curve) return curve.error();
    return AnyCurve(std::move(*curve));
  }
  if (kind == "bspline") {
    if (!description["degree"].isNumber()) return Error{"B-spline: degree must be a number"};
    auto control = points_of(description["control"], dimension, "control points");
    if (!control) return control.error();
    if (description["knots"].isUndefined()) return Error{"B-spline: knots missing"};
    auto curve = BSplineCurve::make(description["degree"].as<int>(), numbers_of(description["knots"]),
                                    std::move(*control), weights_of(description));
    if (!curve) return curve.error();
    return AnyCurve(std::move(*curve));
  }
  return Error{"curve: kind must be \"bezier\", \"piecewise\" or \"bspline\", not \"" + kind + "\""};
}

val description_of(const BezierCurve& curve) {
  val out = val::object();
  out.set("kind", std::string("bezier"));
  out.set("dimension", curve.dimension());
  out.set("control", float64_array(curve.control_points().coordinates()));
  set_weights(out, curve.weights());
  return out;
}

val description_of(const PiecewiseBezierCurve& curve) {
  val out = val::object();
  out.set("kind", std::string("piecewise"));
  out.set("dimension", curve.dimension());
  val pieces = val::array();
  for (const BezierCurve& piece : curve.pieces()) pieces.call<void>("push", description_of(piece));
  out.set("pieces", pieces);
  return out;
}

val description_of(const BSplineCurve& curve) {
  val out = val::object();
  out.set("kind", std::string("bspline"));
  out.set("dimension", curve.dimension());
  out.set("degree", curve.degree());
  out.set("knots", float64_array(curve.knots()));
  out.set("control", float64_array(curve.control_points().coordinates()));
  set_weights(out, curve.weights());
  return out;
}

val description_of(const AnyCurve& curve) {
  return std::visit([](const auto& kind) { return description_of(kind); }, curve);
}

CurveView view_of(const AnyCurve& curve) {
  return std::visit([](const auto& kind) { return CurveView(kind); }, curve);
}

}  // namespace casteljau::wasm

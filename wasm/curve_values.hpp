#pragma once
// Curves as the page writes them: plain JavaScript objects that mirror the
// model JSON's curve kinds (docs/formats.md), with flat coordinate arrays:
//   {kind: "bezier",    dimension?: 2, control: [x0, y0, ...], weights?: [...]}
//   {kind: "piecewise", dimension?: 2, pieces: [{control, weights?}, ...]}
//   {kind: "bspline",   dimension?: 2, degree, knots: [...], control, weights?}
// Read with the library's own validation (make()), so the page's errors are
// the library's; written back the same way for the page to draw and export.
#include <emscripten/val.h>

#include <variant>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau::wasm {

/// One curve of any kind the page draws.
using AnyCurve = std::variant<BezierCurve, PiecewiseBezierCurve, BSplineCurve>;

/// The curve an object describes (see the file comment); errors name the field.
Expected<AnyCurve> curve_of(const emscripten::val& description);

/// The object that describes `curve` (Float64Array fields).
emscripten::val description_of(const BezierCurve& curve);
emscripten::val description_of(const PiecewiseBezierCurve& curve);
emscripten::val description_of(const BSplineCurve& curve);
emscripten::val description_of(const AnyCurve& curve);

/// A view of whichever kind `curve` holds (it must outlive the view).
CurveView view_of(const AnyCurve& curve);

}  // namespace casteljau::wasm

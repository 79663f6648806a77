#pragma once
// What crosses between JavaScript and the C++ library in the playground's
// module (embind): numbers in and out as Float64Array, point sets as flat
// [x0, y0, x1, y1, ...] arrays, curves as plain objects (curve_values.hpp),
// and errors as values: a binding never throws through WebAssembly; it
// returns {error: message}, which the page's JavaScript wrapper
// (playground/js/library.js) turns into a thrown Error.
#include <emscripten/val.h>

#include <span>
#include <string>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau::wasm {

/// The numbers of a JavaScript Array or typed array (copied).
std::vector<double> numbers_of(const emscripten::val& array);

/// A new Float64Array holding a copy of `values`.
emscripten::val float64_array(std::span<const double> values);

/// The flat coordinates of `array` (dimension d) as points; `what` names the
/// argument in the error ("control points: 7 numbers do not make points of dimension 2").
Expected<PointArray> points_of(const emscripten::val& array, int dimension, const std::string& what);

/// {error: message}: how every binding reports bad input.
emscripten::val error_value(const Error& error);

/// The value of an Expected passed through `to_js`, or its error as error_value.
template <class T, class F>
emscripten::val value_or_error(const Expected<T>& result, F&& to_js) {
  if (!result) return error_value(result.error());
  return to_js(*result);
}

}  // namespace casteljau::wasm

#include "js_values.hpp"

#include <emscripten/val.h>

#include <cstddef>

namespace casteljau::wasm {

using emscripten::val;

std::vector<double> numbers_of(const val& array) {
  return emscripten::convertJSArrayToNumberVector<double>(array);
}

val float64_array(std::span<const double> values) {
  val out = val::global("Float64Array").new_(values.size());
  out.call<void>("set", val(emscripten::typed_memory_view(values.size(), values.data())));
  return out;
}

Expected<PointArray> points_of(const val& array, int dimension, const std::string& what) {
  if (array.isUndefined() || array.isNull()) return Error{what + ": missing"};
  return PointArray::make(dimension, numbers_of(array))
      .transform_error([&](const Error& error) { return Error{what + ": " + error.message, error.kind}; });
}

val error_value(const Error& error) {
  val out = val::object();
  out.set("error", error.message);
  return out;
}

}  // namespace casteljau::wasm

#pragma once
// What every fuzz target does with what a reader accepted: the contract a
// stranger's file relies on. A model the library built evaluates to finite
// points everywhere on its domain, and every operation either answers or
// refuses with a message; an error without a message, a non-finite point of
// a valid curve, a crash, a hang or an unbounded allocation is a finding.
// libFuzzer runs the targets (-fsanitize=fuzzer,address,undefined); the
// same files build a plain driver for the regression inputs (replay.cpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/model.hpp"

namespace casteljau::fuzz {

/// Stops the run with `what` when `ok` is false: a finding.
inline void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz contract broken: %s\n", what);
  std::abort();
}

/// An error must say what is wrong.
inline void require_message(const Error& error, const char* where) {
  if (!error.message.empty()) return;
  std::fprintf(stderr, "fuzz contract broken: %s returned an error without a message\n", where);
  std::abort();
}

/// The operations run on one model are bounded by its size: a model with
/// more control points than this is only evaluated (the quadratic and
/// intersection searches on it would make a slow input, not a finding).
inline constexpr std::size_t kFullExerciseControlPoints = 400;

/// Runs the curve operations (evaluation, split, flatten, arc length, bounds,
/// closest point, self-intersections, arc splines) or, for a surface,
/// evaluation and tessellation, checking the contract above.
void exercise_model(const Model& model);

/// Runs exercise_model on at most `limit` models of a reader's result.
void exercise_models(std::span<const Model> models, std::size_t limit = 8);

/// Runs exercise_model on the curves of the first `limit` items of a reader's
/// result, `curve_of(item)` giving each item's curve.
template <class Items, class CurveOf>
void exercise_curves_of(const Items& items, CurveOf curve_of, std::size_t limit = 4) {
  std::vector<Model> models;
  for (const auto& item : items) {
    if (models.size() == limit) break;
    models.emplace_back(curve_of(item));
  }
  exercise_models(models, limit);
}

/// The fuzzer's bytes as text.
inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace casteljau::fuzz

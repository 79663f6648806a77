#pragma once
// The checks every rational curve's make() runs on its weights, so that
// Bézier and B-spline curves refuse bad weights with the same words.
// Internal to src/.

#include <cstddef>
#include <span>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "number_text.hpp"

namespace casteljau::detail {

/// Empty (a polynomial curve), or one finite weight > 0 per control point:
/// "3 weights for 4 control points, ...", "weight 2 is -1, weights must be > 0".
inline Status check_weights(std::span<const double> weights, std::size_t control_point_count) {
  if (weights.empty()) return {};
  if (weights.size() != control_point_count) {
    return Error{std::to_string(weights.size()) + " weights for " + std::to_string(control_point_count) +
                 " control points, there must be one weight per control point"};
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (auto ok = check_finite(weights[i], "weight " + std::to_string(i)); !ok) return ok;
    if (!(weights[i] > 0.0)) {
      return Error{"weight " + std::to_string(i) + " is " + number_text(weights[i]) + ", weights must be > 0"};
    }
  }
  return {};
}

}  // namespace casteljau::detail

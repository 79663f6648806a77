#pragma once
// The checks every rational curve's make() runs on its weights, so that
// Bézier and B-spline curves refuse bad weights with the same words (each
// weight by check_weight, core/model_numbers.hpp). Internal to src/.

#include <cstddef>
#include <span>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/model_numbers.hpp"

namespace casteljau::detail {

/// Empty (a polynomial curve), or one valid weight (check_weight) per control
/// point: "3 weights for 4 control points, ...", "weight 2 is -1, weights must be > 0".
inline Status check_weights(std::span<const double> weights, std::size_t control_point_count) {
  if (weights.empty()) return {};
  if (weights.size() != control_point_count) {
    return Error{std::to_string(weights.size()) + " weights for " + std::to_string(control_point_count) +
                 " control points, there must be one weight per control point"};
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    // The name is built only for the weight that fails.
    if (is_valid_weight(weights[i])) continue;
    return check_weight(weights[i], "weight " + std::to_string(i));
  }
  return {};
}

}  // namespace casteljau::detail

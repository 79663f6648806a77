#pragma once
// The checks of the control net's numbers shared by BSplineSurface::make and
// BezierSurface::make, so both refuse bad coordinates and weights with the
// same words (core/model_numbers.hpp's ranges). Internal to src/surfaces.
#include <span>

#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/control_net.hpp"

namespace casteljau::detail {

/// Every coordinate a valid coordinate (check_coordinate): "coordinate 2 of
/// control point [1][3] is 1e+308, outside [-1e+100, 1e+100], ...". O(n m d).
Status check_net_coordinates(const ControlNet& net);

/// Empty (a polynomial surface) or one valid weight (check_weight) per
/// control point, row by row: "the weights have 11 entries, the control net
/// has 12 points (3 x 4), ...", "weight [2][1] is -1, weights must be > 0".
Status check_surface_weights(std::span<const double> weights, const ControlNet& net);

}  // namespace casteljau::detail

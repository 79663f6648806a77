#pragma once
// The weight checks shared by BSplineSurface::make and BezierSurface::make,
// so both refuse bad weights with the same words. Internal to src/surfaces.
#include <span>

#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/control_net.hpp"

namespace casteljau::detail {

/// Empty (a polynomial surface) or one finite weight > 0 per control point,
/// row by row: "the weights have 11 entries, the control net has 12 points
/// (3 x 4), ...", "weight [2][1] is -1, weights must be > 0".
Status check_surface_weights(std::span<const double> weights, const ControlNet& net);

}  // namespace casteljau::detail

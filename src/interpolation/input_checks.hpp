#pragma once
// The two checks every interpolation and fitting method makes of its input,
// worded once: finite coordinates, and finite, strictly increasing
// parameters. Internal to src/interpolation.

#include <span>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau::detail {

/// "coordinate k of <what> i is NaN" (or "infinite") for the first
/// non-finite coordinate. O(n d).
Status check_coordinates(const PointArray& points, const char* what = "point");

/// "parameter i is NaN" (or "infinite"), or "parameters must increase
/// strictly: parameter i is 0.5, parameter i-1 is 0.5". O(n).
Status check_increasing(std::span<const double> parameters);

}  // namespace casteljau::detail

#pragma once
// The two checks every interpolation and fitting method makes of its input,
// worded once: valid coordinates, and valid, strictly increasing parameters
// (the ranges of core/model_numbers.hpp: the parameters become knots).
// Internal to src/interpolation.

#include <span>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau::detail {

/// "coordinate k of <what> i is NaN" (or "infinite", or "is 1e+308, outside
/// [-1e+100, 1e+100], the range of coordinates") for the first coordinate
/// that is not a valid coordinate. O(n d).
inline Status check_coordinates(const PointArray& points, const char* what = "point") {
  return casteljau::check_coordinates(points, what);
}

/// "parameter i is NaN" (or "infinite", or outside the range of knots),
/// "parameters must increase strictly: parameter i is 0.5, parameter i-1 is
/// 0.5", or "parameters 2 and 3 (0 and 1e-120) are 1e-120 apart, less than
/// the narrowest knot span 1e-100". O(n).
Status check_increasing(std::span<const double> parameters);

}  // namespace casteljau::detail

#pragma once
// The numbers a curve or surface is made of, as make() accepts them from
// outside: coordinates, weights, knots (and the parameters that
// interpolation and fitting turn into knots). The ranges, and why they make
// every valid object evaluate to finite points and first derivatives, are in
// core/tolerance.hpp ("Valid model numbers"). Each check's message names the
// value and where it is: "coordinate 1 of control point 3 is 1e+308, outside
// [-1e+100, 1e+100], the range of coordinates".

#include <cmath>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {

// The ranges as predicates, for loops that build a message only for the
// value that fails (each is false for NaN).

/// |x| <= tolerances::kMaxCoordinate.
inline bool is_valid_coordinate(double x) { return std::abs(x) <= tolerances::kMaxCoordinate; }
/// tolerances::kMinWeight <= w <= tolerances::kMaxWeight.
inline bool is_valid_weight(double w) { return w >= tolerances::kMinWeight && w <= tolerances::kMaxWeight; }
/// |t| <= tolerances::kMaxKnot.
inline bool is_valid_knot(double t) { return std::abs(t) <= tolerances::kMaxKnot; }
/// upper - lower is 0 or at least tolerances::kMinKnotSpan (lower <= upper, both valid knots).
inline bool is_valid_span(double lower, double upper) {
  const double width = upper - lower;
  return width == 0.0 || width >= tolerances::kMinKnotSpan;
}

/// A coordinate: finite and |value| <= tolerances::kMaxCoordinate. `what`
/// names it ("coordinate 0 of the centre").
Status check_coordinate(double value, const std::string& what);

/// Every coordinate of `points` as check_coordinate; the first bad one is
/// named "coordinate k of <what> i". O(n d).
Status check_coordinates(const PointArray& points, const char* what);

/// A weight: finite and within [tolerances::kMinWeight, tolerances::kMaxWeight]
/// ("weight 2 is -1, weights must be > 0"; "weight 2 is 1e-320, outside
/// [1e-50, 1e+50], the range of weights").
Status check_weight(double value, const std::string& what);

/// A knot or parameter value: finite and |value| <= tolerances::kMaxKnot.
Status check_knot(double value, const std::string& what);

/// Two knots or parameters lower <= upper named by `what` ("knots 1 and 2"):
/// equal, or at least tolerances::kMinKnotSpan apart ("knots 1 and 2 (0 and
/// 5e-324) are 5e-324 apart, less than the narrowest knot span 1e-100").
Status check_span(double lower, double upper, const std::string& what);

}  // namespace casteljau

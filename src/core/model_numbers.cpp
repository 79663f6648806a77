// The ranges of valid model numbers (see model_numbers.hpp, tolerance.hpp).
#include "casteljau/core/model_numbers.hpp"

#include <cmath>
#include <string>

#include "casteljau/core/tolerance.hpp"
#include "number_text.hpp"

namespace casteljau {
namespace {

using detail::number_text;

/// "<what> is <value>, outside [-limit, limit], the range of <kind>".
Status check_magnitude(double value, bool valid, double limit, const std::string& what, const char* kind) {
  if (auto ok = check_finite(value, what); !ok) return ok;
  if (!valid) {
    return Error{what + " is " + number_text(value) + ", outside [" + number_text(-limit) + ", " +
                 number_text(limit) + "], the range of " + kind, ErrorKind::limit};
  }
  return {};
}

}  // namespace

Status check_coordinate(double value, const std::string& what) {
  return check_magnitude(value, is_valid_coordinate(value), tolerances::kMaxCoordinate, what, "coordinates");
}

Status check_coordinates(const PointArray& points, const char* what) {
  const std::span<const double> coordinates = points.coordinates();
  const auto d = static_cast<std::size_t>(points.dimension());
  for (std::size_t k = 0; k < coordinates.size(); ++k) {
    // The name is built only for the value that fails.
    if (is_valid_coordinate(coordinates[k])) continue;
    return check_coordinate(coordinates[k], "coordinate " + std::to_string(k % d) + " of " + what + " " +
                                                std::to_string(k / d));
  }
  return {};
}

Status check_weight(double value, const std::string& what) {
  if (auto ok = check_finite(value, what); !ok) return ok;
  if (!(value > 0.0)) return Error{what + " is " + number_text(value) + ", weights must be > 0"};
  if (!is_valid_weight(value)) {
    return Error{what + " is " + number_text(value) + ", outside [" + number_text(tolerances::kMinWeight) + ", " +
                 number_text(tolerances::kMaxWeight) + "], the range of weights"};
  }
  return {};
}

Status check_knot(double value, const std::string& what) {
  return check_magnitude(value, is_valid_knot(value), tolerances::kMaxKnot, what, "knots");
}

Status check_span(double lower, double upper, const std::string& what) {
  if (is_valid_span(lower, upper)) return {};
  return Error{what + " (" + number_text(lower) + " and " + number_text(upper) + ") are " + number_text(upper - lower) +
               " apart, less than the narrowest knot span " + number_text(tolerances::kMinKnotSpan)};
}

}  // namespace casteljau

// Input checks shared by the interpolation layer (see input_checks.hpp).

#include "input_checks.hpp"

#include <cmath>
#include <string>

#include "../core/number_text.hpp"

namespace casteljau::detail {

Status check_coordinates(const PointArray& points, const char* what) {
  const std::span<const double> coordinates = points.coordinates();
  const auto d = static_cast<std::size_t>(points.dimension());
  for (std::size_t j = 0; j < coordinates.size(); ++j) {
    if (!std::isfinite(coordinates[j])) {
      return Error{"coordinate " + std::to_string(j % d) + " of " + what + " " + std::to_string(j / d) + " is " +
                   (std::isnan(coordinates[j]) ? "NaN" : "infinite")};
    }
  }
  return {};
}

Status check_increasing(std::span<const double> parameters) {
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (!std::isfinite(parameters[i])) {
      return Error{"parameter " + std::to_string(i) + " is " + (std::isnan(parameters[i]) ? "NaN" : "infinite")};
    }
    if (i > 0 && !(parameters[i] > parameters[i - 1])) {
      return Error{"parameters must increase strictly: parameter " + std::to_string(i) + " is " +
                   number_text(parameters[i]) + ", parameter " + std::to_string(i - 1) + " is " +
                   number_text(parameters[i - 1])};
    }
  }
  return {};
}

}  // namespace casteljau::detail

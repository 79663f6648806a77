// Input checks shared by the interpolation layer (see input_checks.hpp).

#include "input_checks.hpp"

#include <string>

#include "../core/number_text.hpp"

namespace casteljau::detail {

Status check_increasing(std::span<const double> parameters) {
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    // Messages are built only for the parameter that fails.
    if (!is_valid_knot(parameters[i])) return check_knot(parameters[i], "parameter " + std::to_string(i));
    if (i == 0) continue;
    if (!(parameters[i] > parameters[i - 1])) {
      return Error{"parameters must increase strictly: parameter " + std::to_string(i) + " is " +
                   number_text(parameters[i]) + ", parameter " + std::to_string(i - 1) + " is " +
                   number_text(parameters[i - 1])};
    }
    if (!is_valid_span(parameters[i - 1], parameters[i])) {
      return check_span(parameters[i - 1], parameters[i],
                        "parameters " + std::to_string(i - 1) + " and " + std::to_string(i));
    }
  }
  return {};
}

}  // namespace casteljau::detail

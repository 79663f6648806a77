#pragma once
// Numbers in error messages: the shortest of %.15g / %.17g that reads back
// to the same double, so "knot 3 is 0.1" rather than 0.10000000000000001.
// Internal to src/ (the io layer formats output with fmt instead).

#include <cstdio>
#include <cstdlib>
#include <string>

namespace casteljau::detail {

inline std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  if (std::strtod(text, nullptr) != value) std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace casteljau::detail

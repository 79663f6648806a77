#pragma once
// Numbers in error messages: the fewest significant digits that read back
// to the same double, so "knot 3 is 0.1" rather than 0.10000000000000001,
// and a subnormal as the user typed it ("5e-324", where %.15g gives
// 4.94065645841247e-324). Written like %.15g otherwise: plain below 1e15
// ("10", not "1e+01"), with an exponent above and below 1e-4.
// Internal to src/ (the io layer formats output with fmt instead).

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace casteljau::detail {

inline std::string number_text(double value) {
  char text[40];
  int digits = 1;
  for (; digits < 17; ++digits) {  // 17 significant digits always read back
    std::snprintf(text, sizeof text, "%.*e", digits - 1, value);
    if (std::strtod(text, nullptr) == value) break;  // never for NaN and inf: "nan", "inf" below
  }
  std::snprintf(text, sizeof text, "%.*e", digits - 1, value);
  const char* e = std::strchr(text, 'e');
  const int exponent = e ? std::atoi(e + 1) : 0;
  // At least the digits %.15g shows before an exponent: 10 stays "10".
  std::snprintf(text, sizeof text, "%.*g", std::max(digits, std::min(exponent + 1, 15)), value);
  return text;
}

}  // namespace casteljau::detail

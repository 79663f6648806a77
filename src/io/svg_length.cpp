// SVG lengths to user units (svg_length.hpp says what).
#include "svg_length.hpp"

#include <fmt/format.h>

#include <string>

#include "svg_scanner.hpp"

namespace casteljau::io_detail {

Expected<SvgLength> parse_svg_length(std::string_view text, std::string_view label) {
  SvgScanner in(text, label);
  in.skip_spaces();
  if (!in.at_number()) return in.error("expected a length (a number, with px, in, cm, mm, Q, pt, pc or %)");
  auto number = in.number();
  if (!number) return number.error();
  const std::size_t unit_at = in.position();
  const std::string_view unit = in.word();
  in.skip_spaces();
  if (!in.done()) return in.error("expected the end of the length");
  // CSS Values 3 §6.2: 1in = 2.54cm = 25.4mm = 101.6Q = 72pt = 6pc = 96px.
  double scale = 0.0, millimetres = 0.0;  // px and mm per unit
  if (unit.empty() || unit == "px") scale = 1.0, millimetres = 25.4 / 96.0;
  else if (unit == "in") scale = 96.0, millimetres = 25.4;
  else if (unit == "cm") scale = 96.0 / 2.54, millimetres = 10.0;
  else if (unit == "mm") scale = 96.0 / 25.4, millimetres = 1.0;
  else if (unit == "Q") scale = 96.0 / 101.6, millimetres = 0.25;
  else if (unit == "pt") scale = 96.0 / 72.0, millimetres = 25.4 / 72.0;
  else if (unit == "pc") scale = 16.0, millimetres = 25.4 / 6.0;
  else if (unit == "%") return SvgLength{*number, true, 0.0};
  else if (unit == "em" || unit == "ex")
    return in.error_at(unit_at, fmt::format("'{}': em and ex lengths depend on fonts, casteljau reads px, in, cm, "
                                            "mm, Q, pt, pc and %",
                                            text.substr(0, 40)));
  else
    return in.error_at(unit_at, fmt::format("'{}' is not a unit of length (px, in, cm, mm, Q, pt, pc, %)",
                                            unit.substr(0, 20)));
  return SvgLength{*number * scale, false, *number * millimetres};
}

Expected<double> svg_length_in_user_units(const SvgLength& length, std::optional<double> reference,
                                          std::string_view label) {
  if (!length.percent) return length.value;
  if (!reference)
    return Error{fmt::format("{}: '{}%' needs a viewport size (the root's viewBox, or its width and height in "
                             "absolute units)",
                             label, length.value),
                 ErrorKind::invalid_argument};
  return length.value / 100.0 * *reference;
}

}  // namespace casteljau::io_detail

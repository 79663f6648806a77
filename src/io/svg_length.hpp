#pragma once
// SVG lengths (SVG 1.1 §4.2, CSS Values 3 §6.2): a number with an optional
// absolute unit or a percentage, in user units (CSS px: 96 to the inch).

#include <optional>
#include <string_view>

#include "casteljau/core/expected.hpp"

namespace casteljau::io_detail {

/// A length as written: its number and whether it was a percentage.
struct SvgLength {
  double value = 0.0;  ///< in user units (px); the percentage itself when `percent`
  bool percent = false;
  /// The same length in mm, from the number and its unit directly (so that
  /// "10mm" is 10 exactly, not 10 * (96 / 25.4) * (25.4 / 96)).
  double millimetres = 0.0;
};

/// number (px|in|cm|mm|Q|pt|pc|%)? with blanks around. em and ex are
/// refused (they depend on fonts this reader does not have): "'2em': em and
/// ex lengths depend on fonts, casteljau reads px, in, cm, mm, Q, pt, pc and %".
/// `label` names the attribute in errors ("width, character 3 ('q'): ...").
Expected<SvgLength> parse_svg_length(std::string_view text, std::string_view label);

/// The length in user units: a percentage of `reference` (the viewport's
/// width, height or normalized diagonal). Without a reference a percentage
/// is an error: "'50%' needs a viewport size (the root's viewBox, or its
/// width and height in absolute units)".
Expected<double> svg_length_in_user_units(const SvgLength& length, std::optional<double> reference,
                                          std::string_view label);

/// Millimetres per user unit at 96 px to the inch: 25.4 / 96.
inline constexpr double kSvgMillimetresPerPixel = 25.4 / 96.0;

}  // namespace casteljau::io_detail

// Fuzz target: font files (io/font): FreeType opens the bytes, then the
// outline decomposition turns each glyph's points into Bézier pieces.
#include <cstddef>
#include <cstdint>
#include <span>

#include "casteljau/io/font.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  const std::span<const unsigned char> bytes(data, size);
  // Latin letters with curves, digits, and a character most fonts lack (.notdef).
  auto outline = text_outline("Og8&\xE2\x82\xAC\n@", bytes, "fuzz.ttf", TextLayout{});
  if (!outline) {
    fuzz::require_message(outline.error(), "text_outline");
    return 0;
  }
  fuzz::exercise_curves_of(outline->contours, [](const GlyphContour& contour) { return contour.curve; });
  return 0;
}

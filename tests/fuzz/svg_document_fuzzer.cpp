// Fuzz target: whole SVG documents (io/svg_drawing: pugixml, styles,
// transforms, <use>, units), in user units and in millimetres.
#include <cstddef>
#include <cstdint>

#include "casteljau/io/svg_drawing.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  const auto text = fuzz::text_of(data, size);
  for (DrawingUnits units : {DrawingUnits::user, DrawingUnits::millimetres}) {
    auto drawing = parse_svg_drawing(text, "fuzz.svg", units);
    if (!drawing) {
      fuzz::require_message(drawing.error(), "parse_svg_drawing");
      continue;
    }
    for (const Error& problem : drawing->problems) fuzz::require_message(problem, "an SVG problem");
    fuzz::exercise_curves_of(drawing->curves, [](const SvgCurve& curve) { return curve.curve; });
  }
  return 0;
}

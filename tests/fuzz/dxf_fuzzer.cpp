// Fuzz target: DXF drawings (io/dxf_reader): sections, entities, splines,
// arcs, polylines with bulges.
#include <cstddef>
#include <cstdint>

#include "casteljau/io/dxf.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  auto drawing = parse_dxf_drawing(fuzz::text_of(data, size), "fuzz.dxf");
  if (!drawing) {
    fuzz::require_message(drawing.error(), "parse_dxf_drawing");
    return 0;
  }
  for (const Error& problem : drawing->problems) fuzz::require_message(problem, "a DXF problem");
  fuzz::exercise_curves_of(drawing->curves, [](const DxfCurve& curve) { return curve.curve; });
  return 0;
}

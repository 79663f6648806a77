// Fuzz target: DXF drawings (io/dxf_reader): sections, entities, splines,
// arcs, polylines with bulges.
#include <cstddef>
#include <cstdint>
#include <vector>

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
  std::vector<Model> models;
  for (const DxfCurve& curve : drawing->curves) {
    if (models.size() == 4) break;
    models.push_back(curve.curve);
  }
  fuzz::exercise_models(models);
  return 0;
}

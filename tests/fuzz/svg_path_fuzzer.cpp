// Fuzz target: SVG path data (io/svg_path), the `d` attribute's grammar;
// every subpath read is a curve the operations must take.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "casteljau/io/svg_path.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  const SvgPathData path = read_svg_path(fuzz::text_of(data, size));
  if (path.error) fuzz::require_message(*path.error, "read_svg_path");
  std::vector<Model> models;
  for (const SvgSubpath& subpath : path.subpaths) models.emplace_back(subpath.curve);
  fuzz::exercise_models(models, 4);
  return 0;
}

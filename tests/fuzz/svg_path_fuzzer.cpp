// Fuzz target: SVG path data (io/svg_path), the `d` attribute's grammar;
// every subpath read is a curve the operations must take.
#include <cstddef>
#include <cstdint>

#include "casteljau/io/svg_path.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  const SvgPathData path = read_svg_path(fuzz::text_of(data, size));
  if (path.error) fuzz::require_message(*path.error, "read_svg_path");
  fuzz::exercise_curves_of(path.subpaths, [](const SvgSubpath& subpath) { return subpath.curve; });
  return 0;
}

// Fuzz target: G-code programs read back (io/gcode_reader), as the tests
// read what `casteljau gcode` writes.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "casteljau/io/gcode.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  if (auto reading = read_gcode(fuzz::text_of(data, size)); !reading) {
    fuzz::require_message(reading.error(), "read_gcode");
  }
  return 0;
}

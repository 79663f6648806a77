// Fuzz target: CSV point sets and number columns (io/csv), as `casteljau
// interpolate`, `fit` and `eval --params` read them.
#include <cstddef>
#include <cstdint>

#include "casteljau/io/csv.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  const auto text = fuzz::text_of(data, size);
  if (auto points = parse_points_csv(text, "fuzz.csv"); !points) {
    fuzz::require_message(points.error(), "parse_points_csv");
  } else {
    for (double c : points->coordinates()) fuzz::require(std::isfinite(c), "a point set read from CSV is finite");
  }
  if (auto numbers = parse_numbers_csv(text, "fuzz.csv", 10000); !numbers) {
    fuzz::require_message(numbers.error(), "parse_numbers_csv");
  }
  return 0;
}

// Fuzz target: model JSON (io/model_json), what every MODEL-taking command
// reads; each model read is then run through the curve or surface operations.
#include <cstddef>
#include <cstdint>

#include "casteljau/io/model_json.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace casteljau;
  if (auto models = parse_models_json(fuzz::text_of(data, size), "fuzz.json"); !models) {
    fuzz::require_message(models.error(), "parse_models_json");
  } else {
    fuzz::require(!models->empty(), "a model file read without error holds a model");
    fuzz::exercise_models(*models);
  }
  return 0;
}

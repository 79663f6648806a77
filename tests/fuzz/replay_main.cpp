// casteljau_fuzz_replay NAME DIR...: feeds every file of the folders (the
// seed corpus, the inputs fuzzers found: regressions/NAME) to fuzz target
// NAME's entry point, as libFuzzer would, in the ordinary test trees (g++,
// and ASan + UBSan in build-asan), so that what a fuzzer once found stays
// fixed. Exit status 0; a broken contract aborts (fuzz_support.hpp). A
// missing folder is fine (a target may have no regressions yet).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#define CASTELJAU_FUZZ_TARGET(name) extern "C" int casteljau_fuzz_##name(const std::uint8_t* data, std::size_t size);
#include "fuzz_targets.inc"
#undef CASTELJAU_FUZZ_TARGET

namespace {

using EntryPoint = int (*)(const std::uint8_t*, std::size_t);

struct Target {
  std::string_view name;
  EntryPoint run;
};

#define CASTELJAU_FUZZ_TARGET(name) Target{#name, &casteljau_fuzz_##name},
const Target kTargets[] = {
#include "fuzz_targets.inc"
};
#undef CASTELJAU_FUZZ_TARGET

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: casteljau_fuzz_replay NAME DIR...\n");
    return 2;
  }
  const std::string_view name = argv[1];
  const auto target = std::find_if(std::begin(kTargets), std::end(kTargets), [&](const Target& t) { return t.name == name; });
  if (target == std::end(kTargets)) {
    std::fprintf(stderr, "casteljau_fuzz_replay: no fuzz target '%s'\n", argv[1]);
    return 2;
  }
  std::vector<std::filesystem::path> inputs;
  for (int i = 2; i < argc; ++i) {
    const std::filesystem::path folder = argv[i];
    if (!std::filesystem::is_directory(folder)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.is_regular_file()) inputs.push_back(entry.path());
  }
  std::sort(inputs.begin(), inputs.end());
  for (const auto& input : inputs) {
    std::ifstream file(input, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    std::fprintf(stderr, "%s\n", input.filename().string().c_str());
    target->run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%s: %zu inputs replayed\n", argv[1], inputs.size());
  return 0;
}

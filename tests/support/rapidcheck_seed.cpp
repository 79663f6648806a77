// Linked into every test executable: rapidcheck reads RC_PARAMS on first use,
// so this fixes the seed and case count for every run, by ctest or by hand,
// unless the caller chose other parameters (house rule: seeded randomness only;
// to explore, run with RC_PARAMS="seed=<other> max_success=2000"). Under the
// sanitizers a property runs 50 cases instead of 200 (support/sanitizers.hpp).
#include <stdlib.h>

#include "support/sanitizers.hpp"

namespace {
[[maybe_unused]] const bool seeded = [] {
  ::setenv("RC_PARAMS",
           casteljau::test::kUnderSanitizers ? "seed=20261122 max_success=50" : "seed=20261122 max_success=200", 0);
  return true;
}();
}  // namespace

#include "support/examples_dir.hpp"

#ifndef CASTELJAU_EXAMPLES_DIR
#error "CASTELJAU_EXAMPLES_DIR must name the examples folder (set by tests/CMakeLists.txt)"
#endif

namespace casteljau::test {

std::filesystem::path examples_dir() { return CASTELJAU_EXAMPLES_DIR; }

}  // namespace casteljau::test

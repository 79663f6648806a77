#pragma once
// The project's examples/ folder, for tests that read its data files.

#include <filesystem>

namespace casteljau::test {

/// The examples/ folder of the source tree this test was built from. Its path
/// is compiled into examples_dir.cpp alone, so that the absolute path of the
/// checkout reaches one translation unit, not every test (ccache then finds
/// the other objects of a fresh clone at another path; docs/development.md).
std::filesystem::path examples_dir();

}  // namespace casteljau::test

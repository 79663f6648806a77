#pragma once
// Files in and out. Nothing is half-written: output goes to a temporary file
// in the same folder, renamed over the target only when complete.

#include <filesystem>
#include <string>
#include <string_view>

#include "casteljau/core/expected.hpp"

namespace casteljau {

/// The whole file as text; errors name the file ("cannot open 'x.csv': No such file").
/// Refuses files larger than 1 GiB (a huge size) before reading them.
Expected<std::string> read_text_file(const std::filesystem::path& path);

/// Writes `contents` to `path` atomically (temporary file + rename).
Status write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace casteljau

#pragma once
// Files in and out. Nothing is half-written: output goes to a temporary file
// in the same folder, renamed over the target only when complete.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {


/// The whole file as text. Errors name the file: "cannot open 'x.csv': No such
/// file or directory", "'dir' is a directory, not a file", "'big.json' is
/// 1.5 GiB, larger than the 1 GiB limit for input files". Regular files are
/// measured before reading; pipes and devices are read up to the same limit.
/// A UTF-8 byte order mark is kept (the parsers skip it). O(size).
Expected<std::string> read_text_file(const std::filesystem::path& path);

/// The path as error messages show it: the text given, with control
/// characters and bytes that are not UTF-8 written as \xNN, so that a message
/// naming any file stays one line of valid text.
std::string display_name(const std::filesystem::path& path);

/// Writes `contents` to `path` atomically: a temporary file in the same folder
/// (so the rename never crosses file systems), written, flushed to disk, given
/// the target's permissions (0666 minus the umask for a new file), then
/// renamed over `path` (POSIX rename replaces it in one step). On any failure
/// the temporary file is removed and `path` is untouched. A symbolic link at
/// `path` is followed: its target is replaced, the link stays.
/// Errors: "cannot write 'out/x.csv': No such file or directory".
Status write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace casteljau

#pragma once
// What the C++ course programs share (as course.py does for the Python ones):
// the refusal they exit with, and writing a file into the output folder
// named on the command line.
#include <casteljau/core/expected.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

namespace course {

/// Prints why something was refused ("error: <message>") and returns the exit status 1.
inline int fail(const casteljau::Error& error) {
  std::fprintf(stderr, "error: %s\n", error.message.c_str());
  return 1;
}

/// Creates `folder` if it is missing (casteljau's writers write into an
/// existing folder), runs `write(path)` for folder/name and prints the path.
template <class Write>
casteljau::Status write_into(const std::filesystem::path& folder, const std::string& name, Write write) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) return casteljau::Error{"cannot create '" + folder.string() + "': " + ec.message(), casteljau::ErrorKind::io};
  const std::filesystem::path path = folder / name;
  if (auto ok = write(path); !ok) return ok.error();
  std::printf("wrote %s\n", path.string().c_str());
  return {};
}

}  // namespace course

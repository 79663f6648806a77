// The shared option readers and the output of every subcommand (options.hpp).
#include "options.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "casteljau/io/file.hpp"

namespace casteljau::cli {

bool given(const CLI::Option* option) { return option != nullptr && option->count() > 0; }

Expected<long long> whole_number(std::string_view option, std::string_view text, long long lowest, long long highest) {
  const std::string_view shown = text.substr(0, 60);
  const bool digits_only = !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
  if (!digits_only) return Error{fmt::format("{}: '{}' is not a whole number", option, shown)};
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range || value > highest) {
    return Error{fmt::format("{}: {} is more than the limit of {}", option, shown, highest)};
  }
  if (value < lowest) return Error{fmt::format("{}: {} is outside {}..{}", option, value, lowest, highest)};
  return value;
}

int fail(std::string_view message) {
  std::cerr << "casteljau: error: " << message << '\n';
  return 2;
}

int fail(const Error& error) { return fail(error.message); }

int write_output(const std::string& path, std::string_view text) {
  if (!path.empty()) {
    if (auto written = casteljau::write_file_atomically(path, text); !written) return fail(written.error());
    return 0;
  }
  if ((!text.empty() && std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) || std::fflush(stdout) != 0) {
    // Not bad input: the environment failed (disk full, closed pipe).
    std::fprintf(stderr, "casteljau: error: cannot write to standard output: %s\n", std::strerror(errno));
    return 1;
  }
  return 0;
}

}  // namespace casteljau::cli

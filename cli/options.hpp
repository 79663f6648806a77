#pragma once
// What every subcommand shares: reading option values the same way, the
// error line and exit status, and writing the output. One place each, so
// that `casteljau eval --samples x` and `casteljau fit --degree x` say the
// same thing in the same words (docs/cli.md, "Exit status").

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

#include "casteljau/core/expected.hpp"

namespace casteljau::cli {

/// Whether `option` was given on the command line (an empty value, `--x ''`,
/// counts as given: it is then checked, not silently taken for the default).
bool given(const CLI::Option* option);

/// A whole number in [lowest, highest] written in decimal digits only (no
/// sign, no exponent, no blanks): "--samples: '2.5' is not a whole number",
/// "--degree: 0 is outside 1..10000", "--derivative: 1001 is more than the
/// limit of 1000" (also for digits beyond 64 bits).
Expected<long long> whole_number(std::string_view option, std::string_view text, long long lowest, long long highest);

/// Prints "casteljau: error: <message>" on stderr and returns 2 (bad input).
int fail(std::string_view message);
/// The same for an Error from the library.
int fail(const Error& error);

/// Writes a command's output: to `path` atomically (nothing is half-written;
/// a file error is bad input, status 2) or, when `path` is empty, to standard
/// output (a failure there is the environment's, status 1). 0 on success.
int write_output(const std::string& path, std::string_view text);

}  // namespace casteljau::cli

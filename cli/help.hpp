#pragma once
// What `casteljau --help`, `casteljau SUBCOMMAND --help` and `--version`
// print: descriptions wrapped to the terminal, one example per subcommand
// (all of them in one table, help.cpp's kExamples), the version from CMake.

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::cli {

/// "casteljau 0.1.0": the VERSION of CMake's project(), which
/// casteljau/version.hpp is generated from (CMakeLists.txt), written nowhere else.
std::string version_line();

/// The width help is wrapped to: COLUMNS when it is a whole number, else the
/// width of the terminal on standard output, else 80 (a pipe, a file); never
/// less than 40, where a description column still holds a few words.
std::size_t help_width();

/// `text` cut into lines of at most `width` characters (UTF-8 code points)
/// at blanks, greedily; a word longer than `width` gets a line of its own; a
/// newline in `text` always ends a line.
std::vector<std::string> wrap(std::string_view text, std::size_t width);

/// casteljau's help on `app` and on each of its subcommands: descriptions
/// and option texts wrapped to help_width(), the overview listing each
/// subcommand's first sentence, each subcommand's example from kExamples
/// under its options, and --version. Call after every subcommand is added.
void set_up_help(CLI::App& app);

}  // namespace casteljau::cli

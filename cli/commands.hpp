#pragma once
// The subcommands of `casteljau`. Each add_*_command registers one subcommand
// on the app; its callback runs the command and stores the exit status in
// `status`: 0 success, 2 bad input (one line on stderr, nothing on stdout),
// 1 internal failure. Front ends translate; no geometry lives here.

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

#include "casteljau/core/expected.hpp"

namespace casteljau::cli {

void add_eval_command(CLI::App& app, int& status);       // cli/eval_command.cpp
void add_plot_command(CLI::App& app, int& status);       // cli/plot_command.cpp
void add_bernstein_command(CLI::App& app, int& status);  // cli/bernstein_command.cpp
void add_gallery_command(CLI::App& app, int& status);    // cli/gallery_command.cpp
void add_convert_command(CLI::App& app, int& status);    // cli/convert_command.cpp
void add_interpolate_command(CLI::App& app, int& status);  // cli/interpolate_command.cpp
void add_fit_command(CLI::App& app, int& status);          // cli/fit_command.cpp
void add_tessellate_command(CLI::App& app, int& status);   // cli/tessellate_command.cpp

/// Prints "casteljau: error: <message>" on stderr and returns 2 (bad input).
int fail(std::string_view message);
/// The same for an Error from the library.
int fail(const Error& error);
/// Writes a command's output: to `path` atomically (nothing is half-written;
/// a file error is bad input, status 2) or, when `path` is empty, to standard
/// output (a failure there is the environment's, status 1). 0 on success.
int write_output(const std::string& path, std::string_view text);

}  // namespace casteljau::cli

#pragma once
// The subcommands of `casteljau`. Each add_*_command registers one subcommand
// on the app; its callback runs the command and stores the exit status in
// `status`: 0 success, 2 bad input (one line on stderr, nothing on stdout),
// 1 internal failure. Front ends translate; no geometry lives here.

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

#include "options.hpp"

namespace casteljau::cli {

void add_eval_command(CLI::App& app, int& status);       // cli/eval_command.cpp
void add_plot_command(CLI::App& app, int& status);       // cli/plot_command.cpp
void add_bernstein_command(CLI::App& app, int& status);  // cli/bernstein_command.cpp
void add_gallery_command(CLI::App& app, int& status);    // cli/gallery_command.cpp
void add_convert_command(CLI::App& app, int& status);    // cli/convert_command.cpp
void add_interpolate_command(CLI::App& app, int& status);  // cli/interpolate_command.cpp
void add_fit_command(CLI::App& app, int& status);          // cli/fit_command.cpp
void add_tessellate_command(CLI::App& app, int& status);   // cli/tessellate_command.cpp
void add_length_command(CLI::App& app, int& status);       // cli/length_command.cpp
void add_closest_command(CLI::App& app, int& status);      // cli/closest_command.cpp
void add_intersect_command(CLI::App& app, int& status);    // cli/intersect_command.cpp
void add_text_command(CLI::App& app, int& status);         // cli/text_command.cpp
void add_gcode_command(CLI::App& app, int& status);        // cli/gcode_command.cpp
void add_info_command(CLI::App& app, int& status);         // cli/info_command.cpp
void add_arcs_command(CLI::App& app, int& status);         // cli/arcs_command.cpp

}  // namespace casteljau::cli

// casteljau: the command line. Parses arguments with CLI11 and dispatches to
// the subcommands in cli/*_command.cpp. Exit status: 0 success, 2 bad input,
// 1 internal failure (../ARCHITECTURE.md, docs/cli.md).
#include <exception>
#include <iostream>

#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace casteljau::cli;
  CLI::App app{"casteljau: Bézier, B-spline and NURBS curves and surfaces, from the Bernstein basis to CNC output"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every subcommand");
  int status = 0;
  add_eval_command(app, status);
  add_plot_command(app, status);
  add_bernstein_command(app, status);
  add_gallery_command(app, status);
  add_convert_command(app, status);
  add_interpolate_command(app, status);
  add_fit_command(app, status);
  add_tessellate_command(app, status);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, exit 2 (bad input), as for every other error.
    return fail(e.what());
  } catch (const std::exception& e) {
    std::cerr << "casteljau: internal error: " << e.what() << '\n';
    return 1;
  }
  return status;
}

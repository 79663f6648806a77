// casteljau: the command line. Parses arguments with CLI11 and dispatches to
// the subcommands in cli/*_command.cpp. Exit status: 0 success, 2 bad input,
// 1 internal failure or an output the environment refused (a full disk, a
// closed pipe) (../ARCHITECTURE.md, docs/cli.md).
#include <csignal>
#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "help.hpp"
#include "suggest.hpp"

int main(int argc, char** argv) {
  using namespace casteljau::cli;
  // A reader that leaves early (`casteljau eval ... | head -1`) makes the next
  // write fail with EPIPE, which write_standard_output turns into status 1,
  // instead of killing the process with SIGPIPE (status 141).
  std::signal(SIGPIPE, SIG_IGN);

  CLI::App app{"casteljau: Bézier, B-spline and NURBS curves and surfaces, from the Bernstein basis to CNC output"};
  app.name("casteljau");  // in usage lines, whatever path it was started by
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
  add_length_command(app, status);
  add_closest_command(app, status);
  add_intersect_command(app, status);
  add_text_command(app, status);
  add_gcode_command(app, status);
  add_info_command(app, status);
  add_arcs_command(app, status);
  set_up_help(app);

  if (const auto unknown = unknown_subcommand(app, argc, argv)) return fail(*unknown);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    // --help, --help-all, --version: printed on standard output, status 0.
    return app.exit(e);
  } catch (const CLI::RequiredError& e) {
    // `casteljau` alone, or `casteljau --bogus`: say what is missing or wrong.
    if (const auto message = unexpected_arguments(app)) return fail(*message);
    if (app.get_subcommands().empty()) return fail(missing_subcommand(app));
    return fail(e.what());
  } catch (const CLI::ExtrasError& e) {
    // One line, exit 2 (bad input), as for every other error.
    if (const auto message = unexpected_arguments(app)) return fail(*message);
    return fail(e.what());
  } catch (const CLI::ParseError& e) {
    return fail(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "casteljau: internal error: %s\n", e.what());
    return 1;
  }
  return status;
}

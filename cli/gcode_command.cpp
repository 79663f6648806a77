// casteljau gcode: a toolpath for the plane curves of the inputs as an
// RS-274/NGC program (docs/cli.md, "gcode"; what is written: docs/formats.md,
// "G-code"): each curve a contour of arcs and lines fitted within
// --tolerance (ops/arc_spline.hpp's fit_arcs), or of lines only with --lines
// (ops/flatten.hpp), written by io/gcode.hpp. The program is built in memory
// and written atomically: on bad input nothing is written.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "casteljau/io/file.hpp"
#include "casteljau/io/gcode.hpp"
#include "casteljau/io/model.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct GcodeCommandOptions {
  std::vector<std::string> inputs;
  std::string tolerance;
  bool arcs = false;
  bool lines = false;
  std::string depth, step_down, safe_z, feed, plunge_feed, decimals;
  std::string units = "mm";
  std::string dialect = "grbl";
  std::string origin = "drawing";
  std::string output;
  const CLI::Option* depth_option = nullptr;
  const CLI::Option* step_down_option = nullptr;
  const CLI::Option* safe_z_option = nullptr;
  const CLI::Option* feed_option = nullptr;
  const CLI::Option* plunge_feed_option = nullptr;
  const CLI::Option* decimals_option = nullptr;
};

/// The program's options: the unit's defaults, then what the command line gives.
Expected<GcodeOptions> program_options(const GcodeCommandOptions& given_options) {
  if (given_options.units != "mm" && given_options.units != "in")
    return Error{fmt::format("--units: '{}' is not mm or in", given_options.units.substr(0, 60))};
  if (given_options.dialect != "grbl" && given_options.dialect != "linuxcnc")
    return Error{fmt::format("--dialect: '{}' is not grbl or linuxcnc", given_options.dialect.substr(0, 60))};
  if (given_options.origin != "drawing" && given_options.origin != "lower-left" && given_options.origin != "centre")
    return Error{fmt::format("--origin: '{}' is not drawing, lower-left or centre", given_options.origin.substr(0, 60))};
  GcodeOptions options =
      default_gcode_options(given_options.units == "mm" ? GcodeUnits::millimetres : GcodeUnits::inches);
  options.origin = given_options.origin == "drawing"      ? GcodeOrigin::drawing
                   : given_options.origin == "lower-left" ? GcodeOrigin::lower_left
                                                          : GcodeOrigin::centre;
  options.dialect = given_options.dialect == "grbl" ? GcodeDialect::grbl : GcodeDialect::linuxcnc;
  for (auto [option, text, value, name] :
       {std::tuple{given_options.depth_option, &given_options.depth, &options.depth, "--depth"},
        std::tuple{given_options.step_down_option, &given_options.step_down, &options.step_down, "--step-down"},
        std::tuple{given_options.safe_z_option, &given_options.safe_z, &options.safe_height, "--safe-z"},
        std::tuple{given_options.feed_option, &given_options.feed, &options.feed, "--feed"},
        std::tuple{given_options.plunge_feed_option, &given_options.plunge_feed, &options.plunge_feed,
                   "--plunge-feed"}}) {
    if (!given(option)) continue;
    auto number = number_option(name, *text);
    if (!number) return number.error();
    if (!(*number > 0.0)) return Error{fmt::format("{}: {} is not > 0", name, *text)};
    *value = *number;
  }
  if (given(given_options.decimals_option)) {
    auto decimals = whole_number("--decimals", given_options.decimals, tolerances::kGcodeFewestDecimals,
                                 tolerances::kGcodeMostDecimals);
    if (!decimals) return decimals.error();
    options.decimals = static_cast<int>(*decimals);
  }
  return options;
}

int run_gcode(const GcodeCommandOptions& options) {
  auto tolerance = number_option("--tolerance", options.tolerance);
  if (!tolerance) return fail(tolerance.error());
  if (!(*tolerance > 0.0)) return fail(fmt::format("--tolerance: {} is not a distance > 0", options.tolerance));
  auto program_settings = program_options(options);
  if (!program_settings) return fail(program_settings.error());

  Toolpath toolpath;
  toolpath.tolerance = Tolerance{*tolerance};
  // The decimals first: the curves are fitted within what their rounding leaves.
  const auto decimals = gcode_decimals(toolpath.tolerance, program_settings->units, program_settings->decimals);
  if (!decimals) return fail(with_context(decimals.error(), "--tolerance"));
  program_settings->decimals = *decimals;
  const GcodeMotion motion = options.lines ? GcodeMotion::lines : GcodeMotion::arcs;
  for (const std::string& path : options.inputs) {
    const auto models = read_model_file(path, "");
    if (!models) return fail(models.error());
    toolpath.sources.push_back(display_name(path));
    for (std::size_t m = 0; m < models->size(); ++m) {
      const Model& model = (*models)[m];
      const std::string name = model_name(*models, m, path);
      if (is_surface(model)) return fail(fmt::format("gcode cuts plane curves; {} is a surface", name));
      if (dimension_of(model) != 2)
        return fail(fmt::format("gcode cuts plane curves; {} lives in R^{}", name, dimension_of(model)));
      auto contour = contour_of(curve_view(model), toolpath.tolerance, *decimals, motion);
      if (!contour) return fail(with_context(contour.error(), name));
      toolpath.contours.push_back(std::move(*contour));
    }
  }
  auto program = write_gcode(toolpath, *program_settings);
  if (!program) return fail(program.error());
  if (int status = write_output(options.output, program->text); status != 0) return status;
  const char* unit = options.units == "mm" ? "mm" : "inch";
  std::string summary = fmt::format(
      "gcode: {} contour{}, {} arc{} (G2/G3) and {} line{} (G1) in {} pass{}, within {} {} of the curves", program->contours,
      program->contours == 1 ? "" : "s", program->arcs, program->arcs == 1 ? "" : "s", program->lines,
      program->lines == 1 ? "" : "s", program->passes, program->passes == 1 ? "" : "es", *tolerance, unit);
  if (program->arcs_as_lines > 0)
    summary += fmt::format(" ({} line{} in place of arcs too small or flat once rounded)", program->arcs_as_lines,
                           program->arcs_as_lines == 1 ? "" : "s");
  return write_summary(options.output, summary);
}

}  // namespace

void add_gcode_command(CLI::App& app, int& status) {
  auto options = std::make_shared<GcodeCommandOptions>();
  CLI::App* gcode = app.add_subcommand(
      "gcode",
      "A toolpath for the plane curves of the inputs as a G-code program (RS-274/NGC, for GRBL or LinuxCNC): "
      "each curve fitted by circular arcs and lines (G2/G3 in the IJK form, G1) within --tolerance, or by lines "
      "only with --lines; contours ordered to shorten the rapid moves (G0 at --safe-z), each cut down to --depth "
      "in passes of at most --step-down. Coordinates are taken as they are, in --units (mm: G21, in: G20); an SVG "
      "drawing in its user units, upright (y up from its page's bottom edge). Surfaces and curves in space are "
      "refused. Numbers have --decimals digits (4 in mm, 5 in inches by default); each arc's start and end radii "
      "agree within 1e-4 after rounding (docs/formats.md, G-code).");
  CLI::Option* inputs =
      gcode->add_option("INPUT", options->inputs, kModelFileHelp)->required();
  gcode->add_option("--tolerance", options->tolerance,
                    "Largest distance E > 0 of the path from the curves (plus the rounding to --decimals)")
      ->type_name("E")
      ->required();
  CLI::Option* arcs = gcode->add_flag("--arcs", options->arcs, "Arcs and lines (G2/G3, G1): the default");
  gcode->add_flag("--lines", options->lines, "Lines only (G1), for controllers without arcs")->excludes(arcs);
  options->depth_option = gcode->add_option("--depth", options->depth,
                                            "Depth D > 0 of the cut below the work surface Z = 0 (default 1 mm, "
                                            "0.04 in): the last pass at Z = -D")
                              ->type_name("D");
  options->step_down_option =
      gcode->add_option("--step-down", options->step_down,
                        "Largest step down S > 0 of one pass (default: the whole depth in one pass); the depth is "
                        "cut in equal passes")
          ->type_name("S");
  options->safe_z_option =
      gcode->add_option("--safe-z", options->safe_z, "Height Z > 0 of every rapid move (default 5 mm, 0.2 in)")
          ->type_name("Z");
  options->feed_option =
      gcode->add_option("--feed", options->feed, "Cutting feed F > 0 per minute (default 600 mm, 24 in)")
          ->type_name("F");
  options->plunge_feed_option =
      gcode->add_option("--plunge-feed", options->plunge_feed, "Feed of the moves down (default 200 mm, 8 in)")
          ->type_name("F");
  add_reading_options(gcode);
  gcode->add_option("--units", options->units, "Units of the program and of the coordinates: mm (G21, the "
                                               "default) or in (G20)")
      ->type_name("mm|in");
  gcode->add_option("--origin", options->origin,
                    "Where the drawing goes: at its own coordinates (drawing, the default), or moved so that the "
                    "lower-left corner or the centre of its box is at the machine's zero")
      ->type_name("drawing|lower-left|centre");
  gcode->add_option("--dialect", options->dialect,
                    "grbl (the default: nothing GRBL refuses) or linuxcnc (adds G91.1 and G64 P)")
      ->type_name("grbl|linuxcnc");
  options->decimals_option =
      gcode->add_option("--decimals", options->decimals, "Digits after the point, 4 to 8 (default 4 in mm, 5 in inches)")
          ->type_name("N");
  CLI::Option* output = gcode->add_option("-o,--output", options->output, kOutputHelp)->type_name("OUT.nc");
  set_action(gcode, status, {{inputs}, output}, [options] { return run_gcode(*options); });
}

}  // namespace casteljau::cli

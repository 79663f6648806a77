// casteljau plot: figures of curves and point sets (docs/cli.md, "plot").
// Translates files and options into render::plot_figure and writes the
// figure atomically; on bad input nothing is written.
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/gcode.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/surface_plots.hpp"
#include "casteljau/render/toolpath_plot.hpp"
#include "casteljau/render/write.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace casteljau::cli {
namespace {

struct PlotCommandOptions {
  std::string units;
  std::vector<std::string> inputs;
  std::string output;
  std::string construction;
  bool control_polygon = false;
  bool points = false;
  bool comb = false;
  bool basis = false;
  bool tangents = false;
  bool points_only = false;
  bool data_points = false;
  bool data_polyline = false;
  std::string view;
  int iso_curves = 11;
  std::string source;  ///< with a G-code program: the curves it was made from
};

/// Whether the file is a G-code program, by its extension.
bool is_program(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  return extension == ".nc" || extension == ".ngc" || extension == ".gcode" || extension == ".tap";
}

/// How a CSV point set is drawn: as the control polygon of one Bézier curve
/// (as for eval, the default), or as data: its points, the polyline through
/// them, or both.
struct CsvStyle {
  bool data_points = false;
  bool data_polyline = false;
  bool as_data() const { return data_points || data_polyline; }
};

/// A file as a plot source: .csv a point set, drawn as `csv` says; any other
/// file as every command reads it (read_model_file: model JSON, an SVG or DXF
/// drawing, by extension or content), a drawing in `units`, upright, its
/// curves one legend entry.
Expected<render::PlotSource> read_source(const std::string& path, const CsvStyle& csv, const std::string& units) {
  const std::string extension = lowercase_extension(path);
  render::PlotSource source;
  source.name = std::filesystem::path(path).filename().string();
  if (extension != ".csv") {
    auto file = read_model_file_with_unit(path, units);
    if (!file) return file.error();
    source.models = std::move(file->models);
    source.drawing = file->is_drawing();
    return source;
  }
  {
    auto points = read_points_csv(path);
    if (!points) return points.error();
    if (csv.as_data()) {
      source.points = std::move(*points);
      source.markers = csv.data_points;
      source.polyline = csv.data_polyline;
      return source;
    }
    auto curve = BezierCurve::make(std::move(*points));
    if (!curve) return with_context(curve.error(), "'" + path + "'");
    source.models.push_back(std::move(*curve));
    return source;
  }
}

/// Writes the figure, with a progress line while its curves are flattened
/// (erased before any message).
int write_plot(const render::Figure& figure, const std::string& path, render::FigureFormat format) {
  TerminalProgress progress("plot");
  return write_figure_output(path, figure, format, progress.callback());
}

/// The preview of a G-code program (render/toolpath_plot.hpp), over --source.
int run_program_plot(const PlotCommandOptions& options, render::FigureFormat format) {
  if (options.inputs.size() != 1)
    return fail("a G-code program is plotted alone (the curves it was made from: --source MODEL)");
  for (const auto& [given, name] :
       {std::pair{!options.construction.empty(), "--construction"}, std::pair{options.control_polygon, "--control-polygon"},
        std::pair{options.points, "--points"}, std::pair{options.comb, "--comb"}, std::pair{options.basis, "--basis"},
        std::pair{options.tangents, "--tangents"}, std::pair{!options.view.empty(), "--view"}}) {
    if (given) return fail(fmt::format("{} applies to curves and surfaces, not to a G-code program", name));
  }
  const std::string& path = options.inputs.front();
  auto text = read_text_file(path);
  if (!text) return fail(text.error());
  auto program = read_gcode(*text);
  if (!program) return fail(with_context(program.error(), display_name(path)));
  std::vector<Model> source;
  if (!options.source.empty()) {
    auto models = read_model_file(options.source, options.units);
    if (!models) return fail(models.error());
    source = std::move(*models);
  }
  auto figure = render::toolpath_figure(*program, std::filesystem::path(path).filename().string(), source,
                                        std::filesystem::path(options.source).filename().string());
  if (!figure) return fail(figure.error());
  return write_plot(*figure, options.output, format);
}

int run_plot(const PlotCommandOptions& options) {
  render::PlotOptions plot;
  plot.bezier.control_polygon = options.control_polygon;
  plot.bezier.control_points = options.points;
  plot.bezier.curvature_comb = options.comb;
  plot.bezier.end_tangents = options.tangents;
  plot.basis = options.basis;
  if (!options.construction.empty()) {
    auto t = number_option("--construction", options.construction);
    if (!t) return fail(t.error());
    plot.bezier.construction = *t;
  }
  // Refuse a bad output name before reading anything.
  const auto format = figure_output_format(options.output);
  if (!format) return fail(format.error());
  if (!options.inputs.empty() && is_program(options.inputs.front())) return run_program_plot(options, *format);
  if (!options.source.empty()) return fail("--source goes with a G-code program (.nc, .ngc, .gcode, .tap)");
  // --points-only is the older name of --data-points.
  const CsvStyle csv{options.data_points || options.points_only, options.data_polyline};
  std::vector<render::PlotSource> sources;
  for (const auto& path : options.inputs) {
    auto source = read_source(path, csv, options.units);
    if (!source) return fail(source.error());
    sources.push_back(std::move(*source));
  }
  // Surfaces: their own figure (iso-curves, control nets; PNG and PDF add a
  // shaded image). Curve-only options do not apply to them.
  bool any_surface = false;
  for (const auto& source : sources)
    for (const auto& model : source.models) any_surface = any_surface || is_surface(model);
  if (!options.view.empty() && !any_surface) return fail("--view applies to surfaces, the inputs hold none");
  if (any_surface) {
    for (const auto& [given, name] : {std::pair{!options.construction.empty(), "--construction"},
                                      std::pair{options.comb, "--comb"}, std::pair{options.basis, "--basis"},
                                      std::pair{options.tangents, "--tangents"}}) {
      if (given) return fail(fmt::format("{} applies to curves, not to surfaces", name));
    }
    render::SurfacePlotOptions surface;
    surface.control_net = options.control_polygon;
    surface.control_points = options.points;
    if (options.iso_curves < 2 || options.iso_curves > 1000)
      return fail(fmt::format("--iso-curves: {} is not in [2, 1000]", options.iso_curves));
    surface.iso_curves = options.iso_curves;
    if (!options.view.empty()) {
      auto view = pair_option("--view", options.view, "a pair azimuth,elevation in degrees");
      if (!view) return fail(view.error());
      const auto [azimuth, elevation] = *view;
      if (!(std::abs(elevation) <= 90.0)) {
        return fail(fmt::format("--view: elevation {} is not in [-90, 90]", elevation));
      }
      surface.view = render::ViewAngles{azimuth, elevation};
    }
    auto figure = render::surface_plot_figure(sources, surface,
                                              *format != render::FigureFormat::svg ? render::Shading::shaded : render::Shading::none);
    if (!figure) return fail(figure.error());
    return write_plot(*figure, options.output, *format);
  }
  auto figure = render::plot_figure(sources, plot);
  if (!figure) return fail(figure.error());
  return write_plot(*figure, options.output, *format);
}

}  // namespace

void add_plot_command(CLI::App& app, int& status) {
  auto options = std::make_shared<PlotCommandOptions>();
  CLI::App* plot = app.add_subcommand(
      "plot",
      "Draws curves and point sets into an SVG, PNG or PDF figure (chosen by the extension of -o). Every curve is "
      "drawn as a polyline within a quarter pixel of it (casteljau's own flattening). A CSV point set is the control "
      "polygon of one Bézier curve (as for eval) unless --data-points or --data-polyline draw it as data beside the "
      "curves (diamonds; control points are red discs); 3D curves are projected on the x, y plane. "
      "Surfaces (drawn apart from curves) are seen in an orthographic view (--view; surfaces in R^2 in their "
      "plane): their iso-curves, with --control-polygon their control nets, with --points their control points; "
      "PNG and PDF add a panel with the surfaces tessellated and shaded (Lambert, painter's algorithm).");
  CLI::Option* inputs = plot->add_option("INPUT", options->inputs,
                                         "Model JSON (.json), CSV point set (.csv) or SVG drawing (.svg); several are "
                                         "drawn together. Or one G-code program (.nc, .ngc, .gcode, .tap): its "
                                         "preview, rapid moves dashed, lines and arcs in two colours, plunges marked")
                            ->required();
  add_units_option(plot, options->units);
  CLI::Option* output =
      plot->add_option("-o,--output", options->output, kFigureOutputHelp)->type_name("FILE")->required();
  plot->add_flag("--control-polygon", options->control_polygon, "Draw each control polygon (dashed gray)");
  plot->add_flag("--points", options->points, "Draw the control points (red discs)");
  plot->add_option("--construction", options->construction,
                   "Draw the de Casteljau construction at parameter T (global parameter of a piecewise curve)")
      ->type_name("T");
  plot->add_flag("--comb", options->comb, "Draw the curvature comb (teeth along the normal, length ~ curvature)");
  plot->add_flag("--basis", options->basis, "Add a panel with the basis of the first curve: Bernstein of its degree, or the B-spline basis of its knots for a bspline model");
  plot->add_flag("--tangents", options->tangents, "Draw the end tangents along the first and last legs (blue)");
  plot->add_flag("--data-points", options->data_points,
                 "Draw CSV point sets as data points (diamonds, named in the legend beside curves), not as the control "
                 "polygon of a curve; works beside model JSON");
  plot->add_flag("--data-polyline", options->data_polyline,
                 "Draw CSV point sets as the polyline through their points (with --data-points, and the points)");
  plot->add_flag("--points-only", options->points_only, "The older name of --data-points");
  plot->add_option("--view", options->view,
                   "Surfaces: the direction they are seen from, azimuth,elevation in degrees (matplotlib's view_init; "
                   "default -60,30), an orthographic projection")
      ->type_name("AZ,EL");
  plot->add_option("--iso-curves", options->iso_curves,
                   "Surfaces: iso-curves per direction, evenly spaced over the domain, ends included (default 11)")
      ->type_name("N");
  CLI::Option* source =
      plot->add_option("--source", options->source,
                       "With a G-code program (.nc, .ngc, .gcode, .tap): the curves it was made from, drawn beneath "
                       "its moves")
          ->type_name("MODEL");
  set_action(plot, status, {{inputs, source}, output}, [options] { return run_plot(*options); });
}

}  // namespace casteljau::cli

// casteljau arcs: each plane curve of a model file as a chain of circular
// arcs and line segments within --tolerance (ops/arc_spline.hpp's fit_arcs,
// certified: docs/cnc.md), written as JSON (the segments' ends and bulges)
// or as a DXF drawing of LWPOLYLINE entities with bulges, which CAD and CAM
// programs read (docs/cli.md, "arcs"). Built in memory, written once every
// curve is fitted: on bad input nothing is written.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/io/dxf.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/ops/arc_spline.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct ArcsOptions {
  std::string model;
  std::string tolerance;
  std::string to;
  std::string output;
  std::string units;
};

/// The JSON document of the splines (docs/formats.md, "Arc splines"): one
/// spline a line, numbers in shortest round-trip form.
std::string arcs_json(const std::vector<ArcSpline>& splines, double tolerance) {
  std::string out = fmt::format("{{\"tolerance\": {}, \"splines\": [\n", tolerance);
  for (std::size_t i = 0; i < splines.size(); ++i) {
    const ArcSpline& spline = splines[i];
    out += fmt::format("{{\"curve\": {}, \"closed\": {}, \"deviation_bound\": {}, \"segments\": [", i,
                       spline.segments.front().start == spline.segments.back().end ? "true" : "false",
                       spline.deviation_bound);
    for (std::size_t k = 0; k < spline.segments.size(); ++k) {
      const ArcSegment& s = spline.segments[k];
      out += fmt::format("{}[{}, {}, {}, {}, {}]", k == 0 ? "" : ", ", s.start[0], s.start[1], s.end[0], s.end[1],
                         s.bulge == 0.0 ? 0.0 : s.bulge);
    }
    out += "], \"parameters\": [";
    for (std::size_t k = 0; k < spline.parameters.size(); ++k)
      out += fmt::format("{}{}", k == 0 ? "" : ", ", spline.parameters[k]);
    out += i + 1 < splines.size() ? "]},\n" : "]}\n";
  }
  return out + "]}\n";
}

int run_arcs(const ArcsOptions& options) {
  auto tolerance = number_option("--tolerance", options.tolerance);
  if (!tolerance) return fail(tolerance.error());
  if (!(*tolerance > 0.0)) return fail(fmt::format("--tolerance: {} is not a distance > 0", options.tolerance));
  std::string to = options.to;
  if (to.empty()) to = lowercase_extension(options.output) == ".dxf" ? "dxf" : "json";
  if (to != "json" && to != "dxf") return fail(fmt::format("--to: '{}' is not json or dxf", to.substr(0, 60)));

  const auto read = read_model_file_with_unit(options.model, options.units);
  if (!read) return fail(read.error());
  std::vector<ArcSpline> splines;
  std::size_t arcs = 0, lines = 0;
  double bound = 0.0;
  for (std::size_t m = 0; m < read->models.size(); ++m) {
    const Model& model = read->models[m];
    const std::string name = model_name(read->models, m, options.model);
    if (is_surface(model)) return fail(fmt::format("arcs fits plane curves; {} is a surface", name));
    if (dimension_of(model) != 2)
      return fail(fmt::format("arcs fits plane curves; {} lives in R^{}", name, dimension_of(model)));
    auto spline = fit_arcs(curve_view(model), Tolerance{*tolerance});
    if (!spline) return fail(with_context(spline.error(), name));
    for (const ArcSegment& s : spline->segments) ++(s.bulge == 0.0 ? lines : arcs);
    bound = std::max(bound, spline->deviation_bound);
    splines.push_back(std::move(*spline));
  }
  if (splines.empty()) return fail(fmt::format("{} holds no curve to fit", display_name(options.model)));
  std::string text;
  if (to == "dxf") {
    // $INSUNITS: the unit the input states (millimetres for a drawing read in mm, a DXF's own), else none.
    auto written = write_dxf_arc_polylines(splines, read->insunits);
    if (!written) return fail(with_context(written.error(), "--to dxf"));
    text = std::move(*written);
  } else {
    text = arcs_json(splines, *tolerance);
  }
  if (int status = write_output(options.output, text); status != 0) return status;
  return write_summary(options.output,
                       fmt::format("arcs: {} curve{}, {} arc{} and {} line segment{}, within {:.4g} of the curves "
                                   "(certified; tolerance {})",
                                   splines.size(), splines.size() == 1 ? "" : "s", arcs, arcs == 1 ? "" : "s", lines,
                                   lines == 1 ? "" : "s", bound, *tolerance));
}

}  // namespace

void add_arcs_command(CLI::App& app, int& status) {
  auto options = std::make_shared<ArcsOptions>();
  CLI::App* arcs = app.add_subcommand(
      "arcs",
      "Each plane curve of MODEL as a chain of circular arcs and line segments within --tolerance, tangent "
      "where the curve is smooth (certified biarcs: every point of every arc within the tolerance of the curve "
      "and back; docs/cnc.md), as JSON (each segment's start, end and bulge) or as a DXF drawing of LWPOLYLINE "
      "entities with bulges, for CAD and CAM programs. Surfaces and curves in space are refused.");
  CLI::Option* model = arcs->add_option("MODEL", options->model, kModelFileHelp)->required();
  add_units_option(arcs, options->units);
  arcs->add_option("--tolerance", options->tolerance, "Largest distance E > 0 between the arcs and the curve")
      ->type_name("E")
      ->required();
  arcs->add_option("--to", options->to, "json (the default) or dxf (LWPOLYLINE with bulges); -o FILE.dxf implies dxf")
      ->type_name("FORMAT");
  CLI::Option* output = arcs->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(arcs, status, {{model}, output}, [options] { return run_arcs(*options); });
}

}  // namespace casteljau::cli

// casteljau convert: a model file rewritten in another representation
// (docs/cli.md, "convert"): the curve kinds of model JSON, and SVG drawings
// (io/svg_writer.hpp), DXF drawings (io/dxf.hpp), IGES and STEP files for
// CAD (io/cad_exchange.hpp); meshes are tessellate's, G-code gcode's. The output is built in memory and
// written atomically: on bad input nothing is written.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/cad_exchange.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/dxf.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/io/svg_drawing.hpp"
#include "casteljau/io/svg_writer.hpp"
#include "casteljau/io/tolerance.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct ConvertOptions {
  std::string model;
  std::string format;
  std::string output;
  std::string units;
  std::string tolerance;
  const CLI::Option* tolerance_option = nullptr;
};

/// std::visit with one lambda per alternative.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

/// The model as a piecewise Bézier curve: a B-spline's Bézier pieces (The
/// NURBS Book A5.6; piece i then covers [i, i+1], the shape is kept), a
/// Bézier curve as its single piece, a piecewise curve unchanged.
Model to_bezier_pieces_model(const Model& model) {
  return std::visit(
      Overloaded{[](const BezierCurve& c) -> Model { return PiecewiseBezierCurve::make({c}).value(); },
                 [](const PiecewiseBezierCurve& c) -> Model { return c; },
                 [](const BSplineCurve& c) -> Model { return to_piecewise_bezier(to_bezier_pieces(c)); },
                 // Surfaces are refused by run_convert before this point.
                 [](const auto& surface) -> Model { return surface; }},
      model);
}

/// The drawing's size: the diagonal of the box of every control point.
double drawing_size(const std::vector<SvgCurve>& curves) {
  double lower[2] = {0, 0}, upper[2] = {0, 0};
  bool first = true;
  for (const SvgCurve& curve : curves)
    for (const BezierCurve& piece : curve.curve.pieces())
      for (const auto p : piece.control_points())
        for (int k = 0; k < 2; ++k) {
          lower[k] = first ? p[k] : std::min(lower[k], p[k]);
          upper[k] = first ? p[k] : std::max(upper[k], p[k]);
          if (k == 1) first = false;
        }
  return std::hypot(upper[0] - lower[0], upper[1] - lower[1]);
}

/// --to svg: the curves of MODEL as an SVG drawing. A drawing read from an
/// SVG file keeps its elements' ids, fill rules and stroke widths; curves
/// from model JSON or CSV get a stroke of 1/500 of the drawing's size.
int convert_to_svg(const ConvertOptions& options) {
  std::optional<double> tolerance;
  if (given(options.tolerance_option)) {
    auto number = number_option("--tolerance", options.tolerance);
    if (!number) return fail(number.error());
    if (!(*number > 0.0)) return fail(fmt::format("--tolerance: {} is not a distance > 0", options.tolerance));
    tolerance = *number;
  }
  std::vector<SvgCurve> curves;
  // An SVG drawing keeps its elements, ids, stroke widths and fill rules;
  // with a selection (--model, --id, --layer) it is read as every model file.
  const bool from_svg = lowercase_extension(options.model) == ".svg" && !models_selected();
  if (from_svg) {
    const auto units = drawing_units_option(options.units);
    if (!units) return fail(units.error());
    auto drawing = read_svg_drawing(options.model, *units);
    if (!drawing) return fail(drawing.error());
    // A drawing with problems or nothing to read is refused as every other
    // command refuses it (issue 39: an empty 1e-300-sized drawing was written).
    if (!drawing->problems.empty() || drawing->curves.empty()) {
      auto refused = read_model_file(options.model, options.units);
      return fail(refused ? Error{"the drawing has nothing to read"} : refused.error());
    }
    if (Status ok = skipped_elements(options.model, drawing->skipped); !ok) return fail(ok.error());
    curves = std::move(drawing->curves);
  } else {
    const auto models = read_model_file(options.model, options.units);
    if (!models) return fail(models.error());
    for (std::size_t m = 0; m < models->size(); ++m) {
      const Model& model = (*models)[m];
      const std::string name = model_name(*models, m, options.model);
      if (is_surface(model))
        return fail(fmt::format("--to svg: {} is a surface; surfaces go to iges and step", name));
      if (dimension_of(model) != 2)
        return fail(fmt::format("--to svg: {} lives in R^{}, SVG drawings are plane", name, dimension_of(model)));
      SvgCurve curve{std::get<PiecewiseBezierCurve>(to_bezier_pieces_model(model)), false, "", "", 0,
                     FillRule::nonzero, 1.0};
      const auto& pieces = curve.curve.pieces();
      const auto start = pieces.front().control_points()[0];
      const auto& last = pieces.back().control_points();
      const auto end = last[last.size() - 1];
      curve.closed = std::equal(start.begin(), start.end(), end.begin());
      curves.push_back(std::move(curve));
    }
  }
  const double size = drawing_size(curves);
  if (!from_svg)
    for (SvgCurve& curve : curves) curve.stroke_width = size > 0.0 ? size / 500.0 : 1.0;
  const double distance = tolerance.value_or(tolerances::kDefaultSvgCubicRelativeTolerance * (size > 0.0 ? size : 1.0));
  auto written = write_svg_drawing(curves, Tolerance{distance});
  if (!written) return fail(with_context(written.error(), "--to svg"));
  if (int status = write_output(options.output, written->text); status != 0) return status;
  std::string summary = fmt::format("convert: {} curve{} to SVG", curves.size(), curves.size() == 1 ? "" : "s");
  if (written->approximated_pieces > 0)
    summary += fmt::format(", {} rational or higher-degree piece{} replaced by {} cubics within {:.3g} "
                           "(--tolerance {:.3g})",
                           written->approximated_pieces, written->approximated_pieces == 1 ? "" : "s",
                           written->cubics, written->deviation_bound, distance);
  else
    summary += ", every piece exact";
  return write_summary(options.output, summary);
}

/// --to dxf: each curve an exact SPLINE entity of an R2000 drawing.
int convert_to_dxf(const ConvertOptions& options) {
  if (given(options.tolerance_option)) return fail("--tolerance applies to --to svg (the cubics' distance)");
  const auto read = read_model_file_with_unit(options.model, options.units);
  if (!read) return fail(read.error());
  const std::vector<Model>* models = &read->models;
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Model& model = (*models)[m];
    const std::string name = model_name(*models, m, options.model);
    if (is_surface(model)) return fail(fmt::format("--to dxf: {} is a surface; surfaces go to iges and step", name));
    if (dimension_of(model) != 2 && dimension_of(model) != 3)
      return fail(fmt::format("--to dxf: {} lives in R^{}, DXF holds plane and space curves", name,
                              dimension_of(model)));
  }
  // $INSUNITS: the unit the input states (millimetres when a drawing was
  // read in mm, a DXF's own unit), else unitless.
  auto written = write_dxf_drawing(*models, read->insunits);
  if (!written) return fail(with_context(written.error(), "--to dxf"));
  return write_output(options.output, *written);
}

/// When the file is written, UTC, as ExchangeHeader wants it: now, or
/// SOURCE_DATE_EPOCH when set (reproducible builds' convention: the same
/// input then gives the same bytes).
std::string exchange_timestamp() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr && *epoch != '\0') {
    char* end = nullptr;
    const long long seconds = std::strtoll(epoch, &end, 10);
    if (*end == '\0' && seconds >= 0) now = static_cast<std::time_t>(seconds);
  }
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  return text;
}

/// --to iges, --to step: each model an exact B-spline curve or surface of a
/// file for CAD, its numbers labelled millimetres.
int convert_to_cad(const ConvertOptions& options, bool iges) {
  const char* format = iges ? "iges" : "step";
  if (given(options.tolerance_option))
    return fail(fmt::format("--tolerance applies to --to svg (the cubics' distance); --to {} is exact", format));
  auto read = read_model_file_with_unit(options.model, options.units);
  if (!read) return fail(read.error());
  // The unit: millimetres or inches as the input states them; another length
  // unit (a DXF in feet, metres...) converted to millimetres; none stated:
  // the numbers labelled millimetres, which the summary says.
  ExchangeHeader header;
  std::string unit_text = "in millimetres";
  double scale = 1.0;
  if (read->insunits == 1) {
    header.unit = ExchangeUnit::inch;
    unit_text = "in inches";
  } else if (read->insunits != 4 && dxf_unit_millimetres(read->insunits) > 0.0) {
    const std::string from = dxf_unit_name(read->insunits);
    scale = dxf_unit_millimetres(read->insunits);
    read = read_model_file_with_unit(options.model, "mm");
    if (!read) return fail(read.error());
    unit_text = fmt::format("converted from {} to millimetres", from);
  } else if (read->insunits != 4) {
    unit_text = read->insunits == 0 ? "labelled millimetres (the input states no unit)"
                                    : fmt::format("labelled millimetres (the input's unit, {}, is no length casteljau "
                                                  "converts)",
                                                  dxf_unit_name(read->insunits));
  }
  const std::vector<Model>* models = &read->models;
  std::size_t surfaces = 0;
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Model& model = (*models)[m];
    const int d = dimension_of(model);
    if (d != 2 && d != 3)
      return fail(fmt::format("--to {}: {} lives in R^{}, {} holds plane and space geometry", format,
                              model_name(*models, m, options.model), d, iges ? "IGES" : "STEP"));
    if (is_surface(model)) ++surfaces;
  }
  const std::filesystem::path named = is_standard_output(options.output) ? options.model : options.output;
  header.file_name = named.filename().string();
  header.timestamp = exchange_timestamp();
  auto written = iges ? write_iges(*models, header) : write_step(*models, header);
  if (!written) return fail(with_context(written.error(), fmt::format("--to {}", format)));
  if (int status = write_output(options.output, *written); status != 0) return status;
  const std::size_t curves = models->size() - surfaces;
  return write_summary(options.output,
                       fmt::format("convert: {} curve{} and {} surface{} to {}, exact ({}), {}",
                                   curves, curves == 1 ? "" : "s", surfaces, surfaces == 1 ? "" : "s",
                                   iges ? "IGES 5.3 (entities 126 and 128)" : "STEP AP214",
                                   scale == 1.0 ? std::string("every knot, control point and weight as it is")
                                                : fmt::format("knots and weights as they are, control points x {:g}",
                                                              scale),
                                   unit_text));
}

int run_convert(const ConvertOptions& options) {
  // --- the target format first: a typo should not wait for a large file ---
  const std::string& format = options.format;
  const bool to_pieces = format == "bezier-pieces", to_spline = format == "bspline", as_json = format == "json";
  if (format == "svg") return convert_to_svg(options);
  if (format == "dxf") return convert_to_dxf(options);
  if (format == "iges" || format == "step") return convert_to_cad(options, format == "iges");
  if (!to_pieces && !to_spline && !as_json) {
    for (const auto& [other, command] : {std::pair{"gcode", "casteljau gcode"}, std::pair{"obj", "casteljau tessellate"},
                                         std::pair{"stl", "casteljau tessellate"}, std::pair{"ply", "casteljau tessellate"}}) {
      if (format == other)
        return fail(fmt::format("--to {}: not a conversion of curves; {} writes it", format, command));
    }
    return fail(fmt::format("--to '{}': unknown format (supported: bezier-pieces, bspline, json, svg, dxf, iges, step)",
                            format.substr(0, 60)));
  }
  if (given(options.tolerance_option)) return fail("--tolerance applies to --to svg (the cubics' distance)");

  const auto models = read_model_file(options.model, options.units);
  if (!models) return fail(models.error());
  std::vector<Model> converted;
  converted.reserve(models->size());
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Model& model = (*models)[m];
    if (to_pieces && is_surface(model)) {
      return fail(fmt::format("--to bezier-pieces: {} is a surface; surfaces convert only to bspline or json",
                              model_name(*models, m, options.model)));
    }
    if (to_pieces) {
      converted.push_back(to_bezier_pieces_model(model));
    } else if (to_spline) {
      auto spline = to_bspline(model);
      if (!spline) return fail(fmt::format("--to bspline: {}: {}", model_name(*models, m, options.model),
                                           spline.error().message));
      converted.push_back(std::move(*spline));
    } else {
      converted.push_back(model);
    }
  }
  const std::string text = models_to_json(converted);
  return write_output(options.output, text);
}

}  // namespace

void add_convert_command(CLI::App& app, int& status) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* convert = app.add_subcommand(
      "convert",
      "Rewrite the curves of MODEL in another representation: as model JSON, bezier-pieces (a piecewise_bezier "
      "model: a B-spline's Bézier pieces, each then on [i, i+1]), bspline (a bspline model: a Bézier curve on "
      "clamped knots, a piecewise curve with its joints as knots of multiplicity p), json (the models as read); or "
      "svg, an SVG drawing of plane curves: lines, quadratics and cubics exactly, other pieces (rational, degree > "
      "3) as cubics within --tolerance, which the summary line and the file state; an SVG input keeps its ids, "
      "fill rules and stroke widths; or dxf, a DXF R2000 drawing with each curve an exact SPLINE entity; or iges "
      "(IGES 5.3, entities 126 and 128) or step (STEP AP214), files for CAD with each curve and surface an exact "
      "B-spline, numbers in millimetres.");
  CLI::Option* model = convert->add_option("MODEL", options->model, kModelFileHelp)->required();
  convert->add_option("--to", options->format, "The target: bezier-pieces, bspline, json, svg, dxf, iges or step")
      ->type_name("FORMAT")
      ->required();
  options->tolerance_option =
      convert
          ->add_option("--tolerance", options->tolerance,
                       "--to svg: the largest distance of the cubics from pieces SVG cannot hold (default 1e-6 of "
                       "the drawing's size, the diagonal of its control points' box)")
          ->type_name("E");
  add_units_option(convert, options->units);
  CLI::Option* output = convert->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(convert, status, {{model}, output}, [options] { return run_convert(*options); });
}

}  // namespace casteljau::cli

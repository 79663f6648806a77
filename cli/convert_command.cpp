// casteljau convert: a model file rewritten in another representation
// (docs/cli.md, "convert"). This version converts between the curve kinds of
// model JSON; the exchange formats of the interface (svg, dxf, iges, gcode,
// meshes) are refused as not supported yet. The output is built in memory and
// written atomically: on bad input nothing is written.
#include <fmt/format.h>

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct ConvertOptions {
  std::string model;
  std::string format;
  std::string output;
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

int run_convert(const ConvertOptions& options) {
  // --- the target format first: a typo should not wait for a large file ---
  const std::string& format = options.format;
  const bool to_pieces = format == "bezier-pieces", to_spline = format == "bspline", as_json = format == "json";
  if (!to_pieces && !to_spline && !as_json) {
    for (const char* later : {"svg", "dxf", "iges", "gcode", "obj", "stl", "ply"}) {
      if (format == later) {
        return fail(fmt::format("--to {}: this format is not supported yet by this version of casteljau "
                                "(supported: bezier-pieces, bspline, json)",
                                format));
      }
    }
    return fail(fmt::format("--to '{}': unknown format (supported: bezier-pieces, bspline, json)",
                            format.substr(0, 60)));
  }

  const auto models = read_models(options.model);
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
      "Rewrite the curves of MODEL in another representation, as model JSON: bezier-pieces (a piecewise_bezier "
      "model: a B-spline's Bézier pieces, each then on [i, i+1]), bspline (a bspline model: a Bézier curve on "
      "clamped knots, a piecewise curve with its joints as knots of multiplicity p), json (the models as read). "
      "svg, dxf, iges, gcode and meshes are not supported yet.");
  CLI::Option* model = convert
                           ->add_option("MODEL", options->model,
                                        "Model JSON, or a CSV point set taken as the control polygon of one "
                                        "Bézier curve")
                           ->required();
  convert->add_option("--to", options->format, "The target: bezier-pieces, bspline or json")
      ->type_name("FORMAT")
      ->required();
  CLI::Option* output = convert->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(convert, status, {{model}, output}, [options] { return run_convert(*options); });
}

}  // namespace casteljau::cli

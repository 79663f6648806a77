// casteljau length: the arc length of each curve of a model file, over its
// domain or [--from, --to], within an absolute --tolerance (default 1e-12 of
// the curve's size), one number a line (docs/cli.md, "length"). The output is
// built in memory and written once every curve has been measured.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct LengthOptions {
  std::string model;
  std::string from;
  std::string to;
  std::string tolerance;
  std::string output;
  std::string units;
  const CLI::Option* from_option = nullptr;
  const CLI::Option* to_option = nullptr;
  const CLI::Option* tolerance_option = nullptr;
};

int run_length(const LengthOptions& options) {
  std::optional<double> from, to, tolerance;
  for (auto [option, text, value, name] :
       {std::tuple{options.from_option, &options.from, &from, "--from"}, std::tuple{options.to_option, &options.to, &to, "--to"},
        std::tuple{options.tolerance_option, &options.tolerance, &tolerance, "--tolerance"}}) {
    if (!given(option)) continue;
    auto number = number_option(name, *text);
    if (!number) return fail(number.error());
    *value = *number;
  }
  const auto models = read_model_file(options.model, options.units);
  if (!models) return fail(models.error());
  std::string out;
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Model& model = (*models)[m];
    const std::string name = model_name(*models, m, options.model);
    if (is_surface(model)) return fail(fmt::format("length measures curves; {} is a surface", name));
    const CurveView curve = curve_view(model);
    const Interval domain = curve.domain();
    const Interval range{from.value_or(domain.lower), to.value_or(domain.upper)};
    const Tolerance accuracy = tolerance ? Tolerance{*tolerance} : default_arc_length_tolerance(curve);
    auto length = arc_length(curve, range, accuracy);
    if (!length) return fail(with_context(length.error(), name));
    append_points_csv(out, std::span<const double>(&*length, 1), 1);
  }
  return write_output(options.output, out);
}

}  // namespace

void add_length_command(CLI::App& app, int& status) {
  auto options = std::make_shared<LengthOptions>();
  CLI::App* length = app.add_subcommand(
      "length",
      "The arc length of each curve in MODEL, one number a line (the shortest text that reads back to the same "
      "double): over the curve's domain, or between the parameters --from and --to, within the absolute "
      "--tolerance (default 1e-12 of the curve's size, the diagonal of its control points' box). Adaptive "
      "Gauss-Kronrod quadrature on the curve's Bezier pieces: the tolerance is met, not only estimated "
      "(docs/curves.md).");
  CLI::Option* model =
      length->add_option("MODEL", options->model, kModelFileHelp)->required();
  add_units_option(length, options->units);
  options->from_option = length->add_option("--from", options->from, "Measure from parameter T0 (default: the start of the domain)")
                             ->type_name("T0");
  options->to_option =
      length->add_option("--to", options->to, "Measure up to parameter T1 (default: the end of the domain)")->type_name("T1");
  options->tolerance_option =
      length->add_option("--tolerance", options->tolerance, "Absolute accuracy of each length (default 1e-12 x size)")
          ->type_name("E");
  CLI::Option* output = length->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(length, status, {{model}, output}, [options] { return run_length(*options); });
}

}  // namespace casteljau::cli

// casteljau intersect: the intersections of the curves of A and B (or the
// self-intersections of A alone; for A alone holding several curves, every
// intersection among them, each naming curve_a and curve_b) as JSON,
// {"intersections": [...]}, one object per intersection sorted by a
// (docs/cli.md, "intersect"; the format is ../shared/docs/interfaces.md's). Numbers are written in the shortest
// text that reads back to the same double.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/ops/intersection.hpp"
#include "casteljau/ops/intersections_among_curves.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct IntersectOptions {
  std::string units;
  std::string first;
  std::string second;
  std::string tolerance;
  std::string output;
  const CLI::Option* second_option = nullptr;
  const CLI::Option* tolerance_option = nullptr;
};

/// The one curve of a model file (errors name the file).
Expected<Model> one_curve(const std::string& path, const std::string& units) {
  auto models = read_model_file(path, units);
  if (!models) return models.error();
  if (models->size() != 1)
    return Error{fmt::format("intersect A B takes one curve per file; '{}' holds {} models (choose one with --model N, "
                             "or give A alone for every intersection among its curves)",
                             path, models->size())};
  if (is_surface(models->front()))
    return Error{fmt::format("intersect takes curves; {} is a surface", model_name(*models, 0, path))};
  return std::move(models->front());
}

std::string number(double x) { return std::isfinite(x) ? fmt::format("{}", x) : "null"; }

/// The JSON document (docs/cli.md, "intersect"); with `curves` (an
/// intersection among a drawing's curves), each entry names its two curves first.
std::string json_of(const std::vector<CurveIntersection>& found,
                    const std::vector<std::pair<std::size_t, std::size_t>>& curves = {}) {
  std::string out = "{\"intersections\": [";
  for (std::size_t i = 0; i < found.size(); ++i) {
    const CurveIntersection& x = found[i];
    out += i == 0 ? "\n  " : ",\n  ";
    out += fmt::format("{{\"kind\": \"{}\", ", kind_name(x.kind));
    if (!curves.empty()) out += fmt::format("\"curve_a\": {}, \"curve_b\": {}, ", curves[i].first, curves[i].second);
    if (x.kind == IntersectionKind::overlap) {
      out += fmt::format("\"a\": [{}, {}], \"b\": [{}, {}]}}", number(x.a.lower), number(x.a.upper), number(x.b.lower),
                         number(x.b.upper));
      continue;
    }
    out += fmt::format("\"a\": {}, \"b\": {}, \"point\": [", number(x.a.lower), number(x.b.lower));
    for (std::size_t j = 0; j < x.point.size(); ++j) out += (j == 0 ? "" : ", ") + number(x.point[j]);
    out += "]";
    if (x.kind == IntersectionKind::tangent) out += fmt::format(", \"multiplicity\": {}", x.multiplicity);
    out += "}";
  }
  out += found.empty() ? "]}\n" : "\n]}\n";
  return out;
}

int run_intersect(const IntersectOptions& options) {
  std::optional<double> tolerance;
  if (given(options.tolerance_option)) {
    auto value = number_option("--tolerance", options.tolerance);
    if (!value) return fail(value.error());
    if (!(*value > 0.0)) return fail(fmt::format("--tolerance: {} is not > 0", *value));
    tolerance = *value;
  }
  if (!given(options.second_option)) {
    // A alone: a drawing's curves among themselves, or one curve's self-intersections.
    auto models = read_model_file(options.first, options.units);
    if (!models) return fail(models.error());
    if (models->size() > 1) {
      std::vector<CurveView> curves;
      for (std::size_t m = 0; m < models->size(); ++m) {
        if (is_surface((*models)[m]))
          return fail(fmt::format("intersect takes curves; {} is a surface", model_name(*models, m, options.first)));
        curves.push_back(curve_view((*models)[m]));
      }
      auto among = intersections_among_curves(curves, tolerance ? std::optional{Tolerance{*tolerance}} : std::nullopt);
      if (!among) return fail(with_context(among.error(), display_name(options.first)));
      std::vector<CurveIntersection> found;
      std::vector<std::pair<std::size_t, std::size_t>> pairs;
      for (IntersectionAmongCurves& x : *among) {
        found.push_back(std::move(x.intersection));
        pairs.emplace_back(x.a, x.b);
      }
      return write_output(options.output, json_of(found, pairs));
    }
  }
  auto first = one_curve(options.first, options.units);
  if (!first) return fail(first.error());
  const CurveView a = curve_view(*first);
  Expected<std::vector<CurveIntersection>> found = Error{};
  if (given(options.second_option)) {
    auto second = one_curve(options.second, options.units);
    if (!second) return fail(second.error());
    const CurveView b = curve_view(*second);
    found = intersections(a, b, tolerance ? Tolerance{*tolerance} : default_intersection_tolerance(a, b));
  } else {
    found = self_intersections(a, tolerance ? Tolerance{*tolerance} : default_intersection_tolerance(a, a));
  }
  if (!found) return fail(found.error());
  return write_output(options.output, json_of(*found));
}

}  // namespace

void add_intersect_command(CLI::App& app, int& status) {
  auto options = std::make_shared<IntersectOptions>();
  CLI::App* intersect = app.add_subcommand(
      "intersect",
      "The intersections of the curves A and B (plane, or both in space), or the self-intersections of A alone, "
      "as JSON "
      "{\"intersections\": [...]} sorted by the parameter on A: each transversal, tangent (with its multiplicity) "
      "or overlap (the two parameter intervals) once, end points and knots included. A alone holding several curves "
      "(a drawing): every intersection among them and of each with itself, each entry naming curve_a and curve_b "
      "(the models' indices, as --model takes them). Curves within --tolerance (default 1e-9 of the larger curve's "
      "size) count as meeting (docs/curves.md).");
  CLI::Option* first =
      intersect
          ->add_option("A", options->first,
                       "A model file: one curve, or, alone, a drawing whose curves are intersected among themselves")
          ->required();
  add_units_option(intersect, options->units);
  options->second_option = intersect->add_option("B", options->second, "The second curve (omit for self-intersections of A)");
  options->tolerance_option =
      intersect->add_option("--tolerance", options->tolerance, "Distance within which curves meet (default 1e-9 x size)")
          ->type_name("E");
  CLI::Option* output = intersect->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(intersect, status, {{first, options->second_option}, output}, [options] { return run_intersect(*options); });
}

}  // namespace casteljau::cli

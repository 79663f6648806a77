// casteljau closest: for each query point (--point, repeated, then the rows
// of --points FILE.csv), the nearest point of the curve of MODEL, as CSV
// query,t,distance,x,y[,z]; with --all every local minimum of the distance,
// the global one first; of a surface, query,u,v,distance,x,y,z (point
// inversion); of a file of several curves (a drawing), the nearest of them
// all, query,curve,t,distance,x,y[,z] (docs/cli.md, "closest"). The output is built in
// memory and written once every query is answered.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/ops/closest_among_curves.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "casteljau/ops/point_inversion.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct ClosestOptions {
  std::string units;
  std::string model;
  std::vector<std::string> points;
  std::string points_file;
  bool all = false;
  std::string output;
  const CLI::Option* points_file_option = nullptr;
};

/// The CSV header: `leading` columns, then x, y, z (x3, x4, ... beyond).
std::string header_of(std::string leading, std::size_t dimension) {
  for (std::size_t j = 0; j < dimension; ++j) leading += j < 3 ? std::string(",") + "xyz"[j] : fmt::format(",x{}", j);
  return leading + '\n';
}

/// One answer as a CSV row: the leading columns (the query's index, the
/// curve's), parameter, distance, the point.
void append_row(std::string& out, std::vector<double> row, const NearestPoint& nearest) {
  row.insert(row.end(), {nearest.parameter, nearest.distance});
  row.insert(row.end(), nearest.point.begin(), nearest.point.end());
  append_points_csv(out, row, static_cast<int>(row.size()));
}

/// A surface: point inversion, CSV query,u,v,distance,x,y,z (--all is the
/// curves' only).
int run_surface(SurfaceView surface, const std::string& name, const std::vector<double>& queries, std::size_t dimension,
                const std::string& output) {
  if (dimension != static_cast<std::size_t>(surface.dimension()))
    return fail(fmt::format("the query points have {} coordinates, {} lives in R^{}", dimension, name, surface.dimension()));
  std::string out = header_of("query,u,v,distance", dimension);
  for (std::size_t i = 0; i * dimension < queries.size(); ++i) {
    auto nearest = closest_point(surface, std::span<const double>(queries).subspan(i * dimension, dimension));
    if (!nearest) return fail(with_context(nearest.error(), fmt::format("query {}", i)));
    std::vector<double> row{static_cast<double>(i), nearest->u, nearest->v, nearest->distance};
    row.insert(row.end(), nearest->point.begin(), nearest->point.end());
    append_points_csv(out, row, static_cast<int>(row.size()));
  }
  return write_output(output, out);
}

/// Several curves (a drawing's): for each query the nearest point of them
/// all, CSV query,curve,t,distance,x,y[,z], `curve` the model's index (as
/// --model takes it); with --all every local minimum of every curve, the
/// global one first, then by curve and parameter.
int run_curves(const std::vector<Model>& models, const ClosestOptions& options, const std::vector<double>& queries,
               std::size_t dimension) {
  std::vector<CurveView> curves;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const std::string name = model_name(models, m, options.model);
    if (is_surface(models[m])) return fail(fmt::format("closest over several models takes curves; {} is a surface", name));
    if (static_cast<std::size_t>(dimension_of(models[m])) != dimension)
      return fail(fmt::format("the query points have {} coordinates, {} lives in R^{}", dimension, name,
                              dimension_of(models[m])));
    curves.push_back(curve_view(models[m]));
  }
  std::string out = header_of("query,curve,t,distance", dimension);
  const auto row = [&](std::size_t query, std::size_t curve, const NearestPoint& nearest) {
    append_row(out, {static_cast<double>(query), static_cast<double>(curve)}, nearest);
  };
  if (!options.all) {
    auto answers = closest_among_curves(curves, queries);
    if (!answers) return fail(answers.error());
    for (std::size_t i = 0; i < answers->size(); ++i) row(i, (*answers)[i].curve, (*answers)[i].nearest);
    return write_output(options.output, out);
  }
  for (std::size_t i = 0; i * dimension < queries.size(); ++i) {
    std::vector<NearestAmongCurves> minima;
    for (std::size_t c = 0; c < curves.size(); ++c) {
      auto local = local_closest_points(curves[c], std::span<const double>(queries).subspan(i * dimension, dimension));
      if (!local) return fail(with_context(local.error(), fmt::format("query {}, {}", i, model_name(models, c, options.model))));
      for (NearestPoint& nearest : *local) minima.push_back(NearestAmongCurves{c, std::move(nearest)});
    }
    // The global minimum first (the first curve's where two are as near), then by curve and parameter.
    const auto global = std::min_element(minima.begin(), minima.end(), [](const auto& x, const auto& y) {
      return x.nearest.distance < y.nearest.distance;
    });
    if (global != minima.end()) std::rotate(minima.begin(), global, global + 1);
    std::sort(minima.begin() + (minima.empty() ? 0 : 1), minima.end(), [](const auto& x, const auto& y) {
      return std::pair{x.curve, x.nearest.parameter} < std::pair{y.curve, y.nearest.parameter};
    });
    for (const NearestAmongCurves& m : minima) row(i, m.curve, m.nearest);
  }
  return write_output(options.output, out);
}

int run_closest(const ClosestOptions& options) {
  std::vector<double> queries;
  std::size_t dimension = 0;
  const auto add = [&](std::span<const double> q, const std::string& what) -> Status {
    if (dimension == 0) dimension = q.size();
    if (q.size() != dimension)
      return Error{fmt::format("{} has {} coordinates, the first query has {}", what, q.size(), dimension)};
    queries.insert(queries.end(), q.begin(), q.end());
    return {};
  };
  for (std::size_t i = 0; i < options.points.size(); ++i) {
    auto point = vector_option("--point", options.points[i]);
    if (!point) return fail(point.error());
    if (Status status = add(*point, fmt::format("--point {}", options.points[i])); !status) return fail(status.error());
  }
  if (given(options.points_file_option)) {
    auto rows = read_points_csv(options.points_file);
    if (!rows) return fail(in_file(options.points_file, rows.error()));
    for (std::size_t i = 0; i < rows->size(); ++i)
      if (Status status = add((*rows)[i], fmt::format("point {} of '{}'", i, options.points_file)); !status)
        return fail(status.error());
  }
  if (queries.empty()) return fail("closest needs query points: --point X,Y[,Z] or --points FILE.csv");
  const auto models = read_model_file(options.model, options.units);
  if (!models) return fail(models.error());
  if (models->size() > 1) return run_curves(*models, options, queries, dimension);
  const Model& model = models->front();
  const std::string name = model_name(*models, 0, options.model);
  if (is_surface(model) && options.all)
    return fail(fmt::format("--all (every local minimum) is for curves; {} is a surface", name));
  if (is_surface(model)) return run_surface(surface_view(model), name, queries, dimension, options.output);
  const CurveView curve = curve_view(model);
  if (dimension != static_cast<std::size_t>(curve.dimension()))
    return fail(fmt::format("the query points have {} coordinates, {} lives in R^{}", dimension, name,
                            curve.dimension()));
  const std::size_t count = queries.size() / dimension;
  std::string out = header_of("query,t,distance", dimension);
  if (options.all) {
    for (std::size_t i = 0; i < count; ++i) {
      auto minima = local_closest_points(curve, std::span<const double>(queries).subspan(i * dimension, dimension));
      if (!minima) return fail(with_context(minima.error(), fmt::format("query {}", i)));
      for (const NearestPoint& nearest : *minima) append_row(out, {static_cast<double>(i)}, nearest);
    }
  } else {
    std::vector<double> parameters(count), distances(count);
    if (Status status = closest_points(curve, queries, parameters, distances); !status)
      return fail(status.error());
    for (std::size_t i = 0; i < count; ++i) {
      NearestPoint nearest{parameters[i], distances[i], point_at(curve, parameters[i])};
      append_row(out, {static_cast<double>(i)}, nearest);
    }
  }
  return write_output(options.output, out);
}

}  // namespace

void add_closest_command(CLI::App& app, int& status) {
  auto options = std::make_shared<ClosestOptions>();
  CLI::App* closest = app.add_subcommand(
      "closest",
      "For each query point, the nearest point of the curve in MODEL, as CSV query,t,distance,x,y[,z]: the global "
      "minimum of the distance over the whole domain, end points and knots included; with --all every local "
      "minimum, the global one first. On a surface, point inversion: query,u,v,distance,x,y,z. Queries: each "
      "--point, then the rows of --points, numbered from 0 (docs/curves.md). A file of several curves (a drawing): "
      "the nearest point of them all, as query,curve,t,distance,x,y[,z], curve the model's index as --model takes it.");
  CLI::Option* model =
      closest->add_option("MODEL", options->model,
                          "Model JSON with one curve or surface, a CSV point set taken as one Bézier curve, or a "
                          "drawing (SVG, DXF) or model file of several curves: the nearest of them all, its index in "
                          "the column curve")
          ->required();
  add_units_option(closest, options->units);
  closest->add_option("--point", options->points, "A query point X,Y[,Z] (repeatable)")->type_name("X,Y[,Z]");
  options->points_file_option =
      closest->add_option("--points", options->points_file, "Query points, one per CSV row")->type_name("FILE.csv");
  closest->add_flag("--all", options->all, "Every local minimum of the distance, the global one first");
  CLI::Option* output = closest->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(closest, status, {{model, options->points_file_option}, output}, [options] { return run_closest(*options); });
}

}  // namespace casteljau::cli

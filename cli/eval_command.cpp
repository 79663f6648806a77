// casteljau eval: points or K-th derivatives of the models in a file, at
// given parameters, as CSV (docs/cli.md, "eval"). The whole output is built
// in memory and written only when every check has passed: on bad input
// nothing reaches stdout or the output file.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/io/tolerance.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct EvalOptions {
  std::string units;
  std::string model;
  std::vector<std::string> at;
  std::string params;
  std::string samples;
  std::string derivative = "0";
  std::string output;
  bool arc_length = false;
};

std::string domain_text(const Interval& domain) { return fmt::format("[{}, {}]", domain.lower, domain.upper); }

/// "[0, 1] x [0, 2]": the parameter rectangle of a surface.
std::string domain_text(const SurfaceView& view) {
  return domain_text(view.domain_u()) + " x " + domain_text(view.domain_v());
}

/// The parameters and derivative order of the curves in the file.
struct CurveRequest {
  std::vector<double> at;
  NumberColumn params;
  int derivative = 0;
};

/// The parameter pairs and derivative orders of the surfaces in the file.
struct SurfaceRequest {
  std::vector<std::array<double, 2>> at;
  PointArray params;  // two columns (u, v), one row per pair
  int derivative_u = 0;
  int derivative_v = 0;
};

/// N evenly spaced parameters over [lower, upper], as numpy.linspace: the
/// product formed first so that integer domains give correctly rounded
/// quotients; the last one is exactly `upper`, and N = 1 gives `lower`.
void append_samples(std::vector<double>& us, const Interval& domain, std::size_t samples) {
  const double width = domain.upper - domain.lower;
  for (std::size_t i = 0; i < samples; ++i) {
    const bool last = samples > 1 && i + 1 == samples;
    us.push_back(samples == 1 ? domain.lower
                 : last       ? domain.upper
                              : domain.lower + width * static_cast<double>(i) / static_cast<double>(samples - 1));
  }
}

/// A surface's points or partial derivatives d^(k+l)S/du^k dv^l: first at the
/// --at pairs, then at the --params rows, then on the N x N grid of --samples
/// (u the slow index: line a*N + b is S(u_a, v_b)). Appends CSV to `out`.
void evaluate_surface(const SurfaceView& view, const SurfaceRequest& request, std::size_t samples, std::string& out) {
  const auto d = static_cast<std::size_t>(view.dimension());
  const bool points = request.derivative_u == 0 && request.derivative_v == 0;
  std::vector<double> block;
  const auto one = [&](double u, double v) {
    const Point value =
        points ? view.point_at(u, v) : view.partial_derivative_at(u, v, request.derivative_u, request.derivative_v);
    block.insert(block.end(), value.begin(), value.end());
  };
  for (const auto& [u, v] : request.at) one(u, v);
  for (std::size_t k = 0; k < request.params.size(); ++k) one(request.params[k][0], request.params[k][1]);
  append_points_csv(out, block, static_cast<int>(d));
  if (samples == 0) return;
  std::vector<double> us, vs;
  append_samples(us, view.domain_u(), samples);
  append_samples(vs, view.domain_v(), samples);
  if (points) {
    // One row of the grid (fixed u) at a time: bounded scratch memory.
    block.resize(samples * d);
    for (const double u : us) {
      view.grid_points_at(std::span<const double>(&u, 1), vs, block);
      append_points_csv(out, block, static_cast<int>(d));
    }
    return;
  }
  for (const double u : us) {
    block.clear();
    for (const double v : vs) one(u, v);
    append_points_csv(out, block, static_cast<int>(d));
  }
}

int run_eval(const EvalOptions& options) {
  constexpr std::size_t kLimit = tolerances::kMaxEvaluationParameters;

  // --- options that do not depend on the models ----------------------------
  std::size_t samples = 0;
  const bool has_samples = !options.samples.empty();
  if (has_samples) {
    auto n = whole_number("--samples", options.samples, 0, static_cast<long long>(kLimit));
    if (!n) return fail(n.error());
    if (*n == 0) return fail("--samples: 0 samples, give N >= 1 (N = 1 is the start of the domain)");
    samples = static_cast<std::size_t>(*n);
  }
  if (options.arc_length && !has_samples)
    return fail("--arc-length spaces the --samples points along the curve: give --samples N too");
  if (options.at.empty() && options.params.empty() && !has_samples) {
    return fail("nothing to evaluate: give --at T (u,v for a surface), --params FILE.csv or --samples N");
  }

  // --- inputs --------------------------------------------------------------
  const auto models = read_model_file(options.model, options.units);
  if (!models) return fail(models.error());
  bool any_curve = false, any_surface = false;
  for (const Model& model : *models) (is_surface(model) ? any_surface : any_curve) = true;
  if (options.arc_length && any_surface)
    return fail("--arc-length spaces points along curves; " + options.model + " holds a surface");

  // --- the options read as the models' kinds need them ----------------------
  // A curve takes T and K, a surface u,v and ku,kv; a file that mixes both
  // kinds can only be sampled (or differentiated with the default 0).
  const long long max_order = tolerances::kMaxDerivativeOrder;
  CurveRequest curve;
  SurfaceRequest surface;
  if (any_curve) {
    for (const auto& text : options.at) {
      auto value = parse_number(text);
      if (!value) {
        return fail(fmt::format("--at: {}{}", value.error().message,
                                text.find(',') != std::string::npos ? " (u,v is for surfaces; a curve takes one T)"
                                                                    : ""));
      }
      curve.at.push_back(*value);
    }
    auto order = whole_number("--derivative", options.derivative, 0, max_order);
    if (!order) return fail(order.error().message + (options.derivative.find(',') != std::string::npos
                                                          ? " (ku,kv is for surfaces; a curve takes one K)"
                                                          : ""));
    curve.derivative = static_cast<int>(*order);
    if (!options.params.empty()) {
      const auto text = read_text_file(options.params);
      if (!text) return fail(text.error());
      auto column = parse_numbers_csv(*text, display_name(options.params), kLimit);
      if (!column) return fail(column.error());
      curve.params = std::move(*column);
    }
  }
  if (any_surface) {
    for (const auto& text : options.at) {
      auto pair = pair_option("--at", text, "a parameter pair u,v");
      if (!pair) return fail(pair.error().message + " (a surface takes u,v)");
      surface.at.push_back(*pair);
    }
    // "0" (the default) is the point for both kinds; otherwise ku,kv.
    if (options.derivative != "0") {
      const auto comma = options.derivative.find(',');
      if (comma == std::string::npos) {
        return fail(fmt::format("--derivative {}: a surface takes two orders ku,kv (d^(ku+kv)S / du^ku dv^kv), "
                                "e.g. 1,0 for dS/du",
                                options.derivative.substr(0, 60)));
      }
      auto ku = whole_number("--derivative", trimmed(std::string_view(options.derivative).substr(0, comma)), 0, max_order);
      if (!ku) return fail(ku.error());
      auto kv = whole_number("--derivative", trimmed(std::string_view(options.derivative).substr(comma + 1)), 0, max_order);
      if (!kv) return fail(kv.error());
      if (*ku + *kv > tolerances::kMaxSurfaceDerivativeOrder) {
        return fail(fmt::format("--derivative {},{}: ku + kv = {} is more than the limit of {} for a surface", *ku, *kv,
                                *ku + *kv, tolerances::kMaxSurfaceDerivativeOrder));
      }
      surface.derivative_u = static_cast<int>(*ku);
      surface.derivative_v = static_cast<int>(*kv);
    }
    if (!options.params.empty()) {
      const auto text = read_text_file(options.params);
      if (!text) return fail(text.error());
      auto pairs = parse_points_csv(*text, display_name(options.params));
      if (!pairs) return fail(pairs.error());
      if (pairs->dimension() != 2) {
        return fail(fmt::format("{}: {} column{}, a surface's parameters are two columns u,v",
                                display_name(options.params), pairs->dimension(), pairs->dimension() == 1 ? "" : "s"));
      }
      surface.params = std::move(*pairs);
    }
  }

  // --- the amount of work ------------------------------------------------
  // Counted in double: N x N grids of many models may overflow size_t.
  const std::size_t curve_count = curve.at.size() + curve.params.values.size() + samples;
  double total = 0.0;
  for (const Model& model : *models) {
    total += is_surface(model) ? static_cast<double>(surface.at.size() + surface.params.size()) +
                                     static_cast<double>(samples) * static_cast<double>(samples)
                               : static_cast<double>(curve_count);
  }
  if (total > static_cast<double>(kLimit)) {
    if (!any_surface) {
      return fail(fmt::format("{} model{} at {} parameters is {} evaluations, more than the limit of {}",
                              models->size(), models->size() == 1 ? "" : "s", curve_count, total, kLimit));
    }
    return fail(fmt::format("{} model{} at these parameters (N x N for a surface) is {} evaluations, more than the "
                            "limit of {}",
                            models->size(), models->size() == 1 ? "" : "s", total, kLimit));
  }

  // --- every parameter checked against every model's domain ---------------
  // The library extrapolates outside the domain (bezier/evaluate.hpp); the
  // command line refuses, since a point off the curve is almost always a
  // mistake in the input. All checks come before any evaluation.
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Model& model = (*models)[m];
    if (is_surface(model)) {
      const SurfaceView view = surface_view(model);
      const auto inside = [&](double u, double v) { return view.domain_u().contains(u) && view.domain_v().contains(v); };
      for (const auto& [u, v] : surface.at) {
        if (!inside(u, v)) {
          return fail(fmt::format("--at {},{} is outside the domain {} of {}", u, v, domain_text(view),
                                  model_name(*models, m, options.model)));
        }
      }
      for (std::size_t k = 0; k < surface.params.size(); ++k) {
        const double u = surface.params[k][0], v = surface.params[k][1];
        if (!inside(u, v)) {
          return fail(fmt::format("{}, row {}: ({}, {}) is outside the domain {} of {}", display_name(options.params),
                                  k + 1, u, v, domain_text(view), model_name(*models, m, options.model)));
        }
      }
      continue;
    }
    const Interval domain = curve_view(model).domain();
    for (const double u : curve.at) {
      if (!domain.contains(u)) {
        return fail(fmt::format("--at {} is outside the domain {} of {}", u, domain_text(domain),
                                model_name(*models, m, options.model)));
      }
    }
    for (std::size_t i = 0; i < curve.params.values.size(); ++i) {
      if (!domain.contains(curve.params.values[i])) {
        return fail(fmt::format("{}, line {}: {} is outside the domain {} of {}", display_name(options.params),
                                curve.params.lines[i], curve.params.values[i], domain_text(domain),
                                model_name(*models, m, options.model)));
      }
    }
  }

  // --- evaluation, one model at a time, into memory -------------------------
  std::string out;
  std::vector<double> us, block;
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Model& model = (*models)[m];
    if (is_surface(model)) {
      evaluate_surface(surface_view(model), surface, samples, out);
      continue;
    }
    const CurveView view = curve_view(model);
    const Interval domain = view.domain();
    us.clear();
    us.insert(us.end(), curve.at.begin(), curve.at.end());
    us.insert(us.end(), curve.params.values.begin(), curve.params.values.end());
    if (options.arc_length && samples > 1) {
      // N points equally spaced along the curve (ops/arc_length.hpp), each
      // length within the default accuracy (1e-12 of the curve's size).
      auto spaced = equal_arc_length_parameters(view, samples, default_arc_length_tolerance(view));
      if (!spaced) return fail(with_context(spaced.error(), model_name(*models, m, options.model)));
      us.insert(us.end(), spaced->begin(), spaced->end());
    } else {
      append_samples(us, domain, samples);
    }

    const auto d = static_cast<std::size_t>(dimension_of(model));
    constexpr std::size_t kBlock = 4096;  // parameters per batch: bounded scratch memory
    for (std::size_t start = 0; start < us.size(); start += kBlock) {
      const std::size_t count = std::min(kBlock, us.size() - start);
      block.resize(count * d);
      const std::span<const double> chunk(us.data() + start, count);
      derivatives_at(view, chunk, curve.derivative, block);  // order 0: the points
      append_points_csv(out, block, static_cast<int>(d));
    }
  }

  return write_output(options.output, out);
}

}  // namespace

void add_eval_command(CLI::App& app, int& status) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* eval = app.add_subcommand(
      "eval",
      "Points (or derivatives) of the curves and surfaces in MODEL at the given parameters, as CSV: one point per "
      "line, coordinates separated by ',', each the shortest text that reads back to the same double. Parameters "
      "must lie in the model's domain ([0,1] for bezier, [0,m] for piecewise_bezier with m pieces, [t_p, t_{n+1}] "
      "for a bspline of degree p with n+1 control points; for a surface the rectangle of its u and v domains, "
      "[0,1] x [0,1] for bezier_surface and coons). A surface takes --at u,v, two-column --params u,v, an N x N "
      "--samples grid (u the slow index: line a*N+b is S(u_a, v_b)) and --derivative ku,kv for the partial "
      "derivative d^(ku+kv)S / du^ku dv^kv. The lines follow the order --at, --params, --samples. For several "
      "models, each is evaluated in order at the same parameters and the lines follow one another.");
  CLI::Option* model =
      eval->add_option("MODEL", options->model,
                       "Model JSON, a CSV point set taken as the control polygon of one Bézier curve, or an SVG "
                       "drawing, one curve per subpath (by extension .json/.csv/.svg, otherwise JSON when the text "
                       "starts with '{', SVG with '<')")
          ->required();
  add_units_option(eval, options->units);
  eval->add_option("--at", options->at,
                   "Evaluate at parameter T of a curve, or u,v of a surface (repeat for several; in the order given)")
      ->type_name("T|u,v")
      ->allow_extra_args(false);
  CLI::Option* params = eval->add_option("--params", options->params,
                                         "Evaluate at the parameters of a CSV file, in order: one column T for a "
                                         "curve, two columns u,v for a surface")
                            ->type_name("FILE.csv");
  eval->add_option(
          "--samples", options->samples,
          "Evaluate at N evenly spaced parameters over the whole domain, ends included (N = 1: the start); N x N for a "
          "surface, u the slow index")
      ->type_name("N");
  eval->add_option(
          "--derivative", options->derivative,
          "Print K-th derivatives instead of points (K = 0: points); for a surface ku,kv, the partial derivative "
          "d^(ku+kv)S / du^ku dv^kv (0 or 0,0: points)")
      ->type_name("K|ku,kv");
  eval->add_flag("--arc-length", options->arc_length,
                 "Space the --samples points equally along the curve (in arc length, within 1e-12 of the curve's "
                 "size) instead of in the parameter; curves only");
  CLI::Option* output = eval->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(eval, status, {{model, params}, output}, [options] { return run_eval(*options); });
}

}  // namespace casteljau::cli

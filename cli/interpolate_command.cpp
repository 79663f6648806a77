// casteljau interpolate: a curve through the points of a CSV file, as model
// JSON (docs/interpolation.md, docs/cli.md). The command only translates:
// it reads the points, checks which options the method takes, computes the
// parameter values (interpolation/parameterization.hpp) and calls one library
// function. Every check runs before anything is written; the output is built
// in memory and written atomically.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/interpolation/catmull_rom.hpp"
#include "casteljau/interpolation/c1_bezier.hpp"
#include "casteljau/interpolation/hermite.hpp"
#include "casteljau/interpolation/lagrange.hpp"
#include "casteljau/interpolation/natural_spline.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "casteljau/interpolation/tolerance.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

enum class Method { c1_bezier, catmull_rom, cubic, bspline, lagrange, natural, hermite };

/// What each method accepts besides the points: an option it does not take
/// is an error rather than silently ignored (a typo in a script should show).
struct MethodRules {
  Method method;
  const char* name;
  bool param = false;     ///< --param
  bool closed = false;    ///< --closed
  bool function = false;  ///< --function
  bool tangents = false;  ///< --start-tangent / --end-tangent
};

constexpr std::array<MethodRules, 7> kMethods{{
    {Method::c1_bezier, "c1-bezier", false, true, false, false},
    {Method::catmull_rom, "catmull-rom", true, true, false, false},
    {Method::cubic, "cubic", true, true, true, true},
    {Method::bspline, "bspline", true, false, true, true},
    {Method::lagrange, "lagrange", true, false, true, false},
    {Method::natural, "natural", true, false, true, false},
    {Method::hermite, "hermite", true, true, false, false},
}};

struct InterpolateOptions {
  std::string points;
  std::string method;
  std::string alpha, param, end, start_tangent, end_tangent, degree, nodes, order;
  bool closed = false;
  bool function = false;
  std::string output;
  // Which options were given (an empty value is not "not given").
  CLI::Option *alpha_option = nullptr, *param_option = nullptr, *end_option = nullptr,
              *start_tangent_option = nullptr, *end_tangent_option = nullptr, *degree_option = nullptr,
              *nodes_option = nullptr, *order_option = nullptr;
};

/// An end tangent for a curve of dimension d. For a function y(x) the
/// tangent may also be given as its d − 1 slopes dy/dx: the x component of
/// the derivative of (x, y(x)) with respect to x is 1.
Expected<Point> tangent_option(const char* option, const std::string& text, int dimension, bool function) {
  auto values = vector_option(option, text);
  if (!values) return values.error();
  const auto d = static_cast<std::size_t>(dimension);
  if (function && values->size() + 1 == d) values->insert(values->begin(), 1.0);
  if (values->size() != d) {
    return Error{fmt::format("{}: {} coordinates given, the points have {}{}", option, values->size(), d,
                             function ? fmt::format(" (or give the {} slope{} dy/dx)", d - 1, d == 2 ? "" : "s")
                                      : std::string())};
  }
  return values;
}

/// The method's entry in kMethods, or an error listing the names.
Expected<MethodRules> method_from_name(const std::string& name) {
  for (const auto& rules : kMethods)
    if (name == rules.name) return rules;
  return Error{fmt::format("--method '{}': unknown method, expected c1-bezier, catmull-rom, cubic, bspline, "
                           "lagrange, natural or hermite",
                           name.substr(0, 60))};
}

/// The options that the method does not take, as an error naming the first.
Status check_options(const MethodRules& rules, const InterpolateOptions& options) {
  const auto refuse = [&](const char* option, const char* why) -> Status {
    return Error{fmt::format("{} does not apply to --method {}{}", option, rules.name, why)};
  };
  if (given(options.alpha_option) && rules.method != Method::c1_bezier) return refuse("--alpha", " (c1-bezier only)");
  if (given(options.param_option) && !rules.param) {
    return refuse("--param", ", whose pieces have fixed parameters (piece i on [i, i+1])");
  }
  if (given(options.end_option) && rules.method != Method::cubic) return refuse("--end", " (cubic only)");
  if ((given(options.start_tangent_option) || given(options.end_tangent_option)) && !rules.tangents) {
    return refuse(given(options.start_tangent_option) ? "--start-tangent" : "--end-tangent",
                  " (cubic --end clamped and bspline only)");
  }
  if (given(options.degree_option) && rules.method != Method::bspline) return refuse("--degree", " (bspline only)");
  if (given(options.nodes_option) && rules.method != Method::lagrange) return refuse("--nodes", " (lagrange only)");
  if (given(options.order_option) && rules.method != Method::natural) return refuse("--order", " (natural only)");
  if (options.closed && !rules.closed) {
    return refuse("--closed",
                  " (closed curves: c1-bezier, catmull-rom, cubic with --end periodic, hermite)");
  }
  if (options.function && !rules.function) return refuse("--function", " (functions y(x): cubic, bspline, lagrange, natural)");
  if (options.function && given(options.param_option)) {
    return Error{"--function takes x (the first column) as the parameter; --param does not apply"};
  }
  if (options.function && options.closed) return Error{"--function and --closed exclude each other: a graph y(x) is not closed"};
  return {};
}

/// What the method reads from each row, checked before anything else: a
/// point of a plane or space curve (2 columns or more: one column alone would
/// give a curve on a line, never what a point set means), or for hermite a
/// point followed by its tangent (2d columns, d >= 2). With --function the
/// library says what a function y(x) needs (function_parameters).
Status check_columns(const MethodRules& rules, const InterpolateOptions& options, const PointArray& points) {
  const int columns = points.dimension();
  const std::string file = display_name(options.points);
  if (rules.method == Method::hermite) {
    if (columns >= 4 && columns % 2 == 0) return {};
    return Error{fmt::format("{}: hermite reads points and tangents: 2d columns (x,y,dx,dy in 2D, x,y,z,dx,dy,dz "
                             "in 3D), got {} column{}",
                             file, columns, columns == 1 ? "" : "s")};
  }
  if (options.function || columns >= 2) return {};
  return Error{fmt::format("{}: {} interpolates points of 2 or more columns (x,y or x,y,z), got 1 column", file,
                           rules.name)};
}

/// --closed as the library's Closure.
Closure closure_of(const InterpolateOptions& options) { return options.closed ? Closure::closed : Closure::open; }

/// The parameter values t_0..t_m (t_{m+1} for the closing step of a closed
/// curve): x with --function, else --param (uniform when not given).
Expected<std::vector<double>> parameters_of(const PointArray& points, const InterpolateOptions& options,
                                            Parameterization kind) {
  if (options.function) return function_parameters(points);
  return parameter_values(points, kind, closure_of(options));
}

Expected<Model> build_model(const MethodRules& rules, const InterpolateOptions& options, PointArray points) {
  // --- options shared by several methods --------------------------------
  Parameterization kind = Parameterization::uniform;
  if (given(options.param_option)) {
    auto parsed = parameterization_from_name(options.param);
    if (!parsed) return with_context(parsed.error(), "--param");
    kind = *parsed;
  }
  // Hermite rows carry tangents: the closing duplicate is judged on the
  // positions alone (below), not on the whole row.
  if (options.closed && rules.method != Method::hermite) points = without_closing_duplicate(points);

  switch (rules.method) {
    case Method::c1_bezier: {
      double alpha = 1.0;
      if (given(options.alpha_option)) {
        auto value = number_option("--alpha", options.alpha);
        if (!value) return value.error();
        if (!(*value > 0.0)) return Error{fmt::format("--alpha: {} is not > 0 (the tangents are divided by 3 alpha)", *value)};
        alpha = *value;
      }
      auto curve = interpolate_c1_bezier(points, alpha, closure_of(options));
      if (!curve) return in_file(options.points, curve.error());
      return Model{std::move(*curve)};
    }
    case Method::catmull_rom: {
      auto parameters = parameter_values(points, kind, closure_of(options));
      if (!parameters) return in_file(options.points, parameters.error());
      auto curve = interpolate_catmull_rom(points, *parameters, closure_of(options));
      if (!curve) return in_file(options.points, curve.error());
      return Model{std::move(*curve)};
    }
    case Method::cubic: {
      CubicEnds ends;
      ends.condition = options.closed ? EndCondition::periodic : EndCondition::not_a_knot;
      if (given(options.end_option)) {
        auto condition = end_condition_from_name(options.end);
        if (!condition) return with_context(condition.error(), "--end");
        ends.condition = *condition;
      }
      if (ends.condition == EndCondition::periodic && !options.closed) {
        if (options.function) return Error{"--end periodic makes a closed curve, which a function y(x) (--function) is not"};
        return Error{"--end periodic makes a closed curve: add --closed (the closing segment runs from the last "
                     "point back to the first)"};
      }
      if (options.closed && ends.condition != EndCondition::periodic) {
        return Error{fmt::format("--closed needs --end periodic (a closed curve has no ends), got --end {}",
                                 options.end)};
      }
      const bool clamped = ends.condition == EndCondition::clamped;
      const bool has_tangents = given(options.start_tangent_option) || given(options.end_tangent_option);
      if (clamped && !(given(options.start_tangent_option) && given(options.end_tangent_option))) {
        return Error{"--end clamped needs both end tangents: --start-tangent x,y[,z] and --end-tangent x,y[,z]"};
      }
      if (!clamped && has_tangents) {
        return Error{fmt::format("--start-tangent/--end-tangent need --end clamped (got --end {})",
                                 name_of(ends.condition))};
      }
      if (clamped) {
        auto start = tangent_option("--start-tangent", options.start_tangent, points.dimension(), options.function);
        if (!start) return start.error();
        auto end = tangent_option("--end-tangent", options.end_tangent, points.dimension(), options.function);
        if (!end) return end.error();
        ends.start_tangent = std::move(*start);
        ends.end_tangent = std::move(*end);
      }
      auto parameters = parameters_of(points, options, kind);
      if (!parameters) return in_file(options.points, parameters.error());
      auto curve = interpolate_cubic(points, *parameters, ends);
      if (!curve) return in_file(options.points, curve.error());
      return Model{std::move(*curve)};
    }
    case Method::bspline: {
      int degree = 3;
      if (given(options.degree_option)) {
        auto value = whole_number("--degree", options.degree, 1, tolerances::kMaxBSplineDegree);
        if (!value) return value.error();
        degree = static_cast<int>(*value);
      }
      std::vector<EndDerivative> derivatives;
      if (given(options.start_tangent_option)) {
        auto start = tangent_option("--start-tangent", options.start_tangent, points.dimension(), options.function);
        if (!start) return start.error();
        derivatives.push_back(EndDerivative{false, 1, std::move(*start)});
      }
      if (given(options.end_tangent_option)) {
        auto end = tangent_option("--end-tangent", options.end_tangent, points.dimension(), options.function);
        if (!end) return end.error();
        derivatives.push_back(EndDerivative{true, 1, std::move(*end)});
      }
      auto parameters = parameters_of(points, options, kind);
      if (!parameters) return in_file(options.points, parameters.error());
      auto curve = interpolate_bspline(points, *parameters, degree, derivatives);
      if (!curve) return in_file(options.points, curve.error());
      return Model{std::move(*curve)};
    }
    case Method::lagrange: {
      std::vector<double> parameters;
      if (given(options.nodes_option)) {
        if (options.nodes != "uniform" && options.nodes != "chebyshev") {
          return Error{fmt::format("--nodes '{}': unknown nodes, expected uniform or chebyshev", options.nodes.substr(0, 60))};
        }
        if (given(options.param_option)) {
          return Error{"--nodes and --param exclude each other: --nodes places the points at fixed parameters"};
        }
        if (options.function) {
          return Error{"--nodes does not apply to --function: x (the first column) gives the nodes"};
        }
        if (points.size() < 2) {
          return in_file(options.points, Error{fmt::format("interpolation needs at least 2 points, got {}", points.size())});
        }
        if (options.nodes == "chebyshev") {
          auto nodes = chebyshev_parameters(points.size());
          if (!nodes) return in_file(options.points, nodes.error());
          parameters = std::move(*nodes);
        } else {
          auto uniform = parameter_values(points, Parameterization::uniform);
          if (!uniform) return in_file(options.points, uniform.error());
          parameters = std::move(*uniform);
        }
      } else {
        auto values = parameters_of(points, options, kind);
        if (!values) return in_file(options.points, values.error());
        parameters = std::move(*values);
      }
      auto interpolant = interpolate_lagrange(points, parameters);
      if (!interpolant) return in_file(options.points, interpolant.error());
      auto curve = to_bezier(*interpolant);
      if (!curve) return in_file(options.points, curve.error());
      return Model{std::move(*curve)};
    }
    case Method::natural: {
      int order = 2;
      if (given(options.order_option)) {
        auto value = whole_number("--order", options.order, 1, tolerances::kMaxNaturalSplineOrder);
        if (!value) return value.error();
        order = static_cast<int>(*value);
      }
      auto parameters = parameters_of(points, options, kind);
      if (!parameters) return in_file(options.points, parameters.error());
      auto curve = interpolate_natural(points, *parameters, order);
      if (!curve) return in_file(options.points, curve.error());
      return Model{std::move(*curve)};
    }
    case Method::hermite: {
      const int d = points.dimension() / 2;
      std::vector<double> positions, tangents;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const auto row = points[i];
        positions.insert(positions.end(), row.begin(), row.begin() + d);
        tangents.insert(tangents.end(), row.begin() + d, row.end());
      }
      PointArray at = PointArray::from_trusted(d, std::move(positions));
      if (options.closed) {
        at = without_closing_duplicate(at);
        tangents.resize(at.size() * static_cast<std::size_t>(d));
      }
      const PointArray slopes = PointArray::from_trusted(d, std::move(tangents));
      auto parameters = parameter_values(at, kind, closure_of(options));
      if (!parameters) return in_file(options.points, parameters.error());
      auto curve = interpolate_hermite(at, slopes, *parameters, closure_of(options));
      if (!curve) return in_file(options.points, curve.error());
      return Model{std::move(*curve)};
    }
  }
  return Error{"unknown method"};
}

int run_interpolate(const InterpolateOptions& options) {
  auto rules = method_from_name(options.method);
  if (!rules) return fail(rules.error());
  if (auto ok = check_options(*rules, options); !ok) return fail(ok.error());
  auto points = read_points_csv(options.points);
  if (!points) return fail(points.error());
  if (auto ok = check_columns(*rules, options, *points); !ok) return fail(ok.error());
  auto model = build_model(*rules, options, std::move(*points));
  if (!model) return fail(model.error());
  const std::string text = models_to_json({*model});
  return write_output(options.output, text);
}

}  // namespace

void add_interpolate_command(CLI::App& app, int& status) {
  auto options = std::make_shared<InterpolateOptions>();
  CLI::App* command = app.add_subcommand(
      "interpolate",
      "A curve through the points of POINTS.csv, as model JSON (docs/interpolation.md). Methods: c1-bezier (seed "
      "000's C1 cubic Bézier pieces, piece i on [i, i+1]), catmull-rom, cubic (C2 cubic B-spline with an end "
      "condition), bspline (any degree, averaged knots), lagrange (one polynomial), natural (order q: degree 2q-1), "
      "hermite (points with tangent columns x,y,dx,dy). Parameters are normalized to [0, 1] unless the method fixes "
      "them; --function takes the first column as x.");
  CLI::Option* points =
      command->add_option("POINTS", options->points, "CSV point set (x,y or x,y,z; hermite: x,y,dx,dy or x,y,z,dx,dy,dz)")
          ->required();
  command->add_option("--method", options->method,
                      "c1-bezier, catmull-rom, cubic, bspline, lagrange, natural or hermite")
      ->type_name("M")
      ->required();
  options->alpha_option =
      command->add_option("--alpha", options->alpha, "c1-bezier: tangent divisor alpha > 0 (default 1; 2 gives "
                                                     "uniform Catmull-Rom tangents)")
          ->type_name("A");
  options->param_option = add_param_option(command, options->param);
  options->end_option = command
                            ->add_option("--end", options->end,
                                         "cubic: natural, clamped, not-a-knot (default) or periodic (default with "
                                         "--closed)")
                            ->type_name("CONDITION");
  options->start_tangent_option =
      command->add_option("--start-tangent", options->start_tangent,
                          "Derivative at the first point (cubic --end clamped; bspline: optional); with --function "
                          "also the slope dy/dx alone")
          ->type_name("x,y[,z]");
  options->end_tangent_option =
      command->add_option("--end-tangent", options->end_tangent, "Derivative at the last point, as --start-tangent")
          ->type_name("x,y[,z]");
  options->degree_option =
      command->add_option("--degree", options->degree, "bspline: the degree p >= 1 (default 3)")->type_name("P");
  options->nodes_option =
      command->add_option("--nodes", options->nodes,
                          "lagrange: the points' parameters, uniform or chebyshev (instead of --param)")
          ->type_name("KIND");
  options->order_option =
      command->add_option("--order", options->order, "natural: the order q >= 1 (default 2: the natural cubic)")
          ->type_name("Q");
  command->add_flag("--closed", options->closed,
                    "A closed curve: the closing segment runs from the last point back to the first (a last point "
                    "equal to the first is dropped)");
  add_function_flag(command, options->function);
  CLI::Option* output = command->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(command, status, {{points}, output}, [options] { return run_interpolate(*options); });
}

}  // namespace casteljau::cli

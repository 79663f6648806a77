// casteljau fit: a B-spline approximating the points of a CSV file, as model
// JSON (docs/cli.md): least squares with a fixed number of control points,
// least squares refined until a tolerance is met, or smoothing with the
// penalty λ ∫‖C''‖² (λ given or chosen by GCV). The command only translates:
// it reads the points, checks the options, computes the parameter values
// (interpolation/parameterization.hpp) and calls one function of
// interpolation/fit.hpp. Every check runs before anything is written; the
// output is built in memory and written atomically.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/interpolation/fit.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace casteljau::cli {
namespace {

struct FitOptions {
  std::string points;
  std::string degree, control_points, tolerance, smoothing, param;
  bool function = false;
  bool free_ends = false;
  std::string output;
  // Which options were given (an empty value is not "not given").
  CLI::Option *control_points_option = nullptr, *tolerance_option = nullptr, *smoothing_option = nullptr,
              *param_option = nullptr;
};

/// What to compute, from the options alone (before the file is read).
struct FitRequest {
  int degree = 3;
  std::size_t control_points = 0;     ///< 0: not given
  std::optional<double> tolerance;    ///< --tolerance
  bool smoothing = false;             ///< --smoothing given
  std::optional<double> lambda;       ///< --smoothing λ (empty: gcv)
  Parameterization kind = Parameterization::uniform;
  FitEnds ends = FitEnds::interpolated;
};

Expected<FitRequest> request_of(const FitOptions& options) {
  FitRequest request;
  auto degree = whole_number("--degree", options.degree, 1, tolerances::kMaxBSplineDegree);
  if (!degree) return degree.error();
  request.degree = static_cast<int>(*degree);
  if (given(options.control_points_option)) {
    auto count = whole_number("--control-points", options.control_points, 2,
                              static_cast<long long>(tolerances::kMaxControlPoints));
    if (!count) return count.error();
    request.control_points = static_cast<std::size_t>(*count);
  }
  if (given(options.tolerance_option)) {
    auto tolerance = number_option("--tolerance", options.tolerance);
    if (!tolerance) return tolerance.error();
    if (!(*tolerance > 0.0)) return Error{fmt::format("--tolerance: {} is not > 0", *tolerance)};
    request.tolerance = *tolerance;
  }
  if (given(options.smoothing_option)) {
    request.smoothing = true;
    if (options.smoothing != "gcv") {
      auto lambda = number_option("--smoothing", options.smoothing);
      if (!lambda) return Error{lambda.error().message + " (give λ >= 0 or gcv)", lambda.error().kind};
      if (*lambda < 0.0) return Error{fmt::format("--smoothing: λ = {} is negative, it must be >= 0 (or gcv)", *lambda)};
      request.lambda = *lambda;
    }
  }
  if (given(options.param_option)) {
    if (options.function) return Error{"--function takes x (the first column) as the parameter; --param does not apply"};
    auto kind = parameterization_from_name(options.param);
    if (!kind) return with_context(kind.error(), "--param");
    request.kind = *kind;
  }
  if (request.tolerance && request.control_points != 0) {
    return Error{"--control-points and --tolerance exclude each other: give the number of control points or the "
                 "tolerance that chooses it"};
  }
  if (request.tolerance && request.smoothing) {
    return Error{"--tolerance and --smoothing exclude each other: smoothing trades the error for smoothness"};
  }
  if (!request.tolerance && request.control_points == 0 && !request.smoothing) {
    return Error{"fit needs --control-points N or --tolerance E (or --smoothing λ|gcv)"};
  }
  if (options.free_ends) request.ends = FitEnds::free;
  return request;
}

Expected<BSplineFit> compute_fit(const FitRequest& request, const FitOptions& options, const PointArray& points) {
  auto parameters = options.function ? function_parameters(points) : parameter_values(points, request.kind);
  if (!parameters) return in_file(options.points, parameters.error());
  Expected<BSplineFit> fit = Error{};
  // GCV over 10⁶ points or a tolerance near the noise takes seconds: say how far
  // it is (on a terminal's stderr, erased before anything else is printed).
  TerminalProgress progress("fit");
  if (request.smoothing) {
    SmoothingOptions smoothing;
    smoothing.degree = request.degree;
    smoothing.control_point_count = request.control_points;
    smoothing.smoothing = request.lambda;
    smoothing.ends = request.ends;
    fit = fit_smoothing(points, *parameters, smoothing, progress.callback());
  } else if (request.tolerance) {
    fit = fit_to_tolerance(points, *parameters, request.degree, Tolerance{*request.tolerance}, request.ends,
                           progress.callback());
  } else {
    fit = fit_least_squares(points, *parameters, request.degree, request.control_points, request.ends);
  }
  if (!fit) return in_file(options.points, fit.error());
  return fit;
}

/// One line: "fit: 12 control points, max error 0.0123 at point 45, rms error
/// 0.0045, lambda 0.00123 (gcv), gcv 1.2e-05, effective degrees of freedom 10.5".
std::string summary_of(const BSplineFit& fit) {
  std::string line = fmt::format("fit: {} control points, max error {:.6g} at point {}, rms error {:.6g}",
                                 fit.curve.control_points().size(), fit.max_error, fit.worst_point, fit.rms_error);
  // λ in full (shortest round trip): --smoothing with it gives the same fit again.
  line += fmt::format(", lambda {}{}", fit.smoothing, fit.smoothing_from_gcv ? " (gcv)" : "");
  line += fmt::format(", gcv {:.6g}, effective degrees of freedom {:.6g}\n", fit.gcv_score,
                      fit.effective_degrees_of_freedom);
  return line;
}

int run_fit(const FitOptions& options) {
  auto request = request_of(options);
  if (!request) return fail(request.error());
  auto points = read_points_csv(options.points);
  if (!points) return fail(points.error());
  // One column would give a curve on a line, never what a point set means
  // (with --function the library says what a function y(x) needs).
  if (points->dimension() < 2 && !options.function) {
    return fail(fmt::format("{}: fit approximates points of 2 or more columns (x,y or x,y,z), got 1 column",
                            display_name(options.points)));
  }
  auto fit = compute_fit(*request, options, *points);
  if (!fit) return fail(fit.error());
  const std::string text = models_to_json({Model{fit->curve}});
  const std::string summary = summary_of(*fit);
  if (const int status = write_output(options.output, text); status != 0) return status;
  return write_summary(options.output, summary);
}

}  // namespace

void add_fit_command(CLI::App& app, int& status) {
  auto options = std::make_shared<FitOptions>();
  CLI::App* command = app.add_subcommand(
      "fit",
      "A B-spline approximating the points of POINTS.csv, as a bspline model JSON (docs/interpolation.md): least "
      "squares with N control points (--control-points), least squares with knots added until every point is within "
      "E of the curve at its parameter (--tolerance), or smoothing with the penalty lambda * integral |C''|^2 "
      "(--smoothing lambda, or gcv to choose lambda by generalized cross-validation; without --control-points the "
      "knots sit at every parameter: with --degree 3, --free-ends and --function that is scipy's "
      "make_smoothing_spline). The curve runs over [t_0, t_m] (the parameters, normalized to [0, 1] unless "
      "--function). A summary line (control points, max and rms error, lambda, GCV score, effective degrees of "
      "freedom) goes to standard output with -o FILE, else to standard error.");
  CLI::Option* points =
      command->add_option("POINTS", options->points, "CSV point set of 2 or more columns (x,y or x,y,z)")->required();
  command->add_option("--degree", options->degree, "The degree p >= 1 (2 or more with --smoothing)")
      ->type_name("P")
      ->required();
  options->control_points_option =
      command->add_option("--control-points", options->control_points,
                          "The number of control points, p+1 to the number of points")
          ->type_name("N");
  options->tolerance_option =
      command->add_option("--tolerance", options->tolerance,
                          "Largest distance |C(t_i) - P_i| allowed (each point at its own parameter)")
          ->type_name("E");
  options->smoothing_option =
      command->add_option("--smoothing", options->smoothing, "The penalty weight lambda >= 0, or gcv")
          ->type_name("LAMBDA|gcv");
  options->param_option = add_param_option(command, options->param);
  add_function_flag(command, options->function);
  command->add_flag("--free-ends", options->free_ends,
                    "Fit the first and last points like the others (default: the curve passes through them)");
  CLI::Option* output = command->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(command, status, {{points}, output}, [options] { return run_fit(*options); });
}

}  // namespace casteljau::cli

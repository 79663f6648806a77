// casteljau eval: points or K-th derivatives of the models in a file, at
// given parameters, as CSV (docs/cli.md, "eval"). The whole output is built
// in memory and written only when every check has passed: on bad input
// nothing reaches stdout or the output file.
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct EvalOptions {
  std::string model;
  std::vector<std::string> at;
  std::string params;
  std::string samples;
  std::string derivative = "0";
  std::string output;
};

/// A whole number in [0, limit] written in decimal digits (no sign, no
/// exponent): "--samples: '1.5' is not a whole number".
Expected<std::size_t> whole_number(const std::string& option, const std::string& text, std::size_t limit) {
  std::size_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  const bool digits_only = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits_only || ptr != end) {
    return Error{fmt::format("{}: '{}' is not a whole number >= 0", option, text.substr(0, 60))};
  }
  if (ec == std::errc::result_out_of_range || value > limit) {
    return Error{fmt::format("{}: {} is more than the limit of {}", option, text.substr(0, 60), limit)};
  }
  return value;
}

/// "the bezier model in 'm.json'" or "models[1] (piecewise_bezier) in 'm.json'".
std::string model_name(const std::vector<Model>& models, std::size_t index, const std::string& file) {
  const std::string name = display_name(file);
  if (models.size() == 1) return fmt::format("the {} model in '{}'", type_name(models[index]), name);
  return fmt::format("models[{}] ({}) in '{}'", index, type_name(models[index]), name);
}

std::string domain_text(const Interval& domain) { return fmt::format("[{}, {}]", domain.lower, domain.upper); }

/// Writes the whole output to stdout; false (with errno) when it fails.
bool write_stdout(const std::string& text) {
  if (!text.empty() && std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) return false;
  return std::fflush(stdout) == 0;
}

int run_eval(const EvalOptions& options) {
  constexpr std::size_t kLimit = tolerances::kMaxEvaluationParameters;

  // --- options -------------------------------------------------------------
  std::vector<double> at_values;
  for (const auto& text : options.at) {
    auto value = parse_number(text);
    if (!value) return fail("--at: " + value.error().message);
    at_values.push_back(*value);
  }
  std::size_t samples = 0;
  const bool has_samples = !options.samples.empty();
  if (has_samples) {
    auto n = whole_number("--samples", options.samples, kLimit);
    if (!n) return fail(n.error());
    if (*n == 0) return fail("--samples: 0 samples, give N >= 1 (N = 1 is the start of the domain)");
    samples = *n;
  }
  auto order =
      whole_number("--derivative", options.derivative, static_cast<std::size_t>(tolerances::kMaxDerivativeOrder));
  if (!order) return fail(order.error());
  const int derivative = static_cast<int>(*order);
  if (at_values.empty() && options.params.empty() && !has_samples) {
    return fail("nothing to evaluate: give --at T, --params FILE.csv or --samples N");
  }

  // --- inputs --------------------------------------------------------------
  const auto models = read_models(options.model);
  if (!models) return fail(models.error());
  NumberColumn params;
  if (!options.params.empty()) {
    const auto text = read_text_file(options.params);
    if (!text) return fail(text.error());
    auto column = parse_numbers_csv(*text, display_name(options.params), kLimit);
    if (!column) return fail(column.error());
    params = std::move(*column);
  }
  const std::size_t per_model = at_values.size() + params.values.size() + samples;
  if (per_model > kLimit || models->size() * per_model > kLimit) {
    return fail(fmt::format("{} model{} at {} parameters is {} evaluations, more than the limit of {}", models->size(),
                            models->size() == 1 ? "" : "s", per_model, models->size() * per_model, kLimit));
  }

  // --- every parameter checked against every model's domain ---------------
  // The library extrapolates outside the domain (bezier/evaluate.hpp); the
  // command line refuses, since a point off the curve is almost always a
  // mistake in the input. All checks come before any evaluation.
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Interval domain = domain_of((*models)[m]);
    for (const double u : at_values) {
      if (!domain.contains(u)) {
        return fail(fmt::format("--at {} is outside the domain {} of {}", u, domain_text(domain),
                                model_name(*models, m, options.model)));
      }
    }
    for (std::size_t i = 0; i < params.values.size(); ++i) {
      if (!domain.contains(params.values[i])) {
        return fail(fmt::format("{}, line {}: {} is outside the domain {} of {}", display_name(options.params),
                                params.lines[i], params.values[i], domain_text(domain),
                                model_name(*models, m, options.model)));
      }
    }
  }

  // --- evaluation, one model at a time, into memory -------------------------
  std::string out;
  std::vector<double> us, block;
  for (std::size_t m = 0; m < models->size(); ++m) {
    const Model& model = (*models)[m];
    const Interval domain = domain_of(model);
    us.clear();
    us.reserve(per_model);
    us.insert(us.end(), at_values.begin(), at_values.end());
    us.insert(us.end(), params.values.begin(), params.values.end());
    // N evenly spaced parameters, as numpy.linspace(lower, upper, N):
    // lower + (upper - lower) i / (N - 1), the product formed first so that
    // for the integer domains of this version each u is the correctly rounded
    // quotient; the last one is exactly `upper`, and N = 1 gives `lower`.
    const double width = domain.upper - domain.lower;
    for (std::size_t i = 0; i < samples; ++i) {
      const bool last = samples > 1 && i + 1 == samples;
      us.push_back(samples == 1 ? domain.lower
                   : last       ? domain.upper
                                : domain.lower + width * static_cast<double>(i) / static_cast<double>(samples - 1));
    }

    const auto d = static_cast<std::size_t>(dimension_of(model));
    constexpr std::size_t kBlock = 4096;  // parameters per batch: bounded scratch memory
    for (std::size_t start = 0; start < us.size(); start += kBlock) {
      const std::size_t count = std::min(kBlock, us.size() - start);
      block.resize(count * d);
      const std::span<const double> chunk(us.data() + start, count);
      if (derivative == 0) {
        points_at(model, chunk, block);
      } else {
        for (std::size_t i = 0; i < count; ++i) {
          const Point value = derivative_at(model, chunk[i], derivative);
          std::copy(value.begin(), value.end(), block.begin() + static_cast<std::ptrdiff_t>(i * d));
        }
      }
      append_points_csv(out, block, static_cast<int>(d));
    }
  }

  // --- output --------------------------------------------------------------
  if (!options.output.empty()) {
    if (auto written = write_file_atomically(options.output, out); !written) return fail(written.error());
    return 0;
  }
  if (!write_stdout(out)) {
    // Not bad input: the environment failed (disk full, closed pipe).
    std::fprintf(stderr, "casteljau: error: cannot write to standard output: %s\n", std::strerror(errno));
    return 1;
  }
  return 0;
}

}  // namespace

void add_eval_command(CLI::App& app, int& status) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* eval = app.add_subcommand(
      "eval",
      "Points (or K-th derivatives) of the curves in MODEL at the given parameters, as CSV: one point per line, "
      "coordinates separated by ',', each the shortest text that reads back to the same double. Parameters must lie "
      "in the model's domain ([0,1] for bezier, [0,m] for piecewise_bezier with m pieces, [t_p, t_{n+1}] for a "
      "bspline of degree p with n+1 control points). For several models, each "
      "is evaluated in order at the same parameters and the lines follow one another.");
  eval->add_option("MODEL", options->model,
                   "Model JSON, or a CSV point set taken as the control polygon of one Bézier curve (by extension "
                   ".json/.csv, otherwise JSON when the text starts with '{')")
      ->required();
  eval->add_option("--at", options->at, "Evaluate at parameter T (repeat for several; in the order given)")
      ->type_name("T")
      ->allow_extra_args(false);
  eval->add_option("--params", options->params, "Evaluate at the parameters of a one-column CSV file, in order")
      ->type_name("FILE.csv");
  eval->add_option("--samples", options->samples,
                   "Evaluate at N evenly spaced parameters over the whole domain, ends included (N = 1: the start)")
      ->type_name("N");
  eval->add_option("--derivative", options->derivative, "Print K-th derivatives instead of points (K = 0: points)")
      ->type_name("K");
  eval->add_option("-o,--output", options->output, "Write to FILE (atomically) instead of standard output")
      ->type_name("FILE");
  eval->callback([options, &status] { status = run_eval(*options); });
}

}  // namespace casteljau::cli

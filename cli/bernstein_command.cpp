// casteljau bernstein: the plot of the Bernstein basis of degree N
// (docs/cli.md, "bernstein"; the seed notebook's plot_bernstein).
#include <fmt/format.h>

#include <memory>
#include <string>

#include "casteljau/render/layout.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/tolerance.hpp"
#include "casteljau/render/write.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace casteljau::cli {
namespace {

struct BernsteinOptions {
  std::string degree;
  std::string output;
  bool without_ends = false;
};

int run_bernstein(const BernsteinOptions& options) {
  const auto format = figure_output_format(options.output);
  if (!format) return fail(format.error());
  const auto n = whole_number("N", options.degree, 1, tolerances::kMaxPlottedBasisDegree);
  if (!n) return fail(n.error());
  auto figure = render::bernstein_basis_figure(static_cast<int>(*n), options.without_ends ? render::BasisEnds::omitted : render::BasisEnds::included);
  if (!figure) return fail(figure.error());
  TerminalProgress progress("bernstein");
  return write_figure_output(options.output, *figure, *format, progress.callback());
}

}  // namespace

void add_bernstein_command(CLI::App& app, int& status) {
  auto options = std::make_shared<BernsteinOptions>();
  CLI::App* bernstein = app.add_subcommand(
      "bernstein",
      fmt::format("Plots the Bernstein basis B_(N,k)(t) = C(N,k) t^k (1-t)^(N-k), k = 0..N, on [0,1] into an SVG, PNG "
                  "or PDF figure (by the extension of -o). 1 <= N <= {}.",
                  tolerances::kMaxPlottedBasisDegree));
  bernstein->add_option("N", options->degree, "The degree")->required();
  CLI::Option* output =
      bernstein->add_option("-o,--output", options->output, kFigureOutputHelp)->type_name("FILE")->required();
  bernstein->add_flag("--without-ends", options->without_ends, "Leave out B_(N,0) and B_(N,N) (N >= 2)");
  set_action(bernstein, status, {{}, output}, [options] { return run_bernstein(*options); });
}

}  // namespace casteljau::cli

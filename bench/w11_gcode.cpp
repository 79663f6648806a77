// W11: G-code of a 10 MB SVG drawing (issue 41). The drawing, generated here
// from a seeded splitmix64 stream into $CASTELJAU_BENCH_DATA (default
// out/bench/w11), is 10 MB of <path> elements in a 1000 x 1000 mm page, in
// no useful order: three in four closed blobs of four cubics (radii 1 to 5
// mm), one in four open waves of two cubics. One timed run = what
// `casteljau gcode FILE --tolerance 0.01` does: the file read into curves,
// each fitted within the tolerance (fit_arcs: G2/G3 and G1; or flatten: the
// G1-only writer, --lines), the contours ordered and the program written in
// memory; items = bytes of SVG. The ordering rows time cutting_order alone
// (k-d tree nearest neighbour, 2-opt on neighbour lists) on the fitted
// contours, and, on the first eighth of them, greedy nearest neighbour by a
// k-d tree beside the plain search the writer used before
// (tests/support/greedy_order_oracle.hpp: quadratic). Checks: one
// contour per path, every contour cut once, the ordered rapid moves shorter
// than the input's order, the indexed greedy order as long as the plain one.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "casteljau/io/gcode.hpp"
#include "casteljau/io/gcode_order.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "support/greedy_order_oracle.hpp"
#include "support/splitmix.hpp"

namespace {

using namespace casteljau;

constexpr std::size_t kBytes = 10'000'000;
constexpr Tolerance kTolerance{0.01};  // mm: what a router engraves to

std::filesystem::path data_dir() {
  const char* dir = std::getenv("CASTELJAU_BENCH_DATA");
  return dir != nullptr && *dir != '\0' ? std::filesystem::path(dir) : std::filesystem::path("out/bench/w11");
}

struct Drawing {
  std::filesystem::path path;
  std::size_t bytes = 0;
  std::size_t paths = 0;
};

Drawing write_drawing() {
  test::SplitMix random{0x6C0DE};
  const auto in = [&](double low, double high) { return low + (high - low) * random.unit(); };
  std::string text =
      "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000mm\" height=\"1000mm\" "
      "viewBox=\"0 0 1000 1000\">\n";
  Drawing d;
  while (text.size() < kBytes - 200) {
    const double x = in(5, 995);
    const double y = in(5, 995);
    const double r = in(1, 5), k = 0.5523 * r;
    // Every draw named first: the order of evaluation of arguments is unspecified.
    if (random.below(4) == 0) {
      const double u = r * in(0.5, 1.5), v = r * in(0.5, 1.5), w = r * in(0.5, 1.5);
      text += fmt::format("<path d=\"M{:.3f} {:.3f}c{:.3f} {:.3f} {:.3f} {:.3f} {:.3f} 0s{:.3f} {:.3f} {:.3f} 0\"/>\n",
                          x - r, y, k, -u, r - k, v, r, r - k, -w, r);
    } else {
      // Quarters from (x + a, y) through (x, y + b), (x - c, y), (x, y - e).
      const double a = r * in(0.7, 1.3), b = r * in(0.7, 1.3), c = r * in(0.7, 1.3), e = r * in(0.7, 1.3);
      text += fmt::format(
          "<path d=\"M{:.3f} {:.3f}c0 {:.3f} {:.3f} {:.3f} {:.3f} {:.3f}s{:.3f} {:.3f} {:.3f} {:.3f}"
          "s{:.3f} {:.3f} {:.3f} {:.3f}s{:.3f} {:.3f} {:.3f} {:.3f}z\"/>\n",
          x + a, y, k, -a + k, b, -a, b, -c, -b + k, -c, -b, c - k, -e, c, -e, a, e - k, a, e);
    }
    ++d.paths;
  }
  text += "</svg>\n";
  d.path = data_dir() / "w11_drawing.svg";
  std::filesystem::create_directories(d.path.parent_path());
  std::ofstream(d.path, std::ios::binary) << text;
  d.bytes = text.size();
  return d;
}

/// The toolpath of the drawing, as `casteljau gcode` makes it.
Expected<Toolpath> toolpath_of(const Drawing& drawing, GcodeMotion motion, int decimals) {
  auto models = read_models(drawing.path);
  if (!models) return models.error();
  Toolpath toolpath;
  toolpath.tolerance = kTolerance;
  toolpath.sources = {drawing.path.string()};
  for (const Model& model : *models) {
    auto contour = contour_of(curve_view(model), kTolerance, decimals, motion);
    if (!contour) return contour.error();
    toolpath.contours.push_back(std::move(*contour));
  }
  return toolpath;
}

void write_program(benchmark::State& state, const Drawing& drawing, GcodeMotion motion) {
  const GcodeOptions options;
  const int decimals = gcode_decimals(kTolerance, options.units).value();
  GcodeProgram program;
  std::size_t contours = 0;
  for (auto _ : state) {
    auto toolpath = toolpath_of(drawing, motion, decimals);
    if (!toolpath) {
      state.SkipWithError(toolpath.error().message.c_str());
      return;
    }
    contours = toolpath->contours.size();
    auto written = write_gcode(*toolpath, options);
    if (!written) {
      state.SkipWithError(written.error().message.c_str());
      return;
    }
    program = std::move(*written);
    benchmark::DoNotOptimize(program.text.data());
  }
  if (contours != drawing.paths || program.contours != drawing.paths)
    state.SkipWithError(fmt::format("{} contours cut of {} for {} paths", program.contours, contours, drawing.paths).c_str());
  else if (!(program.rapid_length < program.rapid_length_unordered))
    state.SkipWithError("the ordered rapid moves are not shorter than the input's order");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * drawing.bytes));
  state.counters["MB"] = static_cast<double>(drawing.bytes) / 1e6;
  state.counters["contours"] = static_cast<double>(program.contours);
  state.counters["arcs"] = static_cast<double>(program.arcs);
  state.counters["lines"] = static_cast<double>(program.lines);
  state.counters["program_MB"] = static_cast<double>(program.text.size()) / 1e6;
  state.counters["rapid_m_given"] = program.rapid_length_unordered / 1000.0;
  state.counters["rapid_m_ordered"] = program.rapid_length / 1000.0;
}

/// The fitted contours (arcs), computed once for the ordering rows.
const std::vector<GcodeContour>& fitted_contours(const Drawing& drawing) {
  static const std::vector<GcodeContour> contours = [&] {
    auto toolpath = toolpath_of(drawing, GcodeMotion::arcs, gcode_decimals(kTolerance, GcodeUnits::millimetres).value());
    return toolpath ? toolpath->contours : std::vector<GcodeContour>{};
  }();
  return contours;
}

void order(benchmark::State& state, const Drawing& drawing) {
  const std::vector<GcodeContour>& contours = fitted_contours(drawing);
  std::vector<GcodeContour> ordered;
  for (auto _ : state) {
    ordered = cutting_order(contours, kTolerance, 1);
    benchmark::DoNotOptimize(ordered.data());
  }
  const double given = rapid_length_of(contours, kTolerance, 1), after = rapid_length_of(ordered, kTolerance, 1);
  if (contours.empty() || ordered.size() != contours.size() || !(after < given))
    state.SkipWithError(fmt::format("{} contours ordered of {}, rapid {} from {}", ordered.size(), contours.size(),
                                    after, given).c_str());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * contours.size()));
  state.counters["contours"] = static_cast<double>(contours.size());
  state.counters["rapid_m_given"] = given / 1000.0;
  state.counters["rapid_m_ordered"] = after / 1000.0;
}

void greedy(benchmark::State& state, const Drawing& drawing, bool indexed) {
  const std::vector<GcodeContour>& all = fitted_contours(drawing);
  const std::span<const GcodeContour> contours(all.data(), all.size() / 8);
  double length = 0.0;
  for (auto _ : state) {
    length = indexed ? rapid_length_of(nearest_neighbour_order(contours, kTolerance, 1), kTolerance, 1)
                     : test::plain_greedy_length(contours, kTolerance, 1);
    benchmark::DoNotOptimize(length);
  }
  static const double plain = test::plain_greedy_length(contours, kTolerance, 1);  // the reference, searched once
  const double reference = indexed ? plain : length;
  if (contours.empty() || std::abs(length - reference) > 1e-9 * reference)
    state.SkipWithError(fmt::format("greedy rapid length {} where the plain search gives {}", length, reference).c_str());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * contours.size()));
  state.counters["contours"] = static_cast<double>(contours.size());
  state.counters["rapid_m"] = length / 1000.0;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  static const Drawing drawing = write_drawing();
  benchmark::RegisterBenchmark("W11/gcode-10MB-svg/casteljau-arcs",
                               [](benchmark::State& state) { write_program(state, drawing, GcodeMotion::arcs); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("W11/gcode-10MB-svg/casteljau-lines",
                               [](benchmark::State& state) { write_program(state, drawing, GcodeMotion::lines); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("W11/order-10MB-svg/casteljau",
                               [](benchmark::State& state) { order(state, drawing); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("W11/greedy-eighth/casteljau-kd-tree",
                               [](benchmark::State& state) { greedy(state, drawing, true); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("W11/greedy-eighth/plain-search",
                               [](benchmark::State& state) { greedy(state, drawing, false); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// W10: reading drawings. A 10 MB SVG file holding one long path (every
// command: L l H V C c S Q q T A, relative and absolute, a new subpath every
// 500 segments) and a 10 MB DXF R2000 file (LINE, ARC, LWPOLYLINE with
// bulges, cubic SPLINE entities in turn), generated here from a seeded
// splitmix64 stream and written to $CASTELJAU_BENCH_DATA (default
// out/bench/w10) so that bench/w10_readers.py times python3-svgelements and
// ezdxf reading the very same files in the same run. One timed read = the
// file read and parsed into curves (read_svg_drawing, read_dxf_drawing);
// throughput in MB of file per second (items = bytes). Checks: the SVG gives
// as many Bézier pieces as segments were written, arcs counted by their
// pieces; the DXF as many curves as entities; else the row fails.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "casteljau/io/dxf.hpp"
#include "casteljau/io/svg_drawing.hpp"
#include "support/splitmix.hpp"

namespace {

using namespace casteljau;

constexpr std::size_t kBytes = 10'000'000;

std::filesystem::path data_dir() {
  const char* dir = std::getenv("CASTELJAU_BENCH_DATA");
  return dir != nullptr && *dir != '\0' ? std::filesystem::path(dir) : std::filesystem::path("out/bench/w10");
}

/// A coordinate with three decimals in [-500, 500).
std::string coordinate(test::SplitMix& random) { return fmt::format("{:.3f}", random.unit() * 1000.0 - 500.0); }

struct Generated {
  std::filesystem::path path;
  std::size_t bytes = 0;
  std::size_t count = 0;  // SVG: segments that draw (arcs excluded); DXF: entities
  std::size_t arcs = 0;   // SVG arcs, whose pieces are counted apart
};

Generated write_svg() {
  test::SplitMix random{0x5710};
  std::string d = "M0 0";
  Generated g;
  const char* commands[] = {"L", "l", "H", "V", "C", "c", "S", "Q", "q", "T", "A"};
  std::size_t in_subpath = 0;
  while (d.size() < kBytes - 200) {
    if (++in_subpath == 500) {
      d += fmt::format(" M{} {}", coordinate(random), coordinate(random));
      in_subpath = 0;
      continue;
    }
    const std::string command = commands[random.below(11)];
    d += ' ' + command;
    const int numbers = command == "L" || command == "l" || command == "T" ? 2
                        : command == "H" || command == "V"                 ? 1
                        : command == "C" || command == "c"                 ? 6
                        : command == "A"                                   ? 0
                                                                           : 4;
    if (command == "A") {
      d += fmt::format("{:.3f} {:.3f} {:.1f} {} {} {} {}", 50.0 + random.unit() * 200, 50.0 + random.unit() * 200,
                       random.unit() * 360, random.below(2), random.below(2), coordinate(random), coordinate(random));
      ++g.arcs;
      continue;
    }
    for (int k = 0; k < numbers; ++k) d += (k == 0 ? "" : " ") + coordinate(random);
    ++g.count;
  }
  const std::string text = "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path d=\"" + d +
                           "\"/>\n</svg>\n";
  g.path = data_dir() / "w10_path.svg";
  std::filesystem::create_directories(g.path.parent_path());
  std::ofstream(g.path, std::ios::binary) << text;
  g.bytes = text.size();
  return g;
}

Generated write_dxf() {
  test::SplitMix random{0xD7F};
  // The sections around the entities: casteljau's own writer, of no curve.
  const std::string frame = write_dxf_drawing({}).value();
  const std::size_t at = frame.find("ENTITIES\n") + 9;
  std::string entities;
  Generated g;
  unsigned handle = 0x1000;
  const auto start = [&](const char* name, const char* subclass) {
    entities += fmt::format("  0\n{}\n  5\n{:X}\n330\n1F\n100\nAcDbEntity\n  8\n0\n100\n{}\n", name, handle++, subclass);
  };
  while (entities.size() + frame.size() < kBytes) {
    switch (g.count % 4) {
      case 0:
        start("LINE", "AcDbLine");
        entities += fmt::format(" 10\n{}\n 20\n{}\n 30\n0\n 11\n{}\n 21\n{}\n 31\n0\n", coordinate(random),
                                coordinate(random), coordinate(random), coordinate(random));
        break;
      case 1:
        start("ARC", "AcDbCircle");
        entities += fmt::format(" 10\n{}\n 20\n{}\n 30\n0\n 40\n{:.3f}\n100\nAcDbArc\n 50\n{:.2f}\n 51\n{:.2f}\n",
                                coordinate(random), coordinate(random), 1.0 + random.unit() * 100,
                                random.unit() * 360, random.unit() * 360);
        break;
      case 2:
        start("LWPOLYLINE", "AcDbPolyline");
        entities += " 90\n8\n 70\n1\n";
        for (int k = 0; k < 8; ++k)
          entities += fmt::format(" 10\n{}\n 20\n{}\n 42\n{:.3f}\n", coordinate(random), coordinate(random),
                                  random.below(2) ? 0.0 : random.unit() - 0.5);
        break;
      default:
        start("SPLINE", "AcDbSpline");
        entities += " 70\n8\n 71\n3\n 72\n12\n 73\n8\n 74\n0\n";
        for (double knot : {0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0})
          entities += fmt::format(" 40\n{}\n", knot);
        for (int k = 0; k < 8; ++k)
          entities += fmt::format(" 10\n{}\n 20\n{}\n 30\n0\n", coordinate(random), coordinate(random));
    }
    ++g.count;
  }
  const std::string text = frame.substr(0, at) + entities + frame.substr(at);
  g.path = data_dir() / "w10_drawing.dxf";
  std::filesystem::create_directories(g.path.parent_path());
  std::ofstream(g.path, std::ios::binary) << text;
  g.bytes = text.size();
  return g;
}

void read_svg(benchmark::State& state, const Generated& g) {
  std::size_t pieces = 0;
  for (auto _ : state) {
    auto drawing = read_svg_drawing(g.path);
    if (!drawing || !drawing->problems.empty()) {
      state.SkipWithError(drawing ? drawing->problems.front().message.c_str() : drawing.error().message.c_str());
      return;
    }
    pieces = 0;
    for (const SvgCurve& curve : drawing->curves) pieces += curve.curve.pieces().size();
    benchmark::DoNotOptimize(pieces);
  }
  // Each arc is 1 to 4 rational pieces (or a line when its ends coincide).
  if (pieces < g.count + g.arcs || pieces > g.count + 4 * g.arcs)
    state.SkipWithError(fmt::format("{} pieces for {} segments and {} arcs", pieces, g.count, g.arcs).c_str());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * g.bytes));
  state.counters["MB"] = static_cast<double>(g.bytes) / 1e6;
  state.counters["segments"] = static_cast<double>(g.count + g.arcs);
}

void read_dxf(benchmark::State& state, const Generated& g) {
  std::size_t curves = 0;
  for (auto _ : state) {
    auto drawing = read_dxf_drawing(g.path);
    if (!drawing || !drawing->problems.empty()) {
      state.SkipWithError(drawing ? drawing->problems.front().message.c_str() : drawing.error().message.c_str());
      return;
    }
    curves = drawing->curves.size();
    benchmark::DoNotOptimize(curves);
  }
  if (curves != g.count) state.SkipWithError(fmt::format("{} curves for {} entities", curves, g.count).c_str());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * g.bytes));
  state.counters["MB"] = static_cast<double>(g.bytes) / 1e6;
  state.counters["entities"] = static_cast<double>(g.count);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  static const Generated svg = write_svg();
  static const Generated dxf = write_dxf();
  benchmark::RegisterBenchmark("W10/svg-10MB/casteljau",
                               [](benchmark::State& state) { read_svg(state, svg); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("W10/dxf-10MB/casteljau",
                               [](benchmark::State& state) { read_dxf(state, dxf); })
      ->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

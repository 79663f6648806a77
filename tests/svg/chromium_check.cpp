// casteljau_svg_chromium_check CORPUS READING.json: compares casteljau's
// reading of every path of the corpus (io/svg_path.hpp) with Chromium's
// (chromium_paths.mjs): every point Chromium puts on the path must lie on
// casteljau's curves, and both must draw the same length, so a segment one
// reader keeps and the other drops (an error rule read differently) shows.
// Prints one line per case and the largest deviations; exit status 1 when
// one passes its bound.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/svg_path.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "casteljau/ops/closest_point.hpp"

namespace {

using namespace casteljau;

// Chromium works in float32 (about 6e-8 relative), evaluates curves in
// float, and measures lengths by flattening (Skia's path measure): its points
// lie on the curve to float rounding, its lengths are within the flattening
// error. Both bounds are fractions of the drawing's size (the diagonal of
// the box of its control points).
constexpr double kPointBound = 1e-5;
constexpr double kLengthBound = 1e-3;
// Blink does not keep arcs: it replaces each by cubics, one per quarter turn
// at most, the classic approximation whose radial error reaches 2.7e-4 of the
// radius on a quarter circle (casteljau's rational pieces are exact). Paths
// with arcs are held to that instead.
constexpr double kArcPointBound = 3e-4;

struct Case {
  std::string name, data;
};

std::string unescaped(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size()) {
      const char c = text[i + 1];
      const char replaced = c == 't' ? '\t' : c == 'n' ? '\n' : c == 'r' ? '\r' : c == 'f' ? '\f' : '\0';
      if (replaced != '\0') {
        out += replaced;
        ++i;
        continue;
      }
    }
    out += text[i];
  }
  return out;
}

std::vector<Case> read_corpus(const char* path) {
  std::ifstream in(path);
  std::vector<Case> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t bar = line.find('|');
    if (bar == std::string::npos) continue;
    std::string name = line.substr(0, bar), data = line.substr(bar + 1);
    name.erase(name.find_last_not_of(' ') + 1);
    if (!data.empty() && data.front() == ' ') data.erase(0, 1);
    if (!data.empty() && data.back() == ' ') data.pop_back();
    cases.push_back({name, unescaped(data)});
  }
  return cases;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s CORPUS READING.json\n", argv[0]);
    return 2;
  }
  const std::vector<Case> cases = read_corpus(argv[1]);
  std::ifstream reading_file(argv[2]);
  const nlohmann::json reading = nlohmann::json::parse(reading_file);
  std::printf("casteljau against %s, %zu paths\n", reading.at("browser").get<std::string>().c_str(), cases.size());
  double worst_point = 0.0, worst_arc_point = 0.0, worst_length = 0.0;
  int failures = 0;
  for (const Case& c : cases) {
    const SvgPathData ours = read_svg_path(c.data);
    const auto& theirs = reading.at("readings").at(c.name);
    const double their_total = theirs.at("total").get<double>();
    double size = 0.0;
    for (const SvgSubpath& subpath : ours.subpaths) size = std::max(size, size_of(subpath.curve));
    const double scale = size > 0.0 ? size : 1.0;
    double our_total = 0.0;
    for (const SvgSubpath& subpath : ours.subpaths)
      our_total += arc_length(subpath.curve, Tolerance{1e-12 * scale}).value();
    double point_gap = 0.0;
    for (const auto& p : theirs.at("points")) {
      const double q[2] = {p.at(0).get<double>(), p.at(1).get<double>()};
      double nearest = INFINITY;
      for (const SvgSubpath& subpath : ours.subpaths)
        nearest = std::min(nearest, closest_point(subpath.curve, q).value().distance);
      point_gap = std::max(point_gap, nearest / scale);
    }
    const double length_gap = std::abs(their_total - our_total) / scale;
    const bool arcs = c.data.find_first_of("Aa") != std::string::npos;
    const bool ok = point_gap <= (arcs ? kArcPointBound : kPointBound) && length_gap <= kLengthBound;
    failures += ok ? 0 : 1;
    (arcs ? worst_arc_point : worst_point) = std::max(arcs ? worst_arc_point : worst_point, point_gap);
    worst_length = std::max(worst_length, length_gap);
    std::printf("%-4s %-30s %zu subpaths, length %.6f (Chromium %.6f), length gap %.1e, point gap %.1e%s%s\n",
                ok ? "ok" : "FAIL", c.name.c_str(), ours.subpaths.size(), our_total, their_total, length_gap,
                point_gap, ours.error ? ", error: " : "", ours.error ? ours.error->message.c_str() : "");
  }
  std::printf("largest point gap %.1e without arcs (bound %.0e), %.1e with arcs (bound %.0e), largest length gap "
              "%.1e (bound %.0e), of the drawing's size; %d of %zu cases differ\n",
              worst_point, kPointBound, worst_arc_point, kArcPointBound, worst_length, kLengthBound, failures,
              cases.size());
  return failures == 0 ? 0 : 1;
}

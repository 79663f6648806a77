// casteljau_svg_chromium_check MODE ...: compares what casteljau reads and
// writes with what Chromium draws. Every point Chromium puts on an element
// must lie on casteljau's curves for it, and both must draw the same length,
// so a segment one reader keeps and the other drops (an error rule read
// differently) shows. Prints one line per case and the largest deviations;
// exit status 1 when one passes its bound.
//   paths CORPUS READING.json     path data (io/svg_path.hpp) against
//                                 chromium_paths.mjs's reading of the corpus
//   drawings DIR READING.json     each DIR/*.svg read (io/svg_drawing.hpp),
//                                 element by element, against
//                                 chromium_drawings.mjs's reading of DIR
//   written DIR READING.json      what casteljau wrote (convert --to svg) of
//                                 each DIR/F (.svg or .json), read by Chromium
//                                 (the reading of F.svg), against casteljau's
//                                 reading of the original F
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/svg_drawing.hpp"
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
// Blink measures the length of a circle, an ellipse and a rounded rect (its
// conics, not a path's cubics) by flattening them at half a unit of the
// element's own coordinates (Skia's contour measure): a polygon inscribed in
// the curve, shorter than it by up to a few percent on small radii (6 % on a
// circle of radius 4 drawn 6 times larger). Their lengths are held to that:
// Chromium's no longer than casteljau's, and not shorter by more than 10 %.
constexpr double kFlattenedShortfall = 0.1;

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

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
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

/// The curves Chromium draws as one element, as casteljau reads them, and
/// where the model's y = 0 lies in the user space Chromium reports (y down):
/// a point (x, y) of Chromium's is (x, page_bottom - y) of the models
/// (docs/formats.md, "The frame").
struct Element {
  std::string name;
  std::vector<PiecewiseBezierCurve> curves;
  double page_bottom = 0.0;
};

/// A file's elements: an SVG drawing's curves grouped by the element that
/// draws them, or each curve model of model JSON.
std::vector<Element> elements_of(const std::string& path) {
  std::vector<Element> elements;
  if (path.size() > 4 && path.substr(path.size() - 4) == ".svg") {
    const SvgDrawing drawing = parse_svg_drawing(read_file(path), path).value();
    for (const Error& problem : drawing.problems) std::printf("problem: %s\n", problem.message.c_str());
    for (std::size_t i = 0; i < drawing.curves.size(); ++i) {
      const SvgCurve& c = drawing.curves[i];
      const bool same = i > 0 && c.line == drawing.curves[i - 1].line && c.id == drawing.curves[i - 1].id;
      if (!same) elements.push_back({c.element + (c.id.empty() ? "" : "#" + c.id), {}, drawing.page_bottom});
      elements.back().curves.push_back(c.curve);
    }
    return elements;
  }
  const auto models = read_models(path).value();
  for (std::size_t m = 0; m < models.size(); ++m) {
    const CurveView view = curve_view(models[m]);
    elements.push_back({"model " + std::to_string(m), {to_piecewise_bezier(to_bezier_pieces(view))}});
  }
  return elements;
}

/// Compares one element; returns whether it is within the bounds.
struct Gaps {
  double point = 0.0, arc_point = 0.0, length = 0.0;
  int failures = 0, cases = 0;
};
void compare(const std::string& label, const std::vector<PiecewiseBezierCurve>& ours, double page_bottom,
             const nlohmann::json& theirs, double scale, bool arcs, bool conic_shape, Gaps& gaps) {
  double our_total = 0.0;
  for (const auto& curve : ours) our_total += arc_length(curve, Tolerance{1e-12 * scale}).value();
  double point_gap = 0.0;
  for (const auto& p : theirs.at("points")) {
    const double q[2] = {p.at(0).get<double>(), page_bottom - p.at(1).get<double>()};
    double nearest = INFINITY;
    for (const auto& curve : ours) nearest = std::min(nearest, closest_point(curve, q).value().distance);
    point_gap = std::max(point_gap, nearest / scale);
  }
  const bool measured = !theirs.at("total").is_null();
  const double their_total = measured ? theirs.at("total").get<double>() : our_total;
  double length_gap = std::abs(their_total - our_total) / scale;
  if (conic_shape)  // a chord length: shorter, by at most kFlattenedShortfall
    length_gap = their_total <= our_total * (1 + 1e-9) && their_total >= (1 - kFlattenedShortfall) * our_total
                     ? 0.0
                     : std::abs(their_total - our_total) / scale;
  const bool ok = point_gap <= (arcs ? kArcPointBound : kPointBound) && length_gap <= kLengthBound &&
                  !theirs.at("points").empty();
  gaps.failures += ok ? 0 : 1;
  ++gaps.cases;
  (arcs ? gaps.arc_point : gaps.point) = std::max(arcs ? gaps.arc_point : gaps.point, point_gap);
  gaps.length = std::max(gaps.length, length_gap);
  std::printf("%-4s %-40s %zu curves, length %.6f (Chromium %s), length gap %.1e, point gap %.1e\n",
              ok ? "ok" : "FAIL", label.c_str(), ours.size(), our_total,
              measured ? std::to_string(their_total).c_str() : "not measured: not a similarity", length_gap,
              point_gap);
}

/// drawings and written: every file of the reading against casteljau's
/// reading of the file in `folder` (for written, of the original: the name
/// without its last ".svg").
int compare_files(const std::string& folder, const nlohmann::json& reading, bool written) {
  Gaps gaps;
  for (const auto& [name, elements] : reading.at("readings").items()) {
    const std::string original = written ? name.substr(0, name.size() - 4) : name;
    const std::vector<Element> ours = elements_of(folder + "/" + original);
    if (ours.size() != elements.size()) {
      std::printf("FAIL %s: casteljau reads %zu elements, Chromium draws %zu\n", name.c_str(), ours.size(),
                  elements.size());
      ++gaps.failures;
      continue;
    }
    double size = 0.0;
    for (const Element& e : ours)
      for (const auto& c : e.curves) size = std::max(size, size_of(CurveView(c)));
    const double scale = size > 0.0 ? size : 1.0;
    for (std::size_t k = 0; k < ours.size(); ++k) {
      // Chromium's arcs are cubics (see kArcPointBound); casteljau's written
      // files hold cubics within 1e-6 of the size, held to kPointBound.
      bool arcs = false;
      if (!written)
        for (const auto& c : ours[k].curves)
          for (const auto& piece : c.pieces()) arcs = arcs || piece.is_rational();
      const std::string tag = elements[k].at("tag").get<std::string>();
      const bool conic_shape = arcs && (tag == "circle" || tag == "ellipse" || tag == "rect");
      // A file casteljau wrote holds the models' points as x -y: its page's
      // bottom is y = 0 of the originals' frame, whatever its viewBox.
      compare(name + " " + ours[k].name, ours[k].curves, written ? 0.0 : ours[k].page_bottom, elements[k], scale,
              arcs, conic_shape, gaps);
    }
  }
  std::printf("%s: largest point gap %.1e without arcs (bound %.0e), %.1e with arcs (bound %.0e), largest length "
              "gap %.1e (bound %.0e; circles, ellipses, rounded rects: Chromium's chord length shorter by at most "
              "10 %%), of the drawing's size; %d of %d elements differ\n",
              written ? "written by casteljau, read by Chromium" : "drawings", gaps.point, kPointBound,
              gaps.arc_point, kArcPointBound, gaps.length, kLengthBound, gaps.failures, gaps.cases);
  return gaps.failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc == 4 ? argv[1] : "";
  if (mode != "paths" && mode != "drawings" && mode != "written") {
    std::fprintf(stderr, "usage: %s paths|drawings|written CORPUS|DIR READING.json\n", argv[0]);
    return 2;
  }
  std::ifstream reading_file(argv[3]);
  const nlohmann::json reading = nlohmann::json::parse(reading_file);
  if (mode != "paths") return compare_files(argv[2], reading, mode == "written");
  const std::vector<Case> cases = read_corpus(argv[2]);
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

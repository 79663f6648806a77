// casteljau info: what a file holds, in a few lines a person reads (docs/cli.md,
// "info"): its format and unit, its models by type, the elements they came
// from with their ids and layers, their Bézier pieces by degree, the tight
// bounding box, and what a drawing draws that casteljau left out.
#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/io/dxf.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/ops/bounds.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct InfoOptions {
  std::string model;
  std::string output;
  std::string units;
};

/// Counts in the order their keys first appear: "path 5, rect 2".
class Tally {
 public:
  void add(const std::string& key, std::size_t count = 1) {
    auto found = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e.first == key; });
    if (found == entries_.end()) entries_.emplace_back(key, count);
    else found->second += count;
  }
  bool empty() const { return entries_.empty(); }
  std::size_t total() const {
    std::size_t sum = 0;
    for (const auto& entry : entries_) sum += entry.second;
    return sum;
  }
  /// "5 path, 2 rect", or with a `format` taking the key and the count.
  template <class Format>
  std::string text(Format format) const {
    std::string out;
    for (const auto& [key, count] : entries_) out += (out.empty() ? "" : ", ") + format(key, count);
    return out;
  }
  std::string text() const {
    return text([](const std::string& key, std::size_t count) { return fmt::format("{} {}", count, key); });
  }

 private:
  std::vector<std::pair<std::string, std::size_t>> entries_;
};

std::string unit_line(const FileModels& file) {
  if (file.insunits == 4) return "millimetres";
  if (file.insunits != 0) {
    const double mm = dxf_unit_millimetres(file.insunits);
    return mm > 0.0 ? fmt::format("{} ($INSUNITS {}, {:g} mm each)", dxf_unit_name(file.insunits), file.insunits, mm)
                    : fmt::format("{} ($INSUNITS {}: no length)", dxf_unit_name(file.insunits), file.insunits);
  }
  if (file.format == ModelFileFormat::svg) return "none stated (the root's user units; --units mm reads millimetres)";
  if (file.format == ModelFileFormat::dxf) return "none stated ($INSUNITS 0)";
  return "none (model JSON and CSV numbers have no unit)";
}

int run_info(const InfoOptions& options) {
  const auto read = read_model_file_with_unit(options.model, options.units, /*report_skipped=*/false);
  if (!read) return fail(read.error());
  const FileModels& file = *read;
  std::string out = fmt::format("{}: {}", display_name(options.model), format_name(file.format));
  if (file.page_bottom)
    out += fmt::format(", upright: y up from its page's bottom edge (y = {:g} in the file)", *file.page_bottom);
  out += fmt::format("\nunit: {}\n", unit_line(file));

  // Models by type and dimension.
  Tally types, dimensions;
  for (const Model& model : file.models) {
    types.add(type_name(model));
    dimensions.add(fmt::format("R^{}", dimension_of(model)));
  }
  const auto spaces = dimensions.text([&](const std::string& key, std::size_t count) {
    return count == file.models.size() ? key : fmt::format("{} in {}", count, key);
  });
  out += fmt::format("models: {} ({}), in {}\n", file.models.size(), types.text(), spaces);

  // Elements of a drawing (a path's subpaths are one element), ids, layers.
  if (file.is_drawing()) {
    Tally elements, layers;
    std::vector<std::string> ids;
    for (std::size_t m = 0; m < file.origins.size(); ++m) {
      const ModelOrigin& o = file.origins[m];
      const bool same = m > 0 && o.line == file.origins[m - 1].line && o.id == file.origins[m - 1].id &&
                        o.element == file.origins[m - 1].element;
      if (same) continue;
      elements.add(o.element);
      if (!o.id.empty()) ids.push_back(o.id);
      if (file.format == ModelFileFormat::dxf) layers.add(o.layer.empty() ? "0" : o.layer);
    }
    out += fmt::format("elements: {} ({})\n", elements.total(), elements.text());
    out += fmt::format("{}: {}\n", file.format == ModelFileFormat::dxf ? "handles" : "ids",
                       ids.empty() ? std::string("none") : listed(ids, 12));
    if (!layers.empty())
      out += fmt::format("layers: {}\n", layers.text([](const std::string& key, std::size_t count) {
                           return fmt::format("{} ({} entit{})", key, count, count == 1 ? "y" : "ies");
                         }));
  }

  // Bézier pieces of the curves by degree, and the box.
  Tally pieces;
  Point lower, upper;
  const auto grow = [&](std::span<const double> lo, std::span<const double> hi) {
    if (lower.size() < lo.size()) {
      lower.resize(lo.size(), std::numeric_limits<double>::infinity());
      upper.resize(lo.size(), -std::numeric_limits<double>::infinity());
    }
    for (std::size_t j = 0; j < lo.size(); ++j) {
      lower[j] = std::min(lower[j], lo[j]);
      upper[j] = std::max(upper[j], hi[j]);
    }
  };
  bool surfaces = false;
  for (const Model& model : file.models) {
    if (is_surface(model)) {
      // A surface lies in its control points' box (convex hull property).
      surfaces = true;
      auto spline = to_bspline(model);
      if (!spline) return fail(with_context(spline.error(), display_name(options.model)));
      const PointArray& points = std::get<BSplineSurface>(*spline).control_net().points();
      for (std::size_t i = 0; i < points.size(); ++i) grow(points[i], points[i]);
      continue;
    }
    const CurveView view = curve_view(model);
    for (const BezierCurve& piece : to_bezier_pieces(view).pieces)
      pieces.add(fmt::format("{}of degree {}", piece.is_rational() ? "rational " : "", piece.degree()));
    const Box box = bounding_box(view);
    grow(box.lower, box.upper);
  }
  if (!pieces.empty()) out += fmt::format("Bezier pieces: {} ({})\n", pieces.total(), pieces.text());
  std::string box;
  const char* axes = "xyzw";
  for (std::size_t j = 0; j < lower.size(); ++j)
    box += fmt::format("{}{} from {:.9g} to {:.9g}", j == 0 ? "" : ", ", j < 4 ? std::string(1, axes[j]) : fmt::format("x{}", j),
                       lower[j], upper[j]);
  out += fmt::format("box: {}{}\n", box, surfaces ? " (surfaces: their control points' box)" : "");

  // What a drawing draws that casteljau left out.
  if (file.skipped.empty()) {
    out += "skipped: nothing\n";
  } else {
    out += fmt::format("skipped: {} ({})\n", file.skipped.size(), skipped_summary(file.skipped));
    for (std::size_t i = 0; i < file.skipped.size() && i < 10; ++i) out += fmt::format("  {}\n", file.skipped[i]);
    if (file.skipped.size() > 10) out += fmt::format("  and {} more\n", file.skipped.size() - 10);
  }
  return write_output(options.output, out);
}

}  // namespace

void add_info_command(CLI::App& app, int& status) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* info = app.add_subcommand(
      "info",
      "What MODEL holds, in a few lines: its format and unit, its models by type, the elements of a drawing with "
      "their ids (SVG) or handles and layers (DXF), the Bezier pieces by degree, the tight bounding box, and what "
      "a drawing draws that casteljau leaves out (text, images, block references...).");
  CLI::Option* model = info->add_option("MODEL", options->model, kModelFileHelp)->required();
  add_units_option(info, options->units);
  CLI::Option* output = info->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(info, status, {{model}, output}, [options] { return run_info(*options); });
}

}  // namespace casteljau::cli

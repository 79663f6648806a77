// Reading the models of a file of any format casteljau reads (model JSON,
// CSV point sets, SVG drawings): io/model_file.hpp says how one is chosen.
#include "casteljau/io/model_file.hpp"

#include <fmt/format.h>

#include <string>
#include <utility>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/io/svg_drawing.hpp"
#include "text.hpp"

namespace casteljau {
namespace {

/// One piecewise_bezier model per subpath of the drawing; its problems are errors.
Expected<std::vector<Model>> models_of_drawing(std::string_view text, const std::string& source, DrawingUnits units) {
  auto drawing = parse_svg_drawing(text, source, units);
  if (!drawing) return drawing.error();
  if (!drawing->problems.empty()) {
    Error first = drawing->problems.front();
    if (drawing->problems.size() > 1)
      first.message += fmt::format(" (and {} more problem{})", drawing->problems.size() - 1,
                                   drawing->problems.size() > 2 ? "s" : "");
    return first;
  }
  if (drawing->curves.empty())
    return Error{fmt::format("{}: the drawing has no path or shape to read{}", source,
                             drawing->skipped.empty() ? "" : fmt::format(" ({})", drawing->skipped.front())),
                 ErrorKind::invalid_argument};
  std::vector<Model> models;
  models.reserve(drawing->curves.size());
  for (SvgCurve& curve : drawing->curves) models.emplace_back(std::move(curve.curve));
  return models;
}

}  // namespace

Expected<std::vector<Model>> read_models(const std::filesystem::path& path, DrawingUnits units) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  const std::string source = display_name(path);
  const std::string name = path.string();
  enum class Format { json, csv, svg } format = Format::csv;
  if (io_detail::has_extension(name, ".json")) {
    format = Format::json;
  } else if (io_detail::has_extension(name, ".svg")) {
    format = Format::svg;
  } else if (!io_detail::has_extension(name, ".csv")) {
    const std::string_view content = io_detail::without_byte_order_mark(*text);
    const auto first = content.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && content[first] == '{') format = Format::json;
    if (first != std::string_view::npos && content[first] == '<') format = Format::svg;
  }
  if (format == Format::svg) return models_of_drawing(*text, source, units);
  if (units != DrawingUnits::user)
    return Error{fmt::format("{}: millimetres are asked of {}, whose numbers have no unit (--units applies to "
                             "drawings: SVG)",
                             source, format == Format::json ? "model JSON" : "a CSV point set"),
                 ErrorKind::invalid_argument};
  if (format == Format::json) return parse_models_json(*text, source);
  auto points = parse_points_csv(*text, source);
  if (!points) return points.error();
  auto curve = BezierCurve::make(std::move(*points));
  if (!curve) return with_context(curve.error(), source);
  return std::vector<Model>{Model{std::move(*curve)}};
}

}  // namespace casteljau

// Reading the models of a file of any format casteljau reads (model JSON,
// CSV point sets, SVG drawings): io/model_file.hpp says how one is chosen.
#include "casteljau/io/model_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <utility>

#include "casteljau/bezier/affine.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/dxf.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/io/svg_drawing.hpp"
#include "text.hpp"

namespace casteljau {
namespace {

/// What a drawing's reading refuses (SVG and DXF alike): its first problem,
/// saying how many more there are, or a drawing with no curve (`what` names
/// what it lacks), naming the first thing it skipped.
std::optional<Error> refusal(const std::vector<Error>& problems, bool no_curves, const std::vector<std::string>& skipped,
                             const std::string& source, std::string_view what) {
  if (!problems.empty()) {
    Error first = problems.front();
    if (problems.size() > 1)
      first.message += fmt::format(" (and {} more problem{})", problems.size() - 1, problems.size() > 2 ? "s" : "");
    return first;
  }
  if (!no_curves) return std::nullopt;
  return Error{fmt::format("{}: the drawing has no {} to read{}", source, what,
                           skipped.empty() ? "" : fmt::format(" ({})", skipped.front())),
               ErrorKind::invalid_argument};
}

/// One piecewise_bezier model per subpath of the drawing; its problems are errors.
Expected<FileModels> models_of_drawing(std::string_view text, const std::string& source, DrawingUnits units) {
  auto drawing = parse_svg_drawing(text, source, units);
  if (!drawing) return drawing.error();
  if (auto refused = refusal(drawing->problems, drawing->curves.empty(), drawing->skipped, source, "path or shape"))
    return *refused;
  FileModels file;
  file.format = ModelFileFormat::svg;
  file.insunits = units == DrawingUnits::millimetres ? 4 : 0;
  file.page_bottom = drawing->page_bottom;
  file.skipped = std::move(drawing->skipped);
  file.models.reserve(drawing->curves.size());
  for (SvgCurve& curve : drawing->curves) {
    file.models.emplace_back(std::move(curve.curve));
    file.origins.push_back({curve.element, curve.id, "", curve.line});
  }
  return file;
}

/// One curve model per curve entity; problems are errors; millimetres
/// through $INSUNITS.
Expected<FileModels> models_of_dxf(std::string_view text, const std::string& source, DrawingUnits units) {
  auto drawing = parse_dxf_drawing(text, source);
  if (!drawing) return drawing.error();
  FileModels file;
  file.format = ModelFileFormat::dxf;
  file.insunits = units == DrawingUnits::millimetres ? 4 : drawing->insunits;
  file.skipped = drawing->skipped;
  if (auto refused = refusal(drawing->problems, drawing->curves.empty(), drawing->skipped, source, "curve entity"))
    return *refused;
  double scale = 1.0;
  if (units == DrawingUnits::millimetres) {
    scale = dxf_unit_millimetres(drawing->insunits);
    if (scale == 0.0)
      return Error{fmt::format("{}: millimetres need the drawing's units, and its $INSUNITS is {} ({})", source,
                               drawing->insunits, drawing->insunits == 0 ? "unitless" : "not a length unit"),
                   ErrorKind::invalid_argument};
  }
  std::vector<Model>& models = file.models;
  models.reserve(drawing->curves.size());
  for (DxfCurve& curve : drawing->curves) {
    file.origins.push_back({curve.entity, curve.handle, curve.layer, curve.line});
    if (scale == 1.0) {
      models.push_back(std::move(curve.curve));
      continue;
    }
    const AffineMap map = AffineMap::scale(dimension_of(curve.curve), scale);
    auto scaled = std::visit(
        [&](const auto& c) -> Expected<Model> {
          using T = std::decay_t<decltype(c)>;
          if constexpr (std::is_same_v<T, BezierCurve> || std::is_same_v<T, PiecewiseBezierCurve> ||
                        std::is_same_v<T, BSplineCurve>) {
            auto t = transformed(c, map);
            if (!t) return t.error();
            return Model{std::move(*t)};
          } else {
            return Model{c};
          }
        },
        curve.curve);
    if (!scaled) return with_context(scaled.error(), source);
    models.push_back(std::move(*scaled));
  }
  return file;
}

}  // namespace

const char* format_name(ModelFileFormat format) {
  switch (format) {
    case ModelFileFormat::model_json: return "model JSON";
    case ModelFileFormat::csv: return "CSV point set";
    case ModelFileFormat::svg: return "SVG drawing";
    case ModelFileFormat::dxf: return "DXF drawing";
  }
  return "";
}

std::string skipped_summary(const std::vector<std::string>& skipped) {
  // The readers write "line 7: <text> (why)" (SVG) and "line 300: TEXT" (DXF).
  std::vector<std::pair<std::string, std::size_t>> kinds;
  for (const std::string& entry : skipped) {
    const auto colon = entry.find(": ");
    std::string kind = colon == std::string::npos ? entry : entry.substr(colon + 2);
    if (const auto paren = kind.find(" ("); paren != std::string::npos) kind.erase(paren);
    if (kind.size() > 2 && kind.front() == '<' && kind.back() == '>') kind = kind.substr(1, kind.size() - 2);
    auto found = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == kind; });
    if (found == kinds.end()) kinds.emplace_back(kind, 1);
    else ++found->second;
  }
  std::string out;
  for (const auto& [kind, count] : kinds) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", count, kind);
  return out;
}

Expected<std::vector<Model>> read_models(const std::filesystem::path& path, DrawingUnits units) {
  auto read = read_file_models(path, units);
  if (!read) return read.error();
  return std::move(read->models);
}

Expected<FileModels> read_file_models(const std::filesystem::path& path, DrawingUnits units) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  const std::string source = display_name(path);
  const std::string name = path.string();
  ModelFileFormat format = ModelFileFormat::csv;
  if (io_detail::has_extension(name, ".json")) {
    format = ModelFileFormat::model_json;
  } else if (io_detail::has_extension(name, ".svg")) {
    format = ModelFileFormat::svg;
  } else if (io_detail::has_extension(name, ".dxf")) {
    format = ModelFileFormat::dxf;
  } else if (!io_detail::has_extension(name, ".csv")) {
    const std::string_view content = io_detail::without_byte_order_mark(*text);
    const auto first = content.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && content[first] == '{') format = ModelFileFormat::model_json;
    if (first != std::string_view::npos && content[first] == '<') format = ModelFileFormat::svg;
    // DXF: a group code 0 (or a 999 comment) on the first line, then SECTION.
    if (first != std::string_view::npos && (content.substr(first, 4) == "999\n" || content.substr(first, 5) == "999\r\n" ||
                                            ((content.substr(first, 2) == "0\n" || content.substr(first, 3) == "0\r\n") &&
                                             content.find("SECTION") < first + 16)))
      format = ModelFileFormat::dxf;
  }
  if (format == ModelFileFormat::svg) return models_of_drawing(*text, source, units);
  if (format == ModelFileFormat::dxf) return models_of_dxf(*text, source, units);
  if (units != DrawingUnits::user)
    return Error{fmt::format("{}: millimetres are asked of {}, whose numbers have no unit (--units applies to "
                             "drawings: SVG, DXF)",
                             source, format == ModelFileFormat::model_json ? "model JSON" : "a CSV point set"),
                 ErrorKind::invalid_argument};
  FileModels file;
  file.format = format;
  if (format == ModelFileFormat::model_json) {
    auto models = parse_models_json(*text, source);
    if (!models) return models.error();
    file.models = std::move(*models);
  } else {
    auto points = parse_points_csv(*text, source);
    if (!points) return points.error();
    auto curve = BezierCurve::make(std::move(*points));
    if (!curve) return with_context(curve.error(), source);
    file.models.emplace_back(std::move(*curve));
  }
  for (const Model& model : file.models) file.origins.push_back({type_name(model), "", "", 0});
  return file;
}

}  // namespace casteljau

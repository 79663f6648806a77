// Model JSON, the document (docs/formats.md, "Model JSON"): one model object,
// or {"models": [...]} for several; the dispatch by a model's type; and the
// public entry points that read JSON text and files. The steps
// behind them: model_json_syntax.cpp (text -> document), model_json_values.cpp
// (values -> containers, make()'s errors placed), model_json_curves.cpp and
// model_json_surfaces.cpp (one reader per type), model_json_write.cpp.
#include "casteljau/io/model_json.hpp"

#include <utility>

#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "model_json_reader.hpp"
#include "text.hpp"

namespace casteljau {
namespace io_detail {

Expected<Model> read_model(JsonReader& reader, const json& value, const std::string& path) {
  if (!value.is_object()) return reader.at(path, "expected a model object, found " + describe(value));
  if (!value.contains("type")) {
    return reader.at(
        path, "missing field 'type' (bezier, piecewise_bezier, bspline, bezier_surface, bspline_surface, coons)");
  }
  const json& type = value["type"];
  if (!type.is_string()) return reader.at(member(path, "type"), "expected a string, found " + describe(type));
  const auto& name = type.get_ref<const std::string&>();
  if (name == "bezier") {
    auto curve = read_bezier(reader, value, path);
    if (!curve) return curve.error();
    return Model{std::move(*curve)};
  }
  if (name == "piecewise_bezier") return read_piecewise_bezier(reader, value, path);
  if (name == "bspline") return read_bspline(reader, value, path);
  if (name == "bezier_surface") return read_bezier_surface(reader, value, path);
  if (name == "bspline_surface") return read_bspline_surface(reader, value, path);
  if (name == "coons") return read_coons(reader, value, path);
  return reader.at(member(path, "type"), "unknown model type " + in_quotes(name) +
                                             " (model JSON version 1 has bezier, piecewise_bezier, bspline, "
                                             "bezier_surface, bspline_surface, coons)");
}

namespace {

/// The whole document: one model object, or {"models": [MODEL, ...]}.
Expected<std::vector<Model>> read_document(JsonReader& reader, const json& root) {
  if (!root.is_object()) {
    return reader.at("", "expected an object (one model, or {\"models\": [...]} for several), found " + describe(root));
  }
  if (!root.contains("models")) {
    reader.start_model();
    auto model = read_model(reader, root, "");
    if (!model) return model.error();
    return std::vector<Model>{std::move(*model)};
  }
  for (const auto& [name, value] : root.items()) {
    if (name != "models") {
      return reader.at("",
                       "unknown field " + in_quotes(name) + " (a file of several models has only the field 'models')");
    }
  }
  const json& models = root["models"];
  if (!models.is_array()) return reader.at("models", "expected an array of models, found " + describe(models));
  if (models.empty()) return reader.at("models", "the array is empty, expected at least one model");
  std::vector<Model> result;
  result.reserve(models.size());
  for (std::size_t i = 0; i < models.size(); ++i) {
    reader.start_model();  // a coons patch's boundaries share their patch's budget
    auto model = read_model(reader, models[i], element("models", i));
    if (!model) return model.error();
    result.push_back(std::move(*model));
  }
  return result;
}

}  // namespace
}  // namespace io_detail

Expected<std::vector<Model>> parse_models_json(std::string_view text, const std::string& source) {
  const auto document = io_detail::parse_json_document(text, source);
  if (!document) return document.error();
  io_detail::JsonReader reader(source);
  return io_detail::read_document(reader, *document);
}

Expected<std::vector<Model>> read_models_json(const std::filesystem::path& path) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  return parse_models_json(*text, display_name(path));
}

}  // namespace casteljau

#pragma once
// Model JSON, version 1 (docs/formats.md): one model object per file, or
// {"models": [...]} for several. Unknown fields are errors, not ignored.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/io/model.hpp"

namespace casteljau {

/// Parses model JSON text; `source` names it in errors ("model.json: line 3,
/// column 5: ..." for syntax errors, "model.json: models[1].control_points[2][0]
/// is not a number" for bad fields, "unknown field 'colour' in models[0]").
Expected<std::vector<Model>> parse_models_json(std::string_view text, const std::string& source);

/// Reads and parses a model JSON file.
Expected<std::vector<Model>> read_models_json(const std::filesystem::path& path);

/// The model as model JSON (one object), numbers in shortest round-trip form.
std::string to_json(const Model& model);

}  // namespace casteljau

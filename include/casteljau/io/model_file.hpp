#pragma once
// The models of a file in any format casteljau reads: model JSON, a CSV point
// set, an SVG or a DXF drawing. What every command that takes a MODEL calls.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/io/drawing_units.hpp"
#include "casteljau/io/model.hpp"

namespace casteljau {

/// Reads the models of a file that is model JSON, a CSV point set, an SVG
/// drawing or a DXF drawing (io/dxf.hpp: one model per curve entity, in the
/// drawing's units, or in mm through its $INSUNITS). A point set is the control polygon of one polynomial Bézier
/// curve; a drawing gives one piecewise_bezier model per subpath in document
/// order (io/svg_drawing.hpp: element and group transforms applied, upright:
/// y up from the page's bottom edge),
/// in `units`. The format is chosen by the extension (".json" JSON, ".csv"
/// CSV, ".svg" SVG, ".dxf" DXF, any case), otherwise by content: JSON when the first
/// character that is not blank (after an optional byte order mark) is '{', SVG
/// when it is '<', DXF when the first line is a group code 0 or 999 before a
/// SECTION, else CSV. A drawing's problems are errors here (the first
/// one, naming its line and element), and so is a drawing that draws no curve;
/// DrawingUnits::millimetres asked of model JSON or CSV is an error too (their
/// numbers have no unit).
Expected<std::vector<Model>> read_models(const std::filesystem::path& path,
                                         DrawingUnits units = DrawingUnits::user);

/// Where a model came from in its file.
struct ModelOrigin {
  /// The SVG element ("path", "rect"...), the DXF entity ("LINE", "SPLINE"...),
  /// or the model's type for model JSON and CSV ("bezier", "bspline_surface"...).
  std::string element;
  std::string id;        ///< the SVG element's id, the DXF entity's handle; "" when none
  std::string layer;     ///< the DXF entity's layer; "" for the other formats
  std::size_t line = 0;  ///< the line where the element starts (drawings); 0 for model JSON and CSV
};

/// The formats read_models reads.
enum class ModelFileFormat { model_json, csv, svg, dxf };

/// The format as messages and `casteljau info` name it: "model JSON", "CSV
/// point set", "SVG drawing", "DXF drawing".
const char* format_name(ModelFileFormat format);

/// The models of a file with what the file states besides them.
struct FileModels {
  std::vector<Model> models;
  std::vector<ModelOrigin> origins;  ///< one per model: a drawing's subpaths share their element's
  ModelFileFormat format = ModelFileFormat::model_json;
  bool is_drawing() const { return format == ModelFileFormat::svg || format == ModelFileFormat::dxf; }
  /// The unit of the numbers as DXF's $INSUNITS code (io/dxf.hpp:
  /// dxf_unit_millimetres, dxf_unit_name): 4 for a drawing read in
  /// millimetres, a DXF drawing's own $INSUNITS when read in its units; 0
  /// when the file states none (model JSON, CSV, an SVG in its user units, a
  /// unitless DXF).
  int insunits = 0;
  /// An SVG drawing's page bottom in its user units (SvgDrawing::page_bottom).
  std::optional<double> page_bottom;
  /// What a drawing draws that is left out (SvgDrawing::skipped, DxfDrawing::skipped).
  std::vector<std::string> skipped;
};

/// What a drawing left out (FileModels::skipped), counted by kind in the order
/// first met: "2 text, 1 image" (SVG's "<text>", DXF's "TEXT" as the readers
/// name them).
std::string skipped_summary(const std::vector<std::string>& skipped);

/// read_models, with where each model came from, the unit the file states
/// (issue 39: conversions lost it, a DXF in inches became a STEP in
/// millimetres of the same numbers) and what a drawing draws that was left
/// out. What `casteljau info` reports.
Expected<FileModels> read_file_models(const std::filesystem::path& path, DrawingUnits units = DrawingUnits::user);

}  // namespace casteljau

#pragma once
// The models of a file in any format casteljau reads: model JSON, a CSV point
// set, an SVG or a DXF drawing. What every command that takes a MODEL calls.

#include <filesystem>
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

/// The models of a file and the length unit of their numbers.
struct UnitModels {
  std::vector<Model> models;
  /// The unit as DXF's $INSUNITS code (io/dxf.hpp: dxf_unit_millimetres,
  /// dxf_unit_name): 4 for a drawing read in millimetres, a DXF drawing's own
  /// $INSUNITS when read in its units; 0 when the file states none (model
  /// JSON, CSV, an SVG read in its user units, a unitless DXF).
  int insunits = 0;
};

/// read_models, with the unit the file states (issue 39: conversions lost it,
/// a DXF in inches became a STEP in millimetres of the same numbers).
Expected<UnitModels> read_models_with_unit(const std::filesystem::path& path,
                                           DrawingUnits units = DrawingUnits::user);

}  // namespace casteljau

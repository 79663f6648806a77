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
/// order (io/svg_drawing.hpp: element and group transforms applied, y down),
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

}  // namespace casteljau

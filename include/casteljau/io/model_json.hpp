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

/// Parses model JSON text (nlohmann-json's SAX parser feeding our own
/// document builder); `source` names it in errors. Every message is
/// "<source>, <where>: <what>":
/// - syntax errors give the line and column (1-based; the column counts UTF-8
///   characters): "model.json, line 3, column 5: syntax error while parsing
///   object key - invalid literal; last read: '{x'"; so do numbers that
///   overflow a double: "model.json, line 2, column 40, control_points[1][0]:
///   the number '1e999' overflows to infinity, numbers must be finite";
/// - the JSON's shape is checked here, each error at its path: unknown or
///   missing fields ("models[0]: unknown field 'colour' (a bezier model has
///   the fields type, control_points, weights)"), duplicate keys, values of
///   the wrong kind ("models[1].control_points[2][0]: expected a number,
///   found the string 'a'"), nested arrays that do not flatten (points of
///   mixed dimension, ragged nets "control_points[2]: row 2 has 3 points, row
///   0 has 4 (a control net is rectangular)", weights[i][j] not in the net's
///   shape), a degree that is not a whole number, more than
///   tolerances::kMaxControlPoints control points in one model (a coons
///   patch's four boundaries together) or tolerances::kMaxInputValues values;
/// - the values are the types' make() to judge (BezierCurve,
///   PiecewiseBezierCurve, BSplineCurve, BezierSurface, BSplineSurface,
///   CoonsPatch, ControlNet, PointArray): their message, unchanged, at the
///   field it is about ("m.json, models[1].knots: knot 4 (0.5) is smaller than
///   knot 3 (0.7), knots must be non-decreasing"; a surface's direction is the
///   element of the pair, "knots[1]: ..."); the corner gaps of a coons patch
///   at "boundaries";
/// - a bspline's knots may have n + p + 2 values or, in the Rhino/openNURBS
///   convention, n + p (completed by knots_from_rhino, whose errors say the
///   convention); a count that is neither says both.
/// Each boundary of a coons patch, a curve model of any kind, becomes a
/// B-spline curve (to_bspline, from_bezier_pieces) that the patch maps to [0,1].
/// O(size of the text); holds the parsed document in memory once.
Expected<std::vector<Model>> parse_models_json(std::string_view text, const std::string& source);

/// Reads and parses a model JSON file (errors name the file as given).
Expected<std::vector<Model>> read_models_json(const std::filesystem::path& path);


/// The model as model JSON (one object, one line), numbers in shortest
/// round-trip form, so parse_models_json(to_json(m)) gives m back exactly.
/// A piecewise curve writes polynomial pieces as arrays of points and
/// rational pieces as bezier objects; a bspline always writes its full knot
/// vector (n+p+2 knots), also when it was read in the Rhino convention; a
/// surface writes nested control_points[i][j] and weights[i][j]; a coons
/// patch writes its blending and its four boundaries as the bspline models
/// it holds (on [0,1]), so the round trip is exact for every kind.
std::string to_json(const Model& model);

/// Several models: the single object for one model, {"models": [...]} for
/// more, ending with a newline.
std::string models_to_json(const std::vector<Model>& models);

}  // namespace casteljau

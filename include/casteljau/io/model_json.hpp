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

/// Parses model JSON text (nlohmann-json's SAX parser feeding our own checks);
/// `source` names it in errors. Messages are "<source>, <where>: <what>":
/// - syntax errors give the line and column (1-based; the column counts UTF-8
///   characters): "model.json, line 3, column 5: syntax error while parsing
///   object key - invalid literal; last read: '{x'";
/// - numbers that overflow a double: "model.json, line 2, column 40,
///   control_points[1][0]: the number 1e999 overflows to infinity";
/// - bad fields name their path: "model.json, models[1].control_points[2][0]:
///   expected a number, found a string", "model.json, models[0]: unknown field
///   'colour' (a bezier model has type, control_points, weights)";
/// - empty control polygons, mixed dimensions, weights <= 0, a weights count
///   that differs from the control points', duplicate keys, more than
///   tolerances::kMaxControlPoints control points in one model;
/// - bspline models: a degree that is not a whole number in [0,
///   kMaxBSplineDegree], fewer than p+1 control points, a knot count that is
///   neither n+p+2 nor the Rhino/openNURBS n+p (converted by knots_from_rhino),
///   knots that validate_knots refuses ("m.json, knots: knot 4 (0.5) is
///   smaller than knot 3 (0.7), knots must be non-decreasing");
/// - surfaces (control_points[i][j]: i along u, j along v): ragged nets
///   ("m.json, control_points[2]: row 2 has 3 points, row 0 has 4 (a control
///   net is rectangular)"), points of mixed dimension, weights[i][j] whose
///   shape differs from the net's ("weights[1]: row 1 has 3 weights, the
///   control net has 4 points per row") or that are <= 0 (path of the
///   weight); bspline_surface: degree [p, q] (each as a curve's degree, path
///   degree[0] / degree[1]), fewer than p+1 rows or q+1 points per row, knots
///   [[u], [v]] checked per direction like a curve's (path knots[0] /
///   knots[1], full or Rhino count);
/// - coons: blending other than linear/cubic, unknown or missing boundaries
///   (u0, u1, v0, v1), a boundary that is a surface, a piecewise boundary
///   whose pieces do not meet, and the corner check of CoonsPatch::make
///   ("m.json, boundaries: the boundaries u1 and v0 do not meet at ...").
///   Each boundary, a curve model of any kind, becomes a B-spline curve
///   (to_bspline, from_bezier_pieces) that the patch maps to [0,1].
/// O(size of the text); holds the parsed document in memory once.
Expected<std::vector<Model>> parse_models_json(std::string_view text, const std::string& source);

/// Reads and parses a model JSON file (errors name the file as given).
Expected<std::vector<Model>> read_models_json(const std::filesystem::path& path);

/// Reads the models of a file that is either model JSON or a CSV point set;
/// a point set is the control polygon of one polynomial Bézier curve. The
/// format is chosen by the extension (".json" JSON, ".csv" CSV, any case),
/// otherwise by content: JSON when the first character that is not blank
/// (after an optional byte order mark) is '{', else CSV.
Expected<std::vector<Model>> read_models(const std::filesystem::path& path);

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

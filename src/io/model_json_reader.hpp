#pragma once
// Reading model JSON, the parts shared by the files of src/io/model_json*.cpp
// (private to src/io). How the reading is divided:
//
//   model_json_syntax.cpp    text -> JSON document (syntax errors with line
//                            and column, duplicate keys, the size limits)
//   model_json_values.cpp    JSON values -> the containers make() takes
//                            (numbers, points, nets, degrees, knots, weights)
//                            and make()'s errors placed at their field
//   model_json_curves.cpp    bezier, piecewise_bezier, bspline
//   model_json_surfaces.cpp  bezier_surface, bspline_surface, coons
//   model_json.cpp           the document: one model or {"models": [...]},
//                            the dispatch by type, the public entry points
//   model_json_write.cpp     models -> text
//
// The division of labour: this layer checks only the JSON's shape (types of
// fields, arrays of numbers, nested arrays that flatten into a rectangle, the
// size limits) and where everything is; the types' make() is the one
// validator of the values (degrees, counts, knots, weights, coordinates).
// Every message is "<file>, <path>: <what>", the path written as in
// JavaScript (models[1].knots[3]), the top-level object "the top level".

#include <cstddef>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/surfaces/control_net.hpp"

namespace casteljau::io_detail {

using json = nlohmann::json;

/// Parses JSON text strictly (RFC 8259, nothing but blanks after the
/// document) into a document; refuses duplicate keys, numbers that overflow
/// a double, more than tolerances::kMaxInputValues values and arrays longer
/// than tolerances::kMaxControlPoints while parsing. Errors:
/// "<source>, line L, column C[, path]: <what>" (column in UTF-8 characters).
Expected<json> parse_json_document(std::string_view text, const std::string& source);

/// "models[1].knots" from "models[1]" and "knots" ("knots" from "" and "knots").
std::string member(const std::string& path, std::string_view name);
/// "knots[3]" from "knots" and 3.
std::string element(const std::string& path, std::size_t index);
/// What a value is, for messages: "the string 'abc'", "the number 3", "an array", "null".
std::string describe(const json& value);

/// A knot vector as read: the values in the full convention (converted from
/// the Rhino/openNURBS one when the count says so) and a note for make()'s
/// knot errors that says which convention was read or could have been.
struct KnotsRead {
  std::vector<double> values;
  std::string note;
};

/// The reader of one file: its name for messages, and what the current model
/// may still hold (tolerances::kMaxControlPoints control points in all).
class JsonReader {
 public:
  explicit JsonReader(std::string source) : source_(std::move(source)) {}

  /// "<source>, <path>: <what>".
  Error at(const std::string& path, const std::string& what) const;

  /// An error of a type's make() for the model at `path` whose JSON fields
  /// are `fields`, placed at the field it is about. make()'s messages name
  /// their subject in words first ("weight 2 is -1, ...", "knot 5 (0.5) is
  /// smaller than ...", "4 control points, a B-spline of degree 4 ..."): the
  /// earliest subject word decides the field ("knots_u: " and "degree_v" the
  /// element of a pair). A message naming no field of the model stays at the
  /// model's path. `notes` are added to the errors of the field they name
  /// ("knots", "knots[1]").
  Error refused(const std::string& path, const Error& error, std::initializer_list<std::string_view> fields,
                std::initializer_list<std::pair<std::string_view, std::string_view>> notes = {}) const;

  /// Starts a new model of the document: its control point budget is full
  /// again (the boundaries of a coons patch share the patch's).
  void start_model() { budget_ = tolerances::kMaxControlPoints; }

  /// Refuses a member of `object` that is not in `fields` ("unknown field
  /// 'colour' (a bezier model has the fields type, control_points,
  /// weights)"; `kind` names the object), then one of `required` that is
  /// missing ("missing field 'knots'").
  Status known_fields(const json& object, const std::string& path, std::initializer_list<std::string_view> fields,
                      const char* kind, std::initializer_list<std::string_view> required = {}) const;

  /// A JSON number (finite: the parser refuses overflow).
  Expected<double> number(const json& value, const std::string& path) const;
  /// An array of numbers.
  Expected<std::vector<double>> numbers(const json& value, const std::string& path) const;
  /// A whole number that fits an int (a degree): 3 and 3.0 alike. Its range
  /// is make()'s to judge.
  Expected<int> whole_number(const json& value, const std::string& path) const;
  /// An array of exactly two values ([p, q], [[u knots], [v knots]]);
  /// `expected` says what they are.
  Status pair(const json& value, const std::string& path, const char* expected) const;

  /// An array of points (arrays of numbers, all of one length) as a
  /// PointArray (PointArray::make; empty for an empty array, which make()
  /// refuses); counts against the model's control point budget.
  Expected<PointArray> points(const json& value, const std::string& path);
  /// A net control_points[i][j]: an array of rows of points, every row as
  /// long as row 0 and every point of one dimension, as a ControlNet
  /// (ControlNet::make, which refuses an empty one).
  Expected<ControlNet> net(const json& value, const std::string& path);

  /// A knot vector of `count` control points of degree `degree` (the values
  /// make() will check): n + p + 2 knots as given, or n + p knots in the
  /// Rhino/openNURBS convention, completed by knots_from_rhino.
  Expected<KnotsRead> knots(const json& value, const std::string& path, int degree, std::size_t count) const;

  /// The optional `weights` of a curve model: an array of numbers (empty
  /// when absent: polynomial).
  Expected<std::vector<double>> weights(const json& model, const std::string& path) const;
  /// The optional `weights[i][j]` of a surface model: rows of numbers with
  /// the shape of the net (rows x columns), returned row by row.
  Expected<std::vector<double>> net_weights(const json& model, const std::string& path, const ControlNet& net) const;

 private:
  std::string source_;
  std::size_t budget_ = tolerances::kMaxControlPoints;
};

/// A model object of any type at `path` (model_json.cpp): the dispatch that
/// the document and a coons patch's boundaries share.
Expected<Model> read_model(JsonReader& reader, const json& value, const std::string& path);

/// model_json_curves.cpp: the fields of each curve type, through its make().
Expected<BezierCurve> read_bezier(JsonReader& reader, const json& value, const std::string& path);
Expected<Model> read_piecewise_bezier(JsonReader& reader, const json& value, const std::string& path);
Expected<Model> read_bspline(JsonReader& reader, const json& value, const std::string& path);

/// model_json_surfaces.cpp: the fields of each surface type, through its make().
Expected<Model> read_bezier_surface(JsonReader& reader, const json& value, const std::string& path);
Expected<Model> read_bspline_surface(JsonReader& reader, const json& value, const std::string& path);
Expected<Model> read_coons(JsonReader& reader, const json& value, const std::string& path);

}  // namespace casteljau::io_detail

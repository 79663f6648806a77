#include "casteljau/io/model_json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "text.hpp"

namespace casteljau {
namespace {

using json = nlohmann::json;
using io_detail::in_quotes;

// ---------------------------------------------------------------------------
// Parsing: nlohmann's SAX parser drives our own document builder, which
// knows where it is (for messages), refuses duplicate keys (the DOM parser
// silently keeps the last one) and stops early on huge inputs.

/// A failure found while parsing, before any field is checked.
struct SyntaxFailure {
  std::size_t offset = 0;  // byte offset of the offending character
  std::string path;        // where in the document, when known
  std::string what;
};

/// The 1-based "line L, column C" of a byte offset; the column counts UTF-8
/// characters (continuation bytes 10xxxxxx are not counted), as editors do.
std::string line_and_column(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  std::size_t column = 1;
  for (std::size_t i = line_start; i < offset; ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++column;
  return fmt::format("line {}, column {}", line, column);
}

class DocumentBuilder {
 public:
  json root;
  std::optional<SyntaxFailure> failure;

  // nlohmann's SAX interface (nlohmann::json_sax<json>), by duck typing.
  bool null() { return add(json(nullptr)); }
  bool boolean(bool value) { return add(json(value)); }
  bool number_integer(json::number_integer_t value) { return add(json(value)); }
  bool number_unsigned(json::number_unsigned_t value) { return add(json(value)); }
  bool number_float(json::number_float_t value, const std::string&) { return add(json(value)); }
  bool string(std::string& value) { return add(json(std::move(value))); }
  bool binary(json::binary_t&) { return fail_here("binary values are not JSON"); }  // never for JSON text
  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& name) {
    Frame& frame = stack_.back();
    if (frame.container->contains(name)) {
      frame.key = name;
      return fail_here("the key " + in_quotes(name) + " appears twice in the same object");
    }
    frame.key = std::move(name);
    return true;
  }
  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& error) {
    // `position` counts the bytes read, the offending one included, so the
    // offending byte is at position - 1 (at the end of the text for an
    // unexpected end of input).
    const std::size_t offset = position > 0 ? position - 1 : 0;
    if (error.id == 406) {  // out_of_range.406: a number beyond the range of double
      // The whole number token has been read: point at its first character.
      const std::size_t start = position >= last_token.size() ? position - last_token.size() : 0;
      failure = SyntaxFailure{start, pending_path(),
                              "the number " + in_quotes(last_token) + " overflows to infinity, numbers must be finite"};
      return false;
    }
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line
    // 1, column 4: syntax error while parsing ...": keep what follows "column N: ".
    std::string_view text = error.what();
    if (const auto column = text.find(", column "); column != text.npos) {
      if (const auto colon = text.find(": ", column); colon != text.npos) text.remove_prefix(colon + 2);
    } else if (const auto bracket = text.find("] "); bracket != text.npos) {
      text.remove_prefix(bracket + 2);
    }
    failure = SyntaxFailure{offset, {}, io_detail::printable(text, 200)};
    return false;
  }

 private:
  struct Frame {
    json* container;
    std::string key;  // objects: the key of the member being read
  };

  /// Where the next value goes: the path of the value that is about to be
  /// added (failures are found before it is).
  std::string pending_path() const {
    std::string out;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Frame& frame = stack_[i];
      const bool top = i + 1 == stack_.size();
      if (frame.container->is_array()) {
        const std::size_t size = frame.container->size();
        out += fmt::format("[{}]", top ? size : size - 1);
      } else {
        if (!out.empty()) out += '.';
        out += io_detail::printable(frame.key);
      }
    }
    return out;
  }

  bool fail_here(std::string what) {
    failure = SyntaxFailure{offset_hint_, pending_path(), std::move(what)};
    return false;
  }

  /// Adds a value where the parser is; returns where it lives, or nullptr
  /// when a limit refuses it.
  json* place(json&& value) {
    if (++values_ > tolerances::kMaxInputValues) {
      fail_here(fmt::format("more than {} JSON values, the limit for one model file", tolerances::kMaxInputValues));
      return nullptr;
    }
    if (stack_.empty()) {
      root = std::move(value);
      return &root;
    }
    Frame& frame = stack_.back();
    if (frame.container->is_array()) {
      if (frame.container->size() >= tolerances::kMaxControlPoints) {
        fail_here(
            fmt::format("an array of more than {} elements, the limit for one model", tolerances::kMaxControlPoints));
        return nullptr;
      }
      frame.container->push_back(std::move(value));
      return &frame.container->back();
    }
    json& slot = (*frame.container)[frame.key];
    slot = std::move(value);
    return &slot;
  }

  bool add(json&& value) { return place(std::move(value)) != nullptr; }

  bool open(json&& container) {
    json* where = place(std::move(container));
    if (where == nullptr) return false;
    stack_.push_back(Frame{where, {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  std::vector<Frame> stack_;
  std::size_t values_ = 0;
  // Failures found by the builder itself (duplicate keys, limits) carry no
  // byte offset from the parser; they are reported by path only.
  std::size_t offset_hint_ = std::string_view::npos;
};

// ---------------------------------------------------------------------------
// Checking the document, field by field. Paths are written as in JavaScript:
// models[1].control_points[2][0]; the empty path is the top-level object.

std::string member(const std::string& path, std::string_view name) {
  return path.empty() ? std::string(name) : path + "." + std::string(name);
}
std::string element(const std::string& path, std::size_t index) { return fmt::format("{}[{}]", path, index); }

/// "a string ('abc')", "the number 3", "an array": what a value is, for messages.
std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case json::value_t::string:
      return "the string " + in_quotes(value.get_ref<const std::string&>());
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return fmt::format("the number {}", value.get<double>());
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    default:
      return "a value that is not JSON";
  }
}

class Checker {
 public:
  explicit Checker(std::string source) : source_(std::move(source)) {}

  Error at(const std::string& path, const std::string& what) const {
    return Error{source_ + ", " + (path.empty() ? std::string("the top level") : path) + ": " + what};
  }

  Expected<std::vector<Model>> document(const json& root) {
    if (!root.is_object()) {
      return at("", "expected an object (one model, or {\"models\": [...]} for several), found " + describe(root));
    }
    if (!root.contains("models")) {
      auto model = this->model(root, "");
      if (!model) return model.error();
      return std::vector<Model>{std::move(*model)};
    }
    for (const auto& [name, value] : root.items()) {
      if (name != "models")
        return at("", "unknown field " + in_quotes(name) + " (a file of several models has only the field 'models')");
    }
    const json& models = root["models"];
    if (!models.is_array()) return at("models", "expected an array of models, found " + describe(models));
    if (models.empty()) return at("models", "the array is empty, expected at least one model");
    std::vector<Model> result;
    result.reserve(models.size());
    for (std::size_t i = 0; i < models.size(); ++i) {
      auto model = this->model(models[i], element("models", i));
      if (!model) return model.error();
      result.push_back(std::move(*model));
    }
    return result;
  }

 private:
  /// Refuses any member not in `allowed`; `kind` names the model in the message.
  Status known_fields(const json& object, const std::string& path, std::initializer_list<std::string_view> allowed,
                      const char* kind) const {
    for (const auto& [name, value] : object.items()) {
      bool known = false;
      for (const auto field : allowed) known = known || name == field;
      if (!known) {
        std::string list;
        for (const auto field : allowed) list += (list.empty() ? "" : ", ") + std::string(field);
        return at(path, "unknown field " + in_quotes(name) + " (" + kind + " has the fields " + list + ")");
      }
    }
    return {};
  }

  Expected<Model> model(const json& value, const std::string& path) {
    if (!value.is_object()) return at(path, "expected a model object, found " + describe(value));
    if (!value.contains("type")) return at(path,
                "missing field 'type' (bezier, piecewise_bezier, bspline, bezier_surface, bspline_surface, coons)");
    const json& type = value["type"];
    if (!type.is_string()) return at(member(path, "type"), "expected a string, found " + describe(type));
    const auto& name = type.get_ref<const std::string&>();
    budget_ = tolerances::kMaxControlPoints;  // per model
    if (name == "bezier") {
      auto curve = bezier(value, path);
      if (!curve) return curve.error();
      return Model{std::move(*curve)};
    }
    if (name == "piecewise_bezier") return piecewise(value, path);
    if (name == "bspline") return bspline(value, path);
    if (name == "bezier_surface") return bezier_surface(value, path);
    if (name == "bspline_surface") return bspline_surface(value, path);
    if (name == "coons") return coons(value, path);
    return at(member(path, "type"), "unknown model type " + in_quotes(name) +
                                        " (model JSON version 1 has bezier, piecewise_bezier, bspline, "
                                        "bezier_surface, bspline_surface, coons)");
  }

  Expected<BezierCurve> bezier(const json& value, const std::string& path) {
    if (auto ok = known_fields(value, path, {"type", "control_points", "weights"}, "a bezier model"); !ok)
      return ok.error();
    if (!value.contains("control_points")) return at(path, "missing field 'control_points'");
    const std::string points_path = member(path, "control_points");
    auto points = this->points(value["control_points"], points_path);
    if (!points) return points.error();
    auto weights = this->weights(value, path, points->size());
    if (!weights) return weights.error();
    auto curve = BezierCurve::make(std::move(*points), std::move(*weights));
    if (!curve) return at(path, curve.error().message);  // checked above; kept as a safety net
    return curve;
  }

  /// The optional `weights` of a model with `count` control points: one
  /// finite number > 0 each (empty when the field is absent: polynomial).
  Expected<std::vector<double>> weights(const json& value, const std::string& path, std::size_t count) const {
    std::vector<double> weights;
    if (!value.contains("weights")) return weights;
    const std::string weights_path = member(path, "weights");
    const json& list = value["weights"];
    if (!list.is_array()) return at(weights_path, "expected an array of numbers, found " + describe(list));
    if (list.size() != count) {
      return at(weights_path, fmt::format("{} weight{} for {} control point{}, expected one weight per control point",
                                          list.size(), list.size() == 1 ? "" : "s", count, count == 1 ? "" : "s"));
    }
    weights.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
      auto w = number(list[i], element(weights_path, i));
      if (!w) return w.error();
      if (!(*w > 0.0))
        return at(element(weights_path, i), fmt::format("the weight {} is not > 0, weights must be positive", *w));
      weights.push_back(*w);
    }
    return weights;
  }

  /// A B-spline or NURBS curve: degree, knots (full, or the Rhino/openNURBS
  /// convention with two knots fewer), control points, optional weights.
  Expected<Model> bspline(const json& value, const std::string& path) {
    if (auto ok = known_fields(value, path, {"type", "degree", "knots", "control_points", "weights"},
                               "a bspline model");
        !ok) {
      return ok.error();
    }
    for (const char* field : {"degree", "knots", "control_points"}) {
      if (!value.contains(field)) return at(path, fmt::format("missing field '{}'", field));
    }
    // degree: a whole number in [0, kMaxBSplineDegree] (3 and 3.0 alike).
    const std::string degree_path = member(path, "degree");
    const json& degree_value = value["degree"];
    if (!degree_value.is_number()) return at(degree_path, "expected a whole number, found " + describe(degree_value));
    const double degree_number = degree_value.get<double>();
    if (!(degree_number >= 0.0 && degree_number <= tolerances::kMaxBSplineDegree) ||
        degree_number != std::floor(degree_number)) {
      return at(degree_path, fmt::format("the degree {} is not a whole number in [0, {}]", degree_number,
                                         tolerances::kMaxBSplineDegree));
    }
    const int degree = static_cast<int>(degree_number);

    const std::string points_path = member(path, "control_points");
    const json& point_list = value["control_points"];
    const auto needed = static_cast<std::size_t>(degree) + 1;
    if (point_list.is_array() && point_list.size() < needed) {
      return at(points_path, fmt::format("{} control point{}, a B-spline of degree {} needs at least {}",
                                         point_list.size(), point_list.size() == 1 ? "" : "s", degree, needed));
    }
    auto points = this->points(point_list, points_path);
    if (!points) return points.error();
    const std::size_t count = points->size();

    const std::string knots_path = member(path, "knots");
    const json& knot_list = value["knots"];
    if (!knot_list.is_array()) return at(knots_path, "expected an array of numbers, found " + describe(knot_list));
    const std::size_t full = count + needed;     // n + p + 2
    const std::size_t rhino = count + static_cast<std::size_t>(degree) - 1;  // n + p, openNURBS
    if (knot_list.size() != full && knot_list.size() != rhino) {
      return at(knots_path, fmt::format("{} knot{} for {} control points of degree {}, expected {} (control points "
                                        "+ degree + 1), or {} in the Rhino/openNURBS convention (control points + "
                                        "degree - 1)",
                                        knot_list.size(), knot_list.size() == 1 ? "" : "s", count, degree, full, rhino));
    }
    std::vector<double> knots;
    knots.reserve(knot_list.size());
    for (std::size_t i = 0; i < knot_list.size(); ++i) {
      auto knot = number(knot_list[i], element(knots_path, i));
      if (!knot) return knot.error();
      knots.push_back(*knot);
    }
    if (knots.size() == full) {
      if (auto ok = validate_knots(knots, degree, count); !ok) return at(knots_path, ok.error().message);
    } else {
      auto converted = knots_from_rhino(knots, degree, count);
      if (!converted) return at(knots_path, converted.error().message + " (read in the Rhino/openNURBS convention)");
      knots = std::move(*converted);
    }

    auto weights = this->weights(value, path, count);
    if (!weights) return weights.error();
    auto curve = BSplineCurve::make(degree, std::move(knots), std::move(*points), std::move(*weights));
    if (!curve) return at(path, curve.error().message);  // checked above; kept as a safety net
    return Model{std::move(*curve)};
  }

  // --- surfaces ------------------------------------------------------------

  /// A control net control_points[i][j]: a non-empty array of rows (i along
  /// u), each a non-empty array of points (j along v), every row as long as
  /// row 0 and every point of one dimension.
  Expected<ControlNet> net(const json& list, const std::string& path) {
    if (!list.is_array()) return at(path, "expected an array of rows of points, found " + describe(list));
    if (list.empty()) return at(path, "the control net is empty, a surface needs at least one row of control points");
    std::size_t columns = 0;
    int dimension = 0;
    std::vector<double> coordinates;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string row_path = element(path, i);
      const json& row = list[i];
      if (!row.is_array()) return at(row_path, "expected a row (an array of points), found " + describe(row));
      if (row.empty()) return at(row_path, "the row is empty, every row of a control net needs at least one point");
      if (i == 0) {
        columns = row.size();
      } else if (row.size() != columns) {
        return at(row_path, fmt::format("row {} has {} point{}, row 0 has {} (a control net is rectangular)", i,
                                        row.size(), row.size() == 1 ? "" : "s", columns));
      }
      auto points = this->points(row, row_path);
      if (!points) return points.error();
      if (i == 0) {
        dimension = points->dimension();
        coordinates.reserve(list.size() * columns * static_cast<std::size_t>(dimension));
      } else if (points->dimension() != dimension) {
        return at(element(row_path, 0),
                  fmt::format("{} coordinate{}, but {} has {} (all points must have the same dimension)",
                              points->dimension(), points->dimension() == 1 ? "" : "s",
                              element(element(path, 0), 0), dimension));
      }
      for (std::size_t j = 0; j < points->size(); ++j) {
        const auto point = (*points)[j];
        coordinates.insert(coordinates.end(), point.begin(), point.end());
      }
    }
    return ControlNet::from_trusted(list.size(), columns,
                                    PointArray::from_trusted(dimension, std::move(coordinates)));
  }

  /// The optional weights[i][j] of a surface, one per control point of the
  /// net (rows x columns), each finite and > 0; returned row by row (empty
  /// when the field is absent).
  Expected<std::vector<double>> net_weights(const json& value, const std::string& path, std::size_t rows,
                                            std::size_t columns) const {
    std::vector<double> weights;
    if (!value.contains("weights")) return weights;
    const std::string weights_path = member(path, "weights");
    const json& list = value["weights"];
    if (!list.is_array()) return at(weights_path, "expected an array of rows of numbers, found " + describe(list));
    if (list.size() != rows) {
      return at(weights_path, fmt::format("{} row{} of weights for a control net of {} row{}, expected one weight "
                                          "per control point",
                                          list.size(), list.size() == 1 ? "" : "s", rows, rows == 1 ? "" : "s"));
    }
    weights.reserve(rows * columns);
    for (std::size_t i = 0; i < rows; ++i) {
      const std::string row_path = element(weights_path, i);
      const json& row = list[i];
      if (!row.is_array()) return at(row_path, "expected a row (an array of numbers), found " + describe(row));
      if (row.size() != columns) {
        return at(row_path, fmt::format("row {} has {} weight{}, the control net has {} point{} per row", i,
                                        row.size(), row.size() == 1 ? "" : "s", columns, columns == 1 ? "" : "s"));
      }
      for (std::size_t j = 0; j < columns; ++j) {
        auto w = number(row[j], element(row_path, j));
        if (!w) return w.error();
        if (!(*w > 0.0))
          return at(element(row_path, j), fmt::format("the weight {} is not > 0, weights must be positive", *w));
        weights.push_back(*w);
      }
    }
    return weights;
  }

  Expected<Model> bezier_surface(const json& value, const std::string& path) {
    if (auto ok = known_fields(value, path, {"type", "control_points", "weights"}, "a bezier_surface model"); !ok)
      return ok.error();
    if (!value.contains("control_points")) return at(path, "missing field 'control_points'");
    auto net = this->net(value["control_points"], member(path, "control_points"));
    if (!net) return net.error();
    auto weights = net_weights(value, path, net->rows(), net->columns());
    if (!weights) return weights.error();
    auto surface = BezierSurface::make(std::move(*net), std::move(*weights));
    if (!surface) return at(path, surface.error().message);
    return Model{std::move(*surface)};
  }

  /// One degree of a pair: a whole number in [0, kMaxBSplineDegree].
  Expected<int> whole_degree(const json& value, const std::string& path) const {
    if (!value.is_number()) return at(path, "expected a whole number, found " + describe(value));
    const double degree = value.get<double>();
    if (!(degree >= 0.0 && degree <= tolerances::kMaxBSplineDegree) || degree != std::floor(degree)) {
      return at(path, fmt::format("the degree {} is not a whole number in [0, {}]", degree,
                                  tolerances::kMaxBSplineDegree));
    }
    return static_cast<int>(degree);
  }

  /// The knot vector of one direction of a surface: `count` control points
  /// along it and `degree`; full (count + degree + 1 knots) or the
  /// Rhino/openNURBS convention (count + degree - 1), checked as for curves.
  Expected<std::vector<double>> direction_knots(const json& list, const std::string& path, const char* direction,
                                                int degree, std::size_t count) const {
    if (!list.is_array()) return at(path, "expected an array of numbers, found " + describe(list));
    const std::size_t full = count + static_cast<std::size_t>(degree) + 1;
    const std::size_t rhino = count + static_cast<std::size_t>(degree) - 1;
    if (list.size() != full && list.size() != rhino) {
      return at(path, fmt::format("{} knot{} for {} control points along {} of degree {}, expected {} (control "
                                  "points + degree + 1), or {} in the Rhino/openNURBS convention",
                                  list.size(), list.size() == 1 ? "" : "s", count, direction, degree, full, rhino));
    }
    std::vector<double> knots;
    knots.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
      auto knot = number(list[i], element(path, i));
      if (!knot) return knot.error();
      knots.push_back(*knot);
    }
    if (knots.size() == full) {
      if (auto ok = validate_knots(knots, degree, count); !ok) return at(path, ok.error().message);
      return knots;
    }
    auto converted = knots_from_rhino(knots, degree, count);
    if (!converted) return at(path, converted.error().message + " (read in the Rhino/openNURBS convention)");
    return converted;
  }

  /// A B-spline or NURBS surface: degree [p, q], knots [[u knots], [v
  /// knots]], control_points[i][j], optional weights[i][j].
  Expected<Model> bspline_surface(const json& value, const std::string& path) {
    if (auto ok = known_fields(value, path, {"type", "degree", "knots", "control_points", "weights"},
                               "a bspline_surface model");
        !ok) {
      return ok.error();
    }
    for (const char* field : {"degree", "knots", "control_points"}) {
      if (!value.contains(field)) return at(path, fmt::format("missing field '{}'", field));
    }
    const std::string degree_path = member(path, "degree");
    const json& degree_list = value["degree"];
    if (!degree_list.is_array() || degree_list.size() != 2) {
      return at(degree_path, "expected [p, q], the degrees in u and in v, found " +
                                 (degree_list.is_array() ? fmt::format("an array of {} elements", degree_list.size())
                                                         : describe(degree_list)));
    }
    auto p = whole_degree(degree_list[0], element(degree_path, 0));
    if (!p) return p.error();
    auto q = whole_degree(degree_list[1], element(degree_path, 1));
    if (!q) return q.error();

    const std::string points_path = member(path, "control_points");
    auto net = this->net(value["control_points"], points_path);
    if (!net) return net.error();
    if (net->rows() < static_cast<std::size_t>(*p) + 1) {
      return at(points_path, fmt::format("{} row{} of control points, a B-spline surface of degree {} in u needs at "
                                         "least {}",
                                         net->rows(), net->rows() == 1 ? "" : "s", *p, *p + 1));
    }
    if (net->columns() < static_cast<std::size_t>(*q) + 1) {
      return at(points_path, fmt::format("{} control point{} per row, a B-spline surface of degree {} in v needs at "
                                         "least {}",
                                         net->columns(), net->columns() == 1 ? "" : "s", *q, *q + 1));
    }

    const std::string knots_path = member(path, "knots");
    const json& knot_lists = value["knots"];
    if (!knot_lists.is_array() || knot_lists.size() != 2) {
      return at(knots_path, "expected [[u knots], [v knots]], two arrays of numbers, found " +
                                (knot_lists.is_array() ? fmt::format("an array of {} elements", knot_lists.size())
                                                       : describe(knot_lists)));
    }
    auto knots_u = direction_knots(knot_lists[0], element(knots_path, 0), "u", *p, net->rows());
    if (!knots_u) return knots_u.error();
    auto knots_v = direction_knots(knot_lists[1], element(knots_path, 1), "v", *q, net->columns());
    if (!knots_v) return knots_v.error();

    auto weights = net_weights(value, path, net->rows(), net->columns());
    if (!weights) return weights.error();
    auto surface = BSplineSurface::make(*p, *q, std::move(*knots_u), std::move(*knots_v), std::move(*net),
                                        std::move(*weights));
    if (!surface) return at(path, surface.error().message);  // checked above; kept as a safety net
    return Model{std::move(*surface)};
  }

  /// A Coons patch: optional blending (linear, the default, or cubic) and the
  /// four boundary curves u0, u1, v0, v1, each a curve model of any kind,
  /// written as a B-spline curve (CoonsPatch::make maps each to [0,1]).
  Expected<Model> coons(const json& value, const std::string& path) {
    if (auto ok = known_fields(value, path, {"type", "blending", "boundaries"}, "a coons model"); !ok)
      return ok.error();
    CoonsBlending blending = CoonsBlending::linear;
    if (value.contains("blending")) {
      const std::string blending_path = member(path, "blending");
      const json& name = value["blending"];
      if (!name.is_string()) return at(blending_path, "expected \"linear\" or \"cubic\", found " + describe(name));
      const auto& text = name.get_ref<const std::string&>();
      if (text == "linear") {
        blending = CoonsBlending::linear;
      } else if (text == "cubic") {
        blending = CoonsBlending::cubic;
      } else {
        return at(blending_path, "unknown blending " + in_quotes(text) + " (linear or cubic)");
      }
    }
    if (!value.contains("boundaries")) return at(path, "missing field 'boundaries' (u0, u1, v0, v1)");
    const std::string boundaries_path = member(path, "boundaries");
    const json& boundaries = value["boundaries"];
    if (!boundaries.is_object()) {
      return at(boundaries_path, "expected an object {\"u0\": curve, \"u1\": curve, \"v0\": curve, \"v1\": curve}, "
                                 "found " + describe(boundaries));
    }
    if (auto ok = known_fields(boundaries, boundaries_path, {"u0", "u1", "v0", "v1"}, "the boundaries object of a coons model");
        !ok) {
      return ok.error();
    }
    std::vector<BSplineCurve> curves;
    for (const char* name : {"u0", "u1", "v0", "v1"}) {
      const std::string curve_path = member(boundaries_path, name);
      if (!boundaries.contains(name)) {
        return at(boundaries_path,
                  fmt::format("missing boundary '{}' (a coons patch needs the four curves u0, u1, v0, v1)", name));
      }
      auto boundary = model(boundaries[name], curve_path);
      if (!boundary) return boundary.error();
      if (is_surface(*boundary)) {
        return at(curve_path, fmt::format("a {} model cannot be a boundary, a coons boundary is a curve (bezier, "
                                          "piecewise_bezier, bspline)",
                                          type_name(*boundary)));
      }
      auto spline = to_bspline(*boundary);
      if (!spline) return at(curve_path, spline.error().message);
      curves.push_back(std::get<BSplineCurve>(std::move(*spline)));
    }
    auto patch = CoonsPatch::make(std::move(curves[0]), std::move(curves[1]), std::move(curves[2]),
                                  std::move(curves[3]), blending);
    if (!patch) return at(boundaries_path, patch.error().message);
    return Model{std::move(*patch)};
  }

  Expected<Model> piecewise(const json& value, const std::string& path) {
    if (auto ok = known_fields(value, path, {"type", "pieces"}, "a piecewise_bezier model"); !ok) return ok.error();
    if (!value.contains("pieces")) return at(path, "missing field 'pieces'");
    const std::string pieces_path = member(path, "pieces");
    const json& list = value["pieces"];
    if (!list.is_array()) return at(pieces_path, "expected an array of pieces, found " + describe(list));
    if (list.empty()) return at(pieces_path, "the array is empty, a piecewise Bézier curve needs at least one piece");
    std::vector<BezierCurve> pieces;
    pieces.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string piece_path = element(pieces_path, i);
      auto curve = piece_curve(list[i], piece_path);
      if (!curve) return curve.error();
      if (!pieces.empty() && curve->dimension() != pieces.front().dimension()) {
        return at(piece_path, fmt::format("the piece has dimension {}, but {} has dimension {}", curve->dimension(),
                                          element(pieces_path, 0), pieces.front().dimension()));
      }
      pieces.push_back(std::move(*curve));
    }
    auto curve = PiecewiseBezierCurve::make(std::move(pieces));
    if (!curve) return at(path, curve.error().message);  // checked above; kept as a safety net
    return Model{std::move(*curve)};
  }

  /// One piece: an array of control points, or (rational) a bezier model object.
  Expected<BezierCurve> piece_curve(const json& piece, const std::string& path) {
    if (piece.is_object()) {
      if (!piece.contains("type")) return at(path, "missing field 'type' (a piece object is a bezier model)");
      const json& type = piece["type"];
      if (!type.is_string() || type.get_ref<const std::string&>() != "bezier") {
        return at(member(path, "type"),
                  "expected \"bezier\" (a piece object is a bezier model), found " + describe(type));
      }
      return bezier(piece, path);
    }
    if (!piece.is_array()) {
      return at(path,
                "expected a piece (an array of control points, or a bezier model object), found " + describe(piece));
    }
    auto points = this->points(piece, path);
    if (!points) return points.error();
    auto curve = BezierCurve::make(std::move(*points));
    if (!curve) return at(path, curve.error().message);  // points() checked it; a safety net
    return curve;
  }

  /// A control polygon: a non-empty array of points, all of one dimension.
  Expected<PointArray> points(const json& list, const std::string& path) {
    if (!list.is_array()) return at(path, "expected an array of points, found " + describe(list));
    if (list.empty()) return at(path, "the control polygon is empty, a Bézier curve needs at least one control point");
    if (list.size() > budget_) {
      return at(path,
                fmt::format("more than {} control points in one model, the limit", tolerances::kMaxControlPoints));
    }
    budget_ -= list.size();
    std::size_t dimension = 0;
    std::vector<double> coordinates;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string point_path = element(path, i);
      const json& point = list[i];
      if (!point.is_array()) return at(point_path, "expected a point (an array of numbers), found " + describe(point));
      if (point.empty()) return at(point_path, "the point has no coordinates");
      if (i == 0) {
        dimension = point.size();
        coordinates.reserve(list.size() * dimension);
      } else if (point.size() != dimension) {
        return at(point_path, fmt::format("{} coordinate{}, but {} has {} (all points must have the same dimension)",
                                          point.size(), point.size() == 1 ? "" : "s", element(path, 0), dimension));
      }
      for (std::size_t j = 0; j < point.size(); ++j) {
        auto x = number(point[j], element(point_path, j));
        if (!x) return x.error();
        coordinates.push_back(*x);
      }
    }
    return PointArray::from_trusted(static_cast<int>(dimension), std::move(coordinates));
  }

  Expected<double> number(const json& value, const std::string& path) const {
    if (!value.is_number()) return at(path, "expected a number, found " + describe(value));
    const double x = value.get<double>();
    // The parser already refuses overflow; a finite check here costs nothing.
    if (!std::isfinite(x)) return at(path, "the number is not finite");
    return x;
  }

  std::string source_;
  std::size_t budget_ = tolerances::kMaxControlPoints;
};

// ---------------------------------------------------------------------------
// Writing.

/// A coordinate in the shortest text that reads back to the same double.
/// -0 is written "-0.0": JSON readers take "-0" for the integer 0 and lose the sign.
void write_number(fmt::memory_buffer& out, double x) {
  if (x == 0.0 && std::signbit(x)) {
    fmt::format_to(std::back_inserter(out), "-0.0");
  } else {
    fmt::format_to(std::back_inserter(out), "{}", x);
  }
}

void write_points(fmt::memory_buffer& out, const PointArray& points) {
  out.push_back('[');
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out.push_back(',');
    out.push_back('[');
    const auto point = points[i];
    for (std::size_t j = 0; j < point.size(); ++j) {
      if (j > 0) out.push_back(',');
      write_number(out, point[j]);
    }
    out.push_back(']');
  }
  out.push_back(']');
}

void write_bezier(fmt::memory_buffer& out, const BezierCurve& curve) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bezier\",\"control_points\":");
  write_points(out, curve.control_points());
  if (curve.is_rational()) {
    fmt::format_to(std::back_inserter(out), ",\"weights\":[");
    for (std::size_t i = 0; i < curve.weights().size(); ++i) {
      if (i > 0) out.push_back(',');
      write_number(out, curve.weights()[i]);
    }
    out.push_back(']');
  }
  out.push_back('}');
}

void write_numbers(fmt::memory_buffer& out, std::span<const double> values) {
  out.push_back('[');
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out.push_back(',');
    write_number(out, values[i]);
  }
  out.push_back(']');
}

/// Always the full knot vector (n + p + 2 knots), whatever convention was read.
void write_bspline(fmt::memory_buffer& out, const BSplineCurve& curve) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bspline\",\"degree\":{},\"knots\":", curve.degree());
  write_numbers(out, curve.knots());
  fmt::format_to(std::back_inserter(out), ",\"control_points\":");
  write_points(out, curve.control_points());
  if (curve.is_rational()) {
    fmt::format_to(std::back_inserter(out), ",\"weights\":");
    write_numbers(out, curve.weights());
  }
  out.push_back('}');
}

/// control_points[i][j] of a net, row by row.
void write_net(fmt::memory_buffer& out, const ControlNet& net) {
  out.push_back('[');
  for (std::size_t i = 0; i < net.rows(); ++i) {
    if (i > 0) out.push_back(',');
    out.push_back('[');
    for (std::size_t j = 0; j < net.columns(); ++j) {
      if (j > 0) out.push_back(',');
      const auto point = net(i, j);
      write_numbers(out, point);
    }
    out.push_back(']');
  }
  out.push_back(']');
}

/// weights[i][j] from the row-by-row weights of a net.
void write_net_weights(fmt::memory_buffer& out, std::span<const double> weights, std::size_t columns) {
  out.push_back('[');
  for (std::size_t i = 0; i * columns < weights.size(); ++i) {
    if (i > 0) out.push_back(',');
    write_numbers(out, weights.subspan(i * columns, columns));
  }
  out.push_back(']');
}

void write_bezier_surface(fmt::memory_buffer& out, const BezierSurface& surface) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bezier_surface\",\"control_points\":");
  write_net(out, surface.control_net());
  if (surface.is_rational()) {
    fmt::format_to(std::back_inserter(out), ",\"weights\":");
    write_net_weights(out, surface.weights(), surface.control_net().columns());
  }
  out.push_back('}');
}

/// Always the full knot vectors, whatever convention was read.
void write_bspline_surface(fmt::memory_buffer& out, const BSplineSurface& surface) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"bspline_surface\",\"degree\":[{},{}],\"knots\":[",
                 surface.degree_u(), surface.degree_v());
  write_numbers(out, surface.knots_u());
  out.push_back(',');
  write_numbers(out, surface.knots_v());
  fmt::format_to(std::back_inserter(out), "],\"control_points\":");
  write_net(out, surface.control_net());
  if (surface.is_rational()) {
    fmt::format_to(std::back_inserter(out), ",\"weights\":");
    write_net_weights(out, surface.weights(), surface.control_net().columns());
  }
  out.push_back('}');
}

/// The boundaries as the B-spline curves the patch holds (on [0,1]).
void write_coons(fmt::memory_buffer& out, const CoonsPatch& patch) {
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"coons\",\"blending\":\"{}\",\"boundaries\":{{",
                 blending_name(patch.blending()));
  const std::pair<const char*, const BSplineCurve*> boundaries[] = {
      {"u0", &patch.u0()}, {"u1", &patch.u1()}, {"v0", &patch.v0()}, {"v1", &patch.v1()}};
  for (std::size_t k = 0; k < 4; ++k) {
    if (k > 0) out.push_back(',');
    fmt::format_to(std::back_inserter(out), "\"{}\":", boundaries[k].first);
    write_bspline(out, *boundaries[k].second);
  }
  fmt::format_to(std::back_inserter(out), "}}}}");
}

void write_model(fmt::memory_buffer& out, const Model& model) {
  if (const auto* surface = std::get_if<BezierSurface>(&model)) {
    write_bezier_surface(out, *surface);
    return;
  }
  if (const auto* surface = std::get_if<BSplineSurface>(&model)) {
    write_bspline_surface(out, *surface);
    return;
  }
  if (const auto* patch = std::get_if<CoonsPatch>(&model)) {
    write_coons(out, *patch);
    return;
  }
  if (const auto* curve = std::get_if<BezierCurve>(&model)) {
    write_bezier(out, *curve);
    return;
  }
  if (const auto* curve = std::get_if<BSplineCurve>(&model)) {
    write_bspline(out, *curve);
    return;
  }
  const auto& piecewise = std::get<PiecewiseBezierCurve>(model);
  fmt::format_to(std::back_inserter(out), "{{\"type\":\"piecewise_bezier\",\"pieces\":[");
  for (std::size_t i = 0; i < piecewise.pieces().size(); ++i) {
    if (i > 0) out.push_back(',');
    const auto& piece = piecewise.pieces()[i];
    if (piece.is_rational()) {
      write_bezier(out, piece);
    } else {
      write_points(out, piece.control_points());
    }
  }
  fmt::format_to(std::back_inserter(out), "]}}");
}

}  // namespace

Expected<std::vector<Model>> parse_models_json(std::string_view text, const std::string& source) {
  DocumentBuilder builder;
  bool parsed = false;
  try {
    // strict: nothing but blanks may follow the document.
    parsed = json::sax_parse(text.begin(), text.end(), &builder, json::input_format_t::json, true);
  } catch (const json::exception& error) {
    // sax_parse reports through parse_error(); this is only a safety net so
    // that no exception leaves the library.
    return Error{source + ": " + io_detail::printable(error.what(), 200)};
  }
  if (!parsed) {
    if (!builder.failure) return Error{source + ": the JSON text could not be parsed"};
    const SyntaxFailure& failure = *builder.failure;
    std::string where = source;
    if (failure.offset != std::string_view::npos) where += ", " + line_and_column(text, failure.offset);
    if (!failure.path.empty()) where += ", " + failure.path;
    return Error{where + ": " + failure.what};
  }
  return Checker(source).document(builder.root);
}

Expected<std::vector<Model>> read_models_json(const std::filesystem::path& path) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  return parse_models_json(*text, display_name(path));
}

Expected<std::vector<Model>> read_models(const std::filesystem::path& path) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  const std::string source = display_name(path);
  const std::string name = path.string();
  bool is_json = false;
  if (io_detail::has_extension(name, ".json")) {
    is_json = true;
  } else if (!io_detail::has_extension(name, ".csv")) {
    const std::string_view content = io_detail::without_byte_order_mark(*text);
    const auto first = content.find_first_not_of(" \t\r\n");
    is_json = first != std::string_view::npos && content[first] == '{';
  }
  if (is_json) return parse_models_json(*text, source);
  auto points = parse_points_csv(*text, source);
  if (!points) return points.error();
  auto curve = BezierCurve::make(std::move(*points));
  if (!curve) return with_context(curve.error(), source);
  return std::vector<Model>{Model{std::move(*curve)}};
}

std::string to_json(const Model& model) {
  fmt::memory_buffer out;
  write_model(out, model);
  return fmt::to_string(out);
}

std::string models_to_json(const std::vector<Model>& models) {
  fmt::memory_buffer out;
  if (models.size() == 1) {
    write_model(out, models.front());
  } else {
    fmt::format_to(std::back_inserter(out), "{{\"models\":[\n");
    for (std::size_t i = 0; i < models.size(); ++i) {
      write_model(out, models[i]);
      if (i + 1 < models.size()) out.push_back(',');
      out.push_back('\n');
    }
    out.push_back(']');
    out.push_back('}');
  }
  out.push_back('\n');
  return fmt::to_string(out);
}

}  // namespace casteljau

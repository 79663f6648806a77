// Model JSON, step 2: JSON values become the containers the types' make()
// takes (numbers, PointArray, ControlNet, degrees, knot vectors, weights),
// checking only their JSON shape, and make()'s errors are placed at the
// field they are about. A nested array is checked here only where flattening
// needs it (points of one length, rows of one length, weights in the net's
// shape): the flat containers could not say which row was short.
#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <utility>

#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/tolerance.hpp"
#include "model_json_reader.hpp"
#include "text.hpp"

namespace casteljau::io_detail {

std::string member(const std::string& path, std::string_view name) {
  return path.empty() ? std::string(name) : path + "." + std::string(name);
}

std::string element(const std::string& path, std::size_t index) { return fmt::format("{}[{}]", path, index); }

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
      return value.empty() ? "an empty array" : "an array";
    default:
      return "a value that is not JSON";
  }
}

Error JsonReader::at(const std::string& path, const std::string& what) const {
  return Error{source_ + ", " + (path.empty() ? std::string("the top level") : path) + ": " + what, ErrorKind::parse};
}

namespace {

/// A word with which make()'s messages name their subject, and the model
/// JSON field that holds it.
struct Subject {
  std::string_view word;
  std::string_view field;
};

// Singular stems: "knot" finds "knots", "weight" "weights", "control"
// "control points" / "control net" / "control polygon".
constexpr Subject kSubjects[] = {{"knot", "knots"},
                                 {"weight", "weights"},
                                 {"degree", "degree"},
                                 {"coordinate", "control_points"},
                                 {"control", "control_points"},
                                 {"piece", "pieces"}};

/// A surface's make() names the direction of its pairs: "knots_u: <what>"
/// (a prefix, dropped since the path says it) and "degree_v 3 is ...".
struct DirectedSubject {
  std::string_view word;
  std::string_view field;
  std::size_t index;
  bool prefix;  // the word and ": " lead the message and are dropped
};

constexpr DirectedSubject kDirectedSubjects[] = {{"knots_u: ", "knots", 0, true},
                                                 {"knots_v: ", "knots", 1, true},
                                                 {"degree_u", "degree", 0, false},
                                                 {"degree_v", "degree", 1, false}};

bool has_field(std::initializer_list<std::string_view> fields, std::string_view field) {
  return std::find(fields.begin(), fields.end(), field) != fields.end();
}

}  // namespace

Error JsonReader::refused(const std::string& path, const Error& error, std::initializer_list<std::string_view> fields,
                          std::initializer_list<std::pair<std::string_view, std::string_view>> notes) const {
  std::string message = error.message;
  std::string field;  // relative to the model: "knots", "knots[0]"; empty: the model itself
  for (const DirectedSubject& subject : kDirectedSubjects) {
    if (message.rfind(subject.word, 0) == 0 && has_field(fields, subject.field)) {
      field = element(std::string(subject.field), subject.index);
      if (subject.prefix) message.erase(0, subject.word.size());
      break;
    }
  }
  if (field.empty()) {
    std::size_t earliest = std::string::npos;
    for (const Subject& subject : kSubjects) {
      const std::size_t found = message.find(subject.word);
      if (found < earliest && has_field(fields, subject.field)) {
        earliest = found;
        field = subject.field;
      }
    }
  }
  if (field.empty()) return at(path, message);
  for (const auto& [noted, note] : notes) {
    if (noted == field) message += note;
  }
  return at(member(path, field), message);
}

Status JsonReader::known_fields(const json& object, const std::string& path,
                                std::initializer_list<std::string_view> fields, const char* kind,
                                std::initializer_list<std::string_view> required) const {
  for (const auto& [name, value] : object.items()) {
    if (has_field(fields, name)) continue;
    std::string list;
    for (const auto field : fields) list += (list.empty() ? "" : ", ") + std::string(field);
    return at(path, "unknown field " + in_quotes(name) + " (" + kind + " has the fields " + list + ")");
  }
  for (const auto field : required) {
    if (!object.contains(field)) return at(path, fmt::format("missing field '{}'", field));
  }
  return {};
}

Expected<double> JsonReader::number(const json& value, const std::string& path) const {
  if (!value.is_number()) return at(path, "expected a number, found " + describe(value));
  return value.get<double>();  // finite: the parser refuses numbers that overflow
}

Expected<std::vector<double>> JsonReader::numbers(const json& value, const std::string& path) const {
  if (!value.is_array()) return at(path, "expected an array of numbers, found " + describe(value));
  std::vector<double> result;
  result.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    auto x = number(value[i], element(path, i));
    if (!x) return x.error();
    result.push_back(*x);
  }
  return result;
}

Expected<int> JsonReader::whole_number(const json& value, const std::string& path) const {
  if (!value.is_number()) return at(path, "expected a whole number, found " + describe(value));
  const double x = value.get<double>();
  if (x != std::floor(x)) return at(path, "expected a whole number, found " + describe(value));
  // Converting a double beyond int's range is undefined behaviour: such a
  // number is no int, whatever make() would have said of its size.
  if (!(x >= INT_MIN && x <= INT_MAX)) {
    return at(path, "expected a whole number, found " + describe(value) + ", beyond the range of an int");
  }
  return static_cast<int>(x);
}

Status JsonReader::pair(const json& value, const std::string& path, const char* expected) const {
  if (value.is_array() && value.size() == 2) return {};
  return at(path,
            fmt::format("expected {}, found {}", expected,
                        value.is_array() ? fmt::format("an array of {} elements", value.size()) : describe(value)));
}

Expected<PointArray> JsonReader::points(const json& value, const std::string& path) {
  if (!value.is_array()) return at(path, "expected an array of points, found " + describe(value));
  if (value.size() > budget_) {
    return at(path, fmt::format("more than {} control points in one model, the limit", tolerances::kMaxControlPoints));
  }
  budget_ -= value.size();
  if (value.empty()) return PointArray{};
  std::size_t dimension = 0;
  std::vector<double> coordinates;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string point_path = element(path, i);
    const json& point = value[i];
    if (!point.is_array()) return at(point_path, "expected a point (an array of numbers), found " + describe(point));
    if (point.empty()) return at(point_path, "the point has no coordinates");
    if (i == 0) {
      dimension = point.size();
      coordinates.reserve(value.size() * dimension);
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
  auto points = PointArray::make(static_cast<int>(dimension), std::move(coordinates), "control point");
  if (!points) return at(path, points.error().message);
  return points;
}

Expected<ControlNet> JsonReader::net(const json& value, const std::string& path) {
  if (!value.is_array()) return at(path, "expected an array of rows of points, found " + describe(value));
  const std::size_t rows = value.size();
  std::size_t columns = 0;
  int dimension = 0;
  std::vector<double> coordinates;
  for (std::size_t i = 0; i < rows; ++i) {
    const std::string row_path = element(path, i);
    const json& row = value[i];
    if (!row.is_array()) return at(row_path, "expected a row (an array of points), found " + describe(row));
    if (i == 0) {
      columns = row.size();
    } else if (row.size() != columns) {
      return at(row_path, fmt::format("row {} has {} point{}, row 0 has {} (a control net is rectangular)", i,
                                      row.size(), row.size() == 1 ? "" : "s", columns));
    }
    auto points = this->points(row, row_path);
    if (!points) return points.error();
    if (points->empty()) continue;  // every row is empty: ControlNet::make refuses the net
    if (i == 0) {
      dimension = points->dimension();
      coordinates.reserve(rows * columns * static_cast<std::size_t>(dimension));
    } else if (points->dimension() != dimension) {
      return at(element(row_path, 0), fmt::format("{} coordinate{}, but {} has {} (all points must have the same "
                                                  "dimension)",
                                                  points->dimension(), points->dimension() == 1 ? "" : "s",
                                                  element(element(path, 0), 0), dimension));
    }
    coordinates.insert(coordinates.end(), points->coordinates().begin(), points->coordinates().end());
  }
  PointArray flat;
  if (!coordinates.empty()) flat = PointArray::from_trusted(dimension, std::move(coordinates));  // rows checked
  auto net = ControlNet::make(rows, columns, std::move(flat));
  if (!net) return at(path, net.error().message);
  return net;
}

Expected<KnotsRead> JsonReader::knots(const json& value, const std::string& path, int degree, std::size_t count) const {
  auto values = numbers(value, path);
  if (!values) return values.error();
  KnotsRead knots{std::move(*values), {}};
  if (degree < 1) return knots;  // degree 0 has no Rhino form; make() judges a negative degree
  const std::size_t p = static_cast<std::size_t>(degree);
  const std::size_t full = count + p + 1, rhino = count + p - 1;
  if (knots.values.size() == rhino) {
    auto converted = knots_from_rhino(knots.values, degree, count);
    if (!converted) return at(path, converted.error().message + " (read in the Rhino/openNURBS convention)");
    knots.values = std::move(*converted);
    knots.note = " (read in the Rhino/openNURBS convention)";
  } else if (knots.values.size() != full) {
    knots.note = fmt::format(
        "; model JSON also reads {} knots (control points + degree - 1, the Rhino/openNURBS "
        "convention)",
        rhino);
  }
  return knots;
}

Expected<std::vector<double>> JsonReader::weights(const json& model, const std::string& path) const {
  if (!model.contains("weights")) return std::vector<double>{};
  return numbers(model["weights"], member(path, "weights"));
}

Expected<std::vector<double>> JsonReader::net_weights(const json& model, const std::string& path,
                                                      const ControlNet& net) const {
  std::vector<double> weights;
  if (!model.contains("weights")) return weights;
  const std::string weights_path = member(path, "weights");
  const json& rows = model["weights"];
  if (!rows.is_array()) return at(weights_path, "expected an array of rows of numbers, found " + describe(rows));
  if (rows.size() != net.rows()) {
    return at(weights_path,
              fmt::format("{} row{} of weights for a control net of {} row{}, expected one weight per "
                          "control point",
                          rows.size(), rows.size() == 1 ? "" : "s", net.rows(), net.rows() == 1 ? "" : "s"));
  }
  weights.reserve(net.rows() * net.columns());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string row_path = element(weights_path, i);
    if (!rows[i].is_array()) return at(row_path, "expected a row (an array of numbers), found " + describe(rows[i]));
    if (rows[i].size() != net.columns()) {
      return at(row_path,
                fmt::format("row {} has {} weight{}, the control net has {} point{} per row", i, rows[i].size(),
                            rows[i].size() == 1 ? "" : "s", net.columns(), net.columns() == 1 ? "" : "s"));
    }
    auto row = numbers(rows[i], row_path);
    if (!row) return row.error();
    weights.insert(weights.end(), row->begin(), row->end());
  }
  return weights;
}

}  // namespace casteljau::io_detail

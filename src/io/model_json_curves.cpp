// Model JSON curve types (docs/formats.md, "Types"): bezier, piecewise_bezier
// and bspline. Each reads its fields' JSON shape (model_json_values.cpp) and
// hands the values to its type's make(), whose error is placed at the field.
#include <utility>

#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "model_json_reader.hpp"

namespace casteljau::io_detail {

Expected<BezierCurve> read_bezier(JsonReader& reader, const json& value, const std::string& path) {
  if (auto ok =
          reader.known_fields(value, path, {"type", "control_points", "weights"}, "a bezier model", {"control_points"});
      !ok) {
    return ok.error();
  }
  auto points = reader.points(value["control_points"], member(path, "control_points"));
  if (!points) return points.error();
  auto weights = reader.weights(value, path);
  if (!weights) return weights.error();
  auto curve = BezierCurve::make(std::move(*points), std::move(*weights));
  if (!curve) return reader.refused(path, curve.error(), {"control_points", "weights"});
  return curve;
}

namespace {

/// One piece: an array of control points, or (rational) a bezier model object.
Expected<BezierCurve> read_piece(JsonReader& reader, const json& piece, const std::string& path) {
  if (piece.is_object()) {
    if (!piece.contains("type")) return reader.at(path, "missing field 'type' (a piece object is a bezier model)");
    const json& type = piece["type"];
    if (!type.is_string() || type.get_ref<const std::string&>() != "bezier") {
      return reader.at(member(path, "type"),
                       "expected \"bezier\" (a piece object is a bezier model), found " + describe(type));
    }
    return read_bezier(reader, piece, path);
  }
  if (!piece.is_array()) {
    return reader.at(
        path, "expected a piece (an array of control points, or a bezier model object), found " + describe(piece));
  }
  auto points = reader.points(piece, path);
  if (!points) return points.error();
  auto curve = BezierCurve::make(std::move(*points));
  if (!curve) return reader.at(path, curve.error().message);  // the piece is its control points
  return curve;
}

}  // namespace

Expected<Model> read_piecewise_bezier(JsonReader& reader, const json& value, const std::string& path) {
  if (auto ok = reader.known_fields(value, path, {"type", "pieces"}, "a piecewise_bezier model", {"pieces"}); !ok) {
    return ok.error();
  }
  const std::string pieces_path = member(path, "pieces");
  const json& list = value["pieces"];
  if (!list.is_array()) return reader.at(pieces_path, "expected an array of pieces, found " + describe(list));
  std::vector<BezierCurve> pieces;
  pieces.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    auto piece = read_piece(reader, list[i], element(pieces_path, i));
    if (!piece) return piece.error();
    pieces.push_back(std::move(*piece));
  }
  auto curve = PiecewiseBezierCurve::make(std::move(pieces));
  if (!curve) return reader.refused(path, curve.error(), {"pieces"});
  return Model{std::move(*curve)};
}

Expected<Model> read_bspline(JsonReader& reader, const json& value, const std::string& path) {
  if (auto ok = reader.known_fields(value, path, {"type", "degree", "knots", "control_points", "weights"},
                                    "a bspline model", {"degree", "knots", "control_points"});
      !ok) {
    return ok.error();
  }
  auto degree = reader.whole_number(value["degree"], member(path, "degree"));
  if (!degree) return degree.error();
  auto points = reader.points(value["control_points"], member(path, "control_points"));
  if (!points) return points.error();
  auto knots = reader.knots(value["knots"], member(path, "knots"), *degree, points->size());
  if (!knots) return knots.error();
  auto weights = reader.weights(value, path);
  if (!weights) return weights.error();
  auto curve = BSplineCurve::make(*degree, std::move(knots->values), std::move(*points), std::move(*weights));
  if (!curve) {
    return reader.refused(path, curve.error(), {"degree", "knots", "control_points", "weights"},
                          {{"knots", knots->note}});
  }
  return Model{std::move(*curve)};
}

}  // namespace casteljau::io_detail

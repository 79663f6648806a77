// Model JSON surface types (docs/formats.md, "Types"): bezier_surface,
// bspline_surface and coons. Nets are control_points[i][j], i along u and j
// along v; a bspline_surface's degree and knots are pairs [u, v], each read
// as a curve's (model_json_values.cpp); the types' make() checks the values
// and its error is placed at the field (knots_u becomes knots[0]).
#include <fmt/format.h>

#include <utility>

#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/coons.hpp"
#include "model_json_reader.hpp"
#include "text.hpp"

namespace casteljau::io_detail {

Expected<Model> read_bezier_surface(JsonReader& reader, const json& value, const std::string& path) {
  if (auto ok = reader.known_fields(value, path, {"type", "control_points", "weights"}, "a bezier_surface model",
                                    {"control_points"});
      !ok) {
    return ok.error();
  }
  auto net = reader.net(value["control_points"], member(path, "control_points"));
  if (!net) return net.error();
  auto weights = reader.net_weights(value, path, *net);
  if (!weights) return weights.error();
  auto surface = BezierSurface::make(std::move(*net), std::move(*weights));
  if (!surface) return reader.refused(path, surface.error(), {"control_points", "weights"});
  return Model{std::move(*surface)};
}

Expected<Model> read_bspline_surface(JsonReader& reader, const json& value, const std::string& path) {
  if (auto ok = reader.known_fields(value, path, {"type", "degree", "knots", "control_points", "weights"},
                                    "a bspline_surface model", {"degree", "knots", "control_points"});
      !ok) {
    return ok.error();
  }
  const std::string degree_path = member(path, "degree");
  const json& degrees = value["degree"];
  if (auto ok = reader.pair(degrees, degree_path, "[p, q], the degrees in u and in v"); !ok) return ok.error();
  auto p = reader.whole_number(degrees[0], element(degree_path, 0));
  if (!p) return p.error();
  auto q = reader.whole_number(degrees[1], element(degree_path, 1));
  if (!q) return q.error();
  auto net = reader.net(value["control_points"], member(path, "control_points"));
  if (!net) return net.error();
  const std::string knots_path = member(path, "knots");
  const json& knot_lists = value["knots"];
  if (auto ok = reader.pair(knot_lists, knots_path, "[[u knots], [v knots]], two arrays of numbers"); !ok) {
    return ok.error();
  }
  auto knots_u = reader.knots(knot_lists[0], element(knots_path, 0), *p, net->rows());
  if (!knots_u) return knots_u.error();
  auto knots_v = reader.knots(knot_lists[1], element(knots_path, 1), *q, net->columns());
  if (!knots_v) return knots_v.error();
  auto weights = reader.net_weights(value, path, *net);
  if (!weights) return weights.error();
  auto surface = BSplineSurface::make(*p, *q, std::move(knots_u->values), std::move(knots_v->values), std::move(*net),
                                      std::move(*weights));
  if (!surface) {
    return reader.refused(path, surface.error(), {"degree", "knots", "control_points", "weights"},
                          {{"knots[0]", knots_u->note}, {"knots[1]", knots_v->note}});
  }
  return Model{std::move(*surface)};
}

Expected<Model> read_coons(JsonReader& reader, const json& value, const std::string& path) {
  if (auto ok = reader.known_fields(value, path, {"type", "blending", "boundaries"}, "a coons model"); !ok) {
    return ok.error();
  }
  CoonsBlending blending = CoonsBlending::linear;
  if (value.contains("blending")) {
    const std::string blending_path = member(path, "blending");
    const json& name = value["blending"];
    if (!name.is_string()) return reader.at(blending_path, "expected \"linear\" or \"cubic\", found " + describe(name));
    const auto& text = name.get_ref<const std::string&>();
    if (text == "linear") {
      blending = CoonsBlending::linear;
    } else if (text == "cubic") {
      blending = CoonsBlending::cubic;
    } else {
      return reader.at(blending_path, "unknown blending " + in_quotes(text) + " (linear or cubic)");
    }
  }
  if (!value.contains("boundaries")) return reader.at(path, "missing field 'boundaries' (u0, u1, v0, v1)");
  const std::string boundaries_path = member(path, "boundaries");
  const json& boundaries = value["boundaries"];
  if (!boundaries.is_object()) {
    return reader.at(boundaries_path,
                     "expected an object {\"u0\": curve, \"u1\": curve, \"v0\": curve, \"v1\": "
                     "curve}, found " +
                         describe(boundaries));
  }
  if (auto ok = reader.known_fields(boundaries, boundaries_path, {"u0", "u1", "v0", "v1"},
                                    "the boundaries object of a coons model");
      !ok) {
    return ok.error();
  }
  std::vector<BSplineCurve> curves;
  for (const char* name : {"u0", "u1", "v0", "v1"}) {
    if (!boundaries.contains(name)) {
      return reader.at(boundaries_path,
                       fmt::format("missing boundary '{}' (a coons patch needs the four curves u0, u1, v0, v1)", name));
    }
    const std::string curve_path = member(boundaries_path, name);
    auto boundary = read_model(reader, boundaries[name], curve_path);
    if (!boundary) return boundary.error();
    if (is_surface(*boundary)) {
      return reader.at(curve_path, fmt::format("a {} model cannot be a boundary, a coons boundary is a curve "
                                               "(bezier, piecewise_bezier, bspline)",
                                               type_name(*boundary)));
    }
    auto spline = to_bspline(*boundary);  // refuses pieces that do not meet
    if (!spline) return reader.at(curve_path, spline.error().message);
    curves.push_back(std::get<BSplineCurve>(std::move(*spline)));
  }
  auto patch = CoonsPatch::make(std::move(curves[0]), std::move(curves[1]), std::move(curves[2]), std::move(curves[3]),
                                blending);
  if (!patch) return reader.at(boundaries_path, patch.error().message);  // names the boundaries and the corner
  return Model{std::move(*patch)};
}

}  // namespace casteljau::io_detail

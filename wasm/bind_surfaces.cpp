// The playground's surface view (seeds 001, 003): Bézier and B-spline patches
// from a control net, and Coons patches from four boundary curves with either
// blending, evaluated on a grid for the page's 3D drawing.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/coons.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "curve_values.hpp"
#include "js_values.hpp"

namespace casteljau::wasm {
namespace {

using emscripten::val;

// The largest grid the page may ask for in one direction (a 20 x 20 net drawn
// with 8 samples per span needs 160).
constexpr int kMaxGridSamples = 1000;

std::vector<double> grid_parameters(int count) {
  std::vector<double> out(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) out[i] = static_cast<double>(i) / (count - 1);
  return out;
}

Status check_grid(int samples_u, int samples_v) {
  if (samples_u < 2 || samples_v < 2 || samples_u > kMaxGridSamples || samples_v > kMaxGridSamples) {
    return Error{"a surface grid needs 2.." + std::to_string(kMaxGridSamples) + " samples in each direction"};
  }
  return {};
}

Expected<ControlNet> net_of(const val& description) {
  if (!description["rows"].isNumber() || !description["columns"].isNumber()) {
    return Error{"surface: rows and columns must be numbers"};
  }
  const int rows = description["rows"].as<int>(), columns = description["columns"].as<int>();
  if (rows < 1 || columns < 1) return Error{"surface: rows and columns must be at least 1"};
  auto points = points_of(description["net"], 3, "control net");
  if (!points) return points.error();
  return ControlNet::make(static_cast<std::size_t>(rows), static_cast<std::size_t>(columns), std::move(*points));
}

/// Points S(u_a, v_b) on a samples_u x samples_v grid over [0,1]^2 (u the
/// slow index), of {kind: "bezier_surface" | "bspline_surface", rows, columns,
/// net: [x, y, z, ...] row by row, degreeU?, degreeV?, knotsU?, knotsV?, weights?}.
val surface_grid(const val& description, int samples_u, int samples_v) {
  if (const Status ok = check_grid(samples_u, samples_v); !ok) return error_value(ok.error());
  auto net = net_of(description);
  if (!net) return error_value(net.error());
  std::vector<double> weights;
  if (!description["weights"].isUndefined() && !description["weights"].isNull()) weights = numbers_of(description["weights"]);
  const std::vector<double> us = grid_parameters(samples_u), vs = grid_parameters(samples_v);
  std::vector<double> out(us.size() * vs.size() * 3);
  const std::string kind = description["kind"].isString() ? description["kind"].as<std::string>() : "";
  if (kind == "bezier_surface") {
    const auto surface = BezierSurface::make(std::move(*net), std::move(weights));
    if (!surface) return error_value(surface.error());
    grid_points_at(*surface, us, vs, out);
    return float64_array(out);
  }
  if (kind == "bspline_surface") {
    if (!description["degreeU"].isNumber() || !description["degreeV"].isNumber()) {
      return error_value(Error{"B-spline surface: degreeU and degreeV must be numbers"});
    }
    const auto surface = BSplineSurface::make(description["degreeU"].as<int>(), description["degreeV"].as<int>(),
                                              numbers_of(description["knotsU"]), numbers_of(description["knotsV"]),
                                              std::move(*net), std::move(weights));
    if (!surface) return error_value(surface.error());
    // The grid spans the surface's own domain.
    const Interval du = surface->domain(Direction::u), dv = surface->domain(Direction::v);
    std::vector<double> su(us), sv(vs);
    for (double& u : su) u = du.lower + u * (du.upper - du.lower);
    for (double& v : sv) v = dv.lower + v * (dv.upper - dv.lower);
    grid_points_at(*surface, su, sv, out);
    return float64_array(out);
  }
  return error_value(Error{"surface: kind must be \"bezier_surface\" or \"bspline_surface\", not \"" + kind + "\""});
}

Expected<BSplineCurve> boundary_of(const val& description, const char* name) {
  auto curve = curve_of(description);
  if (!curve) return Error{std::string(name) + ": " + curve.error().message, curve.error().kind};
  if (auto* bspline = std::get_if<BSplineCurve>(&*curve)) return std::move(*bspline);
  if (auto* bezier = std::get_if<BezierCurve>(&*curve)) return to_bspline(*bezier);
  const auto joined = from_bezier_pieces(to_bezier_pieces(std::get<PiecewiseBezierCurve>(*curve)));
  if (!joined) return Error{std::string(name) + ": " + joined.error().message, joined.error().kind};
  return *joined;
}

/// The Coons patch of boundaries {u0, u1, v0, v1} (curve descriptions of
/// dimension 3) with "linear" or "cubic" blending, on a grid over [0,1]^2.
val coons_grid(const val& boundaries, const std::string& blending, int samples_u, int samples_v) {
  if (const Status ok = check_grid(samples_u, samples_v); !ok) return error_value(ok.error());
  if (blending != "linear" && blending != "cubic") return error_value(Error{"Coons blending must be \"linear\" or \"cubic\""});
  auto u0 = boundary_of(boundaries["u0"], "u0");
  if (!u0) return error_value(u0.error());
  auto u1 = boundary_of(boundaries["u1"], "u1");
  if (!u1) return error_value(u1.error());
  auto v0 = boundary_of(boundaries["v0"], "v0");
  if (!v0) return error_value(v0.error());
  auto v1 = boundary_of(boundaries["v1"], "v1");
  if (!v1) return error_value(v1.error());
  const auto patch = CoonsPatch::make(std::move(*u0), std::move(*u1), std::move(*v0), std::move(*v1),
                                      blending == "cubic" ? CoonsBlending::cubic : CoonsBlending::linear);
  if (!patch) return error_value(patch.error());
  const std::vector<double> us = grid_parameters(samples_u), vs = grid_parameters(samples_v);
  std::vector<double> out(us.size() * vs.size() * static_cast<std::size_t>(patch->dimension()));
  grid_points_at(*patch, us, vs, out);
  return float64_array(out);
}

}  // namespace
}  // namespace casteljau::wasm

EMSCRIPTEN_BINDINGS(casteljau_surfaces) {
  using namespace casteljau::wasm;
  emscripten::function("surfaceGrid", &surface_grid);
  emscripten::function("coonsGrid", &coons_grid);
}

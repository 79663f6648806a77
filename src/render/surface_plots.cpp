#include "casteljau/render/surface_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "casteljau/ops/tessellate.hpp"
#include "casteljau/render/bspline_plots.hpp"
#include "casteljau/render/tolerance.hpp"
#include "casteljau/surfaces/iso_curve.hpp"

namespace casteljau::render {
namespace {

/// The page axes r, u and the direction to the viewer e of a view.
struct Frame {
  Vec3 right, up, toward;
};

Frame frame_of(const ViewAngles& view) {
  const double a = view.azimuth * std::numbers::pi / 180.0, e = view.elevation * std::numbers::pi / 180.0;
  return Frame{Vec3{{-std::sin(a), std::cos(a), 0.0}},
               Vec3{{-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)}},
               Vec3{{std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)}}};
}

double dot3(const Vec3& a, std::span<const double> p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < 3 && i < p.size(); ++i) sum += a[i] * p[i];
  return sum;
}

/// The surface of a model as a B-spline surface when it has one (Bézier and
/// B-spline surfaces always, a Coons patch with polynomial boundaries).
std::optional<BSplineSurface> bspline_form(const Model& model) {
  if (const auto* s = std::get_if<BSplineSurface>(&model)) return *s;
  if (const auto* s = std::get_if<BezierSurface>(&model)) return to_bspline_surface(*s);
  if (const auto* p = std::get_if<CoonsPatch>(&model)) {
    auto surface = to_bspline_surface(*p);
    if (surface) return std::move(*surface);
  }
  return std::nullopt;
}

/// A curve of R^d projected on the page: control points projected, weights kept.
Expected<BSplineCurve> projected(const BSplineCurve& curve, const ViewAngles& view) {
  std::vector<double> coordinates;
  coordinates.reserve(curve.control_points().size() * 2);
  for (std::size_t i = 0; i < curve.control_points().size(); ++i) {
    const Vec2 p = project(view, curve.control_points()[i]);
    coordinates.push_back(p[0]);
    coordinates.push_back(p[1]);
  }
  return BSplineCurve::make(curve.degree(), std::vector<double>(curve.knots().begin(), curve.knots().end()),
                            PointArray::from_trusted(2, std::move(coordinates)),
                            std::vector<double>(curve.weights().begin(), curve.weights().end()));
}

/// Adds a projected B-spline curve as curve items.
Status add_projected_curve(Panel& panel, const BSplineCurve& curve, const ViewAngles& view, const Stroke& stroke,
                           const std::string& label) {
  auto plane = projected(curve, view);
  if (!plane) return plane.error();
  // An iso-curve collapsed to a point (the pole of a sphere, a degenerate
  // edge) is nothing to draw, and has no extent to flatten against.
  const PointArray& points = plane->control_points();
  bool collapsed = true;
  for (std::size_t i = 1; i < points.size() && collapsed; ++i)
    collapsed = points[i][0] == points[0][0] && points[i][1] == points[0][1];
  if (collapsed) return {};
  auto pieces = plane_pieces(*plane);
  if (!pieces) return pieces.error();
  for (auto& item : curve_items(*pieces, 0, pieces->pieces.size(), stroke, label)) panel.curves.push_back(std::move(item));
  return {};
}

std::vector<double> even_parameters(const Interval& domain, int count) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i) {
    values.push_back(i + 1 == count ? domain.upper
                                    : domain.lower + (domain.upper - domain.lower) * i / (count - 1));
  }
  return values;
}

/// The rows and columns of a net as projected polylines.
void add_net(Panel& panel, const ControlNet& net, const ViewAngles& view, const SurfacePlotOptions& options) {
  if (options.control_net) {
    const std::string label = label_once(panel, "control net");
    for (std::size_t i = 0; i < net.rows(); ++i) {
      PolylineItem row{{}, dashed(colors::gray, 1.0), i == 0 ? label : ""};
      for (std::size_t j = 0; j < net.columns(); ++j) row.points.push_back(project(view, net(i, j)));
      panel.polylines.push_back(std::move(row));
    }
    for (std::size_t j = 0; j < net.columns(); ++j) {
      PolylineItem column{{}, dashed(colors::gray, 1.0), ""};
      for (std::size_t i = 0; i < net.rows(); ++i) column.points.push_back(project(view, net(i, j)));
      panel.polylines.push_back(std::move(column));
    }
  }
  if (options.control_points) {
    MarkerItem markers{{}, colors::red, 5.0 * kPixelsPerPoint, label_once(panel, "control points")};
    for (std::size_t k = 0; k < net.points().size(); ++k) markers.points.push_back(project(view, net.points()[k]));
    panel.markers.push_back(std::move(markers));
  }
}

/// The control points of a surface: its net's, or a Coons patch's boundaries'.
std::vector<const PointArray*> control_point_sets(const Model& model) {
  if (const auto* s = std::get_if<BSplineSurface>(&model)) return {&s->control_net().points()};
  if (const auto* s = std::get_if<BezierSurface>(&model)) return {&s->control_net().points()};
  if (const auto* p = std::get_if<CoonsPatch>(&model))
    return {&p->u0().control_points(), &p->u1().control_points(), &p->v0().control_points(), &p->v1().control_points()};
  return {};
}

/// The corners of the bounding box of every control point of a surface.
void extend_box(const Model& model, std::array<double, 3>& low, std::array<double, 3>& high) {
  for (const PointArray* points : control_point_sets(model))
    for (std::size_t k = 0; k < points->size(); ++k)
      for (std::size_t c = 0; c < 3 && c < (*points)[k].size(); ++c) {
        low[c] = std::min(low[c], (*points)[k][c]);
        high[c] = std::max(high[c], (*points)[k][c]);
      }
}

}  // namespace

Vec2 project(const ViewAngles& view, std::span<const double> point) {
  if (point.size() == 2) return Vec2{{point[0], point[1]}};
  const Frame f = frame_of(view);
  return Vec2{{dot3(f.right, point), dot3(f.up, point)}};
}

double depth(const ViewAngles& view, std::span<const double> point) { return dot3(frame_of(view).toward, point); }

Status add_surface_wireframe(Panel& panel, const Model& surface, const SurfacePlotOptions& options, Color color,
                             const std::string& label) {
  assert(is_surface(surface));
  const int d = dimension_of(surface);
  if (d != 2 && d != 3) {
    return Error{fmt::format("a {} in R^{} cannot be drawn, plot draws surfaces in R^2 or R^3", type_name(surface), d)};
  }
  if (options.iso_curves < 2) return Error{fmt::format("{} iso-curves per direction, at least 2", options.iso_curves)};
  // The net first: drawn beneath the surface's lines (polylines come before curves).
  if (const auto* s = std::get_if<BSplineSurface>(&surface)) add_net(panel, s->control_net(), options.view, options);
  if (const auto* s = std::get_if<BezierSurface>(&surface)) add_net(panel, s->control_net(), options.view, options);
  if (const auto* p = std::get_if<CoonsPatch>(&surface)) {
    for (const BSplineCurve* c : {&p->u0(), &p->u1(), &p->v0(), &p->v1()}) {
      add_net(panel, ControlNet::from_trusted(1, c->control_points().size(), c->control_points()), options.view,
              options);
    }
  }
  const SurfaceView view = surface_view(surface);
  const Stroke stroke = solid(color, 1.0);
  const auto us = even_parameters(view.domain_u(), options.iso_curves);
  const auto vs = even_parameters(view.domain_v(), options.iso_curves);
  bool labelled = false;
  const auto next_label = [&] {
    const std::string text = labelled ? "" : label;
    labelled = true;
    return text;
  };
  if (const auto spline = bspline_form(surface)) {
    for (const auto& [direction, values] : {std::pair{Direction::u, us}, std::pair{Direction::v, vs}}) {
      for (const double value : values) {
        auto curve = iso_curve(*spline, direction, value);
        if (!curve) return curve.error();
        if (auto ok = add_projected_curve(panel, *curve, options.view, stroke, next_label()); !ok) return ok;
      }
    }
    return {};
  }
  // No B-spline form (a Coons patch with rational boundaries): sampled.
  constexpr int kSamples = 129;
  const auto ts_u = even_parameters(view.domain_u(), kSamples);
  const auto ts_v = even_parameters(view.domain_v(), kSamples);
  for (const double u : us) {
    PolylineItem line{{}, stroke, next_label()};
    for (const double v : ts_v) line.points.push_back(project(options.view, view.point_at(u, v)));
    panel.polylines.push_back(std::move(line));
  }
  for (const double v : vs) {
    PolylineItem line{{}, stroke, ""};
    for (const double u : ts_u) line.points.push_back(project(options.view, view.point_at(u, v)));
    panel.polylines.push_back(std::move(line));
  }
  return {};
}

void add_shaded_mesh(Panel& panel, const TriangleMesh& mesh, const ViewAngles& view, Color base, MeshEdges edges) {
  const Frame f = frame_of(view);
  // A light from over the viewer's left shoulder.
  Vec3 light = f.toward + 0.6 * f.up - 0.4 * f.right;
  const double length = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  light *= 1.0 / length;
  std::vector<std::pair<double, std::size_t>> order;
  order.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    double sum = 0.0;
    for (const auto v : mesh.triangles[t]) sum += dot3(f.toward, mesh.vertices[v]);
    order.emplace_back(sum / 3.0, t);
  }
  std::sort(order.begin(), order.end());  // far (small depth) first
  SegmentItem lines{{}, solid(Color{40, 40, 40, 0.6}, 0.3), false, ""};
  for (const auto& [ignored, t] : order) {
    const auto& tri = mesh.triangles[t];
    const Vec3 a = Vec3::from(mesh.vertices[tri[0]]), b = Vec3::from(mesh.vertices[tri[1]]),
               c = Vec3::from(mesh.vertices[tri[2]]);
    const Vec3 e1 = b - a, e2 = c - a;
    Vec3 n{{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]}};
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double cosine = norm > 0.0 ? std::abs(n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / norm : 0.0;
    const double intensity = 0.25 + 0.75 * cosine;
    const auto scale = [&](unsigned char channel) {
      return static_cast<unsigned char>(std::lround(std::min(255.0, channel * intensity)));
    };
    RegionItem region;
    region.fill = Color{scale(base.red), scale(base.green), scale(base.blue), 1.0};
    for (const auto v : tri) region.boundary.push_back(project(view, mesh.vertices[v]));
    // Edges of triangles that face away (by the mesh's vertex normals) are
    // left out: on a closed surface they are hidden behind the front.
    double facing = 0.0;
    if (mesh.normals.size() == mesh.vertices.size()) {
      for (const auto v : tri) facing += dot3(f.toward, mesh.normals[v]);
    }
    if (edges == MeshEdges::drawn && facing >= 0.0) {
      for (int k = 0; k < 3; ++k) lines.segments.push_back({region.boundary[k], region.boundary[(k + 1) % 3]});
    }
    panel.regions.push_back(std::move(region));
  }
  if (edges == MeshEdges::drawn) panel.segments.push_back(std::move(lines));
}

Status add_shaded_surfaces(Panel& panel, const std::vector<const Model*>& surfaces, const ViewAngles& view,
                           double relative_tolerance, Color base) {
  std::vector<SurfaceView> patches;
  std::array<double, 3> low{HUGE_VAL, HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Model* model : surfaces) {
    if (dimension_of(*model) != 3) {
      return Error{fmt::format("a {} in R^{} has no shaded image, shading needs surfaces in R^3", type_name(*model),
                               dimension_of(*model))};
    }
    patches.push_back(surface_view(*model));
    extend_box(*model, low, high);
  }
  double diagonal = 0.0;
  for (int c = 0; c < 3; ++c) diagonal += (high[c] - low[c]) * (high[c] - low[c]);
  diagonal = std::sqrt(diagonal);
  if (!(diagonal > 0.0)) return Error{"the surfaces have no extent to shade"};
  auto mesh = tessellate(patches, Tolerance{relative_tolerance * diagonal});
  if (!mesh) return mesh.error();
  add_shaded_mesh(panel, *mesh, view, base);
  return {};
}

Expected<Figure> surface_plot_figure(const std::vector<PlotSource>& sources, const SurfacePlotOptions& options,
                                     Shading shading) {
  const bool shaded = shading == Shading::shaded;
  std::vector<std::pair<std::string, const Model*>> surfaces;
  for (const auto& source : sources) {
    if (source.models.empty()) {
      return Error{fmt::format("{} is a point set; plot draws curves and surfaces in separate figures", source.name)};
    }
    for (std::size_t m = 0; m < source.models.size(); ++m) {
      const std::string name = source.models.size() == 1 ? source.name : fmt::format("{}[{}]", source.name, m);
      if (!is_surface(source.models[m])) {
        return Error{fmt::format("{} is a curve ({}); plot draws curves and surfaces in separate figures", name,
                                 type_name(source.models[m]))};
      }
      surfaces.emplace_back(name, &source.models[m]);
    }
  }
  if (surfaces.empty()) return Error{"nothing to plot: no surface"};
  bool all_plane = true, all_space = true;
  for (const auto& [name, model] : surfaces) {
    all_plane = all_plane && dimension_of(*model) == 2;
    all_space = all_space && dimension_of(*model) == 3;
  }
  const std::string view_text =
      all_plane ? std::string("in the plane")
                : fmt::format("orthographic view, azimuth {}°, elevation {}°", options.view.azimuth,
                              options.view.elevation);
  Panel lines;
  lines.title = "iso-curves, " + view_text;
  lines.equal_aspect = true;
  lines.grid = all_plane;
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    std::vector<Vec2> projected_points;
    for (const PointArray* points : control_point_sets(*surfaces[k].second))
      for (std::size_t i = 0; i < points->size(); ++i) projected_points.push_back(project(options.view, (*points)[i]));
    if (auto ok = check_plottable_extent(projected_points, surfaces[k].first + ": the projected control points span"); !ok)
      return ok.error();
    const Color color = surfaces.size() == 1 ? colors::black : cycle_color(static_cast<int>(k));
    const std::size_t first_curve = lines.curves.size();
    if (auto ok = add_surface_wireframe(lines, *surfaces[k].second, options, color,
                                        surfaces.size() == 1 ? "" : surfaces[k].first);
        !ok) {
      return with_context(ok.error(), surfaces[k].first);
    }
    // Layout errors about its iso-curves name the surface.
    for (std::size_t i = first_curve; i < lines.curves.size(); ++i) lines.curves[i].source = surfaces[k].first;
  }
  Figure figure;
  figure.width = 900;
  figure.height = 700;
  if (shaded && all_space) {
    Panel image;
    image.title = "shaded, " + view_text;
    image.equal_aspect = true;
    image.grid = false;
    std::vector<const Model*> models;
    for (const auto& [name, model] : surfaces) models.push_back(model);
    if (auto ok = add_shaded_surfaces(image, models, options.view, tolerances::kShadedSurfaceRelativeTolerance,
                                      Color{120, 160, 210, 1.0});
        !ok) {
      return ok.error();
    }
    figure.width = 1500;
    figure.columns = 2;
    figure.panels.push_back(std::move(image));
  }
  figure.panels.push_back(std::move(lines));
  return figure;
}

}  // namespace casteljau::render

// The surface figures of the gallery (issue 5): a bicubic Bézier patch with
// its control net (seed 003 figure 6), a Coons patch with both blendings,
// B-spline surface local control, the exact NURBS sphere and torus, and a
// tessellation at two tolerances. Numbered 30 to 34, after the interpolation
// figures.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/ops/tessellate.hpp"
#include "casteljau/render/surface_plots.hpp"
#include "casteljau/render/tolerance.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "figure_list.hpp"

namespace casteljau::render::detail {
namespace {

Panel view_panel(std::string title) {
  Panel panel;
  panel.title = std::move(title);
  panel.equal_aspect = true;
  panel.grid = false;
  panel.legend = LegendPlace::upper_right;
  return panel;
}

/// The 4 x 4 net of the bicubic patch: a hump over the square [0,3]^2 that
/// rises towards one corner (seed 003 gives no coordinates for its figure 6;
/// this net shows the same things: the patch passes through the four corner
/// points, is tangent to the net's border legs there, and stays in the
/// convex hull of the net).
BezierSurface bicubic_patch() {
  const double heights[4][4] = {{0.0, 0.6, 0.6, 0.0}, {0.5, 2.0, 1.6, 0.4}, {0.4, 1.8, 2.6, 0.9}, {0.0, 0.5, 1.0, 0.3}};
  std::vector<double> coordinates;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      coordinates.insert(coordinates.end(), {static_cast<double>(i), static_cast<double>(j), heights[i][j]});
    }
  }
  return BezierSurface::from_trusted(ControlNet::from_trusted(4, 4, PointArray::from_trusted(3, std::move(coordinates))));
}

Expected<GalleryFigure> bezier_patch_figure() {
  const Model patch{bicubic_patch()};
  SurfacePlotOptions options;
  options.control_net = options.control_points = true;
  Figure figure = figure_of("Bicubic Bézier patch and its control net", 1500, 700, 2);
  Panel shaded = view_panel("shaded (Lambert, painter's algorithm)");
  if (auto ok = add_shaded_surfaces(shaded, {&patch}, options.view, tolerances::kShadedSurfaceRelativeTolerance,
                                    Color{120, 160, 210, 1.0});
      !ok) {
    return ok.error();
  }
  Panel lines = view_panel("iso-curves u, v = k/10 and the control net");
  if (auto ok = add_surface_wireframe(lines, patch, options, colors::black, "patch"); !ok) return ok.error();
  figure.panels.push_back(std::move(shaded));
  figure.panels.push_back(std::move(lines));
  return GalleryFigure{"30_bezier_patch",
                       "Seed 003 figure 6: a bicubic Bézier patch S(u,v) = sum B_i^3(u) B_j^3(v) P_ij over its 4 x 4 "
                       "control net (x = i, y = j, heights chosen here), seen at azimuth -60°, elevation 30°. The "
                       "patch interpolates the four corner points and is tangent to the border legs of the net there.",
                       std::move(figure)};
}

BSplineCurve bezier_boundary(std::vector<double> coordinates) {
  return to_bspline(BezierCurve::from_trusted(PointArray::from_trusted(3, std::move(coordinates))));
}

Expected<GalleryFigure> coons_figure() {
  // Four boundaries over the unit square: two cubic arches, a quadratic dip
  // and a straight edge. Corners P00 = (0,0,0), P01 = (0,1,0), P10 = (1,0,0),
  // P11 = (1,1,0.3).
  const BSplineCurve u0 = bezier_boundary({0, 0, 0, -0.1, 0.33, 0.6, 0.1, 0.66, 0.6, 0, 1, 0});
  const BSplineCurve u1 = bezier_boundary({1, 0, 0, 1, 0.5, -0.5, 1, 1, 0.3});
  const BSplineCurve v0 = bezier_boundary({0, 0, 0, 0.33, -0.1, 0.5, 0.66, 0.1, 0.5, 1, 0, 0});
  const BSplineCurve v1 = bezier_boundary({0, 1, 0, 1, 1, 0.3});
  Figure figure = figure_of("Coons patch from four boundary curves, both blendings", 1500, 700, 2);
  SurfacePlotOptions options;
  options.control_net = true;
  for (const auto blending : {CoonsBlending::linear, CoonsBlending::cubic}) {
    auto patch = CoonsPatch::make(u0, u1, v0, v1, blending);
    if (!patch) return patch.error();
    const Model model{std::move(*patch)};
    Panel panel = view_panel(blending == CoonsBlending::linear
                                 ? "bilinearly blended: f0(t) = 1 - t, f1(t) = t"
                                 : "cubic blending: f0(t) = 2t³ - 3t² + 1, f1(t) = 3t² - 2t³");
    if (auto ok = add_surface_wireframe(panel, model, options); !ok) return ok.error();
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{"31_coons_blendings",
                       "A Coons patch spanned by four boundary curves (two cubic arches, a parabola and a segment; "
                       "their control polygons dashed), with the bilinear blending (left) and the cubic Hermite "
                       "blending of seed 001 (right, with the corrected f0 = 2t³ - 3t² + 1). Both reproduce the four "
                       "boundaries; the cubic blending flattens the patch across each boundary (zero cross-boundary "
                       "derivative of the blend).",
                       std::move(figure)};
}

Expected<GalleryFigure> local_control_figure() {
  // A bicubic B-spline surface on a 7 x 7 net over [0,6]^2 with uniform
  // clamped knots 0 0 0 0 1 2 3 4 4 4 4 in both directions.
  constexpr int kCount = 7;
  const std::vector<double> knots{0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4};
  std::vector<double> coordinates;
  for (int i = 0; i < kCount; ++i) {
    for (int j = 0; j < kCount; ++j) {
      coordinates.insert(coordinates.end(),
                         {static_cast<double>(i), static_cast<double>(j), 0.3 * std::sin(0.9 * i) * std::cos(0.7 * j)});
    }
  }
  auto original =
      BSplineSurface::make(3, 3, knots, knots, ControlNet::from_trusted(kCount, kCount, PointArray::from_trusted(3, coordinates)));
  if (!original) return original.error();
  // P_55 moved up by 2: N_5,3 vanishes outside [t_5, t_9) = [2, 4), so only
  // (u,v) in [2,4] x [2,4] changes.
  coordinates[(5 * kCount + 5) * 3 + 2] += 2.0;
  auto moved =
      BSplineSurface::make(3, 3, knots, knots, ControlNet::from_trusted(kCount, kCount, PointArray::from_trusted(3, coordinates)));
  if (!moved) return moved.error();
  Figure figure = figure_of("B-spline surface: local control", 1500, 700, 2);
  SurfacePlotOptions options;
  options.iso_curves = 17;  // iso-curves at u, v = k/4: the knots fall on them
  Panel before = view_panel("before: bicubic, knots 0,0,0,0,1,2,3,4,4,4,4 in u and v");
  if (auto ok = add_surface_wireframe(before, Model{*original}, options); !ok) return ok.error();
  Panel after = view_panel("after moving P(5,5) up by 2: only [2,4] x [2,4] changes (blue)");
  options.control_points = false;
  if (auto ok = add_surface_wireframe(after, Model{*original}, options, Color{150, 150, 150, 1.0}, "before"); !ok)
    return ok.error();
  if (auto ok = add_surface_wireframe(after, Model{*moved}, options, colors::blue, "after"); !ok) return ok.error();
  MarkerItem moved_point{{project(options.view, std::array<double, 3>{5, 5, coordinates[(5 * kCount + 5) * 3 + 2]})},
                         colors::red, 6.0 * kPixelsPerPoint, "moved control point P(5,5)"};
  after.markers.push_back(std::move(moved_point));
  figure.panels.push_back(std::move(before));
  figure.panels.push_back(std::move(after));
  return GalleryFigure{"32_bspline_surface_local_control",
                       "Local control of a bicubic B-spline surface (7 x 7 net, clamped uniform knots): raising one "
                       "control point P(5,5) changes the surface only where N_5,3(u) N_5,3(v) is nonzero, the "
                       "parameter square [2,4] x [2,4]; elsewhere the new iso-curves (blue) lie exactly on the old "
                       "ones (gray).",
                       std::move(figure)};
}

Expected<GalleryFigure> sphere_torus_figure() {
  const std::array<double, 3> origin{0, 0, 0}, axis{0, 0, 1};
  auto sphere = make_sphere(origin, 1.0);
  if (!sphere) return sphere.error();
  auto torus = make_torus(origin, axis, 2.0, 0.7);
  if (!torus) return torus.error();
  const Model sphere_model{std::move(*sphere)}, torus_model{std::move(*torus)};
  Figure figure = figure_of("Exact NURBS sphere and torus", 1500, 700, 2);
  SurfacePlotOptions options;
  options.iso_curves = 13;
  for (const auto& [model, title] :
       {std::pair{&sphere_model, "sphere, radius 1: degree (2,2), 9 x 5 control points"},
        std::pair{&torus_model, "torus, radii 2 and 0.7: degree (2,2), 9 x 9 control points"}}) {
    Panel panel = view_panel(title);
    if (auto ok = add_shaded_surfaces(panel, {model}, options.view, tolerances::kShadedSurfaceRelativeTolerance,
                                      Color{200, 170, 120, 1.0});
        !ok) {
      return ok.error();
    }
    options.control_net = true;
    if (auto ok = add_surface_wireframe(panel, *model, options, Color{60, 60, 60, 0.6}); !ok) return ok.error();
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{"33_nurbs_sphere_torus",
                       "Surfaces of revolution that are exact, not approximations: the semicircle and the circle as "
                       "rational quadratic NURBS (weights 1 and sqrt(2)/2) revolved about the z axis by the 9-point "
                       "NURBS circle. Shaded from a tessellation, with iso-curves and the control nets (dashed).",
                       std::move(figure)};
}

Expected<GalleryFigure> tessellation_figure() {
  const std::array<double, 3> origin{0, 0, 0};
  auto sphere = make_sphere(origin, 1.0);
  if (!sphere) return sphere.error();
  Figure figure = figure_of("Tessellation of the NURBS sphere at two tolerances", 1500, 700, 2);
  const ViewAngles view;
  for (const double tolerance : {0.05, 0.005}) {
    const SurfaceView patch(*sphere);
    auto mesh = tessellate(std::span<const SurfaceView>(&patch, 1), Tolerance{tolerance});
    if (!mesh) return mesh.error();
    Panel panel = view_panel(fmt::format("tolerance {} (radius 1): {} triangles, {} vertices", tolerance,
                                         mesh->triangles.size(), mesh->vertices.size()));
    add_shaded_mesh(panel, *mesh, view, Color{120, 190, 140, 1.0}, MeshEdges::drawn);
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{"34_tessellation_tolerances",
                       "The unit NURBS sphere tessellated adaptively within 0.05 (left) and 0.005 (right): every point "
                       "of every triangle lies within the tolerance of the sphere, the quadtree refines where the "
                       "surface bends, and vertices are shared along the seam and at the poles (a watertight mesh).",
                       std::move(figure)};
}

}  // namespace

Expected<std::vector<GalleryFigure>> surface_gallery_figures() {
  std::vector<GalleryFigure> figures;
  for (auto* builder : {&bezier_patch_figure, &coons_figure, &local_control_figure, &sphere_torus_figure,
                        &tessellation_figure}) {
    if (auto ok = append_figure(figures, builder()); !ok) return ok.error();
  }
  return figures;
}

}  // namespace casteljau::render::detail

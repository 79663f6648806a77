#pragma once
// Figures of surfaces: a fixed orthographic (axonometric) view of a surface
// in R^3, with iso-curves, the control net, and a shaded image drawn by the
// painter's algorithm with Lambert shading. Used by `plot` for surface models
// and by the gallery. A surface in R^2 is drawn in its own plane.

#include <string>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/ops/mesh.hpp"
#include "casteljau/render/figure.hpp"
#include "casteljau/render/plots.hpp"

namespace casteljau::render {

/// The direction the surface is seen from, in degrees, as matplotlib's 3D
/// axes (view_init): the viewer sits at azimuth `azimuth` around the z axis
/// (from the x axis towards y) and `elevation` above the xy plane; z points
/// up on the page. The default is matplotlib's (-60, 30).
struct ViewAngles {
  double azimuth = -60.0;
  double elevation = 30.0;
};

/// The orthographic projection of a point of R^3 (or R^2: z = 0 is not
/// added, a plane point is drawn as it is) on the page: x along
/// r = (-sin a, cos a, 0), y along u = (-sin e cos a, -sin e sin a, cos e),
/// both perpendicular to the direction to the viewer
/// e = (cos e cos a, cos e sin a, sin e). Cost O(1).
Vec2 project(const ViewAngles& view, std::span<const double> point);

/// The distance of a point towards the viewer (e . p): larger is nearer.
double depth(const ViewAngles& view, std::span<const double> point);

/// What to draw with a surface.
struct SurfacePlotOptions {
  int iso_curves = 11;          ///< per direction, evenly spaced over the domain, ends included (>= 2)
  bool control_net = false;     ///< the rows and columns of the control net, dashed gray (Coons: the
                                ///< boundaries' control polygons)
  bool control_points = false;  ///< the control points as red dots
  ViewAngles view{};
};

/// Adds the iso-curves of a surface model (asserts is_surface) to a panel:
/// `options.iso_curves` curves u = const and as many v = const. For a
/// Bézier or B-spline surface each iso-curve is a B-spline curve
/// (surfaces/iso_curve.hpp) whose projected control points give exactly the
/// projected curve (the projection is linear; weights unchanged), drawn by
/// the certified flattening of CurveItem; a Coons patch uses its B-spline
/// form when it has one, otherwise 129 points per iso-curve. The control
/// net, when asked, is drawn beneath. Errors: a surface not in R^2 or R^3,
/// iso_curves < 2.
Status add_surface_wireframe(Panel& panel, const Model& surface, const SurfacePlotOptions& options,
                             Color color = colors::black, const std::string& label = "");

/// Whether a shaded mesh shows the edges of its visible triangles.
enum class MeshEdges { hidden, drawn };

/// Whether the surface figure adds a shaded view beside the wireframe one.
enum class Shading { none, shaded };

/// Adds a triangle mesh as a shaded image: triangles sorted by their mean
/// depth and drawn far to near (painter's algorithm), each filled with
/// `base` scaled by Lambert's cosine law, 0.25 + 0.75 |n . l| (two-sided,
/// n the triangle's unit normal, l a light from over the viewer's left
/// shoulder). With MeshEdges::drawn, the edges of the triangles that face the viewer
/// (by the mesh's vertex normals) are drawn on top in thin dark lines, a
/// wireframe of the tessellation without the hidden back of a closed
/// surface. O(t log t) for t triangles.
void add_shaded_mesh(Panel& panel, const TriangleMesh& mesh, const ViewAngles& view, Color base,
                     MeshEdges edges = MeshEdges::hidden);

/// The surfaces tessellated together (ops/tessellate.hpp) within
/// `relative_tolerance` of their control points' bounding-box diagonal,
/// and drawn by add_shaded_mesh. Errors: a surface not in R^3, a
/// tessellation error.
Status add_shaded_surfaces(Panel& panel, const std::vector<const Model*>& surfaces, const ViewAngles& view,
                           double relative_tolerance, Color base);

/// The figure of `plot` for surface models: one panel with the iso-curves
/// (and control nets) of every surface (black for one, the tab10 cycle for
/// several), and with Shading::shaded (PNG and PDF output) a second panel on its
/// left with the shaded surfaces when all of them are in R^3 (a plane
/// surface has nothing to shade). Errors: no surface,
/// a source with curves or a point set (curves and surfaces are plotted
/// separately), errors of the functions above.
Expected<Figure> surface_plot_figure(const std::vector<PlotSource>& sources, const SurfacePlotOptions& options,
                                     Shading shading);

}  // namespace casteljau::render

// Exercise (seed 001 §2.1): a Coons patch fills the inside of four boundary
// curves that meet at four corners. Here: four cubic Bézier curves in space
// around the unit square, blended by the seed's cubic functions (corrected:
// f0(t) = 2t³ - 3t² + 1, f1(t) = 3t² - 2t³). Evaluate the centre, mesh it.
//
// casteljau calls: BezierCurve::make, to_bspline (a patch stores B-splines),
// CoonsPatch::make (checks the corners meet), point_at(patch, u, v),
// tessellate, to_obj, write_file_atomically (io), and for the figure
// render::add_shaded_mesh and render::add_surface_wireframe.
//
// What to look at: at u = v = 1/2 both blending functions are 1/2, so the
// centre is half the sum of the boundaries' midpoints minus a quarter of the
// corners' sum: (0.5, 0.5, 0.3375). Open coons_patch.obj in a mesh viewer
// (Blender, MeshLab); coons_patch.svg shows it shaded and as iso-curves.
#include <casteljau/bspline/bspline_curve.hpp>  // to_bspline
#include <casteljau/io/file.hpp>                // write_file_atomically
#include <casteljau/io/obj.hpp>                 // to_obj
#include <casteljau/ops/tessellate.hpp>         // tessellate
#include <casteljau/render/surface_plots.hpp>   // add_shaded_mesh, add_surface_wireframe
#include <casteljau/render/write.hpp>           // write_svg
#include <casteljau/surfaces/coons.hpp>         // CoonsPatch

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "course.hpp"  // fail, write_into

using namespace casteljau;
using course::fail;

// A cubic boundary from its 4 control points, as the B-spline a patch stores.
Expected<BSplineCurve> boundary(const std::vector<std::vector<double>>& points) {
  auto control = PointArray::make(points);
  if (!control) return control.error();
  return BezierCurve::make(*control).transform([](const BezierCurve& c) { return to_bspline(c); });
}

int main(int argc, char** argv) {
  if (argc < 2) return fail(Error{std::string("usage: ") + argv[0] + " OUTPUT_DIR"});
  const std::filesystem::path out = argv[1];
  const double a = 1.0 / 3.0, b = 2.0 / 3.0;
  auto u0 = boundary({{0, 0, 0}, {0, a, 0.5}, {0, b, 0.5}, {0, 1, 0}});   // P(0, v): an arch
  auto u1 = boundary({{1, 0, 0}, {1, a, -0.3}, {1, b, -0.3}, {1, 1, 0}}); // P(1, v): a dip
  auto v0 = boundary({{0, 0, 0}, {a, 0, 0.4}, {b, 0, 0.4}, {1, 0, 0}});   // P(u, 0): an arch
  auto v1 = boundary({{0, 1, 0}, {a, 1, 0}, {b, 1, 0.6}, {1, 1, 0}});     // P(u, 1): a bump
  for (const auto* curve : {&u0, &u1, &v0, &v1})
    if (!*curve) return fail(curve->error());
  auto patch = CoonsPatch::make(*u0, *u1, *v0, *v1, CoonsBlending::cubic);
  if (!patch) return fail(patch.error());  // e.g. two boundaries that miss a corner

  const Point centre = point_at(*patch, 0.5, 0.5);
  std::printf("P(0.5, 0.5) = (%g, %g, %g)\n", centre[0], centre[1], centre[2]);

  auto mesh = tessellate(*patch, Tolerance{1e-3});  // every triangle within 0.001 of the patch
  if (!mesh) return fail(mesh.error());
  std::printf("mesh: %zu triangles, %zu vertices\n", mesh->triangles.size(), mesh->vertices.size());

  render::Figure figure;
  figure.title = "Coons patch, cubic blending";
  figure.width = 1400; figure.height = 620; figure.columns = 2;
  render::Panel shaded, lines;
  shaded.title = "the mesh, shaded";
  lines.title = "iso-curves, the boundaries' control polygons dashed";
  shaded.equal_aspect = lines.equal_aspect = true;
  shaded.grid = lines.grid = false;  // the page axes of a 3D view mean nothing
  render::SurfacePlotOptions options;
  options.control_net = true;
  render::add_shaded_mesh(shaded, *mesh, options.view, render::Color{120, 160, 210});
  if (auto ok = render::add_surface_wireframe(lines, Model{*patch}, options); !ok) return fail(ok.error());
  figure.panels = {shaded, lines};

  const std::string text = to_obj(*mesh);
  auto obj = course::write_into(out, "coons_patch.obj", [&](const auto& path) { return write_file_atomically(path, text); });
  if (!obj) return fail(obj.error());
  auto svg = course::write_into(out, "coons_patch.svg", [&](const auto& path) { return render::write_svg(figure, path); });
  if (!svg) return fail(svg.error());
  return 0;
}

// Exercise (seed 000 §1 and seed 004 §3): evaluate the Bézier curve of the
// control points (0,0), (1,2), (2,2), (4,1), (4,0) by de Casteljau's algorithm
// (cut every side of the polygon at the ratio t, join the cuts, repeat until
// one point is left) and draw the curve, its polygon and the steps at t = 0.5.
//
// casteljau calls: PointArray::make and BezierCurve::make (checked: they
// return an Expected), casteljau_construction (each level of the triangle),
// point_at (de Casteljau), render::add_bezier, render::write_svg.
//
// What to look at: the levels printed shrink by one point each, the last one
// is B(0.5) = (2.25, 1.5). In de_casteljau.svg the dashed polygons join the
// midpoints of the previous level (t = 0.5) and end at the red point B(0.5).
#include <casteljau/bezier/bezier_curve.hpp>  // BezierCurve
#include <casteljau/bezier/construction.hpp>  // casteljau_construction
#include <casteljau/bezier/evaluate.hpp>      // point_at
#include <casteljau/render/plots.hpp>         // add_bezier, BezierPlotOptions
#include <casteljau/render/write.hpp>         // write_svg

#include <cstdio>
#include <filesystem>
#include <string>

#include "course.hpp"  // fail, write_into

using namespace casteljau;
using course::fail;

int main(int argc, char** argv) {
  if (argc < 2) return fail(Error{std::string("usage: ") + argv[0] + " OUTPUT_DIR"});
  const std::filesystem::path out = argv[1];
  auto polygon = PointArray::make({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}});
  if (!polygon) return fail(polygon.error());  // test every Expected before using its value
  auto curve = BezierCurve::make(*polygon);
  if (!curve) return fail(curve.error());

  const double t = 0.5;
  const auto levels = casteljau_construction(*curve, t);  // level 0 is the control polygon
  for (std::size_t r = 0; r < levels.size(); ++r) {
    std::printf("level %zu:", r);
    for (auto p : levels[r]) std::printf(" (%g, %g)", p[0], p[1]);
    std::printf("\n");
  }
  const Point b = point_at(*curve, t);  // the last level, in one call
  std::printf("B(%g) = (%g, %g)\n", t, b[0], b[1]);

  render::Figure figure;
  figure.title = "de Casteljau construction at t = 0.5";
  figure.width = 900; figure.height = 560;
  render::Panel& panel = figure.panels.emplace_back();
  panel.equal_aspect = true;  // one unit as long across as up
  const render::BezierPlotOptions options{.control_polygon = true, .control_points = true, .construction = t};
  render::add_bezier(panel, *curve, options, render::colors::black, "Bézier curve, degree 4");

  auto written = course::write_into(out, "de_casteljau.svg", [&](const auto& path) { return render::write_svg(figure, path); });
  if (!written) return fail(written.error());
  return 0;
}

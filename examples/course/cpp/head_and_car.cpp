// Exercise (seed 000 §2): through the points of a drawing (the head, then the
// car), build the C¹ curve made of cubic Bézier pieces: piece i runs from P_i
// to P_{i+1}, and its two inner control points Q_i, R_i are set along the
// chords P_{i-1}P_{i+1} scaled by 1/(3α), so neighbouring pieces share their
// tangent at each data point. Here α = 2 (the uniform Catmull–Rom tangents).
//
// casteljau calls: read_points_csv (io), interpolate_c1_bezier (a
// PiecewiseBezierCurve), point_at on it (piece i covers [i, i+1]),
// render::add_bezier for each piece with its control polygon, write_svg. The
// data folder is argv[2], else the one CMake names in COURSE_DATA_DIR.
//
// What to look at: the pieces printed (one fewer than the points), the curve's
// distance to the data (0 up to rounding), and in head_and_car.svg the dashed
// polygons: the two that meet at a data point are aligned there (C¹ joint).
#include <casteljau/bezier/piecewise_bezier.hpp>  // PiecewiseBezierCurve, point_at
#include <casteljau/interpolation/c1_bezier.hpp>  // interpolate_c1_bezier
#include <casteljau/io/csv.hpp>                   // read_points_csv
#include <casteljau/render/plots.hpp>             // add_bezier
#include <casteljau/render/write.hpp>             // write_svg

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "course.hpp"  // fail, write_into

using namespace casteljau;
using course::fail;

int main(int argc, char** argv) {
  if (argc < 2) return fail(Error{std::string("usage: ") + argv[0] + " OUTPUT_DIR [DATA_DIR]"});
  const std::filesystem::path out = argv[1], data = argc > 2 ? argv[2] : COURSE_DATA_DIR;
  const double alpha = 2.0;

  render::Figure figure;  // two panels side by side
  figure.title = "C¹ cubic Bézier interpolation, α = 2";
  figure.width = 1400; figure.height = 560; figure.columns = 2;
  for (const char* name : {"head", "car"}) {
    auto points = read_points_csv(data / (std::string(name) + ".csv"));  // "#" comment, header x,y
    if (!points) return fail(points.error());
    auto curve = interpolate_c1_bezier(*points, alpha);
    if (!curve) return fail(curve.error());
    double worst = 0.0;  // the curve passes through P_i at the parameter u = i
    for (std::size_t i = 0; i < points->size(); ++i)
      worst = std::max(worst, distance(point_at(*curve, double(i)), (*points)[i]));
    std::printf("%s: %zu points, %d pieces, largest |C(i) - P_i| = %.1e\n", name, points->size(), curve->size(), worst);

    render::Panel& panel = figure.panels.emplace_back();
    panel.title = std::string(name) + ", " + std::to_string(curve->size()) + " pieces";
    panel.equal_aspect = true;
    render::BezierPlotOptions options;
    options.control_polygon = options.control_points = true;
    for (const BezierCurve& piece : curve->pieces()) render::add_bezier(panel, piece, options);
    panel.markers.push_back({render::plane_points(*points), render::colors::black, 7.0, "data points P_i",
                             render::MarkerShape::diamond});  // over the red dots: the P_i among Q_i, R_i
  }

  auto written = course::write_into(out, "head_and_car.svg", [&](const auto& path) { return render::write_svg(figure, path); });
  if (!written) return fail(written.error());
  return 0;
}

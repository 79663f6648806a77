// Runs under node (compiled by em++): the core layers (Bézier, B-spline,
// interpolation, surfaces, tessellation) give known values in WebAssembly too. Prints one line per check; exit status 1 on any failure.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "casteljau/bezier/construction.hpp"
#include "casteljau/bezier/degree.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/ops/tessellate.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "casteljau/surfaces/revolution.hpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what);
  if (!ok) ++failures;
}

}  // namespace

int main() {
  using namespace casteljau;
  const auto curve = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}}).value()).value();
  check(point_at(curve, 0.5) == Point{2.25, 1.5}, "notebook polygon: B(0.5) = (2.25, 1.5)");
  const auto points = subdivide_recursive(curve, 10);
  check(points && points->size() == 1025, "recursive subdivision r = 10 gives 1025 points");
  std::vector<double> ts{0.0, 0.25, 0.5, 0.75, 1.0}, out(10);
  points_at(curve, ts, out);
  check(out[4] == 2.25 && out[5] == 1.5, "batch evaluation agrees with point_at");
  const auto [left, right] = split_at(curve, 0.3).value();
  check(point_at(left, 1.0) == point_at(curve, 0.3), "split point is point_at bit for bit");
  check(elevate_degree(curve, 2).degree() == 6, "degree elevation");
  check(casteljau_construction(curve, 0.5).size() == 5, "de Casteljau construction levels");
  const auto arc = BezierCurve::make(PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(), {1, std::sqrt(0.5), 1}).value();
  const Point p = point_at(arc, 0.3);
  check(std::abs(std::hypot(p[0], p[1]) - 1.0) < 1e-15, "rational quarter circle has radius 1");
  const auto line = flatten(curve, Tolerance{0.01});
  check(line && line->points.size() > 2, "flattening within 0.01");
  check(!BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value(), {1, -1}).has_value(), "negative weight refused");
  // B-splines: the Bézier curve as a clamped B-spline, a batch over a cubic
  // with interior knots (the portable lanes of the batch kernel run here).
  const BSplineCurve as_spline = to_bspline(curve);
  check(point_at(as_spline, 0.5) == Point{2.25, 1.5}, "B-spline of the notebook polygon: C(0.5) = (2.25, 1.5)");
  const auto cubic = BSplineCurve::make(3, clamped_uniform_knots(3, 6),
                                        PointArray::make({{0, 0}, {1, 3}, {3, 4}, {5, 1}, {7, 3}, {9, 0}}).value());
  check(cubic.has_value(), "cubic B-spline with clamped uniform knots");
  std::vector<double> us(37), batch(74);
  for (std::size_t i = 0; i < us.size(); ++i) us[i] = static_cast<double>(i) / 36.0;
  points_at(*cubic, us, batch);
  bool same = true;
  for (std::size_t i = 0; i < us.size(); ++i) {
    const Point q = point_at(*cubic, us[i]);
    same = same && std::abs(q[0] - batch[2 * i]) <= 1e-14 && std::abs(q[1] - batch[2 * i + 1]) <= 1e-14;
  }
  check(same, "B-spline batch evaluation agrees with point_at");
  check(point_at(*cubic, 1.0) == Point{9, 0}, "clamped B-spline ends at its last control point");
  check(!BSplineCurve::make(1, {0, 0, 0.5, 0.4, 1}, PointArray::make({{0}, {1}, {2}}).value()).has_value(),
        "decreasing knots refused");
  // Interpolation: not-a-knot cubics reproduce cubic polynomials, here
  // y = x³ through x = 0..5 (the tridiagonal sweep runs here too).
  const auto graph = PointArray::make({{0, 0}, {1, 1}, {2, 8}, {3, 27}, {4, 64}, {5, 125}}).value();
  const auto xs = function_parameters(graph);
  const auto spline = xs ? interpolate_cubic(graph, *xs, CubicEnds{EndCondition::not_a_knot, {}, {}})
                         : Expected<BSplineCurve>(xs.error());
  check(spline && std::abs(point_at(*spline, 2.5)[1] - 15.625) < 1e-12, "not-a-knot cubic reproduces y = x^3");
  const auto chords = parameter_values(graph, Parameterization::chord_length);
  check(chords && chords->back() == 1.0, "chord-length parameters end at 1");
  // Surfaces: the exact NURBS sphere keeps its radius, and its tessellation
  // closes up (the seam and the poles are shared).
  const double center[3] = {1.0, -2.0, 0.5};
  const auto sphere = make_sphere(center, 2.0);
  check(sphere.has_value(), "NURBS sphere of radius 2");
  if (sphere) {
    double worst = 0.0;
    for (int a = 0; a <= 8; ++a) {
      for (int b = 0; b <= 8; ++b) {
        const Point s = point_at(*sphere, sphere->domain_u().lerp(a / 8.0), sphere->domain_v().lerp(b / 8.0));
        worst = std::max(worst, std::abs(std::hypot(s[0] - 1.0, s[1] + 2.0, s[2] - 0.5) - 2.0));
      }
    }
    check(worst < 1e-14, "sphere points are at distance 2 from the centre");
    const SurfaceView view(*sphere);
    const auto mesh = tessellate(std::span<const SurfaceView>(&view, 1), Tolerance{0.01});
    check(mesh && mesh_topology(*mesh).watertight(), "sphere tessellation is watertight");
  }
  std::printf("%d failed\n", failures);
  return failures == 0 ? 0 : 1;
}

// The gallery of seed figures (issue "Foundation"): the seed notebook's
// pictures (seed 004), the semicircle of seed 003 (with the exact NURBS arc of
// issue 4), and figures that explain subdivision, flattening, degree
// elevation and Bézier's vector form. The B-spline and NURBS figures are in
// gallery_bspline.cpp and come last.
#include "figure_list.hpp"
#include "markup.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/render/gallery.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <system_error>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/degree.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bezier/vector_form.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/render/bspline_plots.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/write.hpp"

#ifndef CASTELJAU_EXAMPLES_DIR
#error "CASTELJAU_EXAMPLES_DIR must name the examples folder (set by CMakeLists.txt)"
#endif

namespace casteljau::render {
namespace {

Expected<BezierCurve> read_curve(const std::filesystem::path& dir, const char* name) {
  auto points = read_points_csv(dir / name);
  if (!points) return points.error();
  if (points->dimension() != 2)
    return Error{fmt::format("'{}': expected points with 2 coordinates, got {}", (dir / name).string(), points->dimension())};
  return BezierCurve::make(std::move(*points));
}

Figure single(std::string title, int width, int height, Panel panel) {
  Figure figure;
  figure.title = std::move(title);
  figure.width = width;
  figure.height = height;
  figure.panels.push_back(std::move(panel));
  return figure;
}

Panel geometry_panel() {
  Panel panel;
  panel.equal_aspect = true;
  return panel;
}

GalleryFigure bernstein_figure(int n, BasisEnds ends, std::string name, std::string explanation) {
  return {std::move(name), std::move(explanation), *bernstein_basis_figure(n, ends)};
}

GalleryFigure notebook_polygon_figure(const BezierCurve& curve) {
  Panel panel = geometry_panel();
  BezierPlotOptions options;
  options.control_points = options.end_tangents = true;
  add_bezier(panel, curve, options, colors::black, "Bézier curve, degree 4");
  return {"03_notebook_polygon",
          "The notebook's plot_bezier2: the degree-4 curve of (0,0), (1,2), (2,2), (4,1), (4,0), its control points, "
          "and its end tangents along P0P1 and P3P4 (C'(0) = 4(P1 - P0), C'(1) = 4(P4 - P3)).",
          single("Bézier curve with control points and end tangents", 1000, 560, std::move(panel))};
}

GalleryFigure cycle_figure(const BezierCurve& curve, int n, std::string name) {
  Panel panel = geometry_panel();
  BezierPlotOptions options;
  options.control_points = true;
  add_bezier(panel, curve, options, colors::black, fmt::format("Bézier curve, degree {}", n));
  return {std::move(name),
          fmt::format("The notebook's cycle({0}): the Bézier curve of the {1} spiral points (cos t_k, sin t_k)/(k+1), "
                      "t_k = -π/2 + 2kπ/{0}; the curve stays far inside its control points (convex hull, smoothing).",
                      n, n + 1),
          single(fmt::format("cycle({})", n), 800, 800, std::move(panel))};
}

GalleryFigure construction_figure(const BezierCurve& curve, double t, std::string title, std::string name,
                                  std::string what, int width, int height) {
  Panel panel = geometry_panel();
  BezierPlotOptions options;
  options.construction = t;
  add_bezier(panel, curve, options, colors::black, "Bézier curve");
  return {std::move(name),
          fmt::format("The notebook's demo_casteljau on {}: each dashed polygon joins the points dividing the previous "
                      "one's sides in the ratio t : 1 - t (t = {}); the last point is C(t), in red.",
                      what, t),
          single(std::move(title), width, height, std::move(panel))};
}

GalleryFigure split_figure(const BezierCurve& curve, double t) {
  const auto [left, right] = split_at(curve, t).value();  // the gallery splits inside (0, 1)
  Panel panel = geometry_panel();
  panel.polylines.push_back({plane_points(curve.control_points()), dotted(colors::gray, 1.0), "original polygon"});
  const Color a = cycle_color(0), b = cycle_color(1);
  panel.polylines.push_back({plane_points(left.control_points()), dashed(a, 1.2), fmt::format("left half [0, {}]", t)});
  panel.polylines.push_back({plane_points(right.control_points()), dashed(b, 1.2), fmt::format("right half [{}, 1]", t)});
  panel.curves.push_back({{left}, solid(a, 2.0), ""});
  panel.curves.push_back({{right}, solid(b, 2.0), ""});
  panel.markers.push_back({plane_points(left.control_points()), a, 6.0 * kPixelsPerPoint, ""});
  panel.markers.push_back({plane_points(right.control_points()), b, 6.0 * kPixelsPerPoint, ""});
  const auto split_point = plane_points(right.control_points())[0];
  panel.markers.push_back({{split_point}, colors::red, 8.0 * kPixelsPerPoint, fmt::format("C({})", t)});
  return {"08_split_halves",
          fmt::format("split_at(C, {}): the outer points of the de Casteljau triangle are the control polygons of the two "
                      "halves, each a Bézier curve of the same degree; together they are the same curve.",
                      t),
          single("Subdivision into two halves", 1000, 560, std::move(panel))};
}

GalleryFigure degree_200_figure(const BezierCurve& curve, const EvaluatorComparison& comparison) {
  Figure figure;
  figure.title = "Degree 200: direct Bernstein sum against de Casteljau, on cycle(200)";
  figure.width = 800;
  figure.height = 1100;
  Panel curves = geometry_panel();
  curves.title = "the curve by both evaluators";
  curves.curves.push_back({{curve}, solid(colors::black, 2.5), "de Casteljau (point_at)"});
  // The direct sum's points as dots on top of de Casteljau's line: where they
  // sit on it, the two evaluators agree to within the drawing's resolution.
  std::vector<Vec2> direct;
  for (std::size_t i = 0; i < comparison.parameters.size(); i += 20) {
    const Point p = point_at_bernstein_sum(curve, comparison.parameters[i]);
    direct.push_back(Vec2{{p[0], p[1]}});
  }
  // Most of the curve of degree 200 lies close to the origin, far inside its
  // first control points: frame that part (the curve starts at (0, -1)).
  curves.x.range = std::array<double, 2>{-0.06, 0.06};
  curves.y.range = std::array<double, 2>{-0.12, 0.03};
  curves.markers.push_back({direct, cycle_color(1), 4.0 * kPixelsPerPoint,
                            fmt::format("Bernstein sum (point_at_bernstein_sum), {} parameters", direct.size())});
  Panel error;
  error.title = fmt::format("|Bernstein sum - de Casteljau|, max {:.2e} at t = {:.3f}", comparison.maximum, comparison.at);
  error.x.label = "t";
  error.y.label = "distance";
  error.y.logarithmic = true;
  std::vector<Vec2> distances;
  for (std::size_t i = 0; i < comparison.parameters.size(); ++i)
    distances.push_back(Vec2{{comparison.parameters[i], comparison.differences[i]}});
  error.polylines.push_back({distances, solid(cycle_color(0), 1.0), ""});
  figure.panels.push_back(std::move(curves));
  figure.panels.push_back(std::move(error));
  return {"09_degree_200",
          fmt::format("Degree 200 (cycle(200)): the notebook's direct sum of C(200,k) t^k (1-t)^(200-k) P_k against de "
                      "Casteljau at {} parameters; measured maximum distance {:.3e} (at t = {:.3f}), both curves coincide "
                      "on screen; where the distance is 0 the log plot has a gap.",
                      comparison.parameters.size(), comparison.maximum, comparison.at),
          std::move(figure)};
}

GalleryFigure repeated_point_figure(const BezierCurve& curve, int index) {
  Panel panel = geometry_panel();
  const auto points = plane_points(curve.control_points());
  panel.polylines.push_back({points, dashed(colors::gray, 1.0), "control polygon"});
  for (int multiplicity = 1; multiplicity <= 4; ++multiplicity) {
    const BezierCurve repeated = repeat_control_point(curve, index, multiplicity - 1);
    panel.curves.push_back({{repeated},
                            solid(cycle_color(multiplicity - 1)),
                            fmt::format("P{} × {} (degree {})", index, multiplicity, repeated.degree())});
  }
  panel.markers.push_back({points, colors::red, 6.0 * kPixelsPerPoint, "control points"});
  panel.texts.push_back({points[static_cast<std::size_t>(index)], fmt::format("P{}", index), colors::black,
                         10.0 * kPixelsPerPoint, Anchor::start, Vec2{{6.0, 6.0}}});
  return {"10_repeated_control_point",
          fmt::format("Seed 003: repeating the control point P{} = ({:g}, {:g}) 1 to 4 times pulls the curve toward it, "
                      "at the cost of a higher degree (repeat_control_point; not a degree elevation).",
                      index, points[static_cast<std::size_t>(index)][0], points[static_cast<std::size_t>(index)][1]),
          single("A repeated control point pulls the curve", 1000, 560, std::move(panel))};
}

Expected<GalleryFigure> semicircle_figure(const BezierCurve& curve, const RadialError& error) {
  // The exact half circle is seed_semicircle(): the NURBS arc of issue 4
  // (two rational quadratic quarter arcs), drawn like every B-spline.
  const BSplineCurve arc = seed_semicircle();
  const RadialError exact = radial_error(arc, 3.0, static_cast<int>(error.parameters.size()));
  Figure figure;
  figure.title = "Seed 003: a cubic Bézier curve for a half circle of radius 3";
  figure.width = 800;
  figure.height = 1300;
  Panel shape = geometry_panel();
  shape.title = "A(-3,0) B(-3,4) C(3,4) D(3,0) against the exact NURBS half circle";
  shape.y.range = std::array<double, 2>{-0.4, 7.6};  // room above for the legend
  shape.polylines.push_back({plane_points(curve.control_points()), dashed(colors::gray, 1.0), "control polygon"});
  shape.polylines.push_back({plane_points(arc.control_points()), dotted(cycle_color(0), 1.0), "NURBS control polygon"});
  if (auto ok = add_bspline(shape, arc, BSplinePlotOptions{}, cycle_color(0), "half circle, radius 3 (NURBS, exact)"); !ok)
    return ok.error();
  shape.curves.back().stroke = solid(cycle_color(0), 3.0);
  shape.curves.push_back({{curve}, solid(colors::black, 1.2), "cubic Bézier ABCD"});
  shape.markers.push_back({plane_points(curve.control_points()), colors::red, 6.0 * kPixelsPerPoint, "control points"});
  shape.markers.push_back({plane_points(arc.control_points()), cycle_color(0), 5.0 * kPixelsPerPoint, ""});
  const char* names[] = {"A", "B", "C", "D"};
  const auto points = plane_points(curve.control_points());
  for (std::size_t i = 0; i < 4 && i < points.size(); ++i)
    shape.texts.push_back({points[i], names[i], colors::black, 10.0 * kPixelsPerPoint,
                           i < 2 ? Anchor::end : Anchor::start, Vec2{{i < 2 ? -7.0 : 7.0, 5.0}}});
  Panel radial;
  radial.title = fmt::format("radial error |C(t)| - 3, max |error| = {:.4f} at t = {:.3f}", error.maximum, error.at);
  radial.x.label = "t";
  radial.y.label = "|C(t)| - 3";
  std::vector<Vec2> values;
  // The maximum is measured on every sample; 1 in 10 is plenty to draw.
  for (std::size_t i = 0; i < error.parameters.size(); i += 10)
    values.push_back(Vec2{{error.parameters[i], error.errors[i]}});
  radial.polylines.push_back({values, solid(colors::black), ""});
  radial.polylines.push_back({{Vec2{{0.0, 0.0}}, Vec2{{1.0, 0.0}}}, dashed(colors::gray, 1.0), ""});
  // Both errors on a log axis: 14 orders of magnitude apart. Where the
  // NURBS arc's computed radius is exactly 3 the log plot has a gap.
  Panel both;
  both.title = fmt::format("| |C| - 3 | on a log axis: cubic max {:.2e}, NURBS arc max {:.1e}", error.maximum, exact.maximum);
  both.x.label = "t (cubic), u (NURBS arc)";
  both.y.label = "| |C| - 3 |";
  both.y.logarithmic = true;
  std::vector<Vec2> cubic_values, exact_values;
  for (std::size_t i = 0; i < error.parameters.size(); i += 10)
    cubic_values.push_back(Vec2{{error.parameters[i], std::abs(error.errors[i])}});
  for (std::size_t i = 0; i < exact.parameters.size(); i += 10)
    exact_values.push_back(Vec2{{exact.parameters[i], std::abs(exact.errors[i])}});
  both.polylines.push_back({cubic_values, solid(colors::black, 1.2), "cubic Bézier"});
  both.polylines.push_back({exact_values, solid(cycle_color(0), 1.0), "NURBS arc"});
  both.legend = LegendPlace::lower_right;
  figure.panels.push_back(std::move(shape));
  figure.panels.push_back(std::move(radial));
  figure.panels.push_back(std::move(both));
  return GalleryFigure{
      "11_semicircle",
      fmt::format("Seed 003's CNC example: the cubic A(-3,0) B(-3,4) C(3,4) D(3,0) against the exact half circle of "
                  "radius 3 (seed_semicircle(), a NURBS arc of two rational quadratic pieces); measured largest radial "
                  "error of the cubic {:.4f} ({:.2f} % of the radius, at t = {:.3f}), not the 1/100 the seed claims; "
                  "of the NURBS arc {:.1e} ({:.1e} of the radius: rounding only).",
                  error.maximum, 100.0 * error.maximum / 3.0, error.at, exact.maximum, exact.maximum / 3.0),
      std::move(figure)};
}

Expected<GalleryFigure> subdivision_figure(const BezierCurve& curve) {
  Figure figure;
  figure.title = "Recursive subdivision at t = 1/2: 2^r + 1 points of the curve";
  figure.width = 1000;
  figure.height = 700;
  figure.columns = 2;
  for (int r = 1; r <= 4; ++r) {
    auto points = subdivide_recursive(curve, r, 0.5);
    if (!points) return points.error();
    Panel panel = geometry_panel();
    panel.title = fmt::format("r = {}: {} points", r, points->size());
    panel.curves.push_back({{curve}, solid(colors::grid, 3.0), r == 1 ? "curve" : ""});
    panel.polylines.push_back({plane_points(*points), solid(colors::black, 1.2), r == 1 ? "polyline through the points" : ""});
    panel.markers.push_back({plane_points(*points), colors::red, 5.0 * kPixelsPerPoint, ""});
    panel.legend = r == 1 ? LegendPlace::best : LegendPlace::none;
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{"12_recursive_subdivision",
                       "The notebook's bezier(Ps, r): subdividing r times at t = 1/2 gives the 2^r + 1 curve points "
                       "C(i/2^r); the polyline through them approaches the curve (r = 10 gives 1025 points).",
                       std::move(figure)};
}

Expected<GalleryFigure> flattening_figure(const BezierCurve& curve) {
  Figure figure;
  figure.title = "Flattening within a tolerance (casteljau's flatten)";
  figure.width = 1100;
  figure.height = 560;
  figure.columns = 2;
  std::string counts;
  for (double tolerance : {0.1, 0.01}) {
    auto line = flatten(curve, Tolerance{tolerance});
    if (!line) return line.error();
    const auto points = plane_points(line->points);
    Panel panel = geometry_panel();
    panel.title = fmt::format("tolerance {:g}", tolerance);
    panel.curves.push_back({{curve}, solid(colors::grid, 4.0), "curve"});
    panel.polylines.push_back(
        {points, solid(cycle_color(0), 1.2), fmt::format("{} vertices, {} segments", points.size(), points.size() - 1)});
    panel.markers.push_back({points, cycle_color(0), 4.0 * kPixelsPerPoint, ""});
    counts += fmt::format("{}{} segments at {:g}", counts.empty() ? "" : ", ", points.size() - 1, tolerance);
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{"13_flattening",
                       fmt::format("Every curve here is drawn as a polyline guaranteed within a tolerance of the curve "
                                   "(a quarter pixel on screen); at coarse tolerances the polygons show: {}.",
                                   counts),
                       std::move(figure)};
}

GalleryFigure elevation_figure(const BezierCurve& curve) {
  Panel panel = geometry_panel();
  const BezierCurve once = elevate_degree(curve, 1), thrice = elevate_degree(curve, 4);
  panel.polylines.push_back({plane_points(curve.control_points()), dashed(colors::gray, 1.2),
                             fmt::format("degree {} polygon", curve.degree())});
  panel.polylines.push_back({plane_points(once.control_points()), dashed(cycle_color(0), 1.2),
                             fmt::format("elevated to degree {}", once.degree())});
  panel.polylines.push_back({plane_points(thrice.control_points()), dashed(cycle_color(1), 1.2),
                             fmt::format("elevated to degree {}", thrice.degree())});
  panel.curves.push_back({{curve}, solid(colors::black, 2.0), "the same curve"});
  panel.markers.push_back({plane_points(curve.control_points()), colors::red, 6.0 * kPixelsPerPoint, ""});
  panel.markers.push_back({plane_points(once.control_points()), cycle_color(0), 5.0 * kPixelsPerPoint, ""});
  panel.markers.push_back({plane_points(thrice.control_points()), cycle_color(1), 5.0 * kPixelsPerPoint, ""});
  return {"14_degree_elevation",
          fmt::format("elevate_degree: the same curve written with degree {} and {}; each new polygon cuts the corners "
                      "of the previous one (Q_i = i/(n+1) P_(i-1) + (1 - i/(n+1)) P_i) and approaches the curve.",
                      once.degree(), thrice.degree()),
          single("Degree elevation: same curve, new control polygons", 1000, 560, std::move(panel))};
}

GalleryFigure vector_form_figure(const BezierCurve& curve, double t) {
  const PointArray vectors = to_vector_form(curve.control_points());
  const int n = curve.degree();
  Panel panel = geometry_panel();
  SegmentItem sides{{}, solid(cycle_color(0), 1.5), true, "V_0 = P_0, V_i = P_i - P_(i-1)"};
  SegmentItem scaled{{}, solid(cycle_color(3), 2.0), true, fmt::format("f_i({}) V_i, head to tail", t)};
  Vec2 head{{0.0, 0.0}}, scaled_head{{0.0, 0.0}};
  for (int i = 0; i <= n; ++i) {
    const auto v = vectors[static_cast<std::size_t>(i)];
    const Vec2 step{{v[0], v[1]}};
    sides.segments.push_back({head, head + step});
    head = head + step;
    const double f = bezier_basis_polynomial(n, i, t);
    scaled.segments.push_back({scaled_head, scaled_head + f * step});
    scaled_head = scaled_head + f * step;
  }
  panel.segments.push_back(std::move(sides));
  panel.segments.push_back(std::move(scaled));
  panel.curves.push_back({{curve}, solid(colors::black), "P(t) = Σ f_i(t) V_i"});
  const Point p = point_at_vector_form(vectors, t);
  panel.markers.push_back({{Vec2{{0.0, 0.0}}}, colors::black, 5.0 * kPixelsPerPoint, "origin"});
  panel.markers.push_back({{Vec2{{p[0], p[1]}}}, colors::red, 8.0 * kPixelsPerPoint, fmt::format("P({})", t)});
  return {"15_vector_form",
          fmt::format("Bézier's own vector form (seed 003): the sides V_i of the polygon drawn head to tail from the "
                      "origin; scaling each by f_i(t) = Σ_(k≥i) B_(n,k)(t) and chaining them lands on P(t) (t = {}).",
                      t),
          single("Bézier's vector form P(t) = Σ f_i(t) V_i", 1000, 640, std::move(panel))};
}

GalleryFigure comb_figure(const BezierCurve& curve, int n) {
  Panel panel = geometry_panel();
  BezierPlotOptions options;
  options.curvature_comb = options.control_points = options.control_polygon = true;
  add_bezier(panel, curve, options, colors::black, fmt::format("cycle({})", n));
  return {"16_curvature_comb",
          fmt::format("The curvature comb of cycle({}): teeth along the normal, outside each bend, as long as the "
                      "curvature; the curve is smooth where the tips' line is.",
                      n),
          single(fmt::format("Curvature comb of cycle({})", n), 800, 800, std::move(panel))};
}


}  // namespace

std::filesystem::path default_examples_dir() { return CASTELJAU_EXAMPLES_DIR; }

PointArray notebook_cycle(int n) {
  std::vector<double> coordinates;
  for (int k = 0; k <= n; ++k) {
    const double t = -std::numbers::pi / 2.0 + 2.0 * k * std::numbers::pi / n;
    coordinates.push_back(std::cos(t) / (k + 1));
    coordinates.push_back(std::sin(t) / (k + 1));
  }
  return PointArray::from_trusted(2, std::move(coordinates));
}

EvaluatorComparison compare_evaluators_on_cycle(int degree, int samples) {
  const BezierCurve curve = BezierCurve::from_trusted(notebook_cycle(degree));
  EvaluatorComparison result;
  for (int i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / (samples - 1);
    const double d = distance(point_at_bernstein_sum(curve, t), point_at(curve, t));
    result.parameters.push_back(t);
    result.differences.push_back(d);
    if (d > result.maximum) result.maximum = d, result.at = t;
  }
  return result;
}

RadialError radial_error(const PointArray& control_points, double radius, int samples) {
  const BezierCurve curve = BezierCurve::from_trusted(control_points);
  RadialError result;
  for (int i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / (samples - 1);
    const Point p = point_at(curve, t);
    const double e = std::hypot(p[0], p[1]) - radius;
    result.parameters.push_back(t);
    result.errors.push_back(e);
    if (std::abs(e) > result.maximum) result.maximum = std::abs(e), result.at = t;
  }
  return result;
}

RadialError radial_error(const BSplineCurve& curve, double radius, int samples) {
  const Interval domain = curve.domain();
  RadialError result;
  for (int i = 0; i < samples; ++i) {
    const double u = domain.lerp(static_cast<double>(i) / (samples - 1));
    const Point p = point_at(curve, u);
    const double e = std::hypot(p[0], p[1]) - radius;
    result.parameters.push_back(u);
    result.errors.push_back(e);
    if (std::abs(e) > result.maximum) result.maximum = std::abs(e), result.at = u;
  }
  return result;
}

std::span<const GallerySection> gallery_sections() {
  static constexpr GallerySection kSections[] = {
      {1, 16,
       "Bézier curves: the Bernstein basis of degree 20, the notebook's curves and spirals, de Casteljau "
       "constructions, splitting, the degree-200 evaluators, a repeated control point, the semicircle and the exact "
       "NURBS arc, recursive subdivision, flattening, degree elevation, the vector form, a curvature comb"},
      {17, 22,
       "B-splines and NURBS: the basis for clamped and uniform knots, local control, knot multiplicity and "
       "continuity, the NURBS circle, the pull of one weight"},
      {23, 29,
       "interpolation: the head and the car through every method, Runge's oscillation, natural splines, smoothing"},
      {30, 34,
       "surfaces: a bicubic Bézier patch, Coons patches with both blendings, B-spline surface local control, the NURBS "
       "sphere and torus, a tessellation at two tolerances"},
      {35, 38,
       "questions asked of a curve: equal-parameter against equal-arc-length samples on the head, curvature combs "
       "of the car's C¹ and C² interpolants, the head's closest-point field, intersections with their kinds"},
      {39, 40, "drawings read: an SVG drawing with the control polygons of its Bézier pieces, a word in a TrueType font with its on- and off-curve points"},
      {41, 43, "G-code: the head and the car cut within 0.01 mm, the seed's half circle as one G2 arc, a word engraved; each program read back and drawn over its curves"},
  };
  return kSections;
}

std::string gallery_contents() {
  std::string text;
  for (const auto& section : gallery_sections())
    text += fmt::format("{}{:02}-{:02} {}", text.empty() ? "" : "; ", section.first, section.last, section.topics);
  return text;
}

Expected<std::vector<GalleryFigure>> gallery_figures(const std::filesystem::path& examples_dir) {
  auto polygon = read_curve(examples_dir, "notebook_polygon.csv");
  if (!polygon) return polygon.error();
  auto cycle5 = read_curve(examples_dir, "spiral_5.csv");
  if (!cycle5) return cycle5.error();
  auto cycle8 = read_curve(examples_dir, "spiral_8.csv");
  if (!cycle8) return cycle8.error();
  auto cycle10 = read_curve(examples_dir, "spiral_10.csv");
  if (!cycle10) return cycle10.error();
  auto cycle20 = read_curve(examples_dir, "spiral_20.csv");
  if (!cycle20) return cycle20.error();
  auto semicircle = read_curve(examples_dir, "semicircle.csv");
  if (!semicircle) return semicircle.error();

  std::vector<GalleryFigure> figures;
  figures.push_back(bernstein_figure(20, BasisEnds::included, "01_bernstein_20",
                                     "The 21 Bernstein polynomials B_(20,k)(t) = C(20,k) t^k (1-t)^(20-k) on [0,1] (the "
                                     "notebook's plot_bernstein(20)): positive, summing to 1, B_(20,k) peaking at t = k/20."));
  figures.push_back(bernstein_figure(20, BasisEnds::omitted, "02_bernstein_20_without_ends",
                                     "The same basis without B_(20,0) and B_(20,20), which dominate near the ends: the "
                                     "inner functions peak at k/20 with heights falling toward the middle."));
  figures.push_back(notebook_polygon_figure(*polygon));
  figures.push_back(cycle_figure(*cycle10, 10, "04_cycle_10"));
  figures.push_back(cycle_figure(*cycle20, 20, "05_cycle_20"));
  figures.push_back(construction_figure(*polygon, 0.5, "de Casteljau construction at t = 0.5",
                                        "06_construction_notebook_polygon", "the notebook polygon", 1000, 560));
  figures.push_back(construction_figure(*cycle5, 0.6, "de Casteljau construction of cycle(5) at t = 0.6",
                                        "07_construction_cycle_5", "cycle(5)", 800, 800));
  figures.push_back(split_figure(*polygon, 0.5));
  constexpr int kDegree = 200;
  const auto comparison = compare_evaluators_on_cycle(kDegree, 2001);
  figures.push_back(degree_200_figure(BezierCurve::from_trusted(notebook_cycle(kDegree)), comparison));
  figures.push_back(repeated_point_figure(*polygon, 2));
  const auto error = radial_error(semicircle->control_points(), 3.0, 20001);
  Expected<GalleryFigure> built[] = {semicircle_figure(*semicircle, error), subdivision_figure(*polygon),
                                     flattening_figure(*cycle8)};
  for (auto& figure : built) {
    if (auto ok = detail::append_figure(figures, std::move(figure)); !ok) return ok.error();
  }
  figures.push_back(elevation_figure(*polygon));
  figures.push_back(vector_form_figure(*semicircle, 0.4));
  figures.push_back(comb_figure(*cycle8, 8));
  auto bspline = bspline_gallery_figures();
  if (!bspline) return bspline.error();
  for (auto& f : *bspline) figures.push_back(std::move(f));
  auto interpolation = interpolation_gallery_figures(examples_dir);
  if (!interpolation) return interpolation.error();
  for (auto& f : *interpolation) figures.push_back(std::move(f));
  auto surfaces = detail::surface_gallery_figures();
  if (!surfaces) return surfaces.error();
  for (auto& f : *surfaces) figures.push_back(std::move(f));
  auto queries = detail::query_gallery_figures(examples_dir);
  if (!queries) return queries.error();
  for (auto& f : *queries) figures.push_back(std::move(f));
  auto drawings = detail::drawing_gallery_figures(examples_dir);
  if (!drawings) return drawings.error();
  for (auto& f : *drawings) figures.push_back(std::move(f));
  auto gcode = detail::gcode_gallery_figures(examples_dir);
  if (!gcode) return gcode.error();
  for (auto& f : *gcode) figures.push_back(std::move(f));
  return figures;
}

std::string gallery_index_html(const std::vector<GalleryFigure>& figures) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>casteljau gallery</title>\n<link rel=\"icon\" href=\"data:,\">\n"
      "<style>body{font-family:'DejaVu Sans',sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}"
      "figure{margin:2.5em 0;border-top:1px solid #ddd;padding-top:1em}img{max-width:100%;height:auto}"
      "figcaption{margin-top:.5em}h2{font-size:1.15em}</style>\n</head>\n<body>\n"
      "<h1>casteljau gallery</h1>\n<p>The seed figures, drawn by casteljau: every curve is flattened by casteljau "
      "itself within a quarter pixel. Each figure is available as SVG and PNG.</p>\n";
  for (const auto& f : figures) {
    html += fmt::format(
        "<figure id=\"{0}\">\n<h2>{1}</h2>\n<img src=\"{0}.svg\" alt=\"{1}\" width=\"{3}\" height=\"{4}\">\n"
        "<figcaption>{2} <a href=\"{0}.svg\">SVG</a> · <a href=\"{0}.png\">PNG</a></figcaption>\n</figure>\n",
        f.name, detail::xml_escaped(f.figure.title), detail::xml_escaped(f.explanation), f.figure.width, f.figure.height);
  }
  html += "</body>\n</html>\n";
  return html;
}

namespace {

/// Building every figure, as a fraction of the whole gallery's work.
constexpr double kBuildingShare = 0.1;

}  // namespace

Expected<std::vector<GalleryFigure>> write_gallery(const std::filesystem::path& dir,
                                                   const std::filesystem::path& examples_dir, Progress progress) {
  progress(0.0);
  auto figures = gallery_figures(examples_dir);
  if (!figures) return figures.error();
  progress(kBuildingShare);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    return Error{fmt::format("cannot create the folder '{}': {}", dir.string(),
                             error ? error.message() : std::string("a file of that name exists"))};
  // Each figure's share of the rest, half for its SVG and half for its PNG
  // (each lays the figure out): part k of 2 N ends where part k + 1 begins.
  const double parts = 2.0 * static_cast<double>(figures->size());
  auto bound = [&](std::size_t k) { return kBuildingShare + (1.0 - kBuildingShare) * static_cast<double>(k) / parts; };
  for (std::size_t i = 0; i < figures->size(); ++i) {
    const auto& f = (*figures)[i];
    ProgressPart svg(progress, bound(2 * i), bound(2 * i + 1)), png(progress, bound(2 * i + 1), bound(2 * i + 2));
    if (auto ok = write_svg(f.figure, dir / (f.name + ".svg"), svg.callback()); !ok)
      return with_context(ok.error(), f.name);
    if (auto ok = write_png(f.figure, dir / (f.name + ".png"), png.callback()); !ok)
      return with_context(ok.error(), f.name);
  }
  if (auto ok = write_file_atomically(dir / "index.html", gallery_index_html(*figures)); !ok) return ok.error();
  progress(1.0);
  return figures;
}

}  // namespace casteljau::render

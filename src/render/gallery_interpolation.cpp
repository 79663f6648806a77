// The gallery's interpolation figures (issue 3): seed 000's head and car
// through the C¹ Bézier interpolant at α = 1 and 2 and the closed C² cubic;
// every method side by side on each data set; Runge's oscillation against
// Chebyshev nodes (seed 001, problem P1); natural splines of order q = 1, 2,
// 3 (problem P2); smoothing with increasing λ. Every curve is drawn through
// its Bézier pieces and the certified flattening, like the other figures;
// the numbers in the captions are measured here at every run.
#include "casteljau/render/gallery.hpp"
#include "casteljau/core/tolerance.hpp"
#include "figure_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/interpolation/c1_bezier.hpp"
#include "casteljau/interpolation/catmull_rom.hpp"
#include "casteljau/interpolation/fit.hpp"
#include "casteljau/interpolation/hermite.hpp"
#include "casteljau/interpolation/lagrange.hpp"
#include "casteljau/interpolation/natural_spline.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "casteljau/ops/bounds.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "casteljau/ops/curvature_extrema.hpp"
#include "casteljau/ops/inflections.hpp"
#include "casteljau/ops/intersection.hpp"
#include "casteljau/curves/differential_geometry.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/render/bspline_plots.hpp"
#include "casteljau/render/plots.hpp"

namespace casteljau::render {
namespace {

using detail::figure_of;

Expected<PointArray> read_plane_points(const std::filesystem::path& dir, const char* name) {
  auto points = read_points_csv(dir / name);
  if (!points) return points.error();
  if (points->dimension() != 2)
    return Error{fmt::format("'{}': expected points with 2 coordinates, got {}", (dir / name).string(),
                             points->dimension())};
  return points;
}

/// The data points as black dots (drawn above the curves).
void add_data_points(Panel& panel, const PointArray& points, const std::string& label = "data points") {
  panel.markers.push_back({plane_points(points), colors::black, 5.0 * kPixelsPerPoint, label_once(panel, label)});
}

/// A piecewise Bézier curve piece by piece, optionally with each piece's
/// control polygon and points (the polygons of neighbouring pieces meet at
/// the data points).
void add_pieces(Panel& panel, const PiecewiseBezierCurve& curve, bool with_polygons, Color color,
                const std::string& label) {
  BezierPlotOptions options;
  options.control_polygon = options.control_points = with_polygons;
  for (std::size_t i = 0; i < curve.pieces().size(); ++i)
    add_bezier(panel, curve.pieces()[i], options, color, i == 0 ? label : "");
}

/// The largest distance |C(t_i) − P_i| over the data (a check the figures
/// state: every interpolant passes through its points).
template <class Curve>
double data_error(const Curve& curve, const PointArray& points, std::span<const double> parameters) {
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    worst = std::max(worst, distance(point_at(curve, parameters[i]), points[i]));
  return worst;
}

/// A fixed view of the data's bounding box widened by `margin` of its size
/// on every side: curves that leave it (Lagrange's) are clipped.
void frame_data(Panel& panel, const PointArray& points, double margin) {
  double x0 = points[0][0], x1 = x0, y0 = points[0][1], y1 = y0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    x0 = std::min(x0, points[i][0]), x1 = std::max(x1, points[i][0]);
    y0 = std::min(y0, points[i][1]), y1 = std::max(y1, points[i][1]);
  }
  const double pad = margin * std::max(x1 - x0, y1 - y0);
  panel.x.range = std::array<double, 2>{x0 - pad, x1 + pad};
  panel.y.range = std::array<double, 2>{y0 - pad, y1 + pad};
}

/// max over k = 0..2 of |C^(k)(end) − C^(k)(start)| relative to the largest
/// |C^(k)| on the curve: how well a closed curve closes with C² continuity.
double seam_gap(const BSplineCurve& curve) {
  const Interval domain = curve.domain();
  double worst = 0.0;
  for (int k = 0; k <= 2; ++k) {
    double size = 0.0;
    for (int i = 0; i <= 400; ++i) {
      const Point value = derivative_at(curve, domain.lerp(i / 400.0), k);
      for (double c : value) size = std::max(size, std::abs(c));
    }
    worst = std::max(worst, distance(derivative_at(curve, domain.lower, k), derivative_at(curve, domain.upper, k)) /
                                std::max(size, tolerances::kScaleFloor));
  }
  return worst;
}

/// The largest jump of the first derivative at the joints of a piecewise
/// curve (relative to the largest derivative there): 0 for a C¹ curve up to rounding.
double largest_tangent_jump(const PiecewiseBezierCurve& curve, bool closed) {
  double worst = 0.0, size = 0.0;
  const auto& pieces = curve.pieces();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const bool last = i + 1 == pieces.size();
    if (last && !closed) break;
    const Point left = derivative_at(pieces[i], 1.0, 1);
    const Point right = derivative_at(pieces[last ? 0 : i + 1], 0.0, 1);
    worst = std::max(worst, distance(left, right));
    for (double c : left) size = std::max(size, std::abs(c));
  }
  return worst / std::max(size, tolerances::kScaleFloor);
}

// --- head and car: c1-bezier at α = 1 and 2, the closed C² cubic -------------------

Expected<GalleryFigure> interpolants_figure(const PointArray& data, const std::string& set, const std::string& stem,
                                            bool wide) {
  Figure figure = figure_of(fmt::format("The {} (seed 000): C¹ Bézier pieces at α = 1 and α = 2, the closed C² cubic",
                                        set),
                            wide ? 1800 : 1500, wide ? 470 : 560, 3);
  std::string measured;
  for (const double alpha : {1.0, 2.0}) {
    auto curve = interpolate_c1_bezier(data, alpha);
    if (!curve) return curve.error();
    Panel panel;
    panel.equal_aspect = true;
    panel.title = fmt::format("c1-bezier, α = {:g} ({} pieces)", alpha, curve->size());
    add_pieces(panel, *curve, true, colors::black, "C¹ curve");
    add_data_points(panel, data);
    panel.legend = LegendPlace::none;
    figure.panels.push_back(std::move(panel));
    std::vector<double> joints(data.size());
    for (std::size_t i = 0; i < joints.size(); ++i) joints[i] = static_cast<double>(i);
    measured += fmt::format("α = {:g}: largest tangent jump at a joint {:.1e}, largest |C(i) − P_i| {:.1e}; ", alpha,
                            largest_tangent_jump(*curve, false), data_error(*curve, data, joints));
  }
  const PointArray closed_points = without_closing_duplicate(data);
  auto parameters = parameter_values(closed_points, Parameterization::centripetal, Closure::closed);
  if (!parameters) return parameters.error();
  auto cubic = interpolate_cubic(closed_points, *parameters, CubicEnds{EndCondition::periodic, {}, {}});
  if (!cubic) return cubic.error();
  Panel panel;
  panel.equal_aspect = true;
  panel.title = fmt::format("closed C² cubic (periodic, centripetal), {} control points", cubic->control_points().size());
  BSplinePlotOptions options;
  options.control_polygon = options.control_points = true;
  if (auto ok = add_bspline(panel, *cubic, options, cycle_color(0), "closed cubic B-spline"); !ok) return ok.error();
  add_data_points(panel, data);
  panel.legend = LegendPlace::none;
  figure.panels.push_back(std::move(panel));
  measured += fmt::format("closed cubic: largest |C(t_i) − P_i| {:.1e}, seam gap in C, C', C'' {:.1e} (relative)",
                          data_error(*cubic, closed_points, *parameters), seam_gap(*cubic));
  return GalleryFigure{
      stem,
      fmt::format("Seed 000's {} ({} points, black): the C¹ curve of cubic Bézier pieces P_i, Q_i, R_i, P_(i+1) with "
                  "Q_i = P_i + (P_(i+1) − P_(i−1))/(3α), R_i = P_(i+1) − (P_(i+2) − P_i)/(3α) (dashed: each piece's "
                  "control polygon, red: Q_i and R_i); α = 2 halves the tangents (uniform Catmull–Rom) and tightens "
                  "the curve. Right: the closed C² cubic spline (periodic end condition, centripetal parameters) "
                  "with its B-spline control polygon. Measured: {}.",
                  set, data.size(), measured),
      std::move(figure)};
}

// --- equal parameter vs equal arc length on the head (issue 16) -----------------------

/// Ratio of the longest to the shortest chord between consecutive samples.
double chord_spread(const PiecewiseBezierCurve& curve, std::span<const double> us) {
  double shortest = INFINITY, longest = 0.0;
  for (std::size_t i = 0; i + 1 < us.size(); ++i) {
    const double chord = distance(point_at(curve, us[i]), point_at(curve, us[i + 1]));
    shortest = std::min(shortest, chord), longest = std::max(longest, chord);
  }
  return longest / shortest;
}

Expected<GalleryFigure> arc_length_samples_figure(const PointArray& data) {
  constexpr std::size_t kSamples = 80;
  auto curve = interpolate_c1_bezier(data, 2.0);
  if (!curve) return curve.error();
  const Interval domain = curve->domain();
  std::vector<double> uniform(kSamples);
  for (std::size_t i = 0; i < kSamples; ++i) uniform[i] = domain.lerp(static_cast<double>(i) / (kSamples - 1));
  auto spaced = equal_arc_length_parameters(*curve, kSamples, default_arc_length_tolerance(*curve));
  if (!spaced) return spaced.error();
  auto length = arc_length(*curve, default_arc_length_tolerance(*curve));
  if (!length) return length.error();
  Figure figure = figure_of("The head's C¹ curve sampled at equal parameter steps and at equal arc-length steps", 1500,
                            620, 2);
  for (const auto& [us, title] : {std::pair{&uniform, "80 equal steps in the parameter u"},
                                  std::pair{&*spaced, "80 equal steps in arc length"}}) {
    Panel panel;
    panel.equal_aspect = true;
    panel.title = fmt::format("{} (longest / shortest chord {:.2f})", title, chord_spread(*curve, *us));
    add_pieces(panel, *curve, false, colors::gray, "C¹ curve, α = 2");
    std::vector<Vec2> samples;
    for (const double u : *us) {
      const Point p = point_at(*curve, u);
      samples.push_back(Vec2{{p[0], p[1]}});
    }
    panel.markers.push_back({std::move(samples), cycle_color(0), 5.0 * kPixelsPerPoint, "samples"});
    panel.legend = LegendPlace::none;
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{
      "35_head_arc_length_samples",
      fmt::format("The head's C¹ Bézier curve (α = 2, {} pieces, length {:.6g}) sampled at 80 points. Left: equal steps "
                  "in the parameter, which crowd where the pieces are short and spread where they are long (each piece "
                  "spans one unit of u whatever its size). Right: equal steps in arc length (equal_arc_length_parameters, "
                  "each length within 1e-12 of the size: ops/arc_length.hpp), the spacing a CNC feed or a dashed line "
                  "needs. Measured: longest / shortest chord {:.2f} against {:.3f}.",
                  curve->size(), *length, chord_spread(*curve, uniform), chord_spread(*curve, *spaced)),
      std::move(figure)};
}

// --- curvature combs, closest points, intersections -------------------------------------

/// The largest jump of the signed curvature where consecutive pieces meet.
double largest_curvature_jump(CurveView curve) {
  const BezierPieces pieces = to_bezier_pieces(curve);
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < pieces.pieces.size(); ++k)
    worst = std::max(worst, std::abs(signed_curvature_at(pieces.pieces[k], 1.0) -
                                     signed_curvature_at(pieces.pieces[k + 1], 0.0)));
  return worst;
}

/// Markers at the points C(u) of a plane curve, labelled once per panel.
void add_markers_at(Panel& panel, CurveView curve, const std::vector<double>& parameters, Color color,
                    const char* label) {
  std::vector<Vec2> points;
  for (const double u : parameters) {
    const Point p = point_at(curve, u);
    points.push_back(Vec2{{p[0], p[1]}});
  }
  if (!points.empty()) panel.markers.push_back({std::move(points), color, 7.0 * kPixelsPerPoint, label_once(panel, label)});
}

/// The inflections, the maxima of |curvature| and the cusps of a plane curve as markers.
Status add_curvature_features(Panel& panel, CurveView curve) {
  auto inflections = inflection_parameters(curve);
  if (!inflections) return inflections.error();
  auto extrema = curvature_extrema(curve);
  if (!extrema) return extrema.error();
  auto cusps = cusp_parameters(curve);
  if (!cusps) return cusps.error();
  std::vector<double> maxima;
  for (const CurvatureExtremum& e : *extrema)
    if (e.maximum) maxima.push_back(e.parameter);
  add_markers_at(panel, curve, *inflections, cycle_color(3), "inflections");
  add_markers_at(panel, curve, maxima, cycle_color(1), "curvature maxima");
  add_markers_at(panel, curve, *cusps, cycle_color(2), "cusps");
  return {};
}

/// The car's two interpolants that figures 36 and 38 compare: seed 000's C¹
/// Bézier curve (α = 1) and the C² natural cubic on chord-length parameters.
struct CarInterpolants {
  PiecewiseBezierCurve c1;
  BSplineCurve c2;
};

Expected<CarInterpolants> car_interpolants(const PointArray& car) {
  auto c1 = interpolate_c1_bezier(car, 1.0);
  if (!c1) return c1.error();
  auto chord = parameter_values(car, Parameterization::chord_length);
  if (!chord) return chord.error();
  auto c2 = interpolate_cubic(car, *chord, CubicEnds{EndCondition::natural, {}, {}});
  if (!c2) return c2.error();
  return CarInterpolants{std::move(*c1), std::move(*c2)};
}

Expected<GalleryFigure> car_curvature_combs_figure(const PointArray& car, const CarInterpolants& curves) {
  const PiecewiseBezierCurve& c1 = curves.c1;
  const BSplineCurve& c2 = curves.c2;
  const double size = std::max(size_of(c1), size_of(c2));
  Figure figure = figure_of("Curvature combs of the car's C¹ Bézier and C² cubic interpolants", 1500, 700, 2);
  const double jump1 = largest_curvature_jump(c1), jump2 = largest_curvature_jump(c2);
  // One scale for both combs, the C² curve's largest curvature a tooth of 8 % of the size.
  double reference = 0.0;
  for (int i = 0; i <= 2000; ++i)
    reference = std::max(reference, std::abs(signed_curvature_at(c2, c2.domain().lerp(i / 2000.0))));
  for (int k = 0; k < 2; ++k) {
    Panel panel;
    panel.equal_aspect = true;
    if (k == 0) {
      panel.title = fmt::format("C¹ Bézier (α = 1): curvature jumps up to {:.3g} at the joints", jump1);
      add_pieces(panel, c1, false, colors::black, "C¹ curve");
      add_curvature_comb(panel, c1, 0.08 * size, 24, cycle_color(0), reference);
      if (auto ok = add_curvature_features(panel, c1); !ok) return ok.error();
    } else {
      panel.title = fmt::format("C² natural cubic, chord length: largest jump {:.1g}", jump2);
      if (auto ok = add_bspline(panel, c2, BSplinePlotOptions{}, colors::black); !ok) return ok.error();
      add_curvature_comb(panel, c2, 0.08 * size, 24, cycle_color(0), reference);
      if (auto ok = add_curvature_features(panel, c2); !ok) return ok.error();
    }
    add_data_points(panel, car);
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{
      "36_car_curvature_combs",
      fmt::format("Curvature combs (teeth along the normal, outside each bend, one scale for both, teeth cut at twice "
                  "the C² curve's longest) of the car's two "
                  "interpolants, inflections (ops/inflections.hpp) and the maxima of |curvature| inside the pieces and at "
                  "joints where it is continuous (ops/curvature_extrema.hpp) marked. The C¹ Bézier curve of seed 000 matches "
                  "tangents at the data points but not curvatures: its comb breaks at every joint (largest jump "
                  "{:.3g}); the C² cubic's comb runs on unbroken (largest jump {:.1g}, rounding).",
                  jump1, jump2),
      std::move(figure)};
}

Expected<GalleryFigure> closest_point_field_figure(const PointArray& head) {
  auto curve = interpolate_c1_bezier(head, 2.0);
  if (!curve) return curve.error();
  const Box box = bounding_box(*curve);
  const double width = box.upper[0] - box.lower[0], height = box.upper[1] - box.lower[1];
  constexpr int kColumns = 24, kRows = 20;
  std::vector<double> queries;
  for (int i = 0; i < kRows; ++i)
    for (int j = 0; j < kColumns; ++j) {
      queries.push_back(box.lower[0] - 0.2 * width + 1.4 * width * j / (kColumns - 1));
      queries.push_back(box.lower[1] - 0.2 * height + 1.4 * height * i / (kRows - 1));
    }
  const std::size_t count = queries.size() / 2;
  std::vector<double> parameters(count), distances(count);
  if (auto ok = closest_points(*curve, queries, parameters, distances); !ok) return ok.error();
  Panel panel;
  panel.equal_aspect = true;
  panel.title = fmt::format("{} query points and their nearest points on the head's C¹ curve", count);
  SegmentItem feet{{}, solid(cycle_color(0), 0.8), false, "query to nearest point"};
  std::vector<Vec2> ends, points;
  int at_ends = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Point p = point_at(*curve, parameters[i]);
    const Vec2 q{{queries[2 * i], queries[2 * i + 1]}};
    feet.segments.push_back({q, Vec2{{p[0], p[1]}}});
    points.push_back(q);
    if (parameters[i] == curve->domain().lower || parameters[i] == curve->domain().upper) {
      ends.push_back(Vec2{{p[0], p[1]}});
      ++at_ends;
    }
  }
  panel.segments.push_back(std::move(feet));
  add_pieces(panel, *curve, false, colors::black, "C¹ curve, α = 2");
  panel.markers.push_back({std::move(points), colors::gray, 2.5 * kPixelsPerPoint, "queries"});
  if (!ends.empty()) panel.markers.push_back({std::move(ends), cycle_color(3), 6.0 * kPixelsPerPoint, "nearest at an end"});
  Figure figure = figure_of("Closest points on the head's C¹ curve", 900, 900, 1);
  figure.panels.push_back(std::move(panel));
  return GalleryFigure{
      "37_head_closest_point_field",
      fmt::format("The closest-point field of the head's C¹ Bézier curve: from each point of a {} × {} grid over its "
                  "box (grown by a fifth on every side), the segment to its nearest point (closest_points: branch and "
                  "bound on the Bernstein coefficients of the squared distance, ops/closest_point.hpp). Segments meet "
                  "the curve at right angles except at its two ends, where {} of the queries land; where two "
                  "branches are equally near (the medial axis) neighbouring segments part.",
                  kColumns, kRows, at_ends),
      std::move(figure)};
}

Expected<GalleryFigure> intersections_figure(const CarInterpolants& curves) {
  const PiecewiseBezierCurve& c1 = curves.c1;
  const BSplineCurve& c2 = curves.c2;
  // The second panel: a stretch of the C² curve (an overlap) and the tangent line at one of its points (a tangency).
  const Interval domain = c2.domain();
  auto stretch = segment(c2, domain.lerp(0.15), domain.lerp(0.35));
  if (!stretch) return stretch.error();
  const double at = domain.lerp(0.6);
  const Point p = point_at(c2, at), tangent = unit_tangent_at(c2, at);
  const double reach = 0.15 * size_of(c2);
  auto line = BezierCurve::make(
      PointArray::make(2, {p[0] - reach * tangent[0], p[1] - reach * tangent[1], p[0] + reach * tangent[0],
                           p[1] + reach * tangent[1]})
          .value());
  if (!line) return line.error();
  Figure figure = figure_of("Intersections of the car's interpolants, each with its kind", 1500, 700, 2);
  int counts[3] = {0, 0, 0};
  const auto mark = [&](Panel& panel, CurveView a, CurveView b) -> Status {
    auto found = intersections(a, b, default_intersection_tolerance(a, b));
    if (!found) return found.error();
    std::vector<Vec2> transversal, tangent_points;
    for (const CurveIntersection& x : *found) {
      ++counts[static_cast<int>(x.kind)];
      if (x.kind == IntersectionKind::overlap) {
        std::vector<Vec2> arc;
        for (int i = 0; i <= 64; ++i) {
          const Point q = point_at(a, x.a.lerp(i / 64.0));
          arc.push_back(Vec2{{q[0], q[1]}});
        }
        panel.polylines.push_back({std::move(arc), solid(cycle_color(2), 6.0), label_once(panel, "overlap")});
        continue;
      }
      (x.kind == IntersectionKind::transversal ? transversal : tangent_points).push_back(Vec2{{x.point[0], x.point[1]}});
    }
    if (!transversal.empty())
      panel.markers.push_back({std::move(transversal), cycle_color(0), 7.0 * kPixelsPerPoint, label_once(panel, "transversal")});
    if (!tangent_points.empty())
      panel.markers.push_back({std::move(tangent_points), cycle_color(3), 9.0 * kPixelsPerPoint,
                               label_once(panel, "tangent"), MarkerShape::diamond});
    return {};
  };
  Panel both;
  both.equal_aspect = true;
  both.title = "C¹ Bézier (gray) against C² cubic (black)";
  add_pieces(both, c1, false, colors::gray, "C¹ curve");
  if (auto ok = add_bspline(both, c2, BSplinePlotOptions{}, colors::black); !ok) return ok.error();
  if (auto ok = mark(both, c1, c2); !ok) return ok.error();
  const int first_panel_points = counts[0] + counts[1];
  Panel shared;
  shared.equal_aspect = true;
  shared.title = "C² cubic against a stretch of itself and a tangent line";
  if (auto ok = add_bspline(shared, c2, BSplinePlotOptions{}, colors::black); !ok) return ok.error();
  add_bezier(shared, *line, BezierPlotOptions{}, cycle_color(1), "tangent line");
  if (auto ok = mark(shared, c2, *stretch); !ok) return ok.error();
  if (auto ok = mark(shared, c2, *line); !ok) return ok.error();
  figure.panels.push_back(std::move(both));
  figure.panels.push_back(std::move(shared));
  return GalleryFigure{
      "38_car_intersections",
      fmt::format("intersections (ops/intersection.hpp: the lower-degree piece implicitized, the roots of the "
                  "substituted polynomial with their multiplicities) of the car's C¹ and C² interpolants ({} points, "
                  "at the data points and between them), and of the C² cubic with its own stretch u ∈ [15 %, 35 %] "
                  "of the domain (an overlap) and with its tangent line at 60 % (a tangency). In all: {} transversal, "
                  "{} tangent, {} overlap.",
                  first_panel_points, counts[0], counts[1], counts[2]),
      std::move(figure)};
}

// --- every method side by side ---------------------------------------------------------

/// Tangents for the Hermite panel: a cardinal spline of tension 1/2,
/// T_i = (P_{i+1} − P_{i−1}) / (t_{i+1} − t_{i−1}) / 2 (one-sided at the
/// ends), so the curve differs visibly from Catmull–Rom's.
PointArray cardinal_tangents(const PointArray& points, std::span<const double> t) {
  const std::size_t m = points.size() - 1;
  const auto d = static_cast<std::size_t>(points.dimension());
  std::vector<double> tangents;
  for (std::size_t i = 0; i <= m; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i == m ? m : i + 1;
    for (std::size_t k = 0; k < d; ++k) tangents.push_back(0.5 * (points[b][k] - points[a][k]) / (t[b] - t[a]));
  }
  return PointArray::from_trusted(points.dimension(), std::move(tangents));
}

/// Parameters at which the Lagrange panels sample the polynomial.
constexpr int kLagrangeSamples = 8000;

Expected<GalleryFigure> methods_figure(const PointArray& data, const std::string& set, const std::string& stem,
                                       bool wide) {
  const int columns = wide ? 3 : 4;
  Figure figure = figure_of(fmt::format("Every interpolation method on the {}", set), wide ? 1500 : 1600,
                            wide ? 1250 : 1250, columns);
  auto uniform = parameter_values(data, Parameterization::uniform);
  auto chord = parameter_values(data, Parameterization::chord_length);
  auto centripetal = parameter_values(data, Parameterization::centripetal);
  if (!uniform) return uniform.error();
  if (!chord) return chord.error();
  if (!centripetal) return centripetal.error();
  double worst = 0.0;  // the largest |C(t_i) − P_i| over the interpolants
  std::string notes;
  int colour = 0;
  auto panel_for = [&](const std::string& title) {
    Panel panel;
    panel.equal_aspect = true;
    panel.title = title;
    panel.legend = LegendPlace::none;
    frame_data(panel, data, 0.12);
    return panel;
  };
  auto finish = [&](Panel panel) {
    add_data_points(panel, data);
    figure.panels.push_back(std::move(panel));
    ++colour;
  };
  auto spline_panel = [&](const std::string& title, const Expected<BSplineCurve>& curve,
                          std::span<const double> parameters) -> Status {
    if (!curve) return with_context(curve.error(), title);
    Panel panel = panel_for(title);
    if (auto ok = add_bspline(panel, *curve, BSplinePlotOptions{}, cycle_color(colour)); !ok) return ok;
    worst = std::max(worst, data_error(*curve, data, parameters));
    finish(std::move(panel));
    return {};
  };

  {  // seed 000
    auto curve = interpolate_c1_bezier(data, 1.0);
    if (!curve) return curve.error();
    Panel panel = panel_for("c1-bezier, α = 1");
    add_pieces(panel, *curve, false, cycle_color(colour), "");
    std::vector<double> joints(data.size());
    for (std::size_t i = 0; i < joints.size(); ++i) joints[i] = static_cast<double>(i);
    worst = std::max(worst, data_error(*curve, data, joints));
    finish(std::move(panel));
  }
  if (auto ok = spline_panel("catmull-rom, uniform", interpolate_catmull_rom(data, *uniform), *uniform); !ok) return ok.error();
  if (auto ok = spline_panel("catmull-rom, centripetal", interpolate_catmull_rom(data, *centripetal), *centripetal); !ok)
    return ok.error();
  if (auto ok = spline_panel("cubic, natural, chord",
                             interpolate_cubic(data, *chord, CubicEnds{EndCondition::natural, {}, {}}), *chord);
      !ok)
    return ok.error();
  if (auto ok = spline_panel("cubic, not-a-knot, chord",
                             interpolate_cubic(data, *chord, CubicEnds{EndCondition::not_a_knot, {}, {}}), *chord);
      !ok)
    return ok.error();
  {
    const PointArray closed_points = without_closing_duplicate(data);
    auto closed = parameter_values(closed_points, Parameterization::chord_length, Closure::closed);
    if (!closed) return closed.error();
    auto curve = interpolate_cubic(closed_points, *closed, CubicEnds{EndCondition::periodic, {}, {}});
    if (!curve) return curve.error();
    Panel panel = panel_for("cubic, periodic (--closed), chord");
    if (auto ok = add_bspline(panel, *curve, BSplinePlotOptions{}, cycle_color(colour)); !ok) return ok.error();
    worst = std::max(worst, data_error(*curve, closed_points, *closed));
    finish(std::move(panel));
  }
  if (auto ok = spline_panel("bspline, degree 5, chord", interpolate_bspline(data, *chord, 5), *chord); !ok)
    return ok.error();
  if (auto ok = spline_panel("natural, q = 3 (quintic), chord", interpolate_natural(data, *chord, 3), *chord); !ok)
    return ok.error();
  if (auto ok = spline_panel("hermite, cardinal tangents, chord",
                             interpolate_hermite(data, cardinal_tangents(data, *chord), *chord), *chord);
      !ok)
    return ok.error();
  {  // one polynomial through every point: it oscillates between them
    auto polynomial = interpolate_lagrange(data, *chord);
    if (!polynomial) return polynomial.error();
    Panel panel = panel_for(fmt::format("lagrange, degree {}, chord", data.size() - 1));
    // Drawn from the barycentric form (stable) at many parameters, not from
    // its Bézier form: at degree 25 the Bézier control points are millions of
    // times the data's size and no flattening of them can be certified.
    std::vector<Vec2> samples;
    double reach = 0.0;  // how far the polynomial strays: max |p(t)| / scale
    for (int i = 0; i <= kLagrangeSamples; ++i) {
      const Point value = point_at(*polynomial, static_cast<double>(i) / kLagrangeSamples);
      samples.push_back(Vec2{{value[0], value[1]}});
      for (double c : value) reach = std::max(reach, std::abs(c));
    }
    panel.polylines.push_back({std::move(samples), solid(cycle_color(colour), 1.5), ""});
    worst = std::max(worst, data_error(*polynomial, data, *chord));
    notes += fmt::format("the degree-{} polynomial (drawn through {} points of its barycentric form) reaches {:.3g} "
                         "times the data's scale; ",
                         data.size() - 1, kLagrangeSamples + 1, reach / scale_of(data));
    finish(std::move(panel));
  }
  {  // approximation, not interpolation: half as many control points as points
    const std::size_t count = std::max<std::size_t>(4, data.size() / 2);
    auto fit = fit_least_squares(data, *chord, 3, count);
    if (!fit) return fit.error();
    Panel panel = panel_for(fmt::format("fit: least squares, {} control points, chord", count));
    BSplinePlotOptions options;
    options.control_polygon = true;
    if (auto ok = add_bspline(panel, fit->curve, options, cycle_color(colour)); !ok) return ok.error();
    notes += fmt::format("the least-squares cubic with {} control points (fit_least_squares, ends interpolated) is "
                         "within {:.3g} of every point ({:.3g} rms)",
                         count, fit->max_error, fit->rms_error);
    finish(std::move(panel));
  }
  return GalleryFigure{
      stem,
      fmt::format("The {} ({} points) through every method of `casteljau interpolate` (panel titles: method and "
                  "parameters), each view clipped to the data's box: all interpolants pass through the points (largest "
                  "|C(t_i) − P_i| {:.1e}); {}.",
                  set, data.size(), worst, notes),
      std::move(figure)};
}

// --- Runge's oscillation ---------------------------------------------------------------

double runge(double x) { return 1.0 / (1.0 + 25.0 * x * x); }

/// The points (x_j, f(x_j)) at nodes x_j.
PointArray runge_points(const std::vector<double>& nodes) {
  std::vector<double> coordinates;
  for (double x : nodes) coordinates.insert(coordinates.end(), {x, runge(x)});
  return PointArray::from_trusted(2, std::move(coordinates));
}

Expected<GalleryFigure> runge_figure() {
  Figure figure = figure_of("Runge's phenomenon: f(x) = 1/(1 + 25x²) on uniform against Chebyshev nodes", 1500, 1050, 2);
  constexpr int kSamples = 2001;
  std::string measured;
  Panel errors;
  errors.title = "|p(x) − f(x)| on [−1, 1]";
  errors.x.label = "x";
  errors.y.logarithmic = true;
  errors.y.range = std::array<double, 2>{1e-4, 1e2};
  errors.legend = LegendPlace::best;
  std::vector<Panel> panels;
  int colour = 0;
  for (const std::size_t n : {std::size_t{10}, std::size_t{20}}) {
    Panel panel;
    panel.title = fmt::format("n = {} (degree {}, {} nodes)", n, n, n + 1);
    panel.x.label = "x";
    panel.x.range = std::array<double, 2>{-1.05, 1.05};
    panel.y.range = std::array<double, 2>{-0.6, 1.6};
    panel.legend = LegendPlace::upper_right;
    std::vector<Vec2> graph;
    for (int i = 0; i < kSamples; ++i) {
      const double x = -1.0 + 2.0 * i / (kSamples - 1);
      graph.push_back(Vec2{{x, runge(x)}});
    }
    panel.polylines.push_back({graph, dashed(colors::black, 1.2), "f(x) = 1/(1 + 25x²)"});
    for (const bool chebyshev : {false, true}) {
      std::vector<double> nodes(n + 1);
      if (chebyshev) {
        auto values = chebyshev_parameters(n + 1, Interval{-1.0, 1.0});
        if (!values) return values.error();
        nodes = std::move(*values);
      } else {
        for (std::size_t j = 0; j <= n; ++j) nodes[j] = -1.0 + 2.0 * static_cast<double>(j) / static_cast<double>(n);
      }
      const PointArray points = runge_points(nodes);
      auto polynomial = interpolate_lagrange(points, nodes);
      if (!polynomial) return polynomial.error();
      auto curve = to_bezier(*polynomial);
      if (!curve) return curve.error();
      const Color color = cycle_color(chebyshev ? 1 : 0);
      const std::string name = chebyshev ? "Chebyshev nodes" : "uniform nodes";
      add_bezier(panel, *curve, BezierPlotOptions{}, color, fmt::format("p on {}", name));
      panel.markers.push_back({plane_points(points), color, 6.0 * kPixelsPerPoint, ""});
      // The error by the barycentric formula (the stable evaluation), at
      // evenly spaced x.
      double largest = 0.0, at = 0.0;
      std::vector<Vec2> error_line;
      for (int i = 0; i < kSamples; ++i) {
        const double x = -1.0 + 2.0 * i / (kSamples - 1);
        const double e = std::abs(point_at(*polynomial, x)[1] - runge(x));
        if (e > largest) largest = e, at = x;
        error_line.push_back(Vec2{{x, e}});
      }
      errors.polylines.push_back({error_line, chebyshev ? solid(cycle_color(2 + colour), 1.2) : dashed(cycle_color(2 + colour), 1.2),
                                  fmt::format("n = {}, {}", n, name)});
      measured += fmt::format("{}n = {}, {}: {:.3g} (at x = {:.3f})", measured.empty() ? "" : "; ", n, name, largest, at);
    }
    ++colour;
    panels.push_back(std::move(panel));
  }
  for (auto& panel : panels) figure.panels.push_back(std::move(panel));
  figure.panels.push_back(std::move(errors));
  return GalleryFigure{
      "25_runge",
      fmt::format("Seed 001, problem P1: the polynomial of degree n through n+1 points of f(x) = 1/(1 + 25x²) "
                  "(barycentric form, Berrut & Trefethen 2004), drawn as its Bézier form. On uniform nodes it "
                  "oscillates near the ends and the oscillation grows with n; on Chebyshev points x_j = −cos(jπ/n) it "
                  "converges. The views are clipped to [−0.6, 1.6]. Largest |p(x) − f(x)| over {} evenly spaced x: {}.",
                  kSamples, measured),
      std::move(figure)};
}

// --- natural splines of order q --------------------------------------------------------

/// ∫ |s^(q)(x)|² dx of the second coordinate over the domain by Gauss–Legendre
/// with 8 nodes per knot span (exact for the polynomial pieces up to degree 15).
double energy(const BSplineCurve& curve, int order) {
  static constexpr std::array<double, 8> nodes{-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                               -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                               0.7966664774136267,  0.9602898564975363};
  static constexpr std::array<double, 8> weights{0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                                 0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                                 0.2223810344533745, 0.1012285362903763};
  const auto knots = curve.knots();
  const auto p = static_cast<std::size_t>(curve.degree());
  const std::size_t n = curve.control_points().size();
  double sum = 0.0;
  for (std::size_t j = p; j < n; ++j) {
    const double a = knots[j], b = knots[j + 1];
    if (!(b > a)) continue;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * nodes[k];
      const double value = derivative_at(curve, x, order)[1];
      sum += 0.5 * (b - a) * weights[k] * value * value;
    }
  }
  return sum;
}

Expected<GalleryFigure> natural_figure() {
  const PointArray data = PointArray::from_trusted(2, {0, 0, 1, 0.2, 2, 1.4, 3, 3.2, 3.5, 2.6, 4.5, 0.4, 5.5, 0.1, 6.5, 1.1,
                                                       8, 1.3});
  auto x = function_parameters(data);
  if (!x) return x.error();
  Panel panel;
  panel.title = "natural splines s(x) through the same points";
  panel.x.label = "x";
  panel.y.label = "s(x)";
  panel.legend = LegendPlace::upper_right;
  std::string measured;
  for (int q = 1; q <= 3; ++q) {
    auto curve = interpolate_natural(data, *x, q);
    if (!curve) return curve.error();
    const std::string label = q == 1 ? "q = 1: polyline (degree 1)"
                                     : fmt::format("q = {}: degree {}, C{}", q, 2 * q - 1, q == 2 ? "²" : "⁴");
    if (auto ok = add_bspline(panel, *curve, BSplinePlotOptions{}, cycle_color(q - 1), label); !ok) return ok.error();
    measured += fmt::format("{}q = {}: ∫ s^({})² = {:.4g}", measured.empty() ? "" : "; ", q, q, energy(*curve, q));
  }
  // The minimizing property against another C² cubic through the same points.
  auto not_a_knot = interpolate_cubic(data, *x, CubicEnds{EndCondition::not_a_knot, {}, {}});
  if (!not_a_knot) return not_a_knot.error();
  if (auto ok = add_bspline(panel, *not_a_knot, BSplinePlotOptions{}, colors::gray, "not-a-knot cubic (for comparison)"); !ok)
    return ok.error();
  panel.curves.back().stroke = dotted(colors::gray, 1.5);
  add_data_points(panel, data);
  Figure figure = figure_of("Natural splines of order q = 1, 2, 3 (seed 001, problem P2)", 1100, 650, 1);
  figure.panels.push_back(std::move(panel));
  return GalleryFigure{
      "26_natural_splines",
      fmt::format("Seed 001, problem P2: the natural spline of order q is the interpolant minimizing ∫ s^(q)(x)² dx, "
                  "of degree 2q − 1 and C^(2q−2), with s^(j) = 0 at both ends for j = q..2q−2 (computed in the "
                  "B-spline basis, not the seed's ill-conditioned truncated powers). Higher q gives a smoother, "
                  "rounder curve that swings further between the points. Measured (Gauss–Legendre): {}; the "
                  "not-a-knot cubic through the same points has ∫ s''² = {:.4g}, more than the natural cubic's, as "
                  "the minimizing property says.",
                  measured, energy(*not_a_knot, 2)),
      std::move(figure)};
}

// --- smoothing with increasing λ -------------------------------------------------------

/// SplitMix64 (Steele, Lea & Flood 2014): a fixed, portable sequence, so the
/// figure's noisy data is the same on every machine.
std::uint64_t splitmix(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

Expected<GalleryFigure> smoothing_figure() {
  constexpr int kPoints = 41;
  std::uint64_t state = 2026;
  std::vector<double> coordinates;
  for (int i = 0; i < kPoints; ++i) {
    const double x = 6.0 * i / (kPoints - 1);
    // Noise uniform in [−0.3, 0.3] on sin x.
    const double noise = 0.6 * (static_cast<double>(splitmix(state) >> 11) * 0x1.0p-53 - 0.5);
    coordinates.insert(coordinates.end(), {x, std::sin(x) + noise});
  }
  const PointArray data = PointArray::from_trusted(2, std::move(coordinates));
  // The fit is of y alone (a 1D B-spline, drawn as its graph) over the
  // normalized parameter u = x / 6 in [0, 1], the CLI's default; the knots
  // are then scaled by 6 to draw the graph over x (the same curve).
  std::vector<double> u, ys;
  for (std::size_t i = 0; i < data.size(); ++i) u.push_back(static_cast<double>(i) / (kPoints - 1)), ys.push_back(data[i][1]);
  const PointArray y = PointArray::from_trusted(1, std::move(ys));
  const auto over_x = [](const BSplineCurve& curve) {
    std::vector<double> knots(curve.knots().begin(), curve.knots().end());
    for (double& k : knots) k *= 6.0;
    return BSplineCurve::from_trusted(curve.degree(), std::move(knots), curve.control_points());
  };
  Panel panel;
  panel.title = "cubic smoothing splines: min Σ (s(u_i) − y_i)² + λ ∫ s''(u)² du, u = x/6";
  panel.x.label = "x";
  panel.legend = LegendPlace::lower_left;
  std::string measured;
  int colour = 0;
  for (const double lambda : {1e-8, 1e-6, 1e-4, 1e-2}) {
    SmoothingOptions options;
    options.smoothing = lambda;
    auto fit = fit_smoothing(y, u, options);
    if (!fit) return fit.error();
    if (auto ok = add_bspline(panel, over_x(fit->curve), BSplinePlotOptions{}, cycle_color(colour++),
                              fmt::format("λ = {:g}", lambda));
        !ok)
      return ok.error();
    measured += fmt::format("{}λ = {:g}: {:.1f} degrees of freedom, rms residual {:.3f}", measured.empty() ? "" : "; ",
                            lambda, fit->effective_degrees_of_freedom, fit->rms_error);
  }
  auto gcv = fit_smoothing(y, u, SmoothingOptions{});
  if (!gcv) return gcv.error();
  if (auto ok = add_bspline(panel, over_x(gcv->curve), BSplinePlotOptions{}, colors::black,
                            fmt::format("λ = {:.3g} by GCV", gcv->smoothing));
      !ok)
    return ok.error();
  panel.curves.back().stroke = dashed(colors::black, 2.0);
  add_data_points(panel, data, "sin x + noise");
  Figure figure = figure_of("Smoothing with increasing λ", 1100, 650, 1);
  figure.panels.push_back(std::move(panel));
  return GalleryFigure{
      "27_smoothing",
      fmt::format("{} samples of sin x with uniform noise in [−0.3, 0.3] (a fixed SplitMix64 sequence), fitted by "
                  "cubic smoothing splines with a knot at every x_i (fit_smoothing): small λ follows the noise, large "
                  "λ tends to the least-squares straight line. {}; generalized cross-validation (Craven & Wahba 1979) "
                  "chooses λ = {:.3g} ({:.1f} degrees of freedom, rms residual {:.3f}; the noise's standard deviation is "
                  "0.3/√3 ≈ 0.173).",
                  kPoints, measured, gcv->smoothing, gcv->effective_degrees_of_freedom, gcv->rms_error),
      std::move(figure)};
}

}  // namespace

Expected<std::vector<GalleryFigure>> interpolation_gallery_figures(const std::filesystem::path& examples_dir) {
  auto head = read_plane_points(examples_dir, "head.csv");
  if (!head) return head.error();
  auto car = read_plane_points(examples_dir, "car.csv");
  if (!car) return car.error();
  std::vector<GalleryFigure> figures;
  Expected<GalleryFigure> built[] = {interpolants_figure(*head, "head", "23_head_interpolants", false),
                                     interpolants_figure(*car, "car", "24_car_interpolants", true),
                                     runge_figure(),
                                     natural_figure(),
                                     smoothing_figure(),
                                     methods_figure(*head, "head", "28_head_methods", false),
                                     methods_figure(*car, "car", "29_car_methods", true)};
  for (auto& figure : built) {
    if (auto ok = detail::append_figure(figures, std::move(figure)); !ok) return ok.error();
  }
  return figures;
}

namespace detail {

Expected<std::vector<GalleryFigure>> query_gallery_figures(const std::filesystem::path& examples_dir) {
  auto head = read_plane_points(examples_dir, "head.csv");
  if (!head) return head.error();
  std::vector<GalleryFigure> figures;
  auto car = read_plane_points(examples_dir, "car.csv");
  if (!car) return car.error();
  if (auto ok = append_figure(figures, arc_length_samples_figure(*head)); !ok) return ok.error();
  auto curves = car_interpolants(*car);
  if (!curves) return curves.error();
  if (auto ok = append_figure(figures, car_curvature_combs_figure(*car, *curves)); !ok) return ok.error();
  if (auto ok = append_figure(figures, closest_point_field_figure(*head)); !ok) return ok.error();
  if (auto ok = append_figure(figures, intersections_figure(*curves)); !ok) return ok.error();
  return figures;
}

}  // namespace detail

}  // namespace casteljau::render

// The gallery's B-spline and NURBS figures (issue 4): the basis for clamped
// and uniform knots (seed 001 figures 7 and 8), local control, knot
// multiplicity against continuity, the NURBS circle and the pull of one
// weight. Every curve goes through to_bezier_pieces and the certified
// flattening (bspline_plots.hpp), like the Bézier figures.
#include "casteljau/render/gallery.hpp"
#include "casteljau/core/tolerance.hpp"
#include "figure_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/continuity.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/render/bspline_plots.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/curves/differential_geometry.hpp"


namespace casteljau::render {
namespace {

using detail::figure_of;

/// Number of basis functions in each panel of the basis figures.
constexpr int kBasisCount = 6;

Expected<GalleryFigure> basis_figure(bool clamped) {
  Figure figure = figure_of(clamped ? "B-spline basis, clamped knots, degrees 0 to 3"
                                    : "B-spline basis, uniform knots, degrees 0 to 3",
                            1100, 760, 2);
  for (int p = 0; p <= 3; ++p) {
    const std::size_t count = kBasisCount;
    // Integer knots: clamped on [0, n+1-p] (interior knots 1, 2, ...), uniform t_i = i.
    const std::vector<double> knots =
        clamped ? clamped_uniform_knots(p, count, Interval{0.0, static_cast<double>(kBasisCount - p)})
                : uniform_knots(p, count, Interval{static_cast<double>(p), static_cast<double>(kBasisCount)});
    auto panel = bspline_basis_panel(knots, p);
    if (!panel) return panel.error();
    panel->title = fmt::format("p = {} (order k = {}): knots {}", p, p + 1, knots_text(knots));
    if (p < 2) panel->x.label.clear();
    figure.panels.push_back(std::move(*panel));
  }
  if (clamped)
    return GalleryFigure{
        "17_bspline_basis_clamped",
        "Seed 001's basis N_(i,p) by the Cox–de Boor recursion for 6 control points and clamped knots (p+1 equal "
        "knots at each end, dots on the axis, ×m for a knot repeated m times): each N_i is a piecewise polynomial of "
        "degree p on [t_i, t_(i+p+1)], the end functions reach 1 at the ends (the curve interpolates P_0 and P_n), and "
        "the dashed sum is 1 on the whole domain. Degree 0 is the half-open step 1 on [t_i, t_(i+1)).",
        std::move(figure)};
  return GalleryFigure{
      "18_bspline_basis_uniform",
      "The same for uniform knots t_i = i: every N_(i,p) is a shifted copy of one bell (the cardinal B-spline, C^(p-1) "
      "at its knots); the dashed sum is 1 only on the domain [t_p, t_(n+1)] and falls off in the shaded parts, so "
      "the curve does not reach its end control points.",
      std::move(figure)};
}

/// A wavy control polygon along x: the curves of the local-control and
/// continuity figures.
PointArray polygon_of(const std::vector<double>& heights) {
  std::vector<double> coordinates;
  for (std::size_t i = 0; i < heights.size(); ++i) {
    coordinates.push_back(static_cast<double>(i));
    coordinates.push_back(heights[i]);
  }
  return PointArray::from_trusted(2, std::move(coordinates));
}

Expected<GalleryFigure> local_control_figure() {
  constexpr int p = 3;
  constexpr std::size_t moved = 5;
  const PointArray before_points = polygon_of({0.0, 1.6, 2.6, 1.2, 0.4, 2.2, 3.0, 1.4, 0.2, 1.2, 2.2});
  PointArray after_points = before_points;
  after_points[moved][1] -= 2.6;
  const std::vector<double> knots = clamped_uniform_knots(p, before_points.size(), Interval{0.0, 8.0});
  const BSplineCurve before = BSplineCurve::from_trusted(p, knots, before_points);
  const BSplineCurve after = BSplineCurve::from_trusted(p, knots, after_points);
  // P_i only enters N_{i,p}, whose support is [t_i, t_{i+p+1}]: p+1 spans.
  const double from = knots[moved], to = knots[moved + p + 1];
  Figure figure = figure_of(fmt::format("Local control: moving P{} changes the p+1 = {} spans of [{:g}, {:g}] only",
                                        moved, p + 1, from, to),
                            1000, 1150, 1);
  const Stroke unchanged = solid(colors::black, 2.0);
  std::size_t changed_count = 0;
  double largest_change = 0.0;
  for (int side = 0; side < 2; ++side) {
    const BSplineCurve& curve = side == 0 ? before : after;
    auto pieces = plane_pieces(curve);
    if (!pieces) return pieces.error();
    std::size_t first = pieces->pieces.size(), last = 0;  // the changed pieces [first, last)
    for (std::size_t k = 0; k < pieces->pieces.size(); ++k)
      if (pieces->breakpoints[k] >= from && pieces->breakpoints[k + 1] <= to) first = std::min(first, k), last = k + 1;
    changed_count = last - first;
    Panel panel;
    panel.equal_aspect = true;
    panel.title = side == 0 ? "before" : fmt::format("after moving P{} down", moved);
    panel.x.range = std::array<double, 2>{-0.5, 10.5};
    panel.y.range = std::array<double, 2>{-3.0, 3.5};
    if (side == 1) {
      panel.polylines.push_back({plane_points(before_points), dotted(colors::gray, 1.0), "control polygon before"});
      auto old = plane_pieces(before);
      for (auto& item : curve_items(*old, first, last, dotted(colors::gray, 1.5), "the changed spans before"))
        panel.curves.push_back(std::move(item));
    }
    panel.polylines.push_back({plane_points(curve.control_points()), dashed(colors::gray, 1.0), "control polygon"});
    for (auto& item : curve_items(*pieces, 0, first, unchanged, "unchanged spans")) panel.curves.push_back(std::move(item));
    for (auto& item : curve_items(*pieces, last, pieces->pieces.size(), unchanged)) panel.curves.push_back(std::move(item));
    for (auto& item : curve_items(*pieces, first, last, solid(cycle_color(1), 3.0),
                                  fmt::format("the {} spans of [t{}, t{}] = [{:g}, {:g}]", last - first, moved,
                                              moved + p + 1, from, to)))
      panel.curves.push_back(std::move(item));
    std::vector<Vec2> knot_points;
    for (const auto& piece : pieces->pieces) knot_points.push_back(plane_points(piece.control_points()).front());
    knot_points.push_back(plane_points(pieces->pieces.back().control_points()).back());
    panel.markers.push_back({knot_points, colors::black, 5.0 * kPixelsPerPoint, "C(t_j), the span ends"});
    panel.markers.push_back({plane_points(curve.control_points()), colors::red, 6.0 * kPixelsPerPoint, "control points"});
    const Vec2 p5 = plane_points(curve.control_points())[moved];
    panel.markers.push_back({{p5}, cycle_color(1), 9.0 * kPixelsPerPoint, ""});
    panel.texts.push_back({p5, fmt::format("P{}", moved), colors::black, 10.0 * kPixelsPerPoint, Anchor::start,
                           Vec2{{8.0, -4.0}}});
    if (side == 1) {
      panel.segments.push_back({{{plane_points(before_points)[moved], p5}}, solid(cycle_color(1), 1.2), true, ""});
      for (int i = 0; i <= 400; ++i) {
        const double u = 8.0 * i / 400.0;
        largest_change = std::max(largest_change, distance(point_at(before, u), point_at(after, u)));
      }
    }
    panel.legend = LegendPlace::lower_right;
    figure.panels.push_back(std::move(panel));
  }
  return GalleryFigure{
      "19_bspline_local_control",
      fmt::format("A cubic B-spline (11 control points, clamped knots {}): moving P{} by 2.6 changes only the {} spans "
                  "of [{:g}, {:g}], the support of N_({},3) (largest displacement of the curve {:.3f}, at most the "
                  "control point's); the black parts are the same Bézier pieces in both panels.",
                  knots_text(knots), moved, changed_count, from, to, moved, largest_change),
      std::move(figure)};
}

std::string continuity_name(int order) {
  static const char* const superscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  if (order < 0) return "C⁻¹";
  if (order > 9) return fmt::format("C^{}", order);
  return std::string("C") + superscripts[order];
}

Expected<GalleryFigure> continuity_figure() {
  constexpr int p = 3;
  const std::vector<double> knots{0, 0, 0, 0, 1, 2, 2, 3, 3, 3, 4, 4, 4, 4};
  const PointArray points = polygon_of({0.0, 2.0, 2.6, 0.6, 0.0, 1.6, 3.2, 1.0, 0.4, 2.2});
  auto made = BSplineCurve::make(p, knots, points);
  if (!made) return made.error();
  const BSplineCurve& curve = *made;
  auto pieces = plane_pieces(curve);
  if (!pieces) return pieces.error();
  const auto continuity = continuity_at_knots(curve);

  Figure figure = figure_of("Knot multiplicity and continuity: a cubic with interior knots of multiplicity 1, 2, 3",
                            1000, 1100, 1);
  Panel shape;
  shape.equal_aspect = true;
  shape.title = fmt::format("p = 3, knots {}", knots_text(knots));
  shape.y.range = std::array<double, 2>{-0.6, 3.9};
  BSplinePlotOptions options;
  options.control_polygon = options.control_points = true;
  if (auto ok = add_bspline(shape, curve, options, colors::black, "cubic B-spline"); !ok) return ok.error();

  // Curvature along u, piece by piece: continuous at a C² knot, jumping at a
  // C¹ knot; at the C⁰ corner the tangent itself turns.
  Panel bend;
  bend.title = "signed curvature κ(u), sampled on each Bézier piece";
  bend.x.label = "u";
  bend.y.label = "κ(u)";
  std::string measured, orders;
  double lowest = 0.0, highest = 0.0;
  for (std::size_t k = 0; k < pieces->pieces.size(); ++k) {
    const double a = pieces->breakpoints[k], b = pieces->breakpoints[k + 1];
    std::vector<Vec2> samples;
    for (int i = 0; i <= 200; ++i) {
      const double t = i / 200.0;
      samples.push_back(Vec2{{a + t * (b - a), signed_curvature_at(pieces->pieces[k], t)}});
      lowest = std::min(lowest, samples.back()[1]), highest = std::max(highest, samples.back()[1]);
    }
    bend.polylines.push_back({samples, solid(colors::black, 1.5), ""});
  }
  const double margin = 0.08 * (highest - lowest);
  bend.y.range = std::array<double, 2>{lowest - margin, highest + margin};
  for (std::size_t j = 0; j < continuity.size(); ++j) {
    const auto& knot = continuity[j];
    const std::size_t k = j;  // interior knot j ends piece j and starts piece j+1
    const auto& left = pieces->pieces[k];
    const auto& right = pieces->pieces[k + 1];
    const Vec2 at = plane_points(right.control_points()).front();
    const Color color = cycle_color(knot.predicted >= 2 ? 2 : (knot.predicted == 1 ? 0 : 3));
    const std::string name = continuity_name(knot.predicted);
    std::string text = fmt::format("u = {:g}, m = {}: {}", knot.value, knot.multiplicity, name);
    if (knot.measured.parametric != knot.predicted)
      text += fmt::format(" (measured {})", continuity_name(knot.measured.parametric));
    shape.markers.push_back({{at}, color, 9.0 * kPixelsPerPoint, ""});
    // Beside the point, away from the curve (which rises after u = 2).
    const bool left_side = j == 1;
    shape.texts.push_back({at, text, color, 10.0 * kPixelsPerPoint, left_side ? Anchor::end : Anchor::start,
                           Vec2{{left_side ? -10.0 : 10.0, j == 0 ? 8.0 : -16.0}}});
    orders += fmt::format("{}{}", orders.empty() ? "" : ", ", continuity_name(knot.measured.parametric));
    // The jumps, measured on the Bézier pieces at both sides of the knot.
    const Point t0 = unit_tangent_at(left, 1.0), t1 = unit_tangent_at(right, 0.0);
    const double turn = std::atan2(t0[0] * t1[1] - t0[1] * t1[0], t0[0] * t1[0] + t0[1] * t1[1]) * 180.0 / std::numbers::pi;
    const double k0 = signed_curvature_at(left, 1.0), k1 = signed_curvature_at(right, 0.0);
    measured += fmt::format("{}u = {:g}: the tangent turns by {:.1f}°, |Δκ| = {:.3f}", measured.empty() ? "" : "; ",
                            knot.value, std::abs(turn), std::abs(k1 - k0));
    bend.polylines.push_back({{Vec2{{knot.value, lowest - margin}}, Vec2{{knot.value, highest + margin}}}, dotted(color, 1.2), ""});
    bend.texts.push_back({Vec2{{knot.value, 0.0}}, fmt::format("u = {:g}: {}", knot.value, name), color,
                          9.0 * kPixelsPerPoint, Anchor::start, Vec2{{4.0, 6.0}}});
  }
  bend.legend = LegendPlace::none;
  shape.legend = LegendPlace::upper_left;
  figure.panels.push_back(std::move(shape));
  figure.panels.push_back(std::move(bend));
  return GalleryFigure{
      "20_bspline_continuity",
      fmt::format("Seed 001: a knot of multiplicity m lowers the continuity of a degree-p B-spline to C^(p-m): here "
                  "p = 3 with interior knots of multiplicity 1, 2, 3 gives C², C¹ and C⁰ (a corner at the control "
                  "point the curve passes through); continuity_at_knots measures {}. On the Bézier pieces at "
                  "each side: {}.",
                  orders, measured),
      std::move(figure)};
}

std::string weight_text(double w) {
  return std::abs(w - std::numbers::sqrt2 / 2.0) < 1e-15 ? std::string("√½") : fmt::format("{:g}", w);
}

Expected<GalleryFigure> circle_figure() {
  auto circle = make_circle(0.0, 0.0, 1.0);
  if (!circle) return circle.error();
  const RadialError error = radial_error(*circle, 1.0, 100001);
  Panel panel;
  panel.equal_aspect = true;
  panel.x.range = std::array<double, 2>{-1.6, 1.6};
  panel.y.range = std::array<double, 2>{-1.25, 1.25};
  BSplinePlotOptions options;
  options.control_polygon = options.control_points = true;
  if (auto ok = add_bspline(panel, *circle, options, colors::black, "NURBS circle, degree 2"); !ok) return ok.error();
  const auto points = plane_points(circle->control_points());
  const auto weights = circle->weights();
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {  // the last point repeats the first
    const Vec2 outward = points[i] * (1.0 / std::max(norm(points[i]), tolerances::kScaleFloor));
    panel.texts.push_back({points[i], fmt::format("P{} w = {}", i, weight_text(weights[i])), colors::black,
                           9.0 * kPixelsPerPoint, outward[0] < -0.5 ? Anchor::end : (outward[0] > 0.5 ? Anchor::start : Anchor::middle),
                           Vec2{{9.0 * outward[0], 9.0 * outward[1] - (outward[1] < -0.5 ? 9.0 : 0.0)}}});
  }
  panel.legend = LegendPlace::none;
  Figure figure = figure_of("The NURBS circle: 9 control points, weights 1 and √½", 800, 820, 1);
  figure.panels.push_back(std::move(panel));
  return GalleryFigure{
      "21_nurbs_circle",
      fmt::format("The exact unit circle as a rational quadratic B-spline (make_circle, The NURBS Book §7.5): four "
                  "quarter arcs on the square's corners and edge midpoints, weights 1 at the midpoints and √½ = "
                  "cos 45° at the corners, knots {} (the double knots land on the edge midpoints). Measured "
                  "largest | |C(u)| - 1 | over {} parameters: {:.1e} (a polynomial curve cannot do this).",
                  knots_text(circle->knots()), error.parameters.size(), error.maximum),
      std::move(figure)};
}

Expected<GalleryFigure> weight_figure() {
  auto circle = make_circle(0.0, 0.0, 1.0);
  if (!circle) return circle.error();
  constexpr std::size_t pulled = 1;
  Panel panel;
  panel.equal_aspect = true;
  panel.polylines.push_back({plane_points(circle->control_points()), dashed(colors::gray, 1.0), "control polygon"});
  BSplinePlotOptions plain;
  if (auto ok = add_bspline(panel, *circle, plain, colors::black, "circle, w1 = √½"); !ok) return ok.error();
  panel.curves.back().stroke = solid(colors::black, 3.0);
  const std::vector<double> values{0.25, 0.5, 1.0, 2.0, 4.0};
  std::string reached;
  for (std::size_t k = 0; k < values.size(); ++k) {
    std::vector<double> weights(circle->weights().begin(), circle->weights().end());
    weights[pulled] = values[k];
    const BSplineCurve curve = BSplineCurve::from_trusted(2, std::vector<double>(circle->knots().begin(), circle->knots().end()),
                                                          circle->control_points(), weights);
    const Color color = cycle_color(static_cast<int>(k));
    // Only the first quarter is drawn: the rest is the circle's (local support).
    auto pieces = plane_pieces(curve);
    if (!pieces) return pieces.error();
    for (auto& item : curve_items(*pieces, 0, 1, solid(color, 1.5), fmt::format("w{} = {:g}", pulled, values[k])))
      panel.curves.push_back(std::move(item));
    // The middle of the first quarter arc: on the segment from the chord's
    // midpoint toward P1, closer to P1 as w1 grows.
    const Point mid = point_at(curve, 0.125);
    reached += fmt::format("{}{:g}: {:.3f}", reached.empty() ? "" : ", ", values[k],
                           distance(mid, circle->control_points()[pulled]));
  }
  panel.markers.push_back({plane_points(circle->control_points()), colors::red, 6.0 * kPixelsPerPoint, "control points"});
  panel.texts.push_back({plane_points(circle->control_points())[pulled], fmt::format("P{}", pulled), colors::black,
                         10.0 * kPixelsPerPoint, Anchor::start, Vec2{{8.0, 6.0}}});
  panel.x.range = std::array<double, 2>{-1.2, 1.3};
  panel.y.range = std::array<double, 2>{-1.2, 1.3};
  panel.legend = LegendPlace::lower_left;
  Figure figure = figure_of(fmt::format("One weight pulls the curve toward its control point (w{})", pulled), 800, 820, 1);
  figure.panels.push_back(std::move(panel));
  return GalleryFigure{
      "22_nurbs_weight",
      fmt::format("Seed 001: raising the weight w{0} pulls the curve toward P{0} = (1, 1), lowering it pushes the "
                  "curve away (w{0} = √½ is the circle, in black); only the first quarter, the support of N_({0},2), "
                  "moves, and only it is drawn in colour. "
                  "Distance from C(1/8) to P{0} for w{0} = {1}.",
                  pulled, reached),
      std::move(figure)};
}

}  // namespace

Expected<std::vector<GalleryFigure>> bspline_gallery_figures() {
  std::vector<GalleryFigure> figures;
  Expected<GalleryFigure> built[] = {basis_figure(true), basis_figure(false), local_control_figure(),
                                     continuity_figure(), circle_figure(), weight_figure()};
  for (auto& figure : built) {
    if (auto ok = detail::append_figure(figures, std::move(figure)); !ok) return ok.error();
  }
  return figures;
}

}  // namespace casteljau::render

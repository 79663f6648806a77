#include "casteljau/render/bspline_plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/render/layout.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/tolerance.hpp"

namespace casteljau::render {
namespace {

/// The Greville abscissa xi_i = (t_{i+1} + ... + t_{i+p}) / p (p >= 1).
double greville_abscissa(std::span<const double> knots, int degree, std::size_t index) {
  double sum = 0.0;
  for (int j = 1; j <= degree; ++j) sum += knots[index + static_cast<std::size_t>(j)];
  return sum / degree;
}

std::vector<double> copy(std::span<const double> values) { return {values.begin(), values.end()}; }

/// A degree-0 1D B-spline (a step function) as one horizontal segment per
/// non-empty span, every interior knot a jump.
PlanePieces step_pieces(const BSplineCurve& curve) {
  PlanePieces result;
  const auto knots = curve.knots();
  const auto& points = curve.control_points();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double a = knots[i], b = knots[i + 1];
    if (!(a < b)) continue;  // an empty span carries no piece
    const double y = points[i][0];
    if (result.breakpoints.empty()) result.breakpoints.push_back(a);
    result.breakpoints.push_back(b);
    result.pieces.push_back(BezierCurve::from_trusted(PointArray::from_trusted(2, {a, y, b, y})));
  }
  if (!result.pieces.empty()) result.jumps.assign(result.pieces.size() - 1, true);
  return result;
}

PointArray project_on_plane(const PointArray& points) {
  std::vector<double> coordinates;
  coordinates.reserve(2 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    coordinates.push_back(points[i][0]);
    coordinates.push_back(points[i][1]);
  }
  return PointArray::from_trusted(2, std::move(coordinates));
}

}  // namespace

Expected<BSplineCurve> plane_bspline(const BSplineCurve& curve) {
  const int d = curve.dimension();
  if (d == 2) return curve;
  const int p = curve.degree();
  const auto knots = curve.knots();
  const auto& points = curve.control_points();
  if (d >= 3)
    return BSplineCurve::from_trusted(p, copy(knots), project_on_plane(points), copy(curve.weights()));
  if (curve.is_rational())
    return Error{"cannot plot a rational B-spline of dimension 1 (its graph is not a B-spline with points (ξ_i, x_i))"};
  if (p == 0) return Error{"a B-spline of dimension 1 and degree 0 is a step function: draw it with plane_pieces"};
  std::vector<double> coordinates;
  coordinates.reserve(2 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    coordinates.push_back(greville_abscissa(knots, p, i));
    coordinates.push_back(points[i][0]);
  }
  return BSplineCurve::from_trusted(p, copy(knots), PointArray::from_trusted(2, std::move(coordinates)));
}

Expected<PlanePieces> plane_pieces(const BSplineCurve& curve) {
  if (curve.dimension() == 1 && curve.degree() == 0) {
    if (curve.is_rational()) return Error{"cannot plot a rational B-spline of dimension 1"};
    return step_pieces(curve);
  }
  if (curve.degree() == 0)
    return Error{"a B-spline of degree 0 in the plane or in space is a set of points (its control points), not a curve"};
  auto plane = plane_bspline(curve);
  if (!plane) return plane.error();
  BezierPieces pieces = to_bezier_pieces(*plane);
  PlanePieces result;
  result.breakpoints = std::move(pieces.breakpoints);
  result.pieces = std::move(pieces.pieces);
  const int p = curve.degree();
  for (std::size_t i = 1; i + 1 < result.breakpoints.size(); ++i)
    result.jumps.push_back(multiplicity_of(curve.knots(), result.breakpoints[i]) >= p + 1);
  return result;
}

std::vector<CurveItem> curve_items(const PlanePieces& pieces, std::size_t first, std::size_t last, const Stroke& stroke,
                                   const std::string& label) {
  std::vector<CurveItem> items;
  last = std::min(last, pieces.pieces.size());
  for (std::size_t i = first; i < last; ++i) {
    if (i == first || pieces.jumps[i - 1]) items.push_back({{}, stroke, items.empty() ? label : ""});
    items.back().pieces.push_back(pieces.pieces[i]);
  }
  return items;
}

Status add_bspline(Panel& panel, const BSplineCurve& curve, const BSplinePlotOptions& options, Color color,
                   const std::string& label) {
  const Interval domain = curve.domain();
  if (options.construction && !domain.contains(*options.construction))
    return Error{fmt::format("the de Boor construction parameter {} is outside the domain [{}, {}]",
                             *options.construction, domain.lower, domain.upper), ErrorKind::out_of_domain};
  const bool graph = curve.dimension() == 1;
  if (!graph && curve.degree() == 0) {
    // A plane B-spline of degree 0 takes the value P_i on the whole span i: a set of points.
    panel.markers.push_back({plane_points(curve.control_points()), color, 6.0 * kPixelsPerPoint, label});
    return Status{};
  }
  auto pieces = plane_pieces(curve);
  if (!pieces) return pieces.error();
  // The control polygon of what is drawn: the graph's (xi_i, x_i) in 1D.
  std::vector<Vec2> polygon;
  if (graph && curve.degree() >= 1) polygon = plane_points(plane_bspline(curve).value().control_points());
  else if (!graph) polygon = plane_points(curve.control_points());
  if (options.curvature_comb && !graph) {
    for (const auto& piece : pieces->pieces) {
      const auto box = control_box(piece);
      add_curvature_comb(panel, piece, 0.15 * std::hypot(box[2] - box[0], box[3] - box[1]));
    }
  }
  if (options.control_polygon && !polygon.empty())
    panel.polylines.push_back({polygon, dashed(colors::gray, 1.0), label_once(panel, "control polygon")});
  if (options.end_tangents && !pieces->pieces.empty()) {
    const auto first = plane_points(pieces->pieces.front().control_points());
    const auto last = plane_points(pieces->pieces.back().control_points());
    if (first.size() >= 2)
      panel.segments.push_back({{{first[0], first[1]}, {last[last.size() - 1], last[last.size() - 2]}},
                                solid(colors::blue),
                                false,
                                label_once(panel, "end tangents")});
  }
  bool control_points = options.control_points;
  if (options.construction && curve.degree() >= 1) {
    const double u = *options.construction;
    auto plane = plane_bspline(curve);
    const DeBoorNet net = de_boor_net(*plane, u);
    for (std::size_t r = 0; r + 1 < net.levels.size(); ++r)
      panel.polylines.push_back(
          {plane_points(net.levels[r]), dashed(colors::black, 1.0), r == 0 ? label_once(panel, "de Boor net") : ""});
    std::vector<Vec2> intermediate;
    for (std::size_t r = 1; r + 1 < net.levels.size(); ++r)
      for (auto p : plane_points(net.levels[r])) intermediate.push_back(p);
    if (!intermediate.empty()) panel.markers.push_back({intermediate, colors::black, 4.0 * kPixelsPerPoint, ""});
    const Vec2 c = plane_points(net.levels.back())[0];
    panel.markers.push_back({{c}, colors::red, 8.0 * kPixelsPerPoint,
                             fmt::format("C({:g}) = ({:.4g}, {:.4g})", u, c[0], c[1])});
    control_points = true;
  }
  for (auto& item : curve_items(*pieces, 0, pieces->pieces.size(), solid(color), label))
    panel.curves.push_back(std::move(item));
  if (options.knot_points && !pieces->pieces.empty()) {
    // A piece starts at its first control point and ends at its last, weights or not.
    std::vector<Vec2> knots;
    for (const auto& piece : pieces->pieces) knots.push_back(plane_points(piece.control_points()).front());
    knots.push_back(plane_points(pieces->pieces.back().control_points()).back());
    panel.markers.push_back({knots, colors::black, 5.0 * kPixelsPerPoint, label_once(panel, "C(knots)")});
  }
  if (control_points && !polygon.empty())
    panel.markers.push_back({polygon, colors::red, 6.0 * kPixelsPerPoint, label_once(panel, "control points")});
  return Status{};
}

BSplineCurve basis_function_curve(std::span<const double> knots, int degree, int index) {
  const std::size_t count = knots.size() - static_cast<std::size_t>(degree) - 1;  // n+1
  const int front = degree + 1 - multiplicity_of(knots, knots.front());
  const int back = degree + 1 - multiplicity_of(knots, knots.back());
  std::vector<double> padded(static_cast<std::size_t>(front), knots.front());
  padded.insert(padded.end(), knots.begin(), knots.end());
  padded.insert(padded.end(), static_cast<std::size_t>(back), knots.back());
  std::vector<double> coefficients(count + static_cast<std::size_t>(front + back), index < 0 ? 1.0 : 0.0);
  if (index >= 0) coefficients[static_cast<std::size_t>(index + front)] = 1.0;
  else {
    // The padded functions are not the given ones: they do not count in the sum.
    std::fill_n(coefficients.begin(), front, 0.0);
    std::fill_n(coefficients.rbegin(), back, 0.0);
  }
  return BSplineCurve::from_trusted(degree, std::move(padded), PointArray::from_trusted(1, std::move(coefficients)));
}

std::string knots_text(std::span<const double> knots, std::size_t max_count) {
  std::string text;
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (i == max_count) return text + " …";
    text += fmt::format("{}{:g}", i == 0 ? "" : " ", knots[i]);
  }
  return text;
}

Expected<Panel> bspline_basis_panel(std::span<const double> knots, int degree) {
  if (degree < 0 || degree > tolerances::kMaxBSplineDegree)
    return Error{fmt::format("the degree of a B-spline basis must be in [0, {}], got {}", tolerances::kMaxBSplineDegree,
                             degree)};
  if (knots.size() < static_cast<std::size_t>(2 * degree + 2))
    return Error{fmt::format("a B-spline basis of degree {} needs at least {} knots, got {}", degree, 2 * degree + 2,
                             knots.size())};
  const std::size_t count = knots.size() - static_cast<std::size_t>(degree) - 1;
  if (count > static_cast<std::size_t>(tolerances::kMaxPlottedBasisDegree) + 1)
    return Error{fmt::format("{} basis functions are too many to plot (at most {})", count, tolerances::kMaxPlottedBasisDegree + 1), ErrorKind::limit};
  if (auto ok = validate_knots(knots, degree, count); !ok) return ok.error();
  Panel panel;
  panel.x.label = "u";
  panel.y.label = fmt::format("N_(i,{})(u)", degree);
  panel.y.range = std::array<double, 2>{-0.2, 1.18};
  const double a = knots.front(), b = knots.back();
  const double lower = knots[static_cast<std::size_t>(degree)], upper = knots[count];
  panel.x.range = std::array<double, 2>{a - 0.03 * (b - a), b + 0.03 * (b - a)};
  const Color shade{128, 128, 128, 0.15};
  if (a < lower) panel.regions.push_back({{Vec2{{a, -0.2}}, Vec2{{lower, -0.2}}, Vec2{{lower, 1.18}}, Vec2{{a, 1.18}}},
                                          shade, "outside the domain"});
  if (upper < b)
    panel.regions.push_back({{Vec2{{upper, -0.2}}, Vec2{{b, -0.2}}, Vec2{{b, 1.18}}, Vec2{{upper, 1.18}}}, shade,
                             a < lower ? "" : "outside the domain"});
  // The sum first, so that the functions are drawn over it where it is 1.
  auto sum = plane_pieces(basis_function_curve(knots, degree, -1));
  if (!sum) return sum.error();
  for (auto& item : curve_items(*sum, 0, sum->pieces.size(), dashed(colors::black, 1.0), "Σ N_i"))
    panel.curves.push_back(std::move(item));
  for (std::size_t i = 0; i < count; ++i) {
    const BSplineCurve basis = basis_function_curve(knots, degree, static_cast<int>(i));
    auto pieces = plane_pieces(basis);
    if (!pieces) return pieces.error();
    const Color color = cycle_color(static_cast<int>(i));
    // Only the support [t_i, t_{i+p+1}] is drawn: N_i is 0 elsewhere and the
    // zero lines of all functions would hide each other on the axis.
    const double s0 = knots[i], s1 = knots[i + static_cast<std::size_t>(degree) + 1];
    std::size_t first = 0, last = 0;
    for (std::size_t k = 0; k < pieces->pieces.size(); ++k) {
      if (pieces->breakpoints[k + 1] <= s0) first = k + 1;
      if (pieces->breakpoints[k] < s1) last = k + 1;
    }
    for (auto& item : curve_items(*pieces, first, last, solid(color, 1.8))) panel.curves.push_back(std::move(item));
    // The name goes above the function's peak (sampled: a label needs no exact maximum).
    double peak_u = s0, peak = -1.0;
    for (int k = 0; k <= 64; ++k) {
      const double u = s0 + (s1 - s0) * k / 64.0;
      const double value = point_at(basis, u)[0];
      if (value > peak) peak = value, peak_u = u;
    }
    const Anchor anchor = peak_u <= s0 ? Anchor::start : (peak_u >= s1 ? Anchor::end : Anchor::middle);
    panel.texts.push_back({Vec2{{peak_u, peak}}, fmt::format("N{}", i), color, 9.0 * kPixelsPerPoint, anchor,
                           Vec2{{anchor == Anchor::start ? 4.0 : (anchor == Anchor::end ? -4.0 : 0.0), 5.0}}});
  }
  std::vector<Vec2> dots;
  for (const auto& knot : knot_multiplicities(knots)) {
    dots.push_back(Vec2{{knot.value, 0.0}});
    if (knot.multiplicity > 1)
      panel.texts.push_back({Vec2{{knot.value, 0.0}}, fmt::format("×{}", knot.multiplicity), colors::black,
                             8.0 * kPixelsPerPoint, Anchor::middle, Vec2{{0.0, -14.0}}});
  }
  panel.markers.push_back({dots, colors::black, 5.0 * kPixelsPerPoint, "knots"});
  panel.legend = LegendPlace::none;
  return panel;
}

}  // namespace casteljau::render

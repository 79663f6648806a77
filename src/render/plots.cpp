#include "casteljau/render/plots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "casteljau/bezier/construction.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/render/bspline_plots.hpp"
#include "casteljau/render/layout.hpp"
#include "casteljau/curves/differential_geometry.hpp"
#include "casteljau/render/tolerance.hpp"

namespace casteljau::render {
namespace {

std::string once(const Panel& panel, const std::string& text) { return label_once(panel, text); }

Vec2 plane_point(std::span<const double> p) { return Vec2{{p[0], p[1]}}; }

/// True when the variant V has the alternative T: the plot command draws
/// B-splines once io's Model holds them, and compiles before that.
template <class T, class V>
struct holds_alternative_type : std::false_type {};
template <class T, class... Ts>
struct holds_alternative_type<T, std::variant<Ts...>> : std::bool_constant<(std::is_same_v<T, Ts> || ...)> {};

const BSplineCurve* bspline_in(const Model& model) {
  if constexpr (holds_alternative_type<BSplineCurve, Model>::value) return std::get_if<BSplineCurve>(&model);
  else return nullptr;
}

Panel geometry_panel_for_plot() {
  Panel panel;
  panel.equal_aspect = true;
  return panel;
}

}  // namespace

std::string label_once(const Panel& panel, const std::string& text) {
  auto same = [&](const auto& items) {
    return std::any_of(items.begin(), items.end(), [&](const auto& item) { return item.label == text; });
  };
  const bool listed = same(panel.regions) || same(panel.segments) || same(panel.polylines) || same(panel.curves) ||
                      same(panel.markers);
  return listed ? std::string() : text;
}

std::array<double, 4> control_box(const BezierCurve& plane) {
  const auto& p = plane.control_points();
  double x0 = p[0][0], x1 = x0, y0 = p[0][1], y1 = y0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    x0 = std::min(x0, p[i][0]), x1 = std::max(x1, p[i][0]);
    y0 = std::min(y0, p[i][1]), y1 = std::max(y1, p[i][1]);
  }
  const double pad = 0.01 * std::max(x1 - x0, y1 - y0);
  return {x0 - pad, y0 - pad, x1 + pad, y1 + pad};
}

void add_curvature_comb(Panel& panel, CurveView plane, double length, int teeth, Color color, double reference_curvature) {
  teeth = std::max(teeth, 2);
  struct Sample {
    Vec2 point, normal;
    double kappa;
  };
  const BezierPieces pieces = to_bezier_pieces(plane);
  std::vector<std::vector<Sample>> samples(pieces.pieces.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < pieces.pieces.size(); ++k) {
    const BezierCurve& piece = pieces.pieces[k];
    for (int i = 0; i < teeth; ++i) {
      const double t = static_cast<double>(i) / (teeth - 1);
      const double kappa = signed_curvature_at(piece, t);
      if (!std::isfinite(kappa)) continue;  // a cusp: no finite tooth
      const Point tangent = unit_tangent_at(piece, t);
      samples[k].push_back({plane_point(point_at(piece, t)), Vec2{{-tangent[1], tangent[0]}}, kappa});
      largest = std::max(largest, std::abs(kappa));
    }
  }
  const double reference = reference_curvature > 0.0 ? reference_curvature : largest;
  const double scale = reference > 0.0 ? length / reference : 0.0;
  SegmentItem teeth_item{{}, solid(color, 0.8), false, once(panel, "curvature comb")};
  for (const std::vector<Sample>& piece : samples) {
    if (piece.empty()) continue;
    PolylineItem tips{{}, solid(color, 1.0), ""};
    for (const auto& s : piece) {
      // Signed curvature > 0 turns left (centre on the left normal): the tooth
      // points the other way, outside the bend.
      const double tooth = std::clamp(scale * s.kappa, -2.0 * length, 2.0 * length);
      const Vec2 tip = s.point - tooth * s.normal;
      teeth_item.segments.push_back({s.point, tip});
      tips.points.push_back(tip);
    }
    panel.polylines.push_back(std::move(tips));
  }
  if (!teeth_item.segments.empty()) panel.segments.push_back(std::move(teeth_item));
}

void add_bezier(Panel& panel, const BezierCurve& plane, const BezierPlotOptions& options, Color color,
                const std::string& label) {
  const auto points = plane_points(plane.control_points());
  const auto box = control_box(plane);
  const double size = std::hypot(box[2] - box[0], box[3] - box[1]);
  if (options.curvature_comb) add_curvature_comb(panel, plane, 0.15 * size);
  if (options.control_polygon) panel.polylines.push_back({points, dashed(colors::gray, 1.0), once(panel, "control polygon")});
  if (options.end_tangents && points.size() >= 2) {
    const std::size_t n = points.size() - 1;
    panel.segments.push_back({{{points[0], points[1]}, {points[n], points[n - 1]}},
                              solid(colors::blue),
                              false,
                              once(panel, "end tangents")});
  }
  bool control_points = options.control_points;
  if (options.construction) {
    const double t = *options.construction;
    const auto levels = casteljau_construction(plane, t);
    const std::string polygons = once(panel, "intermediate polygons");
    for (std::size_t r = 0; r + 1 < levels.size(); ++r)
      panel.polylines.push_back({plane_points(levels[r]), dashed(colors::black, 1.0), r == 0 ? polygons : ""});
    std::vector<Vec2> intermediate;
    for (std::size_t r = 1; r + 1 < levels.size(); ++r)
      for (auto p : plane_points(levels[r])) intermediate.push_back(p);
    if (!intermediate.empty()) panel.markers.push_back({intermediate, colors::black, 4.0 * kPixelsPerPoint, ""});
    const Vec2 c = plane_points(levels.back())[0];
    panel.markers.push_back({{c}, colors::red, 8.0 * kPixelsPerPoint,
                             fmt::format("C({:g}) = ({:.4g}, {:.4g})", t, c[0], c[1])});
    control_points = true;
  }
  panel.curves.push_back({{plane}, solid(color), label});
  if (control_points) panel.markers.push_back({points, colors::red, 6.0 * kPixelsPerPoint, once(panel, "control points")});
}

BezierCurve bernstein_graph(int n, int k) {
  std::vector<double> coordinates;
  coordinates.reserve(2 * static_cast<std::size_t>(n + 1));
  for (int j = 0; j <= n; ++j) {
    coordinates.push_back(static_cast<double>(j) / n);
    coordinates.push_back(j == k ? 1.0 : 0.0);
  }
  return BezierCurve::from_trusted(PointArray::from_trusted(2, std::move(coordinates)));
}

Expected<Panel> bernstein_basis_panel(int n, BasisEnds ends) {
  const bool without_ends = ends == BasisEnds::omitted;
  if (n < 1) return Error{fmt::format("the degree of the Bernstein basis must be >= 1, got {}", n)};
  if (n > tolerances::kMaxPlottedBasisDegree)
    return Error{fmt::format("the degree of the Bernstein basis must be <= {} to be plotted, got {}",
                             tolerances::kMaxPlottedBasisDegree, n), ErrorKind::limit};
  if (without_ends && n < 2)
    return Error{fmt::format("without k = 0 and k = n nothing is left of the basis of degree {}", n)};
  Panel panel;
  panel.x.label = "t";
  panel.y.label = fmt::format("B_{{{},k}}(t)", n);
  const int first = without_ends ? 1 : 0, last = without_ends ? n - 1 : n;
  for (int k = first; k <= last; ++k) panel.bernstein_graphs.push_back({n, k, solid(colors::black), ""});
  return panel;
}

Expected<Figure> bernstein_basis_figure(int n, BasisEnds ends) {
  auto panel = bernstein_basis_panel(n, ends);
  if (!panel) return panel.error();
  Figure figure;
  figure.width = 800;
  figure.height = 700;
  figure.title = ends == BasisEnds::omitted ? fmt::format("Bernstein basis B_{{{0},k}}, k = 1..{1} (without k = 0 and k = {0})", n, n - 1)
                              : fmt::format("Bernstein basis B_{{{0},k}}, k = 0..{0}", n);
  figure.panels.push_back(std::move(*panel));
  return figure;
}

namespace {

/// The box of points in the plane (their first two coordinates; a 1D point
/// set against x = 0), grown point by point.
struct PlaneBox {
  double lower[2] = {HUGE_VAL, HUGE_VAL}, upper[2] = {-HUGE_VAL, -HUGE_VAL};
  void add(const PointArray& points) {
    for (std::size_t i = 0; i < points.size(); ++i)
      for (std::size_t j = 0; j < 2; ++j) {
        const double v = j < points[i].size() ? points[i][j] : 0.0;
        lower[j] = std::min(lower[j], v), upper[j] = std::max(upper[j], v);
      }
  }
  void add(Vec2 p) {
    for (int j = 0; j < 2; ++j) lower[j] = std::min(lower[j], p[j]), upper[j] = std::max(upper[j], p[j]);
  }
  void add(const PlaneBox& other) {
    for (int j = 0; j < 2; ++j) lower[j] = std::min(lower[j], other.lower[j]), upper[j] = std::max(upper[j], other.upper[j]);
  }
  /// The first axis wider than tolerances::kMaxPlottedWidth (or the diagonal, axis 2), or -1.
  int overflowing_axis() const {
    for (int j = 0; j < 2; ++j)
      if (lower[j] <= upper[j] && !(upper[j] - lower[j] <= tolerances::kMaxPlottedWidth)) return j;
    const bool empty = !(lower[0] <= upper[0]);
    return !empty && !(std::hypot(upper[0] - lower[0], upper[1] - lower[1]) <= tolerances::kMaxPlottedWidth) ? 2 : -1;
  }
};

/// The control points of a curve model, as a box.
PlaneBox control_box_of(const Model& model) {
  PlaneBox box;
  if (const auto* c = std::get_if<BezierCurve>(&model)) box.add(c->control_points());
  if (const auto* p = std::get_if<PiecewiseBezierCurve>(&model))
    for (const auto& piece : p->pieces()) box.add(piece.control_points());
  if (const BSplineCurve* b = bspline_in(model)) box.add(b->control_points());
  return box;
}

/// An error, "<subject> span(s) ...", when the box is too wide for a figure:
/// every item drawn from it (curve, polygon, comb teeth sized by its diagonal)
/// lies in it or near it, and the figure's ranges must stay finite.
Status check_plottable(const PlaneBox& box, const std::string& subject) {
  const int axis = box.overflowing_axis();
  if (axis < 0) return {};
  if (axis == 2)
    return Error{fmt::format("{} x from {:g} to {:g} and y from {:g} to {:g}, too wide to plot (a figure shows a "
                             "diagonal of at most {:.2g})",
                             subject, box.lower[0], box.upper[0], box.lower[1], box.upper[1], tolerances::kMaxPlottedWidth), ErrorKind::limit};
  return Error{fmt::format("{} {} from {:g} to {:g}, too wide to plot (a figure shows a width of at most {:.2g})",
                           subject, axis == 0 ? "x" : "y", box.lower[axis], box.upper[axis], tolerances::kMaxPlottedWidth), ErrorKind::limit};
}

}  // namespace

Status check_plottable_extent(const std::vector<Vec2>& points, const std::string& subject) {
  PlaneBox box;
  for (auto p : points) box.add(p);
  return check_plottable(box, subject);
}

namespace {

/// Gives every curve item from `first` on the source name layout errors use.
void name_curves(Panel& panel, std::size_t first, const std::string& name) {
  for (std::size_t i = first; i < panel.curves.size(); ++i) panel.curves[i].source = name;
}

/// An error for a construction parameter outside the curve's domain.
Status check_construction_domain(double t, Interval domain, const std::string& name) {
  if (domain.contains(t)) return {};
  return Error{fmt::format("--construction {} is outside the domain [{}, {}] of {}", t, domain.lower, domain.upper,
                           name), ErrorKind::out_of_domain};
}

/// An error for a construction asked of a curve beyond kMaxConstructionDegree.
Status check_construction_degree(int degree, const std::string& name) {
  if (degree <= tolerances::kMaxConstructionDegree) return {};
  const long long n = degree;
  return Error{fmt::format("--construction: {} has degree {}, whose construction is {} segments, too many to show "
                           "(at most degree {})",
                           name, degree, n * (n + 1) / 2, tolerances::kMaxConstructionDegree), ErrorKind::limit};
}

}  // namespace

Expected<Figure> plot_figure(const std::vector<PlotSource>& sources, const PlotOptions& options) {
  if (sources.empty()) return Error{"nothing to plot: give at least one input"};
  std::size_t curve_count = 0;
  for (const auto& source : sources) curve_count += source.models.size();
  // Each file's extent on its own, then all together (two files may each be
  // fine and overflow side by side).
  PlaneBox all;
  std::vector<PlaneBox> boxes;
  for (const auto& source : sources) {
    PlaneBox box;
    if (source.models.empty()) box.add(source.points);
    for (std::size_t m = 0; m < source.models.size(); ++m) {
      const PlaneBox model_box = control_box_of(source.models[m]);
      const std::string name = source.models.size() == 1 ? source.name : fmt::format("{}[{}]", source.name, m);
      if (auto ok = check_plottable(model_box, name + ": the points span"); !ok) return ok.error();
      box.add(model_box);
    }
    if (auto ok = check_plottable(box, source.name + ": the points span"); !ok) return ok.error();
    all.add(box);
    boxes.push_back(box);
  }
  if (const int axis = all.overflowing_axis(); axis >= 0) {
    const int j = axis == 2 ? 0 : axis;
    std::size_t low = 0, high = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (boxes[i].lower[j] < boxes[low].lower[j]) low = i;
      if (boxes[i].upper[j] > boxes[high].upper[j]) high = i;
    }
    return check_plottable(all, fmt::format("{} and {} together span", sources[low].name, sources[high].name)).error();
  }
  Panel panel = geometry_panel_for_plot();
  std::optional<int> first_degree;
  std::optional<std::vector<double>> first_knots;  // the first curve's knots when it is a B-spline
  bool first_rational = false;
  std::string first_name;
  std::string title;
  int color_index = 0;
  // Data points go beneath every other marker: larger diamonds, so that a
  // control point on a data point (an interpolant's) shows both.
  std::vector<MarkerItem> data;
  for (const auto& source : sources) {
    title += (title.empty() ? "" : ", ") + source.name;
    if (source.models.empty()) {
      // Data: diamonds (control points are discs), named as data beside curves.
      const Color color = cycle_color(color_index++);
      const auto points = plane_points(source.points);
      const bool named = sources.size() > 1 || curve_count > 0;
      if (source.polyline)
        panel.polylines.push_back({points, solid(color, 1.0), named ? source.name + " (polyline)" : ""});
      if (source.markers || !source.polyline)
        data.push_back({points, color, 9.0 * kPixelsPerPoint, named ? source.name + " (data points)" : "",
                        MarkerShape::diamond});
      continue;
    }
    // A drawing's curves: one color, the file's name on the first only.
    const bool together = source.drawing && source.models.size() > 1 && curve_count > 1;
    const Color drawing_color = together ? cycle_color(color_index++) : colors::black;
    for (std::size_t m = 0; m < source.models.size(); ++m) {
      const std::string name = source.models.size() == 1 ? source.name : fmt::format("{}[{}]", source.name, m);
      const std::string legend = curve_count == 1 ? "" : !together ? name : m == 0 ? source.name : "";
      const std::size_t first_curve = panel.curves.size();
      if (first_name.empty()) first_name = name;
      if (const BSplineCurve* spline = bspline_in(source.models[m])) {
        if (auto ok = check_plotted_degree(spline->degree()); !ok) return with_context(ok.error(), name);
        if (options.bezier.construction) {
          if (auto ok = check_construction_domain(*options.bezier.construction, spline->domain(), name); !ok)
            return ok.error();
          if (auto ok = check_construction_degree(spline->degree(), name); !ok) return ok.error();
        }
        BSplinePlotOptions spline_options;
        spline_options.control_polygon = options.bezier.control_polygon;
        spline_options.control_points = options.bezier.control_points;
        spline_options.end_tangents = options.bezier.end_tangents;
        spline_options.curvature_comb = options.bezier.curvature_comb;
        spline_options.construction = options.bezier.construction;
        const Color color = together ? drawing_color : curve_count == 1 ? colors::black : cycle_color(color_index++);
        if (auto ok = add_bspline(panel, *spline, spline_options, color, legend); !ok)
          return with_context(ok.error(), name);
        name_curves(panel, first_curve, name);
        if (!first_degree) {
          first_degree = spline->degree();
          first_knots = std::vector<double>(spline->knots().begin(), spline->knots().end());
          first_rational = spline->is_rational();
        }
        continue;
      }
      std::vector<BezierCurve> pieces;
      if (const auto* curve = std::get_if<BezierCurve>(&source.models[m])) pieces.push_back(*curve);
      else pieces = std::get<PiecewiseBezierCurve>(source.models[m]).pieces();
      for (const auto& piece : pieces)
        if (auto ok = check_plotted_degree(piece.degree()); !ok) return with_context(ok.error(), name);
      std::optional<std::pair<int, double>> construction;
      if (options.bezier.construction) {
        const double u = *options.bezier.construction;
        if (auto ok = check_construction_domain(u, curve_view(source.models[m]).domain(), name); !ok) return ok.error();
        construction = std::pair<int, double>{0, u};
        if (const auto* piecewise = std::get_if<PiecewiseBezierCurve>(&source.models[m]))
          construction = locate(*piecewise, u);
        const int degree = pieces[static_cast<std::size_t>(construction->first)].degree();
        if (auto ok = check_construction_degree(degree, name); !ok) return ok.error();
      }
      const Color color = together ? drawing_color : curve_count == 1 ? colors::black : cycle_color(color_index++);
      const std::string& label = legend;
      for (std::size_t i = 0; i < pieces.size(); ++i) {
        auto plane = plane_curve(pieces[i]);
        if (!plane) return with_context(plane.error(), name);
        if (!first_degree) first_degree = plane->degree();
        BezierPlotOptions piece_options = options.bezier;
        piece_options.construction.reset();
        if (construction && construction->first == static_cast<int>(i)) piece_options.construction = construction->second;
        if (pieces.size() > 1 && options.bezier.end_tangents) piece_options.end_tangents = false;
        add_bezier(panel, *plane, piece_options, color, i == 0 ? label : "");
        if (pieces.size() > 1 && options.bezier.end_tangents && (i == 0 || i + 1 == pieces.size())) {
          // The whole curve's end tangents: along the first and last legs.
          const auto points = plane_points(plane->control_points());
          const std::size_t n = points.size() - 1;
          if (n >= 1) {
            SegmentItem tangent{{}, solid(colors::blue), false, once(panel, "end tangents")};
            if (i == 0) tangent.segments.push_back({points[0], points[1]});
            if (i + 1 == pieces.size()) tangent.segments.push_back({points[n], points[n - 1]});
            panel.segments.push_back(std::move(tangent));
          }
        }
      }
      name_curves(panel, first_curve, name);
    }
  }
  panel.markers.insert(panel.markers.begin(), data.begin(), data.end());
  Figure figure;
  figure.title = title;
  figure.width = 900;
  figure.height = 700;
  if (options.basis && first_degree && first_knots) {
    auto basis = bspline_basis_panel(*first_knots, *first_degree);
    if (!basis) return with_context(basis.error(), "--basis of " + first_name);
    basis->title = fmt::format("B-spline basis N_(i,{}), knots {}{}", *first_degree, knots_text(*first_knots),
                               first_rational ? " (without the weights)" : "");
    figure.height = 1200;
    figure.panels.push_back(std::move(panel));
    figure.panels.push_back(std::move(*basis));
  } else if (options.basis && first_degree) {
    auto basis = bernstein_basis_panel(std::max(*first_degree, 1));
    if (!basis) return with_context(basis.error(), "--basis of " + first_name);
    basis->title = fmt::format("Bernstein basis of degree {}", std::max(*first_degree, 1));
    figure.height = 1200;
    figure.panels.push_back(std::move(panel));
    figure.panels.push_back(std::move(*basis));
  } else {
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

}  // namespace casteljau::render

// Layout of a Figure into a Scene: ranges, ticks, grid, legend, and curves
// flattened within a quarter pixel. Sizes follow matplotlib's rcParams
// defaults (in points, converted at 100 dpi) so figures look like the seed
// notebook's.
//
// g++ 12 reports -Wmaybe-uninitialized inside std::variant's move constructor
// when a vector<Shape> grows (it mixes the members of two alternatives; a
// known false positive of GCC 12's middle end with variants of optionals).
// The pragma must precede the standard headers, where the warning is located.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "casteljau/render/layout.hpp"
#include "casteljau/core/tolerance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <string>
#include <tuple>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/render/bernstein_graph.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/render/tolerance.hpp"

namespace casteljau::render {
namespace {

constexpr double pt = kPixelsPerPoint;
constexpr double kFontSize = 10.0 * pt;         // font.size
constexpr double kTitleSize = 12.0 * pt;        // axes.titlesize 'large'
constexpr double kFigureTitleSize = 13.0 * pt;  // a little larger than panel titles
constexpr double kTickLength = 3.5 * pt;        // xtick.major.size
constexpr double kTickPad = 3.5 * pt;           // xtick.major.pad
constexpr double kFrameWidth = 0.8 * pt;        // axes.linewidth
constexpr double kGridWidth = 0.8 * pt;         // grid.linewidth
constexpr double kLabelPad = 4.0 * pt;          // axes.labelpad
constexpr double kTitlePad = 6.0 * pt;          // axes.titlepad
constexpr double kMarginFraction = 0.05;        // axes.xmargin / ymargin
constexpr double kOuterPad = 12.0;              // canvas edge to the nearest text, px
// DejaVu Sans digits rise 0.729 em above the baseline: half of that centres a label.
constexpr double kDigitHeight = 0.729;
constexpr double kSuperscriptScale = 0.7;
constexpr double kSuperscriptRise = 0.45;  // of the base size

const Color kLegendEdge{204, 204, 204};  // legend.edgecolor 0.8
const Color kLegendFace{255, 255, 255, 0.8};  // legend.framealpha 0.8

bool finite(Vec2 p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

/// Advance widths of DejaVu Sans for ASCII 32..126, in em.
constexpr std::array<double, 95> kAdvance{
    0.318, 0.401, 0.460, 0.838, 0.636, 0.950, 0.780, 0.275, 0.390, 0.390, 0.500, 0.838, 0.318, 0.361, 0.318, 0.337,
    0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.337, 0.337, 0.838, 0.838, 0.838, 0.531,
    1.000, 0.684, 0.686, 0.698, 0.770, 0.632, 0.575, 0.775, 0.752, 0.295, 0.295, 0.656, 0.557, 0.863, 0.748, 0.787,
    0.603, 0.787, 0.695, 0.635, 0.611, 0.732, 0.684, 0.989, 0.685, 0.611, 0.685, 0.390, 0.337, 0.390, 0.838, 0.500,
    0.500, 0.613, 0.635, 0.550, 0.635, 0.615, 0.352, 0.635, 0.634, 0.278, 0.278, 0.579, 0.278, 0.974, 0.634, 0.612,
    0.635, 0.635, 0.411, 0.521, 0.392, 0.634, 0.592, 0.818, 0.592, 0.592, 0.525, 0.636, 0.337, 0.636, 0.838};

/// A box in data coordinates, grown by points.
struct Bounds {
  double x_lower = std::numeric_limits<double>::infinity(), x_upper = -std::numeric_limits<double>::infinity();
  double y_lower = std::numeric_limits<double>::infinity(), y_upper = -std::numeric_limits<double>::infinity();
  void add(Vec2 p, bool x_log, bool y_log) {
    if (!(x_log && p[0] <= 0.0)) x_lower = std::min(x_lower, p[0]), x_upper = std::max(x_upper, p[0]);
    if (!(y_log && p[1] <= 0.0)) y_lower = std::min(y_lower, p[1]), y_upper = std::max(y_upper, p[1]);
  }
};

/// The plane control points' bounding-box diagonal: the scale of a curve.
double curve_scale(const BezierCurve& curve) {
  const auto& p = curve.control_points();
  double x0 = p[0][0], x1 = x0, y0 = p[0][1], y1 = y0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    x0 = std::min(x0, p[i][0]), x1 = std::max(x1, p[i][0]);
    y0 = std::min(y0, p[i][1]), y1 = std::max(y1, p[i][1]);
  }
  return std::hypot(x1 - x0, y1 - y0);
}

/// Tolerance for a curve in a panel with a logarithmic axis, where a model
/// distance is no fixed number of pixels: kLogAxisRelativeTolerance of its
/// control box's diagonal.
double log_axis_tolerance(const BezierCurve& curve) {
  const double scale = curve_scale(curve);
  const double magnitude = scale_of(curve.control_points());
  return std::max(scale * tolerances::kLogAxisRelativeTolerance, std::max(magnitude, 1.0) * 1e-12);
}

/// The same for a Bernstein graph, whose height is at most 1.
constexpr double kLogAxisGraphTolerance = tolerances::kLogAxisRelativeTolerance;

/// What a curve is called in an error: its source, or its place in the panel.
std::string curve_name(const CurveItem& c, std::size_t index) {
  return c.source.empty() ? fmt::format("curve {}", index) : c.source;
}

Status check_item_points(const std::vector<Vec2>& points, const std::string& what) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!finite(points[i])) return Error{fmt::format("{}: point {} is not finite", what, i)};
  return {};
}

Status check_panel(const Panel& panel, std::size_t index) {
  const std::string where = fmt::format("panel {}", index);
  for (std::size_t i = 0; i < panel.regions.size(); ++i)
    if (auto ok = check_item_points(panel.regions[i].boundary, fmt::format("{}, region {}", where, i)); !ok) return ok;
  for (std::size_t i = 0; i < panel.polylines.size(); ++i)
    if (auto ok = check_item_points(panel.polylines[i].points, fmt::format("{}, polyline {}", where, i)); !ok) return ok;
  for (std::size_t i = 0; i < panel.markers.size(); ++i)
    if (auto ok = check_item_points(panel.markers[i].points, fmt::format("{}, markers {}", where, i)); !ok) return ok;
  for (std::size_t i = 0; i < panel.segments.size(); ++i)
    for (const auto& s : panel.segments[i].segments)
      if (!finite(s[0]) || !finite(s[1])) return Error{fmt::format("{}, segments {}: a point is not finite", where, i)};
  for (std::size_t i = 0; i < panel.curves.size(); ++i)
    for (const auto& piece : panel.curves[i].pieces) {
      if (piece.dimension() != 2)
        return Error{fmt::format("{}, {}: a plane curve is needed, got dimension {}", where,
                                 curve_name(panel.curves[i], i), piece.dimension())};
      if (auto ok = check_plotted_degree(piece.degree()); !ok)
        return with_context(ok.error(), fmt::format("{}, {}", where, curve_name(panel.curves[i], i)));
    }
  for (std::size_t i = 0; i < panel.bernstein_graphs.size(); ++i) {
    const auto& g = panel.bernstein_graphs[i];
    if (g.degree < 1 || g.degree > tolerances::kMaxBezierDegree || g.index < 0 || g.index > g.degree)
      return Error{fmt::format("{}, Bernstein graph {}: B_{{{},{}}} is not a Bernstein polynomial of degree 1..{}", where,
                               i, g.degree, g.index, tolerances::kMaxBezierDegree)};
  }
  for (const Axis* axis : {&panel.x, &panel.y}) {
    if (!axis->range) continue;
    const auto [lo, hi] = *axis->range;
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi))
      return Error{fmt::format("{}: the axis range [{}, {}] is empty or not finite", where, lo, hi)};
    if (axis->logarithmic && lo <= 0.0)
      return Error{fmt::format("{}: a logarithmic axis needs a range > 0, got [{}, {}]", where, lo, hi)};
  }
  return {};
}

/// The box of a panel's items other than curves and Bernstein graphs.
Bounds item_bounds(const Panel& panel) {
  const bool xl = panel.x.logarithmic, yl = panel.y.logarithmic;
  Bounds b;
  for (const auto& r : panel.regions)
    for (auto p : r.boundary) b.add(p, xl, yl);
  for (const auto& s : panel.segments)
    for (const auto& seg : s.segments) b.add(seg[0], xl, yl), b.add(seg[1], xl, yl);
  for (const auto& l : panel.polylines)
    for (auto p : l.points) b.add(p, xl, yl);
  for (const auto& m : panel.markers)
    for (auto p : m.points) b.add(p, xl, yl);
  return b;
}

/// Parameters at which each curve piece is sampled for the first guess of a
/// panel's scale (the end points are its end control points).
constexpr int kGuessSamples = 8;

/// Points on the panel's curves and graphs that are cheap to find: each
/// piece's end points and C(j / kGuessSamples), each graph's ends and peak
/// (B_{n,k} is largest at k/n). Their box lies inside the true extent.
void add_points_on_curves(const Panel& panel, Bounds& b) {
  const bool xl = panel.x.logarithmic, yl = panel.y.logarithmic;
  std::vector<double> ts, out;
  for (int j = 1; j < kGuessSamples; ++j) ts.push_back(static_cast<double>(j) / kGuessSamples);
  out.resize(2 * ts.size());
  for (const auto& c : panel.curves)
    for (const auto& piece : c.pieces) {
      const auto& p = piece.control_points();
      b.add(Vec2{{p[0][0], p[0][1]}}, xl, yl);
      b.add(Vec2{{p[p.size() - 1][0], p[p.size() - 1][1]}}, xl, yl);
      points_at(piece, ts, out);
      for (std::size_t i = 0; i < ts.size(); ++i) b.add(Vec2{{out[2 * i], out[2 * i + 1]}}, xl, yl);
    }
  for (const auto& g : panel.bernstein_graphs) {
    const double peak = static_cast<double>(g.index) / g.degree;
    for (double t : {0.0, peak, 1.0}) b.add(Vec2{{t, bernstein(g.degree, g.index, t)}}, xl, yl);
  }
}

/// The control boxes of the panel's curves (each curve lies in its control
/// points' convex hull) and the unit square of its graphs: a box that holds
/// everything, but can be far larger than the curves (a Lagrange polynomial's
/// Bézier points reach 10^5 where the curve stays under 60).
void add_control_boxes(const Panel& panel, Bounds& b) {
  const bool xl = panel.x.logarithmic, yl = panel.y.logarithmic;
  for (const auto& c : panel.curves)
    for (const auto& piece : c.pieces) {
      const auto& p = piece.control_points();
      for (std::size_t i = 0; i < p.size(); ++i) b.add(Vec2{{p[i][0], p[i][1]}}, xl, yl);
    }
  if (!panel.bernstein_graphs.empty()) b.add(Vec2{{0.0, 0.0}}, xl, yl), b.add(Vec2{{1.0, 1.0}}, xl, yl);
}

/// A panel's curves and Bernstein graphs as polylines in data units.
struct PanelLines {
  std::vector<std::vector<Vec2>> curves;  ///< one per CurveItem, its pieces joined
  std::vector<std::vector<Vec2>> graphs;  ///< one per BernsteinGraphItem
};

using casteljau::ProgressPart;

/// Every curve and graph of the panel flattened within `tolerance` (model
/// units); on a logarithmic axis within each one's own fallback instead.
/// `done` hears the fraction of them flattened.
Expected<PanelLines> flatten_lines(const Panel& panel, double tolerance, ProgressPart& done) {
  const bool logarithmic = panel.x.logarithmic || panel.y.logarithmic;
  const double count = static_cast<double>(panel.curves.size() + panel.bernstein_graphs.size());
  PanelLines lines;
  for (std::size_t i = 0; i < panel.curves.size(); ++i) {
    done(static_cast<double>(i) / count);
    std::vector<Vec2> points;
    for (const auto& piece : panel.curves[i].pieces) {
      auto line = flatten(piece, Tolerance{logarithmic ? log_axis_tolerance(piece) : tolerance});
      if (!line) return with_context(line.error(), curve_name(panel.curves[i], i));
      const auto& p = line->points;
      for (std::size_t j = 0; j < p.size(); ++j) {
        const Vec2 v{{p[j][0], p[j][1]}};
        if (j == 0 && !points.empty() && points.back() == v) continue;  // shared joint
        points.push_back(v);
      }
    }
    lines.curves.push_back(std::move(points));
  }
  for (std::size_t i = 0; i < panel.bernstein_graphs.size(); ++i) {
    done(static_cast<double>(panel.curves.size() + i) / count);
    const auto& g = panel.bernstein_graphs[i];
    auto points = bernstein_graph_polyline(g.degree, g.index, Tolerance{logarithmic ? kLogAxisGraphTolerance : tolerance});
    if (!points) return with_context(points.error(), fmt::format("Bernstein graph {}", i));
    lines.graphs.push_back(std::move(*points));
  }
  done(1.0);
  return lines;
}

/// Adds the polylines' vertices to a box, widened by `widen` on every side.
void add_lines(const PanelLines& lines, double widen, bool xl, bool yl, Bounds& b) {
  for (const auto* group : {&lines.curves, &lines.graphs})
    for (const auto& line : *group)
      for (auto p : line) {
        b.add(Vec2{{p[0] - widen, p[1] - widen}}, xl, yl);
        b.add(Vec2{{p[0] + widen, p[1] + widen}}, xl, yl);
      }
}

/// A range from data extent with matplotlib's 5 % margins (in log space on a log axis).
std::array<double, 2> auto_range(double lower, double upper, bool logarithmic) {
  if (!(lower <= upper)) return logarithmic ? std::array<double, 2>{1.0, 10.0} : std::array<double, 2>{0.0, 1.0};
  if (logarithmic) lower = std::log10(lower), upper = std::log10(upper);
  double width = upper - lower;
  if (width <= tolerances::kScaleFloor || width <= 1e-12 * std::max(std::abs(lower), std::abs(upper))) {
    // A single value: a window around it (matplotlib's nonsingular expansion).
    const double half = lower == 0.0 ? 0.5 : std::max(0.05 * std::abs(lower), tolerances::kScaleFloor);
    lower -= half, upper += half;
    width = upper - lower;
  }
  lower -= kMarginFraction * width;
  upper += kMarginFraction * width;
  if (logarithmic) return {std::pow(10.0, lower), std::pow(10.0, upper)};
  return {lower, upper};
}

/// Formats a tick value with a fixed number of decimals, U+2212 for minus, no "-0".
std::string tick_label(double value, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, decimals);
  if (text.front() == '-') {
    if (text.find_first_not_of("-0.") == std::string::npos) return text.substr(1);  // "-0.00" -> "0.00"
    return "\u2212" + text.substr(1);
  }
  return text;
}

double text_height(double size) { return kDigitHeight * size; }

/// The widest y tick label (with its superscript) for a y range.
double widest_label(const Ticks& ticks, double size) {
  double widest = 0.0;
  for (std::size_t i = 0; i < ticks.labels.size(); ++i)
    widest = std::max(widest, estimated_text_width(ticks.labels[i], size) +
                                  estimated_text_width(ticks.superscripts[i], kSuperscriptScale * size));
  return widest;
}

Ticks ticks_for(double lower, double upper, bool logarithmic, double length, double spacing) {
  const int count = std::clamp(static_cast<int>(length / spacing), 3, 10);
  return logarithmic ? logarithmic_ticks(lower, upper, count) : linear_ticks(lower, upper, count);
}

constexpr double kXTickSpacing = 80.0, kYTickSpacing = 55.0;  // px between ticks at most, about

/// Resolves one panel's frame inside its cell.
PanelFrame resolve_frame(const Panel& panel, const Rectangle& cell, const Bounds& bounds, bool figure_title_here) {
  PanelFrame f;
  f.x_logarithmic = panel.x.logarithmic;
  f.y_logarithmic = panel.y.logarithmic;
  const auto xr = panel.x.range ? *panel.x.range : auto_range(bounds.x_lower, bounds.x_upper, f.x_logarithmic);
  const auto yr = panel.y.range ? *panel.y.range : auto_range(bounds.y_lower, bounds.y_upper, f.y_logarithmic);
  f.x_lower = xr[0], f.x_upper = xr[1], f.y_lower = yr[0], f.y_upper = yr[1];

  const bool has_title = !panel.title.empty() || figure_title_here;
  const double top = kOuterPad + (has_title ? kTitleSize * 1.2 + kTitlePad : 0.0);
  const double bottom = kOuterPad + kTickLength + kTickPad + text_height(kFontSize) +
                        (f.x_logarithmic ? kSuperscriptRise * kFontSize : 0.0) +
                        (panel.x.label.empty() ? 0.0 : kLabelPad + kFontSize * 1.1);
  const double right = kOuterPad + 12.0;
  double left = kOuterPad + 40.0;
  // Two passes: the left margin depends on the y labels, which depend on the
  // range, which (equal aspect) depends on the plot area.
  for (int pass = 0; pass < 2; ++pass) {
    f.area = Rectangle{cell.left + left, cell.top + top, std::max(cell.width - left - right, 10.0),
                       std::max(cell.height - top - bottom, 10.0)};
    f.x_lower = xr[0], f.x_upper = xr[1], f.y_lower = yr[0], f.y_upper = yr[1];
    if (panel.equal_aspect && !f.x_logarithmic && !f.y_logarithmic) {
      const double ux = (f.x_upper - f.x_lower) / f.area.width, uy = (f.y_upper - f.y_lower) / f.area.height;
      if (ux > uy) {
        const double half = 0.5 * ux * f.area.height, mid = 0.5 * (f.y_lower + f.y_upper);
        f.y_lower = mid - half, f.y_upper = mid + half;
      } else {
        const double half = 0.5 * uy * f.area.width, mid = 0.5 * (f.x_lower + f.x_upper);
        f.x_lower = mid - half, f.x_upper = mid + half;
      }
    }
    const Ticks yt = ticks_for(f.y_lower, f.y_upper, f.y_logarithmic, f.area.height, kYTickSpacing);
    left = kOuterPad + widest_label(yt, kFontSize) + kTickPad + kTickLength +
           (panel.y.label.empty() ? 0.0 : kFontSize * 1.1 + kLabelPad);
  }
  return f;
}

/// A panel's frame and the polylines drawn in it.
struct ResolvedPanel {
  PanelFrame frame;
  PanelLines lines;
};

/// A polyline flattened this many times finer than its frame needs has about
/// twice the vertices it needs (the count grows like tolerance^(-1/2)): it is
/// flattened again at the tolerance the frame needs.
constexpr double kFinerThanNeeded = 4.0;
/// Rounds of "flatten, then fit the frame to what was flattened" before the
/// frame is fitted to the vertices widened by the tolerance (which holds the
/// curves whatever the round) and the curves flattened for it once more.
constexpr int kExtentRounds = 3;

/// A frame whose ranges have no finite width (data near +-1e308 on both
/// sides) cannot map data to pixels.
Status check_drawable(const PanelFrame& f) {
  for (const auto& [lower, upper, axis] : {std::tuple{f.x_lower, f.x_upper, "x"}, std::tuple{f.y_lower, f.y_upper, "y"}})
    if (!(std::isfinite(upper - lower) && upper - lower > 0.0))
      return Error{fmt::format("the data spans {} from {:g} to {:g}, too wide to draw (the width overflows a double)",
                               axis, lower, upper), ErrorKind::limit};
  return {};
}

/// The frame of a panel, fitted to the curves themselves, and the curves
/// flattened for it. A polyline within tau of its curve, vertices on it,
/// fixes the curve's extent to within tau: the curve lies in the vertices'
/// box widened by tau. So the frame is fitted to the vertices of the very
/// polylines that are drawn (no separate coarse pass, which would miss what
/// lies within its coarse tolerance, like the Runge polynomial's dips), and
/// as long as tau is at most the frame's drawing tolerance (a quarter pixel),
/// the 5 % margins (at least 25 pixels) hold that widening many times over.
/// tau depends on the frame: the first guess fits the frame to points on the
/// curves (their ends and a few samples, inside the true extent, so the
/// guessed tau is at most what the fitted frame needs); the curves are
/// flattened again when tau turns out coarser than the fitted frame needs (a
/// guess from the control boxes), or kFinerThanNeeded times finer (samples
/// that missed most of a curve: a denser polyline than needed).
Expected<ResolvedPanel> resolve_panel(const Panel& panel, const Rectangle& cell, bool title_here, ProgressPart& done) {
  const bool xl = panel.x.logarithmic, yl = panel.y.logarithmic;
  const Bounds items = item_bounds(panel);
  auto fitted = [&](const PanelLines& lines, double widen) {
    Bounds b = items;
    add_lines(lines, widen, xl, yl, b);
    return resolve_frame(panel, cell, b, title_here);
  };
  if (xl || yl || (panel.curves.empty() && panel.bernstein_graphs.empty())) {
    // No uniform pixel scale (or nothing to flatten): each curve within its
    // own fallback tolerance, the frame fitted to the vertices.
    auto lines = flatten_lines(panel, 0.0, done);
    if (!lines) return lines.error();
    const PanelFrame frame = fitted(*lines, 0.0);
    if (auto ok = check_drawable(frame); !ok) return ok.error();
    return ResolvedPanel{frame, std::move(*lines)};
  }
  auto needed_by = [&](const Bounds& b) {
    return drawing_tolerance(resolve_frame(panel, cell, b, title_here), 0.0).distance;
  };
  Bounds guess = items;
  add_points_on_curves(panel, guess);
  if (auto ok = check_drawable(resolve_frame(panel, cell, guess, title_here)); !ok) return ok.error();
  double tolerance = needed_by(guess);
  bool from_hull = false;
  for (int round = 1;; ++round) {
    auto lines = flatten_lines(panel, tolerance, done);
    if (!lines) {
      // The samples can miss most of a curve (a narrow spike), making the
      // guessed tolerance far too fine: start again from the control boxes,
      // which hold every curve.
      if (from_hull) return lines.error();
      Bounds hull = items;
      add_control_boxes(panel, hull);
      const double coarser = needed_by(hull);
      if (!(coarser > tolerance)) return lines.error();
      tolerance = coarser;
      from_hull = true;
      continue;
    }
    PanelFrame frame = fitted(*lines, 0.0);
    if (auto ok = check_drawable(frame); !ok) return ok.error();
    double needed = drawing_tolerance(frame, 0.0).distance;
    if (tolerance <= needed && kFinerThanNeeded * tolerance >= needed) return ResolvedPanel{frame, std::move(*lines)};
    if (tolerance > needed && round == kExtentRounds) {
      // Not settled: the widened vertices hold the curves, fit to them.
      frame = fitted(*lines, tolerance);
      if (auto ok = check_drawable(frame); !ok) return ok.error();
      needed = drawing_tolerance(frame, 0.0).distance;
    }
    if (tolerance <= needed || round == kExtentRounds) {
      auto final_lines = flatten_lines(panel, needed, done);
      if (!final_lines) return final_lines.error();
      return ResolvedPanel{frame, std::move(*final_lines)};
    }
    tolerance = needed;
  }
}

/// Splits a data polyline into pixel runs, leaving out points a log axis cannot show.
std::vector<std::vector<Vec2>> pixel_runs(const PanelFrame& f, const std::vector<Vec2>& points) {
  std::vector<std::vector<Vec2>> runs(1);
  for (auto p : points) {
    if ((f.x_logarithmic && !(p[0] > 0.0)) || (f.y_logarithmic && !(p[1] > 0.0))) {
      if (!runs.back().empty()) runs.emplace_back();
      continue;
    }
    runs.back().push_back(f.to_pixels(p));
  }
  if (runs.back().empty()) runs.pop_back();
  return runs;
}

/// One legend entry: how to draw its handle, and its text.
struct LegendEntry {
  std::string text;
  std::optional<Stroke> line;
  std::optional<Color> marker;
  double marker_diameter = 0.0;
  std::optional<Color> patch;
  MarkerShape marker_shape = MarkerShape::disc;
};

class PanelPainter {
 public:
  PanelPainter(const Panel& panel, const ResolvedPanel& resolved, std::vector<Shape>& out)
      : panel_(panel), f_(resolved.frame), lines_(resolved.lines), out_(out) {}

  void paint(const std::string& title) {
    grid_and_ticks();
    out_.push_back(ClipBegin{f_.area});
    for (const auto& r : panel_.regions) region(r);
    for (const auto& s : panel_.segments) segments(s);
    for (const auto& l : panel_.polylines) polyline(l.points, l.stroke, l.label);
    for (std::size_t i = 0; i < panel_.curves.size(); ++i)
      polyline(lines_.curves[i], panel_.curves[i].stroke, panel_.curves[i].label);
    for (std::size_t i = 0; i < panel_.bernstein_graphs.size(); ++i)
      polyline(lines_.graphs[i], panel_.bernstein_graphs[i].stroke, panel_.bernstein_graphs[i].label);
    for (const auto& m : panel_.markers) markers(m);
    for (const auto& t : panel_.texts) text(t);
    out_.push_back(ClipEnd{});
    frame_and_labels(title);
    legend();
  }

 private:
  void stroke_path(std::vector<Vec2> points, const Stroke& stroke) {
    for (auto p : points) occupied_.push_back(p);
    out_.push_back(PathShape{std::move(points), false, stroke, std::nullopt});
  }

  void region(const RegionItem& r) {
    for (auto& run : pixel_runs(f_, r.boundary)) {
      for (auto p : run) occupied_.push_back(p);
      out_.push_back(PathShape{std::move(run), true, std::nullopt, r.fill});
    }
    if (!r.label.empty()) entries_.push_back({r.label, std::nullopt, std::nullopt, 0.0, r.fill});
  }

  void segments(const SegmentItem& s) {
    for (const auto& seg : s.segments) {
      auto runs = pixel_runs(f_, {seg[0], seg[1]});
      if (runs.size() != 1 || runs[0].size() != 2) continue;
      const Vec2 a = runs[0][0], b = runs[0][1];
      if (s.arrows) {
        // A filled head whose tip is the end point; the shaft stops at its base
        // so a wide line does not poke through the tip.
        const double length = distance(a, b);
        const double head = std::min(3.0 * s.stroke.width + 6.0, 0.5 * length);
        if (length > 0.0) {
          const Vec2 u = (1.0 / length) * (b - a), n{{-u[1], u[0]}};
          const Vec2 base = b - head * u;
          stroke_path({a, base}, s.stroke);
          out_.push_back(PathShape{{b, base + 0.4 * head * n, base - 0.4 * head * n}, true, std::nullopt, s.stroke.color});
          continue;
        }
      }
      stroke_path({a, b}, s.stroke);
    }
    if (!s.label.empty()) entries_.push_back({s.label, s.stroke, std::nullopt, 0.0, std::nullopt});
  }

  void polyline(const std::vector<Vec2>& points, const Stroke& stroke, const std::string& label) {
    for (auto& run : pixel_runs(f_, points)) stroke_path(std::move(run), stroke);
    if (!label.empty()) entries_.push_back({label, stroke, std::nullopt, 0.0, std::nullopt});
  }

  void markers(const MarkerItem& m) {
    for (auto& run : pixel_runs(f_, m.points))
      for (auto p : run) {
        occupied_.push_back(p);
        marker(p, m.shape, m.diameter, m.color);
      }
    if (!m.label.empty()) entries_.push_back({m.label, std::nullopt, m.color, m.diameter, std::nullopt, m.shape});
  }

  void marker(Vec2 p, MarkerShape shape, double diameter, Color color) {
    const double r = 0.5 * diameter;
    if (shape == MarkerShape::diamond) {
      out_.push_back(PathShape{{p + Vec2{{0.0, -r}}, p + Vec2{{r, 0.0}}, p + Vec2{{0.0, r}}, p + Vec2{{-r, 0.0}}}, true,
                               std::nullopt, color});
    } else {
      out_.push_back(CircleShape{p, r, color});
    }
  }

  void text(const TextItem& t) {
    if ((f_.x_logarithmic && !(t.position[0] > 0.0)) || (f_.y_logarithmic && !(t.position[1] > 0.0))) return;
    const Vec2 p = f_.to_pixels(t.position);
    out_.push_back(TextShape{Vec2{{p[0] + t.offset[0], p[1] - t.offset[1]}}, t.text, t.size, t.color, t.anchor, 0.0, false});
  }

  void grid_and_ticks() {
    x_ticks_ = ticks_for(f_.x_lower, f_.x_upper, f_.x_logarithmic, f_.area.width, kXTickSpacing);
    y_ticks_ = ticks_for(f_.y_lower, f_.y_upper, f_.y_logarithmic, f_.area.height, kYTickSpacing);
    if (!panel_.grid) return;
    const Stroke grid = solid(colors::grid, kGridWidth / pt);
    const double bottom = f_.area.top + f_.area.height, right = f_.area.left + f_.area.width;
    for (double x : x_ticks_.values) {
      const double px = f_.to_pixels(Vec2{{x, f_.y_logarithmic ? f_.y_lower : 0.0}})[0];
      out_.push_back(PathShape{{Vec2{{px, f_.area.top}}, Vec2{{px, bottom}}}, false, grid, std::nullopt});
    }
    for (double y : y_ticks_.values) {
      const double py = f_.to_pixels(Vec2{{f_.x_logarithmic ? f_.x_lower : 0.0, y}})[1];
      out_.push_back(PathShape{{Vec2{{f_.area.left, py}}, Vec2{{right, py}}}, false, grid, std::nullopt});
    }
  }

  void frame_and_labels(const std::string& title) {
    const Rectangle& a = f_.area;
    const double bottom = a.top + a.height, right = a.left + a.width;
    out_.push_back(PathShape{{Vec2{{a.left, a.top}}, Vec2{{right, a.top}}, Vec2{{right, bottom}}, Vec2{{a.left, bottom}}},
                             true, solid(colors::black, kFrameWidth / pt), std::nullopt});
    const Stroke tick = solid(colors::black, kFrameWidth / pt);
    const double sup = kSuperscriptScale * kFontSize;
    for (std::size_t i = 0; i < x_ticks_.values.size(); ++i) {
      const double px = f_.to_pixels(Vec2{{x_ticks_.values[i], f_.y_logarithmic ? f_.y_lower : 0.0}})[0];
      out_.push_back(PathShape{{Vec2{{px, bottom}}, Vec2{{px, bottom + kTickLength}}}, false, tick, std::nullopt});
      const std::string& label = x_ticks_.labels[i];
      const std::string& exponent = x_ticks_.superscripts[i];
      const double extra = exponent.empty() ? 0.0 : kSuperscriptRise * kFontSize;
      const double baseline = bottom + kTickLength + kTickPad + text_height(kFontSize) + extra;
      if (exponent.empty()) {
        out_.push_back(TextShape{Vec2{{px, baseline}}, label, kFontSize, colors::black, Anchor::middle, 0.0, false});
      } else {
        const double w1 = estimated_text_width(label, kFontSize), w2 = estimated_text_width(exponent, sup);
        const double x0 = px - 0.5 * (w1 + w2);
        out_.push_back(TextShape{Vec2{{x0, baseline}}, label, kFontSize, colors::black, Anchor::start, 0.0, false});
        out_.push_back(TextShape{Vec2{{x0 + w1, baseline - kSuperscriptRise * kFontSize}}, exponent, sup, colors::black,
                                 Anchor::start, 0.0, false});
      }
    }
    double widest = 0.0;
    for (std::size_t i = 0; i < y_ticks_.values.size(); ++i) {
      const double py = f_.to_pixels(Vec2{{f_.x_logarithmic ? f_.x_lower : 0.0, y_ticks_.values[i]}})[1];
      out_.push_back(PathShape{{Vec2{{a.left, py}}, Vec2{{a.left - kTickLength, py}}}, false, tick, std::nullopt});
      const double end = a.left - kTickLength - kTickPad;
      const double baseline = py + 0.5 * text_height(kFontSize);
      const std::string& label = y_ticks_.labels[i];
      const std::string& exponent = y_ticks_.superscripts[i];
      if (exponent.empty()) {
        out_.push_back(TextShape{Vec2{{end, baseline}}, label, kFontSize, colors::black, Anchor::end, 0.0, false});
      } else {
        const double w2 = estimated_text_width(exponent, sup);
        out_.push_back(TextShape{Vec2{{end - w2, baseline}}, label, kFontSize, colors::black, Anchor::end, 0.0, false});
        out_.push_back(TextShape{Vec2{{end - w2, baseline - kSuperscriptRise * kFontSize}}, exponent, sup,
                                 colors::black, Anchor::start, 0.0, false});
      }
      widest = std::max(widest, estimated_text_width(label, kFontSize) + estimated_text_width(exponent, sup));
    }
    if (!panel_.x.label.empty()) {
      const double extra = f_.x_logarithmic ? kSuperscriptRise * kFontSize : 0.0;
      const double baseline = bottom + kTickLength + kTickPad + text_height(kFontSize) + extra + kLabelPad + kFontSize;
      out_.push_back(TextShape{Vec2{{a.left + 0.5 * a.width, baseline}}, panel_.x.label, kFontSize, colors::black,
                               Anchor::middle, 0.0, false});
    }
    if (!panel_.y.label.empty()) {
      const double x = a.left - kTickLength - kTickPad - widest - kLabelPad - 0.25 * kFontSize;
      out_.push_back(TextShape{Vec2{{x, a.top + 0.5 * a.height}}, panel_.y.label, kFontSize, colors::black,
                               Anchor::middle, 90.0, false});
    }
    if (!title.empty())
      out_.push_back(TextShape{Vec2{{a.left + 0.5 * a.width, a.top - kTitlePad}}, title, kTitleSize, colors::black,
                               Anchor::middle, 0.0, false});
  }

  void legend() {
    if (panel_.legend == LegendPlace::none || entries_.empty()) return;
    const double size = kFontSize;
    const double border = 0.4 * size, handle = 2.0 * size, gap = 0.8 * size, spacing = 0.5 * size;
    const double outside = 0.5 * size;  // legend.borderaxespad
    double text_width = 0.0;
    for (const auto& e : entries_) text_width = std::max(text_width, estimated_text_width(e.text, size));
    // cairo's hinting rounds each advance up to a whole pixel: leave room for it.
    text_width = 1.04 * text_width + 0.3 * size;
    const double width = 2.0 * border + handle + gap + text_width;
    const double n = static_cast<double>(entries_.size());
    const double height = 2.0 * border + n * size + (n - 1.0) * spacing + 0.3 * size;
    const Rectangle& a = f_.area;
    auto corner = [&](LegendPlace place) {
      const bool right = place == LegendPlace::upper_right || place == LegendPlace::lower_right;
      const bool upper = place == LegendPlace::upper_right || place == LegendPlace::upper_left;
      return Rectangle{right ? a.left + a.width - outside - width : a.left + outside,
                       upper ? a.top + outside : a.top + a.height - outside - height, width, height};
    };
    LegendPlace place = panel_.legend;
    if (place == LegendPlace::best) {
      // matplotlib's 'best': the candidate covering the fewest data points,
      // ties in the order upper right, upper left, lower left, lower right.
      std::size_t fewest = std::numeric_limits<std::size_t>::max();
      for (LegendPlace candidate :
           {LegendPlace::upper_right, LegendPlace::upper_left, LegendPlace::lower_left, LegendPlace::lower_right}) {
        const Rectangle r = corner(candidate);
        std::size_t covered = 0;
        for (auto p : occupied_)
          covered += p[0] >= r.left && p[0] <= r.left + r.width && p[1] >= r.top && p[1] <= r.top + r.height;
        for (std::size_t k = 0; k + 1 < occupied_.size(); ++k) {
          // Count segment midpoints too, so long straight lines count.
          const Vec2 m = 0.5 * (occupied_[k] + occupied_[k + 1]);
          covered += m[0] >= r.left && m[0] <= r.left + r.width && m[1] >= r.top && m[1] <= r.top + r.height;
        }
        if (covered < fewest) fewest = covered, place = candidate;
      }
    }
    const Rectangle r = corner(place);
    out_.push_back(PathShape{{Vec2{{r.left, r.top}}, Vec2{{r.left + r.width, r.top}},
                              Vec2{{r.left + r.width, r.top + r.height}}, Vec2{{r.left, r.top + r.height}}},
                             true, solid(kLegendEdge, 1.0), kLegendFace});
    double y = r.top + border + 0.15 * size;
    for (const auto& e : entries_) {
      const double middle = y + 0.5 * size;
      const double x0 = r.left + border, x1 = x0 + handle;
      if (e.patch)
        out_.push_back(PathShape{{Vec2{{x0, middle - 0.35 * size}}, Vec2{{x1, middle - 0.35 * size}},
                                  Vec2{{x1, middle + 0.35 * size}}, Vec2{{x0, middle + 0.35 * size}}},
                                 true, std::nullopt, *e.patch});
      if (e.line) out_.push_back(PathShape{{Vec2{{x0, middle}}, Vec2{{x1, middle}}}, false, *e.line, std::nullopt});
      if (e.marker) marker(Vec2{{0.5 * (x0 + x1), middle}}, e.marker_shape, e.marker_diameter, *e.marker);
      out_.push_back(TextShape{Vec2{{x1 + gap, middle + 0.5 * text_height(size)}}, e.text, size, colors::black,
                               Anchor::start, 0.0, false});
      y += size + spacing;
    }
  }

  const Panel& panel_;
  const PanelFrame& f_;
  const PanelLines& lines_;
  std::vector<Shape>& out_;
  Ticks x_ticks_, y_ticks_;
  std::vector<LegendEntry> entries_;
  std::vector<Vec2> occupied_;  // pixel positions of drawn data, for the legend
};

Status check_figure(const Figure& figure) {
  if (figure.panels.empty()) return Error{"the figure has no panel"};
  if (figure.width < 16 || figure.width > 16384 || figure.height < 16 || figure.height > 16384)
    return Error{fmt::format("figure size {}x{} pixels is outside 16..16384", figure.width, figure.height)};
  if (figure.columns < 1) return Error{fmt::format("figure columns must be >= 1, got {}", figure.columns)};
  for (std::size_t i = 0; i < figure.panels.size(); ++i)
    if (auto ok = check_panel(figure.panels[i], i); !ok) return ok;
  return {};
}

/// The figure-level title sits in its own band when there are several panels
/// (matplotlib's suptitle); with one panel it is that panel's title.
bool has_title_band(const Figure& figure) { return figure.panels.size() > 1 && !figure.title.empty(); }

std::vector<Rectangle> panel_cells(const Figure& figure) {
  const double band = has_title_band(figure) ? kFigureTitleSize * 2.0 : 0.0;
  const int columns = std::min<int>(figure.columns, static_cast<int>(figure.panels.size()));
  const int rows = (static_cast<int>(figure.panels.size()) + columns - 1) / columns;
  const double w = figure.width / static_cast<double>(columns);
  const double h = (figure.height - band) / static_cast<double>(rows);
  std::vector<Rectangle> cells;
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const int row = static_cast<int>(i) / columns, column = static_cast<int>(i) % columns;
    cells.push_back(Rectangle{column * w, band + row * h, w, h});
  }
  return cells;
}

std::string panel_title(const Figure& figure, std::size_t i) {
  const auto& panel = figure.panels[i];
  if (!panel.title.empty()) return panel.title;
  if (figure.panels.size() == 1) return figure.title;
  return {};
}

}  // namespace

Vec2 PanelFrame::to_pixels(Vec2 p) const {
  auto coordinate = [](double v, double lo, double hi, bool log) {
    if (log) return (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
    return (v - lo) / (hi - lo);
  };
  const double fx = coordinate(p[0], x_lower, x_upper, x_logarithmic);
  const double fy = coordinate(p[1], y_lower, y_upper, y_logarithmic);
  return Vec2{{area.left + fx * area.width, area.top + (1.0 - fy) * area.height}};
}

Vec2 PanelFrame::from_pixels(Vec2 pixel) const {
  auto value = [](double f, double lo, double hi, bool log) {
    if (log) return std::pow(10.0, std::log10(lo) + f * (std::log10(hi) - std::log10(lo)));
    return lo + f * (hi - lo);
  };
  const double fx = (pixel[0] - area.left) / area.width;
  const double fy = 1.0 - (pixel[1] - area.top) / area.height;
  return Vec2{{value(fx, x_lower, x_upper, x_logarithmic), value(fy, y_lower, y_upper, y_logarithmic)}};
}

Status check_plotted_degree(int degree) {
  if (degree <= tolerances::kMaxPlottedCurveDegree) return {};
  return Error{fmt::format("a curve of degree {} is beyond what a figure draws (at most degree {}: certifying the "
                           "drawing costs O(n^2) per segment, seconds at degree 1000, minutes near 10,000); "
                           "eval --samples gives its points",
                           degree, tolerances::kMaxPlottedCurveDegree), ErrorKind::limit};
}

Tolerance drawing_tolerance(const PanelFrame& frame, double fallback) {
  if (frame.x_logarithmic || frame.y_logarithmic) return Tolerance{fallback};
  const double ux = (frame.x_upper - frame.x_lower) / frame.area.width;
  const double uy = (frame.y_upper - frame.y_lower) / frame.area.height;
  return Tolerance{tolerances::kCurveTolerancePixels * std::min(ux, uy)};
}

Ticks linear_ticks(double lower, double upper, int max_count) {
  Ticks ticks;
  // A range whose width overflows (refused by layout, but its margins are
  // measured first) has no ticks.
  if (!(upper > lower) || !std::isfinite(upper - lower) || max_count < 1) return ticks;
  // Candidate steps m * 10^e in increasing order; take the smallest that
  // gives at most max_count intervals, and a smaller one if that leaves fewer
  // than two ticks inside the range (matplotlib's min_n_ticks = 2).
  const double raw = (upper - lower) / max_count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  constexpr std::array<double, 4> kMantissas{1.0, 2.0, 2.5, 5.0};
  std::vector<std::pair<double, double>> steps;  // (step, mantissa), increasing
  for (double scale : {0.01, 0.1, 1.0, 10.0})
    for (double m : kMantissas) steps.push_back({m * magnitude * scale, m});
  std::size_t choice = steps.size() - 1;
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (steps[i].first >= raw * (1.0 - 1e-9)) {
      choice = i;
      break;
    }
  auto range_of = [&](double step) {
    const long first = static_cast<long>(std::ceil(lower / step - 1e-9));
    const long last = static_cast<long>(std::floor(upper / step + 1e-9));
    return std::pair<long, long>{first, last};
  };
  while (choice > 0 && range_of(steps[choice].first).second - range_of(steps[choice].first).first < 1) --choice;
  const auto [step, mantissa] = steps[choice];
  // Decimals that show the step exactly: 0.25 needs one more than 0.2.
  int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  if (mantissa == 2.5) decimals += 1;
  const auto [first, last] = range_of(step);
  for (long i = first; i <= last; ++i) {
    const double value = static_cast<double>(i) * step;
    ticks.values.push_back(value);
    ticks.labels.push_back(tick_label(value, std::min(decimals, 17)));
    ticks.superscripts.emplace_back();
  }
  return ticks;
}

Ticks logarithmic_ticks(double lower, double upper, int max_count) {
  Ticks ticks;
  if (!(lower > 0.0 && upper > lower) || max_count < 1) return ticks;
  const int first = static_cast<int>(std::ceil(std::log10(lower) - 1e-9));
  const int last = static_cast<int>(std::floor(std::log10(upper) + 1e-9));
  const int every = std::max(1, (last - first + max_count) / max_count);
  for (int e = first; e <= last; ++e) {
    if (((e % every) + every) % every != 0) continue;
    ticks.values.push_back(std::pow(10.0, e));
    ticks.labels.emplace_back("10");
    ticks.superscripts.push_back(e < 0 ? "\u2212" + std::to_string(-e) : std::to_string(e));
  }
  return ticks;
}

double estimated_text_width(const std::string& text, double size) {
  double em = 0.0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 32 && c < 127) {
      em += kAdvance[c - 32];
    } else if (c >= 0xC0) {
      // Start of a multi-byte UTF-8 character: Greek letters, U+2212 minus, ×, ≈...
      const bool minus = text.compare(i, 3, "\u2212") == 0;
      em += minus ? 0.838 : 0.68;
    }  // continuation bytes (0x80..0xBF) and controls add nothing
  }
  return em * size;
}

namespace {

/// Every panel of the figure resolved (checked first). Progress: each panel's
/// share is its part of the figure's curves and graphs (flattening is the work).
Expected<std::vector<ResolvedPanel>> resolve_panels(const Figure& figure, Progress progress) {
  if (auto ok = check_figure(figure); !ok) return ok.error();
  const auto cells = panel_cells(figure);
  double total = 0.0;
  for (const auto& panel : figure.panels) total += static_cast<double>(panel.curves.size() + panel.bernstein_graphs.size());
  std::vector<ResolvedPanel> panels;
  double begin = 0.0;
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const auto& panel = figure.panels[i];
    const double share = total > 0.0 ? static_cast<double>(panel.curves.size() + panel.bernstein_graphs.size()) / total : 0.0;
    const double end = i + 1 == figure.panels.size() ? 1.0 : begin + share;
    ProgressPart done(progress, begin, end);
    begin = end;
    auto resolved = resolve_panel(panel, cells[i], !panel_title(figure, i).empty(), done);
    if (!resolved && figure.panels.size() == 1) return resolved.error();  // the curve's own name says enough
    if (!resolved) return with_context(resolved.error(), fmt::format("panel {}", i));
    panels.push_back(std::move(*resolved));
  }
  return panels;
}

}  // namespace

Expected<std::vector<PanelFrame>> panel_frames(const Figure& figure) {
  auto panels = resolve_panels(figure, Progress{});
  if (!panels) return panels.error();
  std::vector<PanelFrame> frames;
  for (const auto& panel : *panels) frames.push_back(panel.frame);
  return frames;
}

Expected<Scene> layout(const Figure& figure, Progress progress) {
  auto panels = resolve_panels(figure, progress);
  if (!panels) return panels.error();
  Scene scene;
  scene.width = figure.width;
  scene.height = figure.height;
  scene.title = figure.title;
  if (has_title_band(figure))
    scene.shapes.push_back(TextShape{Vec2{{0.5 * figure.width, kFigureTitleSize * 1.4}}, figure.title,
                                     kFigureTitleSize, colors::black, Anchor::middle, 0.0, false});
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    PanelPainter painter(figure.panels[i], (*panels)[i], scene.shapes);
    painter.paint(panel_title(figure, i));
  }
  return scene;
}

}  // namespace casteljau::render

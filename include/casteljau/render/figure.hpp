#pragma once
// Figure: a drawing as plain data. Panels (axes) hold layers of curves,
// polylines, markers, segments, text and filled regions in model units; the
// layout step (layout.hpp) turns a Figure into pixels and the writers
// (write.hpp) into SVG, PNG or PDF. Nothing here draws: a Figure can be built,
// compared, copied and inspected in tests like any other value.
//
// Looks follow matplotlib's defaults, as in the seed notebook's figures
// (seed 004): a 100 dpi canvas, 1.5 pt lines, 10 pt tick labels, a light grid,
// black 'k' curves, red 'or' control points, blue 'b' tangents, the tab10
// colour cycle for several curves.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau::render {

/// An sRGB colour with opacity (alpha in [0,1]).
struct Color {
  unsigned char red = 0, green = 0, blue = 0;
  double alpha = 1.0;
  friend bool operator==(const Color&, const Color&) = default;
};

namespace colors {
inline constexpr Color black{0, 0, 0};
inline constexpr Color white{255, 255, 255};
/// matplotlib's 'r' (pure red): the notebook's control points ('or').
inline constexpr Color red{255, 0, 0};
/// matplotlib's 'b' (pure blue): the notebook's end tangents.
inline constexpr Color blue{0, 0, 255};
inline constexpr Color gray{128, 128, 128};
/// matplotlib's grid colour (#b0b0b0).
inline constexpr Color grid{176, 176, 176};
}  // namespace colors

/// Colour i of matplotlib's default cycle "tab10" (i taken modulo 10).
Color cycle_color(int index);

/// 1 point (1/72 in) in pixels at the 100 dpi of matplotlib's default figures.
inline constexpr double kPixelsPerPoint = 100.0 / 72.0;

/// How a line is drawn: colour, width in pixels, dash pattern in pixels
/// (on, off, on, off, ...; empty = solid).
struct Stroke {
  Color color = colors::black;
  double width = 1.5 * kPixelsPerPoint;
  std::vector<double> dash{};
  friend bool operator==(const Stroke&, const Stroke&) = default;
};

/// A solid line (matplotlib '-'); width in points.
Stroke solid(Color color, double width_points = 1.5);
/// A dashed line (matplotlib '--': 3.7 on, 1.6 off, in line widths).
Stroke dashed(Color color, double width_points = 1.5);
/// A dotted line (matplotlib ':': 1 on, 1.65 off, in line widths).
Stroke dotted(Color color, double width_points = 1.5);

/// A curve drawn through casteljau's own flattening at layout time, within a
/// quarter pixel (layout.hpp): one polyline through all pieces, in order.
/// Control points are read in the plane (2 coordinates), see plane_curve().
struct CurveItem {
  std::vector<BezierCurve> pieces{};
  Stroke stroke{};
  std::string label{};   ///< legend text; empty: not in the legend
  std::string source = {};  ///< what layout errors name it by (a file, "file.json[2]"); empty: "curve i"
};

/// The graph t -> (t, B_{n,k}(t)) of one Bernstein polynomial over [0, 1],
/// drawn from its closed form at layout time within a quarter pixel
/// (bernstein_graph.hpp): O(n) per vertex, where the same graph as a Bézier
/// curve of degree n (plots.hpp's bernstein_graph) costs O(n^2).
struct BernsteinGraphItem {
  int degree = 1;  ///< n, in [1, tolerances::kMaxBezierDegree]
  int index = 0;   ///< k, in [0, n]
  Stroke stroke{};
  std::string label{};
};

/// A polyline through given points (data that is not a Bézier curve:
/// polygons, sampled errors, the naive evaluator's points).
struct PolylineItem {
  std::vector<Vec2> points{};
  Stroke stroke{};
  std::string label{};
};

/// The form of a marker: a filled circle (matplotlib 'o', the notebook's
/// control points) or a filled diamond (matplotlib 'D', data points, so that
/// the two stay apart without colour).
enum class MarkerShape { disc, diamond };

/// Filled markers at points; diameter (the diamond's width) in pixels.
struct MarkerItem {
  std::vector<Vec2> points{};
  Color color = colors::red;
  double diameter = 6.0 * kPixelsPerPoint;
  std::string label{};
  MarkerShape shape = MarkerShape::disc;
};

/// Independent straight segments, optionally with an arrow head at the end.
struct SegmentItem {
  std::vector<std::array<Vec2, 2>> segments{};
  Stroke stroke{};
  bool arrows = false;
  std::string label{};
};

/// Where a text's position is along its width.
enum class Anchor { start, middle, end };

/// Text at a point of the data, shifted by `offset` pixels (x right, y up).
struct TextItem {
  Vec2 position{};
  std::string text{};  ///< UTF-8
  Color color = colors::black;
  double size = 10.0 * kPixelsPerPoint;  ///< font size in pixels
  Anchor anchor = Anchor::start;
  Vec2 offset{};
};

/// A filled polygon (its boundary is closed implicitly).
struct RegionItem {
  std::vector<Vec2> boundary{};
  Color fill{31, 119, 180, 0.25};
  std::string label{};
};

/// One axis: label, range (automatic from the content when empty), scale.
struct Axis {
  std::string label{};
  /// Fixed [lower, upper]; otherwise the data's range plus 5 % on each side
  /// (matplotlib's default margins).
  std::optional<std::array<double, 2>> range{};
  /// Base-10 logarithmic scale; values <= 0 are left out (break the lines).
  bool logarithmic = false;
};

/// Where the legend goes; `best` picks the corner covering the fewest data points.
enum class LegendPlace { best, upper_right, upper_left, lower_left, lower_right, none };

/// One set of axes. Layers are drawn in this order: regions, segments,
/// polylines, curves, Bernstein graphs, markers, texts (markers above lines, as in the notebook);
/// inside a layer in insertion order. The legend lists labelled items in the
/// same order.
struct Panel {
  std::string title{};
  Axis x{}, y{};
  /// One model unit is as long across as up (matplotlib's set_aspect('equal')),
  /// obtained by widening the range of one axis.
  bool equal_aspect = false;
  bool grid = true;
  LegendPlace legend = LegendPlace::best;
  std::vector<RegionItem> regions{};
  std::vector<SegmentItem> segments{};
  std::vector<PolylineItem> polylines{};
  std::vector<CurveItem> curves{};
  std::vector<BernsteinGraphItem> bernstein_graphs{};
  std::vector<MarkerItem> markers{};
  std::vector<TextItem> texts{};
};

/// A whole figure: size in pixels (PNG pixels, SVG user units), a title, and
/// panels laid out row by row in `columns` columns.
struct Figure {
  int width = 800;
  int height = 600;
  std::string title{};
  int columns = 1;
  std::vector<Panel> panels{};
};

/// The first two coordinates of each point (d >= 2), or (x, 0) for d = 1.
std::vector<Vec2> plane_points(const PointArray& points);

/// The curve as a plane curve: itself for d = 2; its projection on the first
/// two coordinates for d >= 3 (projection is linear, so projecting the
/// control points projects the curve, weights unchanged); for d = 1 the graph
/// t -> (t, x(t)), which is the Bézier curve with control points (k/n, x_k)
/// (linear precision: sum_k (k/n) B_{n,k}(t) = t). Error for a rational curve
/// of dimension 1 (its graph is not of that form).
Expected<BezierCurve> plane_curve(const BezierCurve& curve);

}  // namespace casteljau::render

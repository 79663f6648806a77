// The toolpath preview (render/toolpath_plot.hpp): one panel, each kind of
// move its own item, so that the legend names them once.
#include "casteljau/render/toolpath_plot.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/nurbs/conics.hpp"

namespace casteljau::render {
namespace {

Vec2 plane_of(const std::array<double, 3>& p) { return Vec2{{p[0], p[1]}}; }

/// The arc a controller moves along, as exact rational pieces: from the
/// start's angle about the centre, clockwise or not, to the end's (a whole
/// turn when they coincide).
Expected<BezierPieces> arc_pieces(const GcodeMove& move) {
  const Vec2 from = plane_of(move.from) - move.centre, to = plane_of(move.to) - move.centre;
  const double radius = (norm(from) + norm(to)) / 2.0;
  const bool clockwise = move.kind == GcodeMove::Kind::clockwise_arc;
  double sweep = std::atan2(cross(from, to), dot(from, to));  // (-pi, pi]
  if (clockwise && sweep >= 0.0) sweep -= 2.0 * std::numbers::pi;
  if (!clockwise && sweep <= 0.0) sweep += 2.0 * std::numbers::pi;
  auto arc = make_arc(move.centre[0], move.centre[1], radius, std::atan2(from[1], from[0]), sweep);
  if (!arc) return with_context(arc.error(), fmt::format("line {}", move.line));
  return to_bezier_pieces(*arc);
}

}  // namespace

Expected<Figure> toolpath_figure(const GcodeReading& program, const std::string& name, const std::vector<Model>& source,
                                 const std::string& source_name) {
  if (program.moves.empty()) return Error{fmt::format("{}: the program makes no move", name)};
  const char* unit = program.units == GcodeUnits::millimetres ? "mm" : "in";
  Panel panel;
  panel.equal_aspect = true;
  panel.x.label = fmt::format("x ({})", unit);
  panel.y.label = fmt::format("y ({})", unit);
  panel.legend = LegendPlace::best;

  // A CurveItem is drawn as one polyline: one item a source curve, and one
  // a run of arcs that follow each other (the legend names the first).
  std::vector<CurveItem> curves;
  for (std::size_t m = 0; m < source.size(); ++m) {
    const std::string model = source.size() == 1 ? source_name : fmt::format("{}[{}]", source_name, m);
    if (is_surface(source[m])) return Error{fmt::format("{} is a surface, not a curve a program cuts", model)};
    const CurveView view = curve_view(source[m]);
    if (view.dimension() != 2) return Error{fmt::format("{} lives in R^{}, not in the plane", model, view.dimension())};
    curves.push_back(CurveItem{to_bezier_pieces(view).pieces, Stroke{Color{190, 190, 190}, 4.0 * kPixelsPerPoint, {}},
                               m == 0 ? "source curves" : "", model});
  }
  // Cuts: runs of lines and runs of arcs, each a CurveItem, drawn above the
  // source curves (segments would be drawn beneath them).
  std::vector<CurveItem> lines, arcs;
  std::array<double, 3> lines_end{}, arcs_end{};
  const auto append = [&name](std::vector<CurveItem>& runs, std::array<double, 3>& end, const GcodeMove& move,
                              std::vector<BezierCurve> pieces, int color, const char* label) {
    if (runs.empty() || end != move.from) runs.push_back(CurveItem{{}, solid(cycle_color(color), 1.2), runs.empty() ? label : "", name});
    for (BezierCurve& piece : pieces) runs.back().pieces.push_back(std::move(piece));
    end = move.to;
  };
  std::size_t line_count = 0;

  SegmentItem rapids{{}, dashed(colors::gray, 1.0), false, "rapid moves (G0)"};
  MarkerItem plunges{{}, colors::red, 5.0 * kPixelsPerPoint, "plunges", MarkerShape::disc};
  std::size_t arc_moves = 0;
  for (const GcodeMove& move : program.moves) {
    const Vec2 from = plane_of(move.from), to = plane_of(move.to);
    const bool in_plane = from != to;
    switch (move.kind) {
      case GcodeMove::Kind::rapid:
        if (in_plane) rapids.segments.push_back({from, to});
        break;
      case GcodeMove::Kind::line:
        if (in_plane) {
          ++line_count;
          append(lines, lines_end, move, {BezierCurve::from_trusted(PointArray::from_trusted(2, {from[0], from[1], to[0], to[1]}))},
                 0, "lines (G1)");
        } else if (move.to[2] < move.from[2] && move.to[2] < 0.0) plunges.points.push_back(to);
        break;
      case GcodeMove::Kind::clockwise_arc:
      case GcodeMove::Kind::counterclockwise_arc: {
        ++arc_moves;
        auto pieces = arc_pieces(move);
        if (!pieces) return with_context(pieces.error(), name);
        append(arcs, arcs_end, move, std::move(pieces->pieces), 1, "arcs (G2, G3)");
        break;
      }
    }
  }
  for (CurveItem& curve : curves) panel.curves.push_back(std::move(curve));
  if (!rapids.segments.empty()) panel.segments.push_back(std::move(rapids));
  for (CurveItem& run : lines) panel.curves.push_back(std::move(run));
  for (CurveItem& run : arcs) panel.curves.push_back(std::move(run));
  const std::size_t plunge_count = plunges.points.size();
  if (!plunges.points.empty()) panel.markers.push_back(std::move(plunges));
  panel.title = fmt::format("{}: {} arc{}, {} line{}, {} plunge{}", name, arc_moves, arc_moves == 1 ? "" : "s",
                            line_count, line_count == 1 ? "" : "s", plunge_count, plunge_count == 1 ? "" : "s");
  Figure figure;
  figure.panels.push_back(std::move(panel));
  return figure;
}

}  // namespace casteljau::render

// The gallery's figures of drawings casteljau reads (issue 17): an SVG
// drawing of examples/ read into curves, and a word set in a TrueType font,
// each drawn with the control polygons and control points of its Bézier
// pieces (figure_list.hpp).
#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/io/font.hpp"
#include "casteljau/io/svg_drawing.hpp"
#include "figure_list.hpp"

namespace casteljau::render::detail {
namespace {

Expected<GalleryFigure> svg_drawing_figure(const std::filesystem::path& examples_dir) {
  const auto drawing = read_svg_drawing(examples_dir / "sailboat.svg");
  if (!drawing) return drawing.error();
  if (!drawing->problems.empty()) return drawing->problems.front();
  Panel panel;
  panel.equal_aspect = true;
  panel.legend = LegendPlace::none;
  std::size_t pieces = 0, rational = 0;
  std::vector<Vec2> points;
  for (const SvgCurve& curve : drawing->curves) {
    CurveItem item{{}, solid(colors::black, 1.6), "", curve.element + (curve.id.empty() ? "" : "#" + curve.id)};
    for (const BezierCurve& piece : curve.curve.pieces()) {
      const BezierCurve& shown = piece;  // read upright (docs/formats.md, "The frame")
      ++pieces;
      rational += piece.is_rational() ? 1 : 0;
      if (shown.degree() > 1) {
        const auto polygon = plane_points(shown.control_points());
        panel.polylines.push_back({polygon, dashed(piece.is_rational() ? cycle_color(3) : cycle_color(0), 0.9), ""});
        points.insert(points.end(), polygon.begin(), polygon.end());
      }
      item.pieces.push_back(shown);
    }
    panel.curves.push_back(std::move(item));
  }
  panel.markers.push_back({points, colors::red, 3.0 * kPixelsPerPoint, ""});
  Figure figure = figure_of("An SVG drawing read by casteljau (examples/sailboat.svg)", 1000, 720, 1);
  figure.panels.push_back(std::move(panel));
  return GalleryFigure{
      "39_svg_drawing",
      fmt::format("examples/sailboat.svg read by read_svg_drawing: {} curves (one per subpath of each path and shape, "
                  "group transforms applied), {} Bézier pieces, {} of them exact rational quadratics (the arcs, "
                  "circles, ellipses and rounded corners, polygons in red dashes; blue dashes for the others), "
                  "upright: y measured up from the page's bottom edge, where the file's points down.",
                  drawing->curves.size(), pieces, rational),
      std::move(figure)};
}

/// Debian's DejaVu Sans (fonts-dejavu-core, which make demo installs).
constexpr const char* kGalleryFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

Expected<GalleryFigure> font_figure() {
  auto text = text_outline("Bézier", kGalleryFont);
  if (!text) return text.error();
  Panel panel;
  panel.equal_aspect = true;
  std::vector<Vec2> on, off;
  std::size_t quadratics = 0;
  for (const GlyphContour& contour : text->contours) {
    CurveItem item{{}, solid(colors::black, 1.8), "", fmt::format("glyph {}", contour.glyph)};
    for (const BezierCurve& piece : contour.curve.pieces()) {
      const auto points = plane_points(piece.control_points());
      on.push_back(points.front());
      if (piece.degree() == 2) {
        ++quadratics;
        off.push_back(points[1]);
        panel.polylines.push_back({points, dashed(cycle_color(0), 0.9), ""});
      }
      item.pieces.push_back(piece);
    }
    panel.curves.push_back(std::move(item));
  }
  panel.markers.push_back({on, colors::red, 5.0 * kPixelsPerPoint, "on-curve points (piece ends)"});
  panel.markers.push_back({off, cycle_color(0), 5.0 * kPixelsPerPoint, "off-curve control points",
                           MarkerShape::diamond});
  Figure figure = figure_of(fmt::format("\"Bézier\" in {} (TrueType quadratic outlines)", text->font_name), 1200, 560, 1);
  figure.panels.push_back(std::move(panel));
  return GalleryFigure{
      "40_font_outlines",
      fmt::format("casteljau text: the word set in DejaVu Sans by FreeType's advances and kerning, in font units ({} "
                  "to the em): {} contours, {} quadratic Bézier pieces whose control points are the font's off-curve "
                  "points (diamonds, polygons dashed); where two off-curve points follow each other TrueType implies "
                  "the on-curve point midway (the discs between diamonds). The é is a composite glyph.",
                  text->units_per_em, text->contours.size(), quadratics),
      std::move(figure)};
}

}  // namespace

Expected<std::vector<GalleryFigure>> drawing_gallery_figures(const std::filesystem::path& examples_dir) {
  std::vector<GalleryFigure> figures;
  if (auto ok = append_figure(figures, svg_drawing_figure(examples_dir)); !ok) return ok.error();
  if (auto ok = append_figure(figures, font_figure()); !ok) return ok.error();
  return figures;
}

}  // namespace casteljau::render::detail

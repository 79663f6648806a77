// The gallery's G-code figures (issue 41): programs written by casteljau
// gcode's own steps (contour_of, write_gcode), read back (read_gcode) and
// drawn as their previews (toolpath_plot.hpp) over the curves they cut.
#include <fmt/format.h>

#include <string>
#include <utility>
#include <vector>

#include "casteljau/interpolation/c1_bezier.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/font.hpp"
#include "casteljau/io/gcode.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/render/toolpath_plot.hpp"
#include "figure_list.hpp"

namespace casteljau::render::detail {
namespace {

/// A program for the curves at `tolerance` mm (casteljau gcode's defaults
/// otherwise), read back: the figure's panel and the program's counts.
struct Preview {
  Panel panel;
  GcodeProgram program;
};

Expected<Preview> preview_of(const std::vector<Model>& curves, double tolerance, const std::string& name, int passes = 1) {
  Toolpath toolpath;
  toolpath.tolerance = Tolerance{tolerance};
  toolpath.sources = {name};
  auto decimals = gcode_decimals(toolpath.tolerance, GcodeUnits::millimetres);
  if (!decimals) return decimals.error();
  for (const Model& model : curves) {
    auto contour = contour_of(curve_view(model), toolpath.tolerance, *decimals, GcodeMotion::arcs);
    if (!contour) return with_context(contour.error(), name);
    toolpath.contours.push_back(std::move(*contour));
  }
  GcodeOptions options = default_gcode_options(GcodeUnits::millimetres);
  options.step_down = options.depth / passes;
  auto program = write_gcode(toolpath, options);
  if (!program) return program.error();
  auto reading = read_gcode(program->text);
  if (!reading) return reading.error();
  auto figure = toolpath_figure(*reading, name + ".nc", curves, name);
  if (!figure) return figure.error();
  return Preview{std::move(figure->panels.front()), std::move(*program)};
}

Expected<GalleryFigure> head_and_car_figure(const std::filesystem::path& examples_dir) {
  Figure figure = figure_of("The head and the car of seed 000 cut within 0.01 mm: G-code read back", 1500, 620, 2);
  std::vector<std::string> counts;
  for (const char* name : {"head", "car"}) {
    auto points = read_points_csv(examples_dir / fmt::format("{}.csv", name));
    if (!points) return points.error();
    auto curve = interpolate_c1_bezier(*points, 1.0);
    if (!curve) return curve.error();
    auto preview = preview_of({Model{*curve}}, 0.01, name, name == std::string("head") ? 1 : 2);
    if (!preview) return preview.error();
    counts.push_back(fmt::format("the {} {} arcs and {} lines ({} bytes, {} pass{})", name, preview->program.arcs,
                                 preview->program.lines, preview->program.text.size(), preview->program.passes,
                                 preview->program.passes == 1 ? "" : "es"));
    figure.panels.push_back(std::move(preview->panel));
  }
  return GalleryFigure{
      "41_gcode_head_and_car",
      fmt::format("casteljau gcode on the C¹ Bézier interpolants (α = 1): {}; {}. Each program is read back by "
                  "casteljau's own G-code reader and drawn over its curve (grey): rapid moves dashed, arcs G2/G3 in "
                  "orange, chords G1 in blue, plunges red. The car is cut in two passes, back and forth: it plunges "
                  "at both ends. LinuxCNC's and cncjs's interpreters read the same programs in make test.",
                  counts[0], counts[1]),
      std::move(figure)};
}

Expected<GalleryFigure> semicircle_figure() {
  auto preview = preview_of({Model{seed_semicircle()}}, 0.01, "semicircle");
  if (!preview) return preview.error();
  Figure figure = figure_of("The seed's half circle (exact NURBS) is one G2 arc", 900, 560, 1);
  figure.panels.push_back(std::move(preview->panel));
  return GalleryFigure{"42_gcode_semicircle",
                       fmt::format("Seed 003's machine example: the exact half circle of radius 3 (a rational "
                                   "B-spline) becomes {} G2 move, I J the centre from the start, nothing else cut.",
                                   preview->program.arcs),
                       std::move(figure)};
}

Expected<GalleryFigure> word_figure() {
  TextLayout layout;
  layout.size = 20.0;
  auto text = text_outline("casteljau", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", layout);
  if (!text) return text.error();
  std::vector<Model> contours;
  for (const GlyphContour& contour : text->contours) contours.push_back(Model{contour.curve});
  auto preview = preview_of(contours, 0.01, "casteljau");
  if (!preview) return preview.error();
  Figure figure = figure_of("\"casteljau\" in DejaVu Sans, 20 mm, engraved within 0.01 mm", 1500, 520, 1);
  figure.panels.push_back(std::move(preview->panel));
  return GalleryFigure{
      "43_gcode_word",
      fmt::format("{} contours in {} arcs and {} lines; the contours ordered by nearest neighbour and 2-opt: rapid "
                  "moves {:.1f} mm against {:.1f} mm in the text's order.",
                  preview->program.contours, preview->program.arcs, preview->program.lines,
                  preview->program.rapid_length, preview->program.rapid_length_unordered),
      std::move(figure)};
}

}  // namespace

Expected<std::vector<GalleryFigure>> gcode_gallery_figures(const std::filesystem::path& examples_dir) {
  std::vector<GalleryFigure> figures;
  if (auto ok = append_figure(figures, head_and_car_figure(examples_dir)); !ok) return ok.error();
  if (auto ok = append_figure(figures, semicircle_figure()); !ok) return ok.error();
  if (auto ok = append_figure(figures, word_figure()); !ok) return ok.error();
  return figures;
}

}  // namespace casteljau::render::detail

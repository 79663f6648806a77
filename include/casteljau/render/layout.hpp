#pragma once
// Layout: from a Figure (model units) to a Scene (pixels): axis ranges, ticks,
// grid, legend, titles, and every curve flattened by casteljau's own
// flatten() within a quarter pixel. The writers only draw Scenes, so SVG, PNG
// and PDF show the same thing.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/render/figure.hpp"

namespace casteljau::render {

/// An error for a curve piece of degree beyond tolerances::kMaxPlottedCurveDegree (the
/// message says why and what to do instead), else nothing.
Status check_plotted_degree(int degree);

/// An axis-aligned rectangle in pixels (y grows downward, like SVG and cairo).
struct Rectangle {
  double left = 0.0, top = 0.0, width = 0.0, height = 0.0;
};

/// Where one panel's data lands on the canvas.
struct PanelFrame {
  Rectangle area;           ///< the plot area (inside the axes' frame)
  double x_lower = 0.0, x_upper = 1.0;  ///< x range shown (data units)
  double y_lower = 0.0, y_upper = 1.0;  ///< y range shown (data units)
  bool x_logarithmic = false, y_logarithmic = false;

  /// Data point to pixel (y flipped); on a log axis the coordinate must be > 0.
  Vec2 to_pixels(Vec2 point) const;
  /// Pixel to data point (inverse of to_pixels).
  Vec2 from_pixels(Vec2 pixel) const;
};

/// The frames of the figure's panels (ranges resolved from the content,
/// margins for tick labels and titles). Errors as for layout().
Expected<std::vector<PanelFrame>> panel_frames(const Figure& figure);

/// The flattening tolerance in model units that keeps a curve within
/// kCurveTolerancePixels on screen: 0.25 px times the smaller of the two
/// model-units-per-pixel ratios (a model displacement v moves at most
/// |v| / min(ux, uy) pixels). For a panel with a logarithmic axis the pixel
/// scale is not uniform; there `fallback` is returned.
Tolerance drawing_tolerance(const PanelFrame& frame, double fallback);

/// Tick positions and their labels on one axis. On a log axis a label is
/// "10" with the exponent as superscript (matplotlib's 10^k).
struct Ticks {
  std::vector<double> values;
  std::vector<std::string> labels;       ///< main text ("0.25", "−1", "10")
  std::vector<std::string> superscripts; ///< exponent text on log axes, else empty strings
};

/// "Nice" ticks inside [lower, upper]: steps of 1, 2, 2.5 or 5 times a power of
/// ten, at most `max_count` of them (the idea of matplotlib's MaxNLocator);
/// all labels with the same number of decimals, U+2212 for minus.
Ticks linear_ticks(double lower, double upper, int max_count);

/// Decades 10^k inside [lower, upper] (0 < lower < upper), every m-th decade
/// when there are more than `max_count`.
Ticks logarithmic_ticks(double lower, double upper, int max_count);

/// Width in pixels of `text` at `size` pixels in DejaVu Sans, from the font's
/// advance widths (digits are all 0.636 em): used to place legends and margins
/// identically for SVG (which cannot measure) and cairo.
double estimated_text_width(const std::string& text, double size);

// ---- Scene: what the writers draw, in pixels --------------------------------

/// An open or closed polyline, stroked and/or filled.
struct PathShape {
  std::vector<Vec2> points;
  bool closed = false;
  std::optional<Stroke> stroke;
  std::optional<Color> fill;
};

/// A filled disc (a marker).
struct CircleShape {
  Vec2 center;
  double radius = 1.0;
  Color fill = colors::black;
};

/// One run of text whose alphabetic baseline starts (or is centred, or ends,
/// by `anchor`) at `position`, rotated counter-clockwise by `rotation_degrees`.
struct TextShape {
  Vec2 position;
  std::string text;
  double size = 10.0;
  Color color = colors::black;
  Anchor anchor = Anchor::start;
  double rotation_degrees = 0.0;
  bool bold = false;
};

/// Starts clipping to a rectangle (until the matching ClipEnd).
struct ClipBegin {
  Rectangle area;
};
/// Ends the innermost clip.
struct ClipEnd {};

using Shape = std::variant<PathShape, CircleShape, TextShape, ClipBegin, ClipEnd>;

/// A canvas of width x height pixels on a white background, shapes in drawing order.
struct Scene {
  double width = 0.0, height = 0.0;
  std::string title;
  std::vector<Shape> shapes;
};

/// Lays the figure out. `progress` hears the fraction of its curves and
/// Bernstein graphs flattened (the work of a big figure). Errors: no panel, a
/// size outside 16..16384 pixels, columns < 1, a non-finite coordinate, a
/// fixed range that is empty or (on a log axis) not positive, data wider
/// than a double can measure, a curve piece of degree beyond
/// kMaxPlottedCurveDegree, a curve that cannot be flattened (named by its
/// CurveItem::source).
Expected<Scene> layout(const Figure& figure, Progress progress = {});

}  // namespace casteljau::render

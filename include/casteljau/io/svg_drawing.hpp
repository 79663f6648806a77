#pragma once
// SVG drawings (SVG 1.1 and SVG 2 documents) read into curves: every path
// and basic shape (rect with rx/ry, circle, ellipse, line, polyline,
// polygon), through groups, nested <svg> viewports and <use> references,
// each subpath one curve placed in the root's user space by the transforms
// on its element and every ancestor (the six transform functions), then
// turned upright into the models' frame (y up, docs/formats.md "The frame"):
// y = bottom - y_file, bottom the page's lower edge (the root viewBox's
// min-y + height, else the root's height, else 0), x as in the file. Arcs and the corners of rounded rects, circles and ellipses
// are exact rational quadratic pieces (io/svg_path.hpp). The XML is parsed by
// pugixml (Debian's libpugixml-dev); the geometry is casteljau's.
//
// What draws but is not geometry is left out and listed (SvgDrawing::skipped:
// text, images, foreignObject, clip-path and mask attributes, which are not
// applied); what only other elements use (defs, symbol, clipPath, mask,
// marker, pattern, gradients, filters) is not drawn, as in SVG; display:none
// hides an element and its children, visibility:hidden an element (children
// may set it back); a <switch> draws its first child. CSS style sheets are not applied; the style attribute is, for the
// properties read here.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/io/drawing_units.hpp"

namespace casteljau {

/// SVG's fill-rule: which points a closed path encloses.
enum class FillRule { nonzero, evenodd };

/// One subpath of a drawing with what a writer can keep of its element.
struct SvgCurve {
  PiecewiseBezierCurve curve;  ///< in R^2, in the drawing's units, piece i on [i, i+1]
  bool closed = false;         ///< ended by a closepath (the shapes: rect, circle, ellipse, polygon)
  std::string element;         ///< the element that draws it: "path", "rect", "circle", ...
  std::string id;              ///< the element's id, "" when it has none
  std::size_t line = 0;        ///< the line of the file where the element starts (1-based)
  FillRule fill_rule = FillRule::nonzero;  ///< fill-rule, inherited as CSS inherits it
  /// stroke-width (inherited, default 1) in the drawing's units: scaled by
  /// the square root of the transforms' area scale, exact for similarities.
  double stroke_width = 1.0;
};

/// What a drawing draws, and what it could not.
struct SvgDrawing {
  std::vector<SvgCurve> curves;  ///< in document order
  DrawingUnits units = DrawingUnits::user;
  /// The page's lower edge in the root's user units, y down as in the file
  /// (the root viewBox's min-y + height, else the root's height, else 0): the
  /// models' y = 0. A point (x, y) of the curves is (x, page_bottom - y) in the
  /// file (DrawingUnits::user).
  double page_bottom = 0.0;
  /// Errors inside elements, each "line 12, <path id='p'>: path data,
  /// character 5 ('x'): ...". SVG's rule: path data is drawn up to its first
  /// error, an element whose attributes are in error is not drawn.
  std::vector<Error> problems;
  /// Elements that draw something this reader leaves out: "line 7: <text>
  /// (text is not read: convert it to paths)".
  std::vector<std::string> skipped;
};

/// Reads an SVG document. `source` names it in errors ("drawing.svg, line 3,
/// column 5: ..." for XML that is not well-formed). The document's errors:
/// not XML; a root that is not <svg>; more than tolerances::kMaxControlPoints
/// control points, elements nested deeper than tolerances::kMaxSvgDepth
/// (<use> references counted), more than tolerances::kMaxSvgElements elements
/// to draw (<use> instances counted); with DrawingUnits::millimetres, a root whose
/// width or height is missing or not an absolute length (mm, cm, in, pt, pc,
/// px or a number: 96 px to the inch, CSS's).
/// Lengths in attributes take those units too, and % of the viewport; em and
/// ex are problems (they depend on fonts).
Expected<SvgDrawing> parse_svg_drawing(std::string_view text, const std::string& source,
                                       DrawingUnits units = DrawingUnits::user);

/// Reads and parses an SVG file (errors name the file as given).
Expected<SvgDrawing> read_svg_drawing(const std::filesystem::path& path, DrawingUnits units = DrawingUnits::user);

}  // namespace casteljau

#pragma once
// Plane curves written as an SVG drawing: one <path> per element of the
// drawing they came from (the subpaths of one element together), or per
// curve. SVG holds lines, quadratics and cubics only: polynomial pieces of
// degree <= 3 are written exactly (numbers in shortest round-trip form, so
// read_svg_drawing gives the same doubles back, for drawings above y = 0); higher degrees and rational
// pieces (arcs, circles, NURBS) are replaced by cubics within a tolerance
// (ops/cubic_approximation.hpp), which the file states in a comment.

#include <cstddef>
#include <span>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/svg_drawing.hpp"

namespace casteljau {

/// The document and what writing it changed.
struct SvgText {
  std::string text;
  std::size_t approximated_pieces = 0;  ///< Bézier pieces replaced by cubics
  std::size_t cubics = 0;               ///< the cubics that replaced them
  double deviation_bound = 0.0;         ///< certified distance of those cubics from the pieces
};

/// Path data of one curve: "M x y" then L, Q or C per piece (absolute
/// coordinates in SVG's user space, y down: a model point (x, y) is written
/// x -y, exactly), a new M where a piece does not start where the previous one
/// ended, and Z when `closed` (the closing segment then has length zero).
/// The curve must be polynomial of degree <= 3 in R^2 (as approximate_by_cubics
/// returns it); a degree-0 piece is a zero-length line.
std::string svg_path_data(const PiecewiseBezierCurve& curve, bool closed);

/// An SVG 1.1 document, upright (models are y up, SVG y down): viewBox the
/// curves' tight bounding box (ops/bounds) grown by half the widest stroke,
/// its bottom edge at y = 0 when no curve goes below it (so that
/// read_svg_drawing, which measures y up from that edge, returns the same
/// doubles; a stroke along y = 0 shows half its width), else under the
/// lowest stroke, width and height the same numbers (user units are px), one <path> per run of consecutive curves from one element
/// (same element, id and line: how read_svg_drawing splits a path into its
/// subpaths), with its id, fill="none", stroke="black", its stroke-width and,
/// for evenodd, its fill-rule. Pieces that are not polynomial of degree <= 3
/// become cubics within `tolerance` (approximate_by_cubics). Errors: a curve
/// not in R^2 ("curve 3 lives in R^3, SVG drawings are plane"), and
/// approximate_by_cubics' own, naming the curve.
Expected<SvgText> write_svg_drawing(std::span<const SvgCurve> curves, Tolerance tolerance);

}  // namespace casteljau

#pragma once
// SVG path data (the `d` attribute of <path>): the whole grammar of SVG 1.1
// §8.3 and SVG 2 §9.3 (M L H V C S Q T A Z, absolute and relative, implicit
// repeats, numbers such as `1.5.5`, `-1e2` and `.5`, arc flags written
// without separators) read into Bézier pieces, exactly:
//   L H V and the closing line of Z   degree 1
//   Q T                               degree 2
//   C S                               degree 3
//   A                                 1 to 4 rational quadratic pieces
// An elliptical arc is the affine image of a circular arc, and a rational
// curve's affine image is the curve of the mapped control points (The NURBS
// Book §4.1), so the arc is exact: nurbs/conics.hpp's make_arc on the unit
// circle, mapped by the ellipse's radii, rotation and centre, with SVG's
// endpoint-to-centre conversion and radius correction (SVG 2 implementation
// notes B.2.4 and B.2.5). Cubics instead would approximate it; a reader that
// needs them can convert the rational pieces within its own tolerance.
//
// Errors follow SVG's rule: what comes before the first error is drawn, the
// command holding the error and everything after it is not, and the error is
// reported (SvgPathData::error). Subpaths that draw nothing (a lone moveto)
// are left out.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// One subpath: its segments, in order, as Bézier pieces in R^2 (piece i on
/// [i, i+1] of the curve's domain), and whether a closepath (Z) ended it, in
/// which case its last piece ends where its first begins.
struct SvgSubpath {
  PiecewiseBezierCurve curve;
  bool closed = false;
};

/// What path data draws: every subpath before the first error, the one in
/// progress cut before the segment that holds the error, and that error
/// ("path data, character 12 ('x'): expected a number, 'L' takes x y").
struct SvgPathData {
  std::vector<SvgSubpath> subpaths;
  std::optional<Error> error;
};

/// Reads SVG path data (SVG 1.1 §8.3.9's grammar, SVG 2 §9.3.9's error
/// handling). Numbers beyond tolerances::kMaxCoordinate, and not finite ones
/// (1e999), are errors like a syntax error. O(length of the data).
SvgPathData read_svg_path(std::string_view data);

}  // namespace casteljau

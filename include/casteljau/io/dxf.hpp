#pragma once
// DXF drawings (ASCII, R12 to current) read into curves, and curves written
// as DXF SPLINE entities (arc splines as LWPOLYLINE entities with bulges).
// The curve entities are read exactly:
//   LINE                                  a Bézier curve of degree 1
//   ARC, CIRCLE, ELLIPSE (and its arcs)   rational quadratic B-splines (nurbs/conics.hpp's
//                                         unit arcs mapped into the entity's plane)
//   LWPOLYLINE, POLYLINE (2D and 3D)      piecewise Bézier curves: a line per segment,
//                                         a rational arc per segment with a bulge
//   SPLINE with control points            the B-spline or NURBS curve itself (its knots,
//                                         weights, closed and periodic flags)
//   SPLINE with fit points only           the cubic through them (chord-length parameters,
//                                         the end tangents when given, else not-a-knot)
// Points in an entity's object coordinate system (ARC, CIRCLE, LWPOLYLINE, 2D
// POLYLINE: their extrusion direction) are mapped to world coordinates by
// DXF's arbitrary axis algorithm. A drawing whose every point has z = 0 is
// read in the plane (curves in R^2), any other in R^3. Other entities
// (TEXT, INSERT of blocks, HATCH, DIMENSION, ...) are listed as skipped.

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/ops/arc_spline.hpp"

namespace casteljau {

/// One curve entity of a drawing, with where it came from.
struct DxfCurve {
  Model curve;           ///< a curve model: bezier, piecewise_bezier or bspline
  std::string entity;    ///< "LINE", "SPLINE", ...
  std::string handle;    ///< group 5, "" when the file has none
  std::string layer;     ///< group 8
  std::size_t line = 0;  ///< the line of the file where the entity starts (1-based)
};

/// What a drawing draws, and what it could not.
struct DxfDrawing {
  std::vector<DxfCurve> curves;  ///< in file order
  int insunits = 0;              ///< $INSUNITS of the header (0 unitless, 1 in, 4 mm, ...)
  /// Errors inside entities, each "drawing.dxf, line 120, SPLINE (handle 2A): ...";
  /// the entity in error is not drawn.
  std::vector<Error> problems;
  /// Entities that draw something this reader leaves out: "line 300: TEXT".
  std::vector<std::string> skipped;
};

/// Reads the ENTITIES section of an ASCII DXF file (group code and value on
/// alternate lines; the HEADER's $INSUNITS is kept). Errors of the file
/// itself, naming the line: a group code that is not a whole number, a value
/// that is not a number where one is needed, a file that ends inside a
/// section or before EOF, binary DXF; more than tolerances::kMaxControlPoints
/// control points. Entity errors are problems (a SPLINE whose counts disagree
/// with its knots and points, decreasing knots, weights <= 0, a zero radius
/// or axis).
Expected<DxfDrawing> parse_dxf_drawing(std::string_view text, const std::string& source);

/// Millimetres per drawing unit of DXF's $INSUNITS code (AutoCAD's DXF
/// reference, HEADER section: 1 in, 2 ft, 3 mi, 4 mm, 5 cm, 6 m, 7 km,
/// 8 microinches, 9 mils, 10 yd, 11 angstroms, 12 nm, 13 microns, 14 dm,
/// 15 dam, 16 hm, 17 Gm, 18 au, 19 light years, 20 parsecs); 0 for 0
/// (unitless) and codes DXF does not define.
double dxf_unit_millimetres(int insunits);

/// The name of a $INSUNITS unit in the plural ("inches", "millimetres"), or
/// "unit code N" for the others.
std::string dxf_unit_name(int insunits);

/// Reads and parses a DXF file (errors name the file as given).
Expected<DxfDrawing> read_dxf_drawing(const std::filesystem::path& path);

/// A DXF R2000 (AC1015) document of the curves, each an exact SPLINE entity
/// (its B-spline form: to_bspline, knots and weights as they are, rational
/// when the curve is): the HEADER ($ACADVER, $HANDSEED, $INSUNITS
/// `insunits`), the CLASSES, TABLES (VPORT, LTYPE, LAYER 0, STYLE, VIEW, UCS,
/// APPID, DIMSTYLE, BLOCK_RECORD), BLOCKS and OBJECTS sections a reader
/// expects, numbers in shortest round-trip form (so reading the file gives
/// the same doubles). Errors: a surface or a curve outside R^2 and R^3
/// ("curve 2 lives in R^4, DXF holds plane and space curves"), and those of
/// to_bspline (pieces that do not meet).
Expected<std::string> write_dxf_drawing(std::span<const Model> curves, int insunits = 0);

/// The same document holding arc splines (ops/arc_spline.hpp's fit_arcs),
/// each one LWPOLYLINE entity in the plane z = 0: a vertex (10, 20) at each
/// segment's start with its bulge (42, omitted for a line: DXF's bulge is
/// ArcSegment's, tan(sweep / 4), positive counterclockwise), then the last
/// end, or, when the last end is the first start bit for bit, flag 70 = 1
/// (closed) and no repeated vertex. Read back (read_dxf_drawing), each is
/// the arc spline exactly: lines and rational arcs. Errors: a spline without
/// segments, a number that is not finite.
Expected<std::string> write_dxf_arc_polylines(std::span<const ArcSpline> splines, int insunits = 0);

}  // namespace casteljau

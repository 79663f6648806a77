#pragma once
// G-code: toolpaths written as RS-274/NGC programs for milling machines,
// routers and lasers (T. Kramer, F. Proctor, E. Messina, "The NIST RS274/NGC
// Interpreter - Version 3", NISTIR 6556, 2000; the LinuxCNC and GRBL 1.1
// G-code references for their dialects). A toolpath is a list of contours,
// each a chain of line segments (G1) and circular arcs (G2 clockwise, G3
// counterclockwise, centre in the IJK form: I J = centre - start), as
// ops/arc_spline.hpp's fit_arcs or ops/flatten.hpp's flatten make them.
// What is written, the ordering, the passes and the radius rule:
// docs/formats.md, "G-code".

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <string>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/tolerance.hpp"
#include "casteljau/ops/arc_spline.hpp"
#include "casteljau/ops/flatten.hpp"

namespace casteljau {

/// One contour: what the tool follows without lifting, segment i starting
/// where segment i - 1 ends; bulge 0 is a line (G1), any other an arc (G2/G3).
using GcodeContour = std::vector<ArcSegment>;

/// What a program cuts, and what it was made from (for its header).
struct Toolpath {
  std::vector<GcodeContour> contours;  ///< in the input's order; the writer orders them
  std::vector<std::string> sources;    ///< the input files' names, in the header
  /// The program's whole budget: how far its path may be from the curves,
  /// rounding included (the header states it). The contours must lie within
  /// tolerance - gcode_rounding_allowance(decimals) of their curves
  /// (contour_of(CurveView, ...) fits them so). A contour whose ends are
  /// this close is closed (its start may be rotated).
  Tolerance tolerance;
};

/// The contour of an arc spline: its arcs and segments as they are.
GcodeContour contour_of(const ArcSpline& spline);

/// The contour of a plane polyline (flatten's): a line segment per edge,
/// G1 moves only (for controllers without arcs). Error: a polyline that is
/// not plane ("G-code contours are plane, this polyline lives in R^3").
Expected<GcodeContour> contour_of(const Polyline& polyline);

/// Units of a program: G21 (mm) or G20 (inch). Every length of the options
/// and of the toolpath is in this unit; nothing is converted.
enum class GcodeUnits { millimetres, inches };

/// How far rounding to `decimals` digits may move a program's path:
/// tolerances::kGcodeRoundingUnits units of the last decimal (5e-4 at 4).
double gcode_rounding_allowance(int decimals);

/// The digits a program within `tolerance` carries: `requested` when not 0
/// (error: outside [kGcodeFewestDecimals, kGcodeMostDecimals], or rounding
/// by as much as the tolerance itself), else the fewest, at least the unit's
/// default (4 in mm, 5 in inches), whose rounding allowance is at most
/// kGcodeRoundingShare of the tolerance (error: a tolerance finer than 8
/// decimals can carry, or not > 0).
Expected<int> gcode_decimals(Tolerance tolerance, GcodeUnits units, int requested = 0);

/// Lines (G1) only, or arcs (G2/G3) and lines.
enum class GcodeMotion { arcs, lines };

/// The contour of a plane curve for a program of `decimals` digits within
/// `tolerance`: fit_arcs (ops/arc_spline.hpp) or, for GcodeMotion::lines,
/// flatten (ops/flatten.hpp), within tolerance - gcode_rounding_allowance
/// (decimals). Errors: a curve not in the plane, or fit_arcs' and flatten's.
Expected<GcodeContour> contour_of(CurveView curve, Tolerance tolerance, int decimals, GcodeMotion motion);

/// The controller written for. Both get G0-G3 (IJK arcs), G17, G20/G21,
/// G90, G94 and M2 only. grbl: nothing else (no G64, no G5 cubics, no G91.1,
/// which GRBL before 1.1 refuses). linuxcnc: also G91.1 (incremental arc
/// centres, whatever the machine's start-up code says) and G64 P (path
/// blending within the program's rounding, no Q: arcs stay arcs).
enum class GcodeDialect { grbl, linuxcnc };

/// Where the drawing sits on the machine: at its own coordinates, or moved
/// so that the lower-left corner (or the centre) of its box, arcs' extreme
/// points included, is at the machine's zero X0 Y0.
enum class GcodeOrigin { drawing, lower_left, centre };

/// How a toolpath is cut. The work surface is Z = 0; rapid moves run at
/// `safe_height` above it, cuts at `depth` below it in passes of at most
/// `step_down` (0: one pass at the depth).
struct GcodeOptions {
  GcodeUnits units = GcodeUnits::millimetres;
  GcodeDialect dialect = GcodeDialect::grbl;
  double safe_height = tolerances::kGcodeDefaultSafeHeightMillimetres;  ///< Z of every rapid move, > 0
  double depth = tolerances::kGcodeDefaultDepthMillimetres;  ///< the final cut at Z = -depth, depth > 0
  double step_down = 0.0;  ///< largest step down per pass, >= 0 (0: the whole depth at once)
  double feed = tolerances::kGcodeDefaultFeedMillimetres;    ///< cutting feed, units per minute, > 0
  double plunge_feed = tolerances::kGcodeDefaultPlungeFeedMillimetres;  ///< feed of moves down, > 0
  /// Digits after the point of every number, in [kGcodeFewestDecimals,
  /// kGcodeMostDecimals]; 0 asks for the unit's default (4 in mm, 5 in inches).
  int decimals = 0;
  GcodeOrigin origin = GcodeOrigin::drawing;  ///< where the drawing's box goes (a translation)
};

/// The options with the defaults of the unit (tolerance.hpp, "G-code"):
/// in mm safe height 5, depth 1, feeds 600 and 200 per minute; in inches
/// 0.2, 0.04, 24 and 8.
GcodeOptions default_gcode_options(GcodeUnits units);

/// A written program and what it holds.
struct GcodeProgram {
  std::string text;  ///< the program, ASCII, one block a line, "\n" line ends
  std::size_t arcs = 0;   ///< G2/G3 moves
  std::size_t lines = 0;  ///< G1 moves in the plane (plunges not counted)
  /// Of the lines, the G1 chords written in place of arcs (or of halves of
  /// arcs) that no centre on the grid writes well (see write_gcode).
  std::size_t arcs_as_lines = 0;
  std::size_t contours = 0;  ///< contours cut (empty ones are left out)
  int passes = 1;            ///< depth passes of every contour
  double rapid_length = 0.0;  ///< total length of the rapid moves in the plane
  /// The same, were the contours cut in the input's order as they are given
  /// (the ordering's gain: the header states both).
  double rapid_length_unordered = 0.0;
  double cut_length = 0.0;     ///< length of the cuts in the plane, every pass
  double plunge_length = 0.0;  ///< length of the moves down at the plunge feed
  int decimals = 0;         ///< digits after the point of every number
};

/// The program that cuts the toolpath (NISTIR 6556 syntax: one block a
/// line, comments in parentheses):
/// - a header of comments (ASCII, no nested parentheses): casteljau and its
///   version, the sources, the tolerance, units, depth, passes and the counts;
/// - set-up "G21 G90 G17 G94" (G20 in inches), the dialect's extra codes;
/// - each contour: G0 up to the safe height, G0 to its entry point, G1 down
///   at the plunge feed to each pass depth in turn, the contour at the
///   cutting feed (an open contour runs back and forth, pass after pass; a
///   closed one round again); then G0 up and M2.
/// Ordering (fewer rapid moves): greedy nearest neighbour from the origin,
/// each contour entered where the tool is nearest: a closed contour (ends
/// within toolpath.tolerance) at any of its joints, rotated to start there;
/// an open one at either end, reversed when entered at its end.
/// Numbers: gcode_decimals(toolpath.tolerance, options.units,
/// options.decimals) digits, no exponent, no "-0". Arcs in the IJK form
/// (never R), I J from the written start to a centre on the decimal grid,
/// within kGcodeCentreSearchSteps of the true one, such that the start and
/// end radii agree within tolerances::kGcodeRadiusAgreement (the nearest
/// with kGcodeRadiusMargin to spare), and the path moves by at most
/// gcode_rounding_allowance: the centre's shift plus the larger gap between
/// a written radius and the true one, and the middle's shift, within
/// kGcodeRoundingUnits units of the last decimal. Where no centre does
/// (nearly straight arcs, whose radii a centre barely changes), where the
/// ends coincide once rounded (a G2/G3 would be a whole circle) or the
/// radius passes kGcodeFlatArcRadius x the drawing's size, the arc is
/// halved until each part passes or sags less than kGcodeChordSagittaUnits
/// from its chord, then written as that G1 chord. No whole circle is written.
/// Errors (the option named): a depth, safe height, step down or feed not
/// finite or out of range, decimals gcode_decimals refuses, a
/// coordinate beyond kGcodeLargestCoordinate, more than kGcodeMostPasses
/// passes or kGcodeMostMoves moves.
Expected<GcodeProgram> write_gcode(const Toolpath& toolpath, const GcodeOptions& options);

/// One move of a program as a controller reads it (lengths in the program's unit).
struct GcodeMove {
  enum class Kind { rapid, line, clockwise_arc, counterclockwise_arc };
  Kind kind = Kind::rapid;
  std::array<double, 3> from{};  ///< X Y Z before the move (the machine starts at 0 0 0)
  std::array<double, 3> to{};    ///< X Y Z after it
  Vec2 centre{};                 ///< an arc's centre (from + I J)
  std::size_t line = 0;          ///< the program's line, from 1
};

/// The motion of a program, in its unit.
struct GcodeReading {
  GcodeUnits units = GcodeUnits::millimetres;
  std::vector<GcodeMove> moves;
};

/// Reads the motion of a program in the subset casteljau writes and most
/// CAM programs for 2.5D milling use (NISTIR 6556 syntax): comments in
/// parentheses or after ';', N words, G0 G1 G2 G3 (modal, IJ centres
/// relative to the start: G91.1), G17, G20, G21, G90, G91.1, G94, G64
/// (P, Q) and G61, F S T words and the spindle and coolant M codes (M3 M4
/// M5 M7 M8 M9) read and ignored, M2 or M30 ending the program. Errors
/// ("line 12: ..."): any other G or M code (G91 incremental coordinates,
/// G18/G19 other planes, G90.1, canned cycles), an arc in the R form, a
/// word without a number or with one that is not finite, a change of
/// units after the first move, more than tolerances::kGcodeMostMoves moves.
Expected<GcodeReading> read_gcode(std::string_view text);

}  // namespace casteljau

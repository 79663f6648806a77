#pragma once
// The io layer's own tolerances and limits: files read and written
// (core/tolerance.hpp says why each layer keeps its tolerances beside its code).

#include <cstddef>
#include <cstdint>

namespace casteljau::tolerances {

// --- Size limits for input files ---------------------------------------------

/// Largest input file read, in bytes (1 GiB). Every text format casteljau
/// reads is parsed in memory, and a model or point set of the largest
/// accepted size takes well under 1 GiB of text; anything larger is refused
/// before a byte is read.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;

/// Most symbolic links followed from an output path to the file it names
/// (write_file_atomically replaces the link's target, not the link). 40 is
/// Linux's own limit (MAXSYMLINKS): past it the kernel answers ELOOP, and so
/// do we, for a link chain or a loop. A count of links, no unit.
inline constexpr int kMaxSymbolicLinks = 40;

/// Deepest nesting of elements in an SVG drawing, <use> references counted
/// as a level each (the reader walks the tree recursively). Hand-made and
/// exported drawings nest a few tens of groups; 256 keeps the walk's stack
/// small on every thread and still reads any drawing a person made.
inline constexpr int kMaxSvgDepth = 256;

/// Most elements one SVG drawing may draw, each instance of a <use> counted
/// (a chain of <use> that doubles at each level would otherwise expand to
/// 2^40 elements from a file of a few kilobytes). A 10 MB drawing holds at
/// most a few hundred thousand elements; the walk visits 10^6 in well under
/// a second.
inline constexpr std::size_t kMaxSvgElements = 1'000'000;

/// Most parameters one `eval` may evaluate (--samples N, and all --at,
/// --params and sample parameters of all models together). The CSV output is
/// built in memory before it is written (nothing half-written), about 70 bytes
/// per 2D point: 10^7 points stay under 1 GB.
inline constexpr std::size_t kMaxEvaluationParameters = 10'000'000;

// --- Files for other programs (io/svg_writer, io/cad_exchange) ---------------

/// Default distance of the cubics `convert --to svg` puts in place of pieces
/// SVG cannot hold (rational, degree > 3), relative to the drawing's size (the
/// diagonal of its control points' box): far below what a screen or a plotter
/// resolves (1e-6 of a metre-wide drawing is a micrometre), while a circle
/// still needs only tens of cubics.
inline constexpr double kDefaultSvgCubicRelativeTolerance = 1e-6;

/// The resolution an IGES file states (global parameter 19, "minimum
/// user-intended resolution") and the uncertainty of a STEP file's context,
/// relative to the model's size: the numbers are written exactly (shortest
/// round-trip form), so the file claims the accuracy they keep; above double
/// rounding (1e-16 of the size) and below every CAD tolerance (OpenCASCADE's
/// confusion distance is 1e-7).
inline constexpr double kExchangeResolutionRelative = 1e-12;

// --- G-code (io/gcode.hpp) ------------------------------------------------------
// Lengths are in the program's unit (mm for G21, inch for G20).

/// Fewest and most decimals of a G-code number. 4 is what LinuxCNC and GRBL
/// documents use for mm (0.1 micrometre) and what an arc's radius check
/// needs (kGcodeRadiusAgreement); 8 keeps every coordinate up to
/// kGcodeLargestCoordinate within the 15 significant digits of a double.
inline constexpr int kGcodeFewestDecimals = 4;
inline constexpr int kGcodeMostDecimals = 8;
/// The decimals written unless asked: 4 in mm (0.1 micrometre), 5 in inches
/// (0.25 micrometre), finer than any machine moves.
inline constexpr int kGcodeDefaultDecimalsMillimetres = 4;
inline constexpr int kGcodeDefaultDecimalsInches = 5;

/// The start and end radii of an arc, measured from its centre as written
/// (after rounding to the decimals), agree within this, in the program's
/// unit: 50 times stricter than LinuxCNC's check (0.005 mm and 0.1 %) and
/// GRBL's (error 33: 0.005 mm and 0.1 %), 20 times the older NIST 0.002 mm,
/// so a program accepted here is accepted by both, in mm and in inches.
inline constexpr double kGcodeRadiusAgreement = 1e-4;
/// Of the centres on the grid that meet kGcodeRadiusAgreement, the nearest
/// to the true centre among those whose radii agree within this fraction of
/// it is written (else the one whose radii agree best): a margin for
/// controllers that compute in single precision (GRBL's float: about 1e-5
/// at 100 mm) without moving the arc further than needed. Dimensionless.
inline constexpr double kGcodeRadiusMargin = 0.5;

/// Grid steps (units of the last decimal) that a written arc centre may move
/// from the rounded true centre, in each direction, to meet
/// kGcodeRadiusAgreement: one step moves the arc by less than 1.5 units of
/// the last decimal, the order of the rounding of its end points.
inline constexpr int kGcodeCentreSearchSteps = 1;

/// How far the rounding of a program's numbers may move its path, in units
/// of the last decimal: an end point moves by up to 0.71 units, a chord
/// written for an arc sags by up to kGcodeChordSagittaUnits more, and an
/// arc is written only when the distance of its written centre from the
/// true one plus the larger difference of its written radii from the true
/// radius is at most this (which bounds the distance of every point the
/// controller moves along from the true circle) and its middle is within
/// this of the true middle. A centre one grid step from the rounded true
/// one and ends rounded both ways stay within about 4 units. The tolerance
/// of a program is its whole budget: the contours are fitted within the
/// tolerance minus this allowance (gcode_rounding_allowance).
inline constexpr double kGcodeRoundingUnits = 5.0;

/// Unless the decimals are asked for, a program carries the fewest (at
/// least the unit's default) whose rounding allowance is at most this share
/// of the tolerance: the fit keeps nine tenths of the budget. Dimensionless.
inline constexpr double kGcodeRoundingShare = 0.1;

/// The smallest radius of an arc written as G2/G3, in inches (in mm: times
/// 25.4, 0.00254 mm): twice what LinuxCNC refuses as a "zero-radius arc"
/// (RADIUS_TOLERANCE_INCH, 5e-5 in, 0.00127 mm). A smaller arc is halved
/// into chords like any arc no centre writes well; its sagitta is at most
/// twice its radius, so three halvings bring it within the rounding.
inline constexpr double kGcodeSmallestArcRadiusInches = 1e-4;

/// An arc whose radius exceeds this multiple of the drawing's size (the
/// diagonal of its box) is written as lines: its centre lies far outside the
/// work area, where controllers refuse it or lose precision, and its sagitta
/// is then below 1/80,000 of the drawing. Dimensionless.
inline constexpr double kGcodeFlatArcRadius = 1e4;

/// An arc written as a single G1 chord (its radius check failed after
/// rounding, or it is flat) when its sagitta is at most this fraction of the
/// last decimal's unit: no further from the arc than the rounding of the
/// points themselves. A larger one is halved and each half tried again, at
/// most kGcodeMostArcHalvings times (each halving divides the sagitta by 4).
inline constexpr double kGcodeChordSagittaUnits = 0.5;
inline constexpr int kGcodeMostArcHalvings = 40;

/// Largest |coordinate| (and safe height, depth) of a program, in its unit:
/// a kilometre in mm, beyond any machine (a larger number is a unit mistake),
/// and small enough that kGcodeMostDecimals fit in a double.
inline constexpr double kGcodeLargestCoordinate = 1e6;

/// The cutting order's 2-opt (io/gcode_order.hpp) tries the moves that join
/// a contour to one of this many nearest contours, a cost linear in the
/// contours where trying every pair was 2 million tries a sweep at 2000
/// contours (and was skipped beyond). On the 300 squares of the G-code
/// tests its rapid moves come to 1,309 where every-pair 2-opt gave 1,324
/// (both stop at a local optimum), 1,271 once each square's joint is chosen
/// again.
inline constexpr std::size_t kGcodeTwoOptNeighbours = 10;

/// Most depth passes of one program, and most moves (lines of motion) in all:
/// beyond these the request (a step down tiny against the depth, a tolerance
/// tiny against the drawing) is refused rather than writing gigabytes.
inline constexpr int kGcodeMostPasses = 10000;
inline constexpr long kGcodeMostMoves = 1L << 24;

/// The passes are ceil(depth / step down) counted with this relative slack,
/// so that a depth of 0.3 in steps of 0.1 (2.9999999999999996 in doubles)
/// takes 3 passes, not 4.
inline constexpr double kGcodePassSlack = 1e-9;

/// Defaults of a program in mm (in inches: the next four): the
/// safe height of rapid moves above the work (Z = 0), the depth of the cut
/// below it, the cutting feed and the plunge feed, in units per minute:
/// a small router engraving wood or plastic.
inline constexpr double kGcodeDefaultSafeHeightMillimetres = 5.0;
inline constexpr double kGcodeDefaultDepthMillimetres = 1.0;
inline constexpr double kGcodeDefaultFeedMillimetres = 600.0;
inline constexpr double kGcodeDefaultPlungeFeedMillimetres = 200.0;
/// The same in inches, round numbers near the mm ones (0.2 in = 5.08 mm).
inline constexpr double kGcodeDefaultSafeHeightInches = 0.2;
inline constexpr double kGcodeDefaultDepthInches = 0.04;
inline constexpr double kGcodeDefaultFeedInches = 24.0;
inline constexpr double kGcodeDefaultPlungeFeedInches = 8.0;

}  // namespace casteljau::tolerances

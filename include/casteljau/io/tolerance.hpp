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

}  // namespace casteljau::tolerances

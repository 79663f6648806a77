#pragma once
// Every epsilon of casteljau lives here, with its unit and its reason
// (style rule 6). Exact operations take no tolerance; approximate ones
// require a Tolerance from the caller. Comparisons are relative to the data's
// scale (scale_of), never numeric_limits::epsilon() used as an absolute.

#include <cstddef>
#include <cstdint>

namespace casteljau {

/// A distance in model units that an approximate operation must stay within
/// (flattening, degree reduction checks, later fitting and tessellation).
/// Must be finite and > 0; operations assert it.
struct Tolerance {
  double distance = 0.0;
};

namespace tolerances {

/// Relative size, against the control points' scale, below which a derivative
/// is treated as vanishing when looking for a tangent direction. A derivative
/// of a curve whose control points are O(s) is computed with an absolute error
/// of about n * 1e-16 * s per order; 1e-12 sits well above that noise for
/// degrees up to a few hundred and well below any real tangent.
inline constexpr double kVanishingDerivative = 1e-12;

/// Largest recursion depth accepted by subdivide_recursive: 2^24 + 1 points
/// (about 400 MB in 3D) is already far beyond any drawing need; deeper is
/// refused as a "huge size" rather than exhausting memory.
inline constexpr int kMaxSubdivisionDepth = 24;

/// Largest number of segments one flattening may produce. A request that
/// would need more (a tolerance tiny against the curve's size) is refused.
inline constexpr long kMaxFlattenSegments = 1L << 24;

/// Degree up to which kernels keep their de Casteljau triangle on the stack.
/// Beyond it, a batch call allocates one workspace for the whole call.
inline constexpr int kMaxStackDegree = 255;

/// Relative rounding unit used when a bound has to absorb floating-point
/// error: a few ulps of double (2^-52 = 2.2e-16) for the handful of
/// operations behind one control point of a subdivided curve.
inline constexpr double kRoundingSlack = 8.0 * 2.220446049250313e-16;

/// Rounding allowance of flattening, relative to the curve's scale (largest
/// absolute control-point coordinate), times max(1, n/4) and the weight ratio
/// max w / min w of a rational curve. flatten() certifies each segment against
/// tolerance minus this amount: it absorbs the rounding of the vertices
/// (de Casteljau, about n ulps of the scale each) and of the deviation bound
/// itself (a few dozen operations on O(scale) numbers), both far below
/// 1e-13 x scale. Unit: fraction of the scale.
inline constexpr double kFlattenRoundingAllowance = 1e-13;

/// Smallest flattening tolerance accepted, as a multiple of that allowance:
/// below 10 x allowance (about 1e-12 x scale) double precision cannot
/// certify the distance, and flatten() refuses the request instead of
/// subdividing down to rounding noise.
inline constexpr double kFlattenSmallestToleranceFactor = 10.0;


// --- Size limits for untrusted input -----------------------------------------
// "Huge sizes" are refused with a clear error instead of exhausting memory or
// running for hours.

/// Highest degree of one Bézier curve accepted from outside (BezierCurve::make).
/// Evaluation costs O(n^2) per point: at n = 10^4 that is already 10^8
/// operations per point (tens of milliseconds), and no design needs more: long
/// point sets are interpolated or split into pieces, not made one polynomial.
inline constexpr int kMaxBezierDegree = 10'000;

/// Most control points in one model (all pieces together), and most points
/// in one CSV point set. 10^7 points in 3D are 240 MB as doubles and about
/// 1 GB as parsed JSON: beyond any drawing or machining need, still inside
/// memory.
inline constexpr std::size_t kMaxControlPoints = 10'000'000;

/// Most values in one input file: JSON values (numbers, arrays, objects,
/// strings...) of a model JSON text, numbers of a CSV file. Exactly what
/// kMaxControlPoints points in 3D with weights need in JSON (10^7 point
/// arrays + 3*10^7 coordinates + 10^7 weights). A parsed JSON document takes
/// about 16 bytes per value and a CSV table 8 bytes per number, so this caps
/// their memory near 1 GB whatever the shape of the file.
inline constexpr std::size_t kMaxInputValues = 50'000'000;

/// Most parameters one `eval` may evaluate (--samples N, and all --at,
/// --params and sample parameters of all models together). The CSV output is
/// built in memory before it is written (nothing half-written), about 70 bytes
/// per 2D point: 10^7 points stay under 1 GB.
inline constexpr std::size_t kMaxEvaluationParameters = 10'000'000;

/// Highest derivative order the front ends accept. A polynomial curve's
/// derivatives of order > n vanish, and n!/(n-k)! overflows a double once
/// k > 170 for any n, so larger orders only make sense as zeros; rational
/// derivatives cost O(k^2) per point (NURBS Book A4.2). 1000 keeps every
/// request cheap.
inline constexpr int kMaxDerivativeOrder = 1000;

/// Largest input file read, in bytes (1 GiB). Every text format casteljau
/// reads is parsed in memory, and a model or point set of the largest
/// accepted size takes well under 1 GiB of text; anything larger is refused
/// before a byte is read.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;

}  // namespace tolerances
}  // namespace casteljau

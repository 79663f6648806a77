#pragma once
// Every epsilon of casteljau lives here, with its unit and its reason
// (style rule 6). Exact operations take no tolerance; approximate ones
// require a Tolerance from the caller. Comparisons are relative to the data's
// scale (scale_of), never numeric_limits::epsilon() used as an absolute.

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

}  // namespace tolerances
}  // namespace casteljau

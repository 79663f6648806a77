#pragma once
// Parameter values for interpolating a point set P_0..P_m: which value t_i of
// the curve's parameter each point is reached at. Every interpolation method
// takes them as an explicit span (as scipy takes x), so the same methods serve
// parametric curves (parameter_values) and functions y(x) (function_parameters).

#include <span>
#include <string_view>
#include <vector>

#include "casteljau/core/closure.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// How parameter values follow the points (Lee 1989, "Choosing nodes in
/// parametric curve interpolation"; Yuksel, Schaefer & Keyser 2011 for the
/// centripetal Catmull–Rom): steps |P_{i+1} − P_i|^e with e = 0, 1, 1/2.
enum class Parameterization { uniform, chord_length, centripetal };

/// The name used by the CLI and docs: "uniform", "chord", "centripetal".
std::string_view name_of(Parameterization kind) noexcept;

/// Reads a name ("uniform", "chord" or "chord-length", "centripetal");
/// the error lists the accepted names.
Expected<Parameterization> parameterization_from_name(std::string_view name);

/// Normalized parameter values 0 = t_0 < t_1 < ... = 1 for the points, with
/// steps proportional to |P_{i+1} − P_i|^e (The NURBS Book eq. 9.4–9.6).
/// `Closure::closed`: one more value, for the closing step from P_m back to P_0
/// (m+2 values, the last one 1); a closed set whose last point repeats the
/// first must be passed through without_closing_duplicate first.
/// Errors: fewer than 2 points; a zero step under chord_length or centripetal
/// ("points 3 and 4 coincide, chord-length parameters need distinct
/// consecutive points"); the closing step likewise. O(m d).
Expected<std::vector<double>> parameter_values(const PointArray& points, Parameterization kind,
                                               Closure closure = Closure::open);

/// The first coordinate of each point as its parameter (interpolation of a
/// function y(x) whose graph is the curve (x, y(x))): x must increase
/// strictly ("x must increase strictly: point 4 has x = 2, point 3 has x = 2")
/// and the points need at least 2 coordinates. The values are not normalized.
Expected<std::vector<double>> function_parameters(const PointArray& points);

/// The points of a closed curve without a last point that repeats the first
/// (within tolerances::kJointRelativeGap of the scale): users often close a
/// polygon by repeating its first vertex, and `--closed` adds the closing
/// segment itself. Other points are returned unchanged.
PointArray without_closing_duplicate(const PointArray& points);

}  // namespace casteljau

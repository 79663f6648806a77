#pragma once
// The C² cubic interpolant in one tridiagonal sweep (W4: 10^6 points in tens
// of milliseconds). The general path (collocation.hpp) builds a banded matrix
// with room for pivoting and solves it; for the cubic with knots at the data
// parameters every collocation row has three non-zeros, so the system is
// tridiagonal once the end rows are written in the right place, and the
// Thomas algorithm (Golub & Van Loan, Matrix Computations §4.3.6, LU without
// pivoting of a band matrix) solves it reading the points once and writing
// the control points once. Without pivoting it is stable here: the interior
// rows form a totally positive collocation matrix (de Boor & Pinkus 1977) and
// the end rows are diagonally dominant; any pivot that comes out zero or
// non-finite (bad input) makes the sweep give up, and interpolate_cubic then
// takes the general path, which finds and names the problem.
//
// Internal to src/interpolation.

#include <span>
#include <vector>

#include "casteljau/core/point_array.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"

namespace casteljau::detail {

/// The fewest points the sweeps take; smaller sets take the general path.
inline constexpr std::size_t kSweepMinimumPoints = 5;

/// Natural or clamped ends (`ends.condition`), knots t_0⁴, t_1..t_{m-1}, t_m⁴
/// (m + 7 values, the sites t_i = knots[i + 3]); the m + 3 control points
/// are written to `control` ((m + 3) d values). False when a pivot is zero or
/// not finite (then `control` holds garbage).
bool sweep_cubic_at_knots(std::span<const double> knots, const PointArray& points, const CubicEnds& ends,
                          std::span<double> control);

/// Not-a-knot ends: knots t_0⁴, t_2..t_{m-2}, t_m⁴ (m + 5 values) at the
/// sites `parameters` (m + 1 values, m + 1 >= kSweepMinimumPoints); the rows
/// of t_1 and t_{m-1} (four non-zeros each) are reduced to three by their
/// neighbours t_2 and t_{m-2} before the sweep. Writes m + 1 control points.
bool sweep_cubic_not_a_knot(std::span<const double> knots, std::span<const double> parameters,
                            const PointArray& points, std::span<double> control);

/// Periodic: the M distinct points of a closed curve on the periodic knots
/// of interpolate_cubic (M + 7 values, sites knots[3 + i]); the cyclic
/// tridiagonal system is solved by the Sherman–Morrison formula (Golub & Van
/// Loan §2.1.4) with two right-hand sides of one sweep. Writes the M + 3
/// control points Q_0..Q_{M-1}, Q_0, Q_1, Q_2.
bool sweep_cubic_periodic(std::span<const double> knots, const PointArray& points, std::span<double> control);

}  // namespace casteljau::detail

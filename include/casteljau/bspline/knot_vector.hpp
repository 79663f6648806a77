#pragma once
// Knot vectors t_0 <= t_1 <= ... <= t_{n+p+1} of a B-spline of degree p with
// n+1 control points: validation, the usual builders, multiplicities, and the
// Rhino/openNURBS convention (n+p-1 knots, the two outermost dropped).
//
// Notation: the seeds count the order k = p + 1 (seed 001: N_{i,k} has degree
// k-1); casteljau, like The NURBS Book, always counts the degree p.

#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

/// Checks the knots of a B-spline of degree p >= 0 with `control_point_count`
/// = n+1 control points (The NURBS Book §2.2, §3.2), as make() accepts them
/// from outside: exactly n+p+2 knots, each a valid knot (finite, |t| <=
/// tolerances::kMaxKnot, so the whole vector's width is finite), non-decreasing,
/// no knot of multiplicity above p+1, a non-empty domain t_p < t_{n+1}, and
/// every non-empty span t_{i+1} - t_i at least tolerances::kMinKnotSpan wide
/// (its reciprocal, times p, representable with room for the coordinates:
/// core/tolerance.hpp). Errors name the offending indices: "knot 4 (0.5) is
/// smaller than knot 3 (0.7), knots must be non-decreasing", "knots 1 and 2
/// (0 and 5e-324) are 5e-324 apart, less than the narrowest knot span 1e-100".
Status validate_knots(std::span<const double> knots, int degree, std::size_t control_point_count);

/// The structure alone, what from_trusted asserts of computed knots: the
/// count, finite, non-decreasing, multiplicities at most p+1, a non-empty
/// domain. Computed knots may go beyond validate_knots' ranges where no
/// caller's value enters (a fit's knots from its data); the operations that
/// place a caller's knot (insertion, refinement, a split, a new domain) check
/// it with check_added_knot_spans or check_span.
Status check_knot_structure(std::span<const double> knots, int degree, std::size_t control_point_count);

/// Knots an operation adds to `knots` (knot insertion, refinement, a split):
/// each value of `added` (sorted) must be equal to, or at least
/// tolerances::kMinKnotSpan from, its neighbours among the old and the added
/// knots, the rule validate_knots applies to a model's knots, so that the
/// result's derivatives stay finite. `what` names the added knots in the
/// message: "knot 1 and the knot to insert (0 and 5e-324) are 5e-324 apart,
/// less than the narrowest knot span 1e-100".
Status check_added_knot_spans(std::span<const double> knots, std::span<const double> added, const std::string& what);

/// Clamped (open) knots with uniform interior spacing over `domain`: p+1
/// copies of each end, n-p evenly spaced interior knots (The NURBS Book eq.
/// 2.13; seed 001 "0…0, 1…1"). Requires n+1 >= p+1 control points.
std::vector<double> clamped_uniform_knots(int degree, std::size_t control_point_count,
                                          Interval domain = {});

/// Uniform (cardinal) knots t_i = a + (i - p) h with the domain [t_p, t_{n+1}]
/// equal to `domain` (seed 001: the uniform B-spline; not clamped, so the
/// curve does not reach its end control points). Requires n+1 >= p+1.
std::vector<double> uniform_knots(int degree, std::size_t control_point_count, Interval domain = {});

/// Knots of a closed (periodic) uniform B-spline with `distinct_control_point_count`
/// = m distinct control points: m + 2p + 1 uniform knots whose domain is
/// `domain`; the curve's control points are P_0..P_{m-1} followed by
/// P_0..P_{p-1} again (see make_periodic in bspline_curve.hpp).
std::vector<double> periodic_knots(int degree, std::size_t distinct_control_point_count,
                                   Interval domain = {});

/// Converts the Rhino/openNURBS knot convention (n+p-1 knots: the first and
/// last knots of the full vector are omitted) to the full vector of n+p+2
/// knots by repeating the first and last knots once more, which is what
/// openNURBS does (the dropped knots do not affect the curve on its domain).
/// The result is validated. Errors as validate_knots, with indices of the
/// given (Rhino) vector.
Expected<std::vector<double>> knots_from_rhino(std::span<const double> rhino_knots, int degree,
                                               std::size_t control_point_count);

/// A distinct knot value and how many times it appears.
struct KnotMultiplicity {
  double value = 0.0;
  int multiplicity = 0;
  friend bool operator==(const KnotMultiplicity&, const KnotMultiplicity&) = default;
};

/// The distinct knot values in increasing order with their multiplicities
/// (exact comparison: knots that differ by one ulp are distinct).
std::vector<KnotMultiplicity> knot_multiplicities(std::span<const double> knots);

/// How many knots are equal to u (0 if u is not a knot).
int multiplicity_of(std::span<const double> knots, double u);

}  // namespace casteljau

#pragma once
// Collocation systems of B-spline interpolation, shared by the cubic spline,
// any-degree interpolation and the natural splines of order q: find the
// control points of a B-spline of degree p on given knots such that
//   C(s_i) = P_i at the sites s_0 < ... < s_m, and
//   C^(k)(s_0) or C^(k)(s_m) = D for each prescribed end derivative,
// one banded system whose rows come straight from the p+1 non-zero basis
// functions at each site (The NURBS Book §9.2.1 eq. 9.10, §9.2.2; de Boor,
// A Practical Guide to Splines, ch. XIII). The d coordinates are the d
// right-hand sides of one factorization. The periodic variant solves the
// cyclic system of a closed spline by the Sherman–Morrison–Woodbury formula
// around a banded core.
//
// Internal to src/interpolation.

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau::detail {

/// C^(order)(site) = value at the first (at_end = false) or last site.
/// An empty value means the zero vector (natural end conditions).
struct EndConstraint {
  bool at_end = false;
  int order = 1;
  std::span<const double> value;
};

/// Checks what every interpolation method needs of its input: `count`
/// parameters, all finite and strictly increasing, and finite coordinates.
/// `needed_points` and `method` word the error for too few points:
/// "cubic interpolation with not-a-knot ends needs at least 4 points, got 3"
/// (the wording of every interpolation method's point count).
Status check_interpolation_input(const PointArray& points, std::span<const double> parameters,
                                 std::size_t count, std::size_t needed_points, const std::string& method);

/// Where the Schoenberg–Whitney condition fails: the first basis function
/// left without a site of its own and, when sites and basis functions are
/// as many (interpolation), the site it was given and vanishes at.
struct SiteGap {
  std::size_t basis_function = 0;
  std::optional<std::size_t> site;
};

/// The Schoenberg–Whitney condition (Schoenberg & Whitney 1953; de Boor, A
/// Practical Guide to Splines, ch. XIII) for the basis functions `columns`
/// (increasing indices) of `degree` on `knots` and the increasing `sites`:
/// each column can be given its own site, in increasing order, where it does
/// not vanish. Then the collocation matrix of those columns and sites is
/// non-singular (interpolation), or the least-squares design matrix has full
/// column rank and BᵀB is positive definite (fits). Sites of weight 0 do not
/// count (`weights` empty: all 1). Each column in turn takes the first
/// remaining site where it is non-zero; the supports move right with the
/// index, so this finds sites whenever any exist. Non-zero: inside the open
/// support (U_j, U_{j+p+1}), or on its ends where basis_function says so
/// (the domain's ends closed as evaluation closes them). Nothing when the
/// condition holds. O(m + n), plus O(p²) per site on the end of a support.
std::optional<SiteGap> schoenberg_whitney_gap(std::span<const double> knots, int degree,
                                              std::span<const std::size_t> columns, std::span<const double> sites,
                                              std::span<const double> weights = {});

/// The error of a gap, one wording for every method: "parameter 3 (3) is not
/// inside the support [0, 2.75) of basis function 3: the knots and parameters
/// violate the Schoenberg–Whitney condition, <consequence>", or, with no site
/// to name, "no point [of positive weight] is left for basis function 4
/// (support [5.05, 5.25)): ...". `first_parameter` is the number of
/// sites[0] among the caller's parameters.
Error schoenberg_whitney_error(std::span<const double> knots, int degree, std::span<const double> sites,
                               const SiteGap& gap, std::size_t first_parameter, bool weighted,
                               const std::string& consequence);

/// The control points (n + 1 = knots.size() - degree - 1 of them) of the
/// clamped B-spline of `degree` on `knots` with C(sites_i) = points_i and the
/// end constraints. Requires n + 1 = sites.size() + constraints.size(),
/// sites increasing with sites.front() = knots[p] and sites.back() = knots[n+1]
/// (asserted). Rows: C(s_0), then the start constraints by increasing order,
/// the interior sites, the end constraints by decreasing order, C(s_m), so
/// that the matrix is banded with bandwidth at most p. A derivative row of
/// order k is scaled by h^k (h the length of its end span) so that all rows
/// are O(1) for the pivot search. Error: a singular system (sites that
/// violate the Schoenberg–Whitney conditions, or end constraints the spline
/// cannot meet). O(n p^2 + n p d) time, O(n p) memory, one allocation per array.
Expected<PointArray> solve_collocation(int degree, std::span<const double> knots, std::span<const double> sites,
                                       const PointArray& points, std::span<const EndConstraint> constraints);

/// The m distinct control points Q_0..Q_{m-1} of a closed B-spline of
/// `degree` on the periodic `knots` (m + 2p + 1 of them, the domain
/// [knots[p], knots[m+p]] holding m spans; the curve's control points are
/// Q_0..Q_{m-1}, Q_0..Q_{p-1}) with C(sites_i) = points_i for the m sites
/// sites_i = knots[p + i]. Requires m >= p. The cyclic matrix is split
/// into its band (columns shifted by floor((p-1)/2) so that the band is
/// centred: a B-spline collocation matrix whose diagonal is positive, hence
/// totally positive and non-singular by Schoenberg–Whitney) and its corners,
/// and solved by Sherman–Morrison–Woodbury (Golub & Van Loan §2.1.4), as
/// scipy's periodic make_interp_spline does. O(m p^2 + m p d).
Expected<PointArray> solve_periodic_collocation(int degree, std::span<const double> knots,
                                                const PointArray& points);

}  // namespace casteljau::detail

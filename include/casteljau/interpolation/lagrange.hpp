#pragma once
// Polynomial interpolation (seed 001, problem P1) in barycentric form
// (Berrut & Trefethen, "Barycentric Lagrange interpolation", SIAM Review
// 46(3), 2004): the polynomial p of degree <= n with p(t_j) = P_j is
//   p(t) = Σ_j w_j P_j / (t − t_j)  /  Σ_j w_j / (t − t_j),
//   w_j = 1 / Π_{k≠j} (t_j − t_k)   (any common factor cancels),
// evaluated in O(n d) per point after O(n²) for the weights. Forward stable
// for nodes with a small Lebesgue constant such as Chebyshev points (Higham,
// IMA J. Numer. Anal. 24, 2004); equispaced nodes are ill-conditioned in any
// form (Runge's phenomenon, Lebesgue constant ~ 2^n / (e n log n)).

#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// The interpolating polynomial as data: nodes t_0 < ... < t_n, barycentric
/// weights w_j (scaled so that max |w_j| = 1) and values P_j. A regular value.
struct BarycentricInterpolant {
  std::vector<double> nodes;    ///< t_0 < ... < t_n
  std::vector<double> weights;  ///< w_0 .. w_n, max |w_j| = 1
  PointArray values;            ///< P_0 .. P_n (n+1 points of R^d)
  /// [t_0, t_n], the interval the interpolant was built on (a member, as every curve's domain()).
  Interval domain() const { return {nodes.front(), nodes.back()}; }
  friend bool operator==(const BarycentricInterpolant&, const BarycentricInterpolant&) = default;
};

/// The polynomial of degree <= n through (t_j, P_j), j = 0..n, in barycentric
/// form (Berrut & Trefethen 2004, eq. 3.2 and 4.2). Weights by the O(n²)
/// product formula, each product carried as mantissa and binary exponent
/// (frexp) so that it neither overflows nor underflows for any n, then scaled
/// so that the largest is 1. When the nodes are exactly
/// chebyshev_parameters(n+1, [t_0, t_n]), the closed form w_j = (−1)^j δ_j,
/// δ_0 = δ_n = 1/2, δ_j = 1 otherwise (Berrut & Trefethen eq. 5.4).
/// Errors: fewer than 2 points, more than tolerances::kMaxLagrangeDegree + 1,
/// parameters not one per point, not finite or not strictly increasing
/// (which also refuses duplicate nodes), a NaN coordinate. O(n² + n d).
Expected<BarycentricInterpolant> interpolate_lagrange(const PointArray& points, std::span<const double> parameters);

/// Chebyshev points of the second kind on [a, b], in increasing order, ends
/// included: t_j = (a + b)/2 + (b − a)/2 · sin(π (2j − n) / (2n)), j = 0..n
/// (= −cos(jπ/n), written with the sine so that the points are symmetric
/// about the midpoint in floating point; Trefethen, "Approximation Theory
/// and Approximation Practice", ch. 2); t_0 = a and t_n = b exactly.
/// Errors: count < 2 or above tolerances::kMaxLagrangeDegree + 1, an interval
/// that is not finite or has lower >= upper. O(count).
Expected<std::vector<double>> chebyshev_parameters(std::size_t count, Interval domain = {});

/// p(t) by the second (true) barycentric formula; exactly P_j at t = t_j
/// (and where t is so close to t_j that w_j / (t − t_j) overflows). Any finite
/// t (outside [t_0, t_n] it extrapolates, badly far away). O(n d).
Point point_at(const BarycentricInterpolant& interpolant, double t);

/// Batch evaluation: out[i*d .. i*d+d) = p(ts[i]), the same arithmetic as
/// point_at. Requires out.size() == ts.size() * d; never allocates. O(n d) per point.
void points_at(const BarycentricInterpolant& interpolant, std::span<const double> ts, std::span<double> out);

/// The same polynomial as a Bézier curve of degree n on [t_0, t_n] mapped to
/// [0, 1] (t = t_0 + s (t_n − t_0)): p is sampled (barycentric formula) at
/// the n+1 Chebyshev points s_j of [0, 1] and the control points solve the
/// Bernstein–Vandermonde system Σ_k c_k B_{n,k}(s_j) = p(t(s_j)) (LU with
/// partial pivoting, Eigen, plus two steps of iterative refinement); c_0 and
/// c_n are set to P_0 and P_n exactly. That system's conditioning grows
/// exponentially with n (the Bernstein basis on [0,1] has condition number
/// ~ 2^n in the max norm; Farouki, CAGD 8, 1991), so degrees above
/// tolerances::kMaxLagrangeBezierDegree (40) are refused. Measured max
/// |Bézier − p| relative to max |p| on Runge's function
/// (tests/interpolation/lagrange_test.cpp): Chebyshev nodes 3e-15, 3e-13,
/// 3e-11, 5e-9 and equispaced nodes 9e-15, 5e-13, 4e-10, 3e-7 at
/// n = 10, 20, 30, 40. O(n³ + n² d).
Expected<BezierCurve> to_bezier(const BarycentricInterpolant& interpolant);

}  // namespace casteljau

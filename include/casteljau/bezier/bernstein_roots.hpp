#pragma once
// Real roots of a polynomial in Bernstein form on [0, 1], the building block
// of the curve questions that reduce to one equation in one parameter: the
// extremes of a coordinate (roots of a hodograph coordinate), inflections
// (roots of C' x C''), the feet of perpendiculars (roots of (C - q) . C').
//
// Isolation by subdivision and the variation-diminishing property of the
// Bernstein basis (Lane & Riesenfeld, "Bounds on a polynomial", BIT 21, 1981;
// Mourrain, Rouillier & Roy, "The Bernstein basis and real root isolation",
// 2005): the number of sign changes V of the coefficients bounds the roots in
// the interval and has its parity; V = 0 means none, V = 1 exactly one. An
// interval with one root is refined by bracketed Newton (falling back to
// bisection), to the double nearest the root or within `resolution` in t.
// Where subdivision cannot separate roots (a multiple root, a cluster closer
// than `resolution`) the interval's midpoint is reported once with the count
// V of roots it may hold as its multiplicity. A root of even multiplicity (a
// tangency) that rounding has lifted off the axis, so that no sign changes,
// is still found: where every coefficient of an interval is zero within the
// rounding of the data (tolerances::kRoundingSlack x (n+1) x the largest
// coefficient), the touching run of such intervals is reported once, at its
// middle, with multiplicity 2; such a root is known to about the square root
// of that noise, as a double root of any method is.

#include <span>
#include <vector>

namespace casteljau {

/// A root t in [0, 1], and how many roots it stands for (1 for an isolated
/// simple root; V >= 2 for a cluster or a multiple root that the resolution
/// could not split, V being the sign changes left on its interval).
struct BernsteinRoot {
  double t = 0.0;
  int multiplicity = 1;
};

/// The roots in [0, 1] of p(t) = sum_i b_i B_{i,n}(t), n = coefficients.size() - 1,
/// increasing, each reported once (roots at 0 and 1 included). The zero
/// polynomial (every coefficient 0) has no isolated roots: an empty result.
/// `resolution` > 0: the width below which an interval is not split again.
/// No allocation beyond the result and one workspace per call.
std::vector<BernsteinRoot> bernstein_roots(std::span<const double> coefficients, double resolution = 1e-14);

/// The coefficients of the product p q of two polynomials in Bernstein form,
/// of degree m + n: c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) p_i q_j (Farin §5.8).
std::vector<double> bernstein_product(std::span<const double> p, std::span<const double> q);

/// p(t) by de Casteljau on the coefficients.
double bernstein_value(std::span<const double> coefficients, double t);

}  // namespace casteljau

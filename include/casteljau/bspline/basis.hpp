#pragma once
// B-spline basis functions N_{i,p} by the Cox–de Boor recursion
// (The NURBS Book, 2nd ed., chapter 2; seed 001 §1.2.3 with order k = p+1):
//   N_{i,0}(u) = 1 if t_i <= u < t_{i+1} else 0,
//   N_{i,p}(u) = (u - t_i)/(t_{i+p} - t_i) N_{i,p-1}(u)
//              + (t_{i+p+1} - u)/(t_{i+p+1} - t_{i+1}) N_{i+1,p-1}(u),   0/0 := 0.
// The half-open rule would make every N vanish at the last knot; casteljau,
// like the book, closes the last non-empty span at the end of the domain.
//
// These functions take a knot vector already checked by validate_knots (or
// built by casteljau) and assert their preconditions.

#include <span>

namespace casteljau {

/// The span index i with t_i <= u < t_{i+1} and t_i < t_{i+1}, p <= i <= n
/// (The NURBS Book A2.1, by bisection, O(log n)). At the end of the domain
/// u = t_{n+1} it returns the last non-empty span (the book's special case,
/// which geomdl, scipy and tinynurbs get wrong when the end knot is
/// repeated); u below the domain gives the first non-empty span and u above
/// it the last (evaluation there extrapolates the end polynomial pieces).
/// Never returns an empty span, so knots that differ only by rounding
/// (spans of one ulp) are handled like any other span. `knots` has n+p+2
/// entries, n+1 = knots.size() - degree - 1.
int find_span(std::span<const double> knots, int degree, double u);

/// The p+1 non-zero basis functions N_{span-p,p}(u) .. N_{span,p}(u) into
/// out[0..p] (The NURBS Book A2.2, O(p^2), no heap). Their sum is 1 up to
/// rounding (partition of unity), each lies in [0,1] on the span.
void basis_functions(std::span<const double> knots, int degree, int span, double u,
                     std::span<double> out);

/// The non-zero basis functions and their derivatives up to order k:
/// out[j*(p+1) + r] = N^(j)_{span-p+r,p}(u) for j = 0..k, r = 0..p
/// (The NURBS Book A2.3, O(p^2 + k p)). Derivatives of order j > p are zero.
/// out.size() must be (k+1)(p+1).
void basis_function_derivatives(std::span<const double> knots, int degree, int span, double u,
                                int order, std::span<double> out);

/// One basis function N_{i,p}(u), 0 <= i <= n, by its own triangle (The
/// NURBS Book A2.4), for every u: the Cox–de Boor definition over the whole
/// knot range (zero outside [t_i, t_{i+p+1}]), with the end of the domain
/// closed as in find_span. Unlike the evaluation functions it does not
/// extrapolate outside the domain, so figures of the basis over all knots
/// are right. O(p^2); the independent half of a differential pair with
/// basis_functions.
double basis_function(std::span<const double> knots, int degree, int index, double u);

}  // namespace casteljau

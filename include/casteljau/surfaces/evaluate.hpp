#pragma once
// Points, partial derivatives and normals of Bézier and B-spline (NURBS)
// surfaces, one at a time and in batches.
//
// As for curves, the functions accept any finite (u,v) and extrapolate
// outside the domain (the end polynomial pieces continued); front ends
// refuse parameters outside the domain before calling them. At the upper
// end of a domain the last non-empty span is used (find_span), so a clamped
// surface interpolates its corner control points exactly.
//
// Batch layout: out[k*d .. k*d+d) is the k-th point; on a grid, point
// k = a * vs.size() + b is S(us[a], vs[b]) (u is the slow index, as rows of
// the control net).
#include <span>
#include <vector>
#include "casteljau/core/point_array.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// S(u,v) by the tensor product: the p+1 rows of the span are combined with
/// the u basis, then the result with the v basis (The NURBS Book A3.5; NURBS
/// on the homogeneous net, A4.3). O((p+1)(q+1) d), no heap up to degree
/// tolerances::kMaxStackDegree.
Point point_at(const BSplineSurface& surface, double u, double v);
/// S(u,v) of a Bézier patch by de Casteljau's algorithm on each row, then on
/// the resulting column (The NURBS Book A1.7; seed 003 §III.3); rational
/// patches on the homogeneous net, then projected.
Point point_at(const BezierSurface& surface, double u, double v);
/// The mixed partial derivative d^(k+l) S / du^k dv^l at (u,v), k, l >= 0
/// (The NURBS Book A3.6; NURBS by eq. 4.20 / A4.4 from the homogeneous
/// derivatives). Zero when k > p or l > q for a polynomial surface. At a
/// knot, the derivative of the span to the right (the left one at the upper
/// end of the domain).
Point partial_derivative_at(const BSplineSurface& surface, double u, double v, int order_u, int order_v);
Point partial_derivative_at(const BezierSurface& surface, double u, double v, int order_u, int order_v);
/// All partial derivatives with k + l <= max_order in one pass:
/// result[k][l] = d^(k+l) S / du^k dv^l (The NURBS Book A3.6 / A4.4's SKL).
std::vector<std::vector<Point>> partial_derivatives_up_to(const BSplineSurface& surface, double u, double v,
                                                       int max_order);
/// The unit normal (S_u x S_v) / |S_u x S_v| of a surface in R^3 (asserts
/// d == 3). Where S_u x S_v vanishes (a degenerate edge such as the pole of a
/// surface of revolution, or a collapsed corner) it returns the limit of the
/// normal approached from inside the domain, from the derivatives one order
/// up (S_u x S_uv or S_uv x S_v, as the vanishing side requires); the zero
/// vector only where that limit does not exist either.
Point normal_at(const BSplineSurface& surface, double u, double v);
Point normal_at(const BezierSurface& surface, double u, double v);

/// Scattered batch: out[k*d ..] = S(us[k], vs[k]). Requires us.size() ==
/// vs.size() and out.size() == us.size() * d. Never allocates (up to degree
/// tolerances::kMaxStackDegree).
void points_at(const BSplineSurface& surface, std::span<const double> us, std::span<const double> vs,
               std::span<double> out);
void points_at(const BezierSurface& surface, std::span<const double> us, std::span<const double> vs,
               std::span<double> out);
/// Grid batch: out[(a * vs.size() + b) * d ..] = S(us[a], vs[b]), parameters
/// in any order (sorted is fastest). Separates the tensor product: the v
/// basis of every vs[b] is computed once, each us[a] contracts the p+1 rows
/// of its span into one row of the net, and each grid point is then a
/// (q+1)-term combination of that row (The NURBS Book §3.4, evaluated on a
/// grid). Allocates the basis tables once (O((|us| + |vs|)(p+q+2)) doubles),
/// nothing per point. Requires out.size() == us.size() * vs.size() * d.
/// Values agree with point_at to rounding (not bit for bit: the order of the
/// sums differs).
void grid_points_at(const BSplineSurface& surface, std::span<const double> us, std::span<const double> vs,
                    std::span<double> out);
void grid_points_at(const BezierSurface& surface, std::span<const double> us, std::span<const double> vs,
                    std::span<double> out);

}  // namespace casteljau

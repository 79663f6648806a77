#pragma once
// The nearest point of any curve kind (CurveView) to a query point q: the
// global minimum of |C(u) - q| over the closed domain, every local minimum on
// request, and a batch over many queries.
//
// On each Bézier piece the squared distance g(t) = |C(t) - q|^2 of a
// polynomial piece is itself a polynomial of degree 2n, whose Bernstein
// coefficients (products of the control points' differences P_i - q, Farin
// §5.8) bound it from below on any sub-interval (convex hull property). The
// global minimum is found by branch and bound on those coefficients: a
// sub-interval whose lowest coefficient exceeds the best distance found is
// dropped, one whose derivative coefficients change sign once holds one
// critical point (refined by bracketed Newton), others are halved. The
// candidates left within rounding of the best are then polished by Newton on
// (C - q) . C' = 0 on the curve itself and compared by their true distance.
// Rational pieces, and degrees beyond the stack kernel, take the roots of the
// numerator of g' (A - q w) . ((A - q w)' w - (A - q w) w') (A the homogeneous
// curve) from bernstein_roots instead; so does local_closest_points, which
// classifies each critical point by the sign of g' on both sides. Pieces are
// visited nearest box first and skipped when their control points' box is
// farther than the best answer (the curve lies in that box). End points and
// junctions of pieces are candidates like any other point: nothing is lost at
// the ends of the domain or at knots. tests/ops/closest_point_test.cpp checks
// the global minimum against a brute-force oracle on 10^5 random queries per
// curve kind; W7 in bench/ measures it beside OpenCASCADE and kurbo.

#include <cstddef>
#include <initializer_list>
#include <span>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/curves/curve_view.hpp"

namespace casteljau {

/// A point of a curve nearest to a query: its parameter u, the point C(u) and
/// the distance |C(u) - q|.
struct NearestPoint {
  double parameter = 0.0;
  double distance = 0.0;
  Point point;
};

/// The global minimum of |C(u) - q| over the curve's closed domain, ends and
/// junctions included. Where several points are equally near within
/// rounding, the one with the smallest parameter. The parameter is polished
/// to full precision where the minimum is a simple one (|C'| > 0, q not at a
/// centre of curvature); the distance is then exact to rounding.
/// Errors: a query of another dimension than the curve, or a coordinate not
/// finite or beyond tolerances::kMaxCoordinate (the message names it).
Expected<NearestPoint> closest_point(CurveView curve, std::span<const double> query);
/// The same with the query written in braces: closest_point(curve, {1.0, 2.0}).
inline Expected<NearestPoint> closest_point(CurveView curve, std::initializer_list<double> query) {
  return closest_point(curve, std::span<const double>(query.begin(), query.size()));
}

/// Every local minimum of the distance from q along the curve, the global one
/// first, then by increasing parameter. An end of the domain counts when the
/// distance grows away from it; so does a corner (a junction where the
/// distance decreases into it from both sides). Where the distance is
/// constant along a stretch (a circular arc about q), the ends of the
/// stretch are reported. Errors as closest_point.
Expected<std::vector<NearestPoint>> local_closest_points(CurveView curve, std::span<const double> query);

/// closest_point for n queries at once: `queries` holds n points of the
/// curve's dimension row-major (n x d values), `parameters` and `distances`
/// receive n values each. The curve's pieces are prepared once; each answer
/// starts from the previous one as its first bound (queries sorted along the
/// curve, or near each other, run fastest; any order gives the same answers).
/// Errors: the sizes do not match (n x d queries, n outputs), a query
/// coordinate as in closest_point (the message names the query).
Status closest_points(CurveView curve, std::span<const double> queries, std::span<double> parameters,
                      std::span<double> distances);

}  // namespace casteljau

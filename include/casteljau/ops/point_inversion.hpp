#pragma once
// Point inversion on surfaces: the parameters (u, v) of the point of a
// surface of any kind (SurfaceView) nearest to a query point q.
//
// The surface is sampled on a grid aligned with its knot lines (each span
// cut in 4 or more, 33 to 129 samples per direction). The nearest point lies
// within about the largest spacing h between neighbouring samples of some
// sample, so the samples within h of the nearest sample's distance are the
// starts (the grid's local minima among them first, one per basin, at
// most 32) of Newton's method on the gradient of g = |S - q|^2 / 2
// (Hessian [S_u.S_u + D.S_uu, S_u.S_v + D.S_uv; ..., S_v.S_v + D.S_vv],
// D = S - q), each step damped (Levenberg–Marquardt) until it brings the point
// nearer and kept inside the domain by fixing a parameter that reaches a
// border (the border is then searched along the other). The answer is never
// farther than the nearest sample. At a pole (a border collapsed to a point,
// S_u = 0) every u is an answer and the damping keeps the step finite; on a
// closed surface the seam's two borders are one, and either is returned.
// Unlike ops/closest_point on curves, the search is not certified (a
// minimum narrower than the sampling can be missed): tests/ops/
// point_inversion_test.cpp measures it against a brute-force oracle ten
// times denser on a bicubic patch and a wavy NURBS surface of 5 x 5 spans,
// and against closed forms on the NURBS sphere (poles) and torus (seams).

#include <initializer_list>
#include <span>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/surfaces/surface_view.hpp"

namespace casteljau {

/// The point of a surface nearest to a query: its parameters, the point, the distance.
struct SurfaceNearestPoint {
  double u = 0.0;
  double v = 0.0;
  double distance = 0.0;
  Point point;
};

/// The point of the surface nearest to `query` (see above), borders included.
/// Errors: a query of another dimension than the surface, or a coordinate not
/// finite or beyond tolerances::kMaxCoordinate.
Expected<SurfaceNearestPoint> closest_point(SurfaceView surface, std::span<const double> query);
/// The same with the query written in braces: closest_point(sphere, {2.0, 0.0, 0.0}).
inline Expected<SurfaceNearestPoint> closest_point(SurfaceView surface, std::initializer_list<double> query) {
  return closest_point(surface, std::span<const double>(query.begin(), query.size()));
}

}  // namespace casteljau

#pragma once
// Surfaces of revolution, exact as NURBS: every point of a profile curve
// turns around an axis on an exact circular arc (The NURBS Book §8.5,
// Algorithm A8.1; the arcs as in nurbs/conics.hpp, A7.1), and the two
// classic closed ones, the sphere and the torus.
#include <initializer_list>
#include <span>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The surface swept by the 3D profile C(v) (B-spline or NURBS) turning by
/// `angle` radians around the axis through `axis_point` along
/// `axis_direction` (any length; turning counterclockwise seen from its
/// tip, i.e. from X towards Y = T x X). u runs around the axis on [0, 1],
/// v is the profile's own parameter (its knots are kept): degree (2, q).
/// The NURBS Book A8.1: the angle is split into ceil(angle / 90°) equal arcs
/// (1 to 4) of sweep dθ; each profile control point P_j with weight w_j,
/// at distance r_j from its foot O_j on the axis, becomes the column of
/// the arc's control points O_j + r_j (cos θ X_j + sin θ Y_j) at the arc
/// ends and O_j + r_j / cos(dθ/2) (cos θ X_j + sin θ Y_j) at the mid
/// angles, with weights w_j and w_j cos(dθ/2); knots_u 0,0,0, 1/k,1/k, ...,
/// 1,1,1. Row 0 is the profile's control net itself (bit for bit), so
/// S(0, v) = C(v); for a full turn (angle == 2π in double) the last row is a
/// copy of row 0, so the seam is shared bit for bit. A profile control point
/// on the axis gives a column of one repeated point (a pole).
/// Sines and cosines of multiples of 45° are exact (0, ±1, ±√½ rounded).
/// O(k n d). Errors: a profile that is not 3D, an axis point or direction
/// that is not 3 finite coordinates, a zero axis direction, an angle not
/// finite, <= 0 or > 2π.
Expected<BSplineSurface> revolve(const BSplineCurve& profile, std::span<const double> axis_point,
                                 std::span<const double> axis_direction, double angle);
/// The same with the axis written in braces: revolve(c, {0, 0, 0}, {0, 0, 1}, π).
inline Expected<BSplineSurface> revolve(const BSplineCurve& profile, std::initializer_list<double> axis_point,
                                        std::initializer_list<double> axis_direction, double angle) {
  return revolve(profile, std::span<const double>(axis_point.begin(), axis_point.size()),
                 std::span<const double>(axis_direction.begin(), axis_direction.size()), angle);
}

/// The sphere |S - center| = radius as an exact NURBS surface of degree
/// (2, 2): the semicircle from the south pole (center - r z) over
/// center + r x to the north pole (nurbs/conics.hpp make_arc, two quarter
/// arcs) revolved a full turn around the z axis through the centre
/// (revolve). 9 x 5 control points; the poles are the columns j = 0 and 4
/// (the iso-curves v = 0 and v = 1), each one point repeated. Normals
/// S_u x S_v point outwards. Errors: centre not 3 finite coordinates,
/// radius not finite or <= 0.
Expected<BSplineSurface> make_sphere(std::span<const double> center, double radius);
/// The same with the centre written in braces: make_sphere({0, 0, 0}, 1.0).
inline Expected<BSplineSurface> make_sphere(std::initializer_list<double> center, double radius) {
  return make_sphere(std::span<const double>(center.begin(), center.size()), radius);
}

/// The torus around the axis through `center` along `axis` (any length):
/// the circle of radius minor_radius centred at distance major_radius from
/// the axis, in a plane containing the axis (make_circle), revolved a full
/// turn: degree (2, 2), 9 x 9 control points, outward normals. Only the ring
/// torus is made: minor_radius >= major_radius (horn and spindle tori) is
/// refused, since the surface then touches or crosses itself on the axis
/// and has no normal there. Errors: centre or axis not 3 finite
/// coordinates, a zero axis, radii not finite or <= 0, minor >= major.
Expected<BSplineSurface> make_torus(std::span<const double> center, std::span<const double> axis,
                                    double major_radius, double minor_radius);
/// The same with centre and axis written in braces: make_torus({0, 0, 0}, {0, 0, 1}, 2, 1).
inline Expected<BSplineSurface> make_torus(std::initializer_list<double> center, std::initializer_list<double> axis,
                                           double major_radius, double minor_radius) {
  return make_torus(std::span<const double>(center.begin(), center.size()),
                    std::span<const double>(axis.begin(), axis.size()), major_radius, minor_radius);
}

}  // namespace casteljau

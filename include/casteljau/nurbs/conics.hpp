#pragma once
// Exact conics as NURBS curves: circles, circular arcs of any sweep, ellipses
// (The NURBS Book, 2nd ed., §7.5, Algorithm A7.1; seed 001 §1.2.4 "exact
// conics", seed 003's semicircle).
//
// A circular arc of sweep dθ <= 90° is one rational quadratic Bézier piece
// with control points P_0, P_1, P_2 (P_1 where the end tangents meet, at
// distance r / cos(dθ/2) from the centre) and weights 1, cos(dθ/2), 1. A
// longer arc is split into 2, 3 or 4 equal pieces joined by double knots
// (A7.1), giving a degree-2 NURBS curve on the domain [0, 1] that is C^1
// (equal pieces on equal knot spans have equal end derivatives). The parameterization is not by arc length; the *shape* is
// exactly the circle: only the rounding of the control points and weights
// (one or two ulps) separates the computed curve from it.

#include <span>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// The plane of a conic in R^d, d >= 2: its centre O and two orthonormal
/// directions X, Y; the point at angle θ of the circle of radius r is
/// O + r (cos θ X + sin θ Y). Angles are measured from X towards Y.
struct ConicFrame {
  Point center;  ///< O, d coordinates
  Point x_axis;  ///< X, unit
  Point y_axis;  ///< Y, unit and orthogonal to X
};

/// The frame of the plane z = 0 in 2D: O = (center_x, center_y), X = (1, 0), Y = (0, 1).
ConicFrame plane_frame(double center_x, double center_y);

/// The circular arc of radius r from angle `start_angle` over `sweep` radians
/// (positive: from X towards Y; negative: the other way), as a rational
/// quadratic B-spline on [0, 1] (The NURBS Book A7.1): ceil(|sweep| / 90°)
/// pieces (1 to 4), each with weights 1, cos(dθ/2), 1 and interior knots of
/// multiplicity 2 at i / pieces. C(0) = O + r (cos a X + sin a Y) and C(1) the
/// point at a + sweep, tangents along the circle. Angles that are multiples
/// of 45° (in double) use exact sines and cosines (0, ±1, ±√½), so a quarter
/// circle starting on an axis has exact control points. Errors: radius not
/// finite or <= 0, angles not finite, sweep 0 or |sweep| > 2π, a frame whose
/// centre and axes differ in dimension, have d < 2 or non-finite coordinates,
/// or axes that are not orthonormal within tolerances::kOrthonormalAxes
/// (accepted axes are re-orthonormalized by Gram–Schmidt). O(d).
Expected<BSplineCurve> make_arc(const ConicFrame& frame, double radius, double start_angle, double sweep);

/// The same in the plane: the arc of the circle of centre (center_x, center_y).
Expected<BSplineCurve> make_arc(double center_x, double center_y, double radius, double start_angle,
                                double sweep);

/// The full circle O + r (cos θ X + sin θ Y), θ from 0 to 2π, as the classic
/// nine-point rational quadratic B-spline (The NURBS Book §7.5, Fig. 7.16):
/// four quarter arcs, control points at the corners and edge midpoints of the
/// square around the circle, weights 1, √½, 1, √½, ..., knots
/// 0,0,0, ¼,¼, ½,½, ¾,¾, 1,1,1. Starts and ends at O + r X. Errors as make_arc.
Expected<BSplineCurve> make_circle(const ConicFrame& frame, double radius);

/// The full circle of centre (center_x, center_y) in the plane.
Expected<BSplineCurve> make_circle(double center_x, double center_y, double radius);

/// The ellipse O + a cos θ X + b sin θ Y (semi-axes a along X, b along Y):
/// the circle's control net mapped by the affine map (x, y) -> (a x, b y),
/// weights unchanged (a rational curve's affine image is the curve of the
/// mapped control points, The NURBS Book §4.1). Errors as make_arc, with a
/// and b each finite and > 0.
Expected<BSplineCurve> make_ellipse(const ConicFrame& frame, double semi_axis_x, double semi_axis_y);

/// The axis-aligned ellipse of centre (center_x, center_y) in the plane.
Expected<BSplineCurve> make_ellipse(double center_x, double center_y, double semi_axis_x,
                                    double semi_axis_y);

/// Seed 003's CNC example, exactly: the upper half of the circle of radius 3
/// centred at the origin, from A = (-3, 0) over (0, 3) to D = (3, 0) (the
/// direction of the seed's cubic), as make_arc(0, 0, 3, π, -π): two quarter
/// arcs, control points (-3,0), (-3,3), (0,3), (3,3), (3,0), weights
/// 1, √½, 1, √½, 1, knots 0,0,0,½,½,1,1,1.
BSplineCurve seed_semicircle();

/// Seed 003's polynomial approximation of the same semicircle: the cubic
/// Bézier curve A(-3,0) B(-3,4) C(3,4) D(3,0) (shared/data/semicircle.csv).
/// Its largest radial error is about 0.055 (1.8 % of the radius; the seed
/// claims 1/100), at the parameters where |C(t)| peaks.
BezierCurve seed_semicircle_cubic();

}  // namespace casteljau

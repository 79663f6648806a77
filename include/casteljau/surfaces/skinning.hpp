#pragma once
// Skinning (lofting): the surface through a list of section curves
// (The NURBS Book §10.3; Woodward 1988).
#include <span>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The parameters v_0 = 0 < ... < v_K = 1 at which skin() places the
/// sections C_0..C_K: the sections are made compatible (surfaces/
/// compatible_curves.hpp), then for each control point index i the column
/// P_i^0..P_i^K gets its own normalized parameters (chord length, centripetal
/// or uniform steps, as interpolation/parameterization.hpp), and v_k is
/// their average over i (The NURBS Book eq. 10.8). A column whose points all
/// coincide (a common end point of every section, an apex) is left out of
/// the average. Errors: those of skin() about the sections; two consecutive
/// sections whose averaged parameters coincide ("sections 1 and 2 coincide,
/// chord-length parameters need distinct sections"). O(K n d).
Expected<std::vector<double>> section_parameters(std::span<const BSplineCurve> sections,
                                                 Parameterization parameterization = Parameterization::chord_length);

/// The skinned surface S(u,v) of degree (p, degree_v) with S(u, v_k) =
/// C_k(u) for every section (u each section's parameter mapped to [0, 1],
/// v_k from section_parameters), The NURBS Book §10.3:
///  1. the sections are made compatible: degree p, knots U, n+1 control
///     points each (make_compatible);
///  2. v_k by averaging (section_parameters), knots V by averaging them
///     (eq. 9.8);
///  3. the K+1 control polygons, each as one wide point of R^((n+1) d)
///     (homogeneous (w P, w) for NURBS sections), are interpolated at the
///     v_k by a curve of degree degree_v (interpolation/
///     spline_interpolation.hpp interpolate_bspline, A9.1): its control
///     points are the columns of the net. S(u, v_k) = C_k(u) up to the
///     rounding of the solve (about 1e-15 of the scale times the system's
///     condition).
/// O(K degree_v^2 n d). Errors: fewer than 2 sections; degree_v < 1 or
/// degree_v > K ("degree_v 3 needs at least 4 sections, found 3");
/// sections of different dimensions ("section 2 has 2 coordinates, section
/// 0 has 3; ..."); coincident sections under chord-length or centripetal
/// parameters; NURBS sections whose interpolated weights are not all > 0
/// (weights varying strongly between sections, interpolated by a high
/// degree_v: the message names the control point).
Expected<BSplineSurface> skin(std::span<const BSplineCurve> sections, int degree_v,
                              Parameterization parameterization = Parameterization::chord_length);

}  // namespace casteljau

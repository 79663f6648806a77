#pragma once
// What the surface constructions (Coons, ruled, skinning, grid
// interpolation) share: curves made compatible with one degree and one knot
// vector, parameters averaged over the rows of a grid or the sections of a
// skin, and points written in error messages. The tensor product seen as a
// curve of wide rows is src/surfaces/surface_rows.hpp. Internal to
// src/surfaces.
#include <span>
#include <string>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau::detail {

/// Curves that are clamped on one common domain, of any dimensions, written
/// with one degree (the highest, by elevate_degree) and one knot vector (the
/// union of the knots with the highest multiplicity of each value, by
/// refine_knots): The NURBS Book §10.3. Each curve keeps its shape and
/// rationality. Errors: the limits of elevation and refinement (sizes).
Expected<std::vector<BSplineCurve>> unify_curves(std::vector<BSplineCurve> curves);

/// make_compatible with the curves named `noun` in its messages ("section 2
/// has 2 coordinates, section 0 has 3").
Expected<std::vector<BSplineCurve>> make_compatible_named(std::span<const BSplineCurve> curves, const char* noun);

/// Parameters 0 = t_0 < ... < t_K = 1 shared by several polylines of K+1
/// points each (lines[l][k] is point k of polyline l), averaged over the
/// polylines (The NURBS Book eq. 9.13 for grids (A9.4), eq. 10.8 for the
/// sections of a skinned surface): each polyline's own normalized
/// parameters with steps |ΔP|^e (e = 0, 1, 1/2 as in parameter_values),
/// summed and divided by the number of polylines. A polyline of total
/// length 0 (all K+1 points equal: a pole, a common end point) carries no
/// information and is left out, as the book does for degenerate rows.
/// Errors name the coincident pair, with `noun` for the indices k ("rows 2
/// and 3 coincide, chord-length parameters need distinct rows"), or all of
/// them coinciding. Uniform: t_k = k/K. O(K L d).
Expected<std::vector<double>> averaged_parameters(const std::vector<PointArray>& lines, Parameterization kind,
                                                  const char* noun);

/// The points "(x, y, z)" for error messages.
std::string point_text(std::span<const double> point);

}  // namespace casteljau::detail

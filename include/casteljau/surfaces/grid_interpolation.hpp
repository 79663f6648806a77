#pragma once
// Interpolation of a rectangular grid of points by a B-spline surface
// (The NURBS Book §9.2.5, Algorithm A9.4): the default is the bicubic
// surface through the grid.
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/control_net.hpp"

namespace casteljau {

/// The parameters (u_0..u_n) of the grid's rows and (v_0..v_m) of its
/// columns.
struct GridParameters {
  std::vector<double> u;
  std::vector<double> v;
  friend bool operator==(const GridParameters&, const GridParameters&) = default;
};

/// The parameters interpolate_grid gives the points Q_kl (k: row, along u;
/// l: column, along v): for each column l, the normalized parameters of
/// Q_0l..Q_nl (chord length, centripetal or uniform steps), averaged over
/// the columns (The NURBS Book eq. 9.13 / A9.3); the v_l likewise along the
/// rows. A row or column whose points all coincide (a pole) is left out of
/// the average. Errors: fewer than 2 rows or columns; two consecutive rows
/// (columns) whose averaged parameters coincide ("rows 2 and 3 coincide,
/// chord-length parameters need distinct rows"). O(n m d).
Expected<GridParameters> grid_parameters(const ControlNet& points,
                                         Parameterization parameterization = Parameterization::chord_length);

/// The B-spline surface of degree (degree_u, degree_v) with S(u_k, v_l) =
/// Q_kl for the parameters of grid_parameters, The NURBS Book A9.4: knots
/// by averaging the parameters (eq. 9.8), then curve interpolation
/// (interpolation/spline_interpolation.hpp interpolate_bspline) first of
/// the columns, all at once with each row of the grid as one wide point,
/// giving intermediate control points R_il; then of the rows of R, each
/// column of R as one wide point, giving the net P_ij. Exact up to the
/// rounding of the two banded solves; a surface that is a polynomial of
/// degree <= (degree_u, degree_v) in the grid's parameters is reproduced.
/// O(n m (p^2 + q^2) d). Errors: a degree < 1; too few rows or columns for
/// the degree ("a grid of 3 rows cannot be interpolated with degree_u 3, it
/// needs at least 4 rows"); coincident rows or columns under chord-length
/// or centripetal parameters.
Expected<BSplineSurface> interpolate_grid(const ControlNet& points, int degree_u = 3, int degree_v = 3,
                                          Parameterization parameterization = Parameterization::chord_length);

}  // namespace casteljau

#pragma once
// Model: a curve or surface whose kind is chosen at run time (model JSON, the
// CLI, the playground), and what every front end needs to do with one
// without knowing its kind. The only std::variant of the library (style rule 1).

#include <cstddef>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/coons.hpp"
#include "casteljau/surfaces/surface_view.hpp"

namespace casteljau {


/// Every model kind of model JSON version 1: the curves `bezier`,
/// `piecewise_bezier`, `bspline` (B-spline or NURBS) and the surfaces
/// `bezier_surface`, `bspline_surface` (B-spline or NURBS) and `coons`.
/// Curves come first: is_surface() tells the two families apart (a curve is
/// an alternative that meets CurveKind, curves/curve.hpp). A new curve kind
/// is its alternative here, its entry in CurveView and its model JSON reader
/// and writer; every curve operation then reaches it through curve_view().
using Model = std::variant<BezierCurve, PiecewiseBezierCurve, BSplineCurve, BezierSurface, BSplineSurface,
                           CoonsPatch>;

/// True for the surface kinds (Bézier, B-spline/NURBS surface, Coons patch),
/// false for the curves. The functions below marked "curves only" assert
/// !is_surface(model); front ends branch on this first.
bool is_surface(const Model& model);

/// A non-owning view of a surface model (asserts is_surface(model)); the
/// model must outlive the view. All surface evaluation of the front ends goes
/// through it: domain_u/domain_v, point_at, partial_derivative_at, grids.
SurfaceView surface_view(const Model& model);
SurfaceView surface_view(const Model&& model) = delete;  // a view of a temporary dangles: name it first

/// A non-owning view of a curve model (asserts !is_surface(model)); the
/// model must outlive the view. All curve work of the front ends goes through
/// it and the functions written on it (curves/curve_view.hpp): domain(),
/// point_at, derivative_at, points_at_within, differential geometry, flatten.
CurveView curve_view(const Model& model);
CurveView curve_view(const Model&& model) = delete;  // a view of a temporary dangles: name it first

/// The dimension of the space the model (curve or surface) lives in.
int dimension_of(const Model& model);

/// The number of control points of the model (all pieces together; a point
/// shared by two pieces counts twice; n+1 for a B-spline; rows x columns for
/// a Bézier or B-spline surface; for a Coons patch, those of its four
/// boundary curves together).
std::size_t control_point_count(const Model& model);

/// The model's type name in model JSON ("bezier", "piecewise_bezier",
/// "bspline", "bezier_surface", "bspline_surface", "coons").
const char* type_name(const Model& model);

/// The same model written as a B-spline (exact): a Bézier curve on the
/// clamped knots 0^(n+1) 1^(n+1), a piecewise curve with its joints as knots
/// of multiplicity p (from_bezier_pieces: the pieces must meet), a Bézier
/// surface on clamped knots, a Coons patch by to_bspline_surface (polynomial
/// boundaries only); B-splines unchanged. A curve gives a BSplineCurve, a
/// surface a BSplineSurface. Errors are those of from_bezier_pieces and
/// to_bspline_surface.
Expected<Model> to_bspline(const Model& model);

}  // namespace casteljau

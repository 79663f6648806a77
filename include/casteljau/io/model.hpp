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
#include "casteljau/core/tolerance.hpp"

namespace casteljau {


/// Every model kind of model JSON version 1 that this version implements:
/// `bezier`, `piecewise_bezier`, `bspline` (B-spline or NURBS). Later layers
/// (surfaces) add their types here.
using Model = std::variant<BezierCurve, PiecewiseBezierCurve, BSplineCurve>;

/// The model's parameter domain: [0,1] for a Bézier curve, [0,m] for m
/// pieces, [t_p, t_{n+1}] for a B-spline of degree p with n+1 control points.
Interval domain_of(const Model& model);

/// The dimension of the space the model lives in.
int dimension_of(const Model& model);

/// The number of control points of the model (all pieces together; a point
/// shared by two pieces counts twice; n+1 for a B-spline).
std::size_t control_point_count(const Model& model);

/// The model's points at the parameters `us` (any order) into out (size
/// us.size() * d), bit for bit as point_at. Parameters outside the domain
/// extrapolate (see bezier/evaluate.hpp, bspline/evaluate.hpp): front ends
/// check them first.
void points_at(const Model& model, std::span<const double> us, std::span<double> out);

/// The k-th derivative at u (k = 0: the point), k >= 0. For a piecewise curve
/// at a junction u = i, the derivative of piece i (the one to the right), and
/// at u = m that of the last piece; for a B-spline at a knot, that of the span
/// to the right, and at the end of the domain that of the last span.
Point derivative_at(const Model& model, double u, int order);

/// The model's type name in model JSON ("bezier", "piecewise_bezier", "bspline").
const char* type_name(const Model& model);

}  // namespace casteljau

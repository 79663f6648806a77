#pragma once
// Figures of B-spline and NURBS curves and of the B-spline basis. A B-spline
// is drawn through its Bézier pieces (to_bezier_pieces, The NURBS Book A5.6)
// and the same certified flattening as every Bézier curve (layout.hpp), so
// no second curve-drawing path exists. The gallery's B-spline figures, the
// CLI's `plot` of a bspline model and `plot --basis` are built from these.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/render/figure.hpp"

namespace casteljau::render {

/// The curve as a plane B-spline (same degree, knots and weights): itself for
/// d = 2; its projection on the first two coordinates for d >= 3 (projection
/// is linear, so projecting the control points projects the curve); for
/// d = 1 and p >= 1 the graph u -> (u, x(u)), the B-spline with control points
/// (xi_i, x_i) at the Greville abscissae xi_i = (t_{i+1} + ... + t_{i+p}) / p
/// (linear precision: sum_i xi_i N_{i,p}(u) = u on the domain, the Greville
/// abscissae of de Boor's "A Practical Guide to Splines"). Errors: a rational curve of
/// dimension 1 (its graph is not of that form), a 1D curve of degree 0 (no
/// Greville abscissae: see plane_pieces, which draws it as steps).
Expected<BSplineCurve> plane_bspline(const BSplineCurve& curve);

/// A B-spline ready to draw: plane Bézier pieces, piece i covering the knot
/// interval [breakpoints[i], breakpoints[i+1]], and jumps[i] true when the
/// curve may be discontinuous between piece i and i+1 (a knot of
/// multiplicity p+1; every knot for p = 0), where the drawing lifts the pen.
struct PlanePieces {
  std::vector<double> breakpoints;
  std::vector<BezierCurve> pieces;
  std::vector<bool> jumps;  ///< size pieces.size() - 1
};

/// The plane pieces of a B-spline (plane_bspline, then to_bezier_pieces).
/// A 1D curve of degree 0 (a step function) becomes one horizontal segment
/// per span, with a jump at every interior knot. Errors as plane_bspline, and
/// a curve of degree 0 in dimension >= 2 (a set of points, not a curve).
Expected<PlanePieces> plane_pieces(const BSplineCurve& curve);

/// The pieces [first, last) as curve items: consecutive pieces in one
/// polyline, a new item after every jump (the first one carries `label`).
std::vector<CurveItem> curve_items(const PlanePieces& pieces, std::size_t first, std::size_t last, const Stroke& stroke,
                                   const std::string& label = "");

/// What to draw with a B-spline curve besides the curve itself.
struct BSplinePlotOptions {
  bool control_polygon = false;  ///< the B-spline's control polygon P_0..P_n, dashed gray
  bool control_points = false;   ///< P_0..P_n as red dots
  bool knot_points = false;      ///< C(t_j) at the distinct knots of the domain, black dots
  bool end_tangents = false;     ///< along the first and last legs of the end pieces, blue
  bool curvature_comb = false;   ///< per Bézier piece, as for a piecewise Bézier curve
  /// De Boor's algorithm at this u (de_boor_net): each level dashed black with
  /// black dots, the point C(u) in red. Must lie in the domain.
  std::optional<double> construction;
};

/// Adds a B-spline or NURBS curve with its options to a panel (3D curves
/// projected, 1D curves as graphs, see plane_bspline; for a 1D curve the
/// control polygon is the one of the graph, (xi_i, x_i)). A plane curve of
/// degree 0 is a set of points and is drawn as dots. Errors: as plane_pieces;
/// a construction parameter outside the domain.
Status add_bspline(Panel& panel, const BSplineCurve& curve, const BSplinePlotOptions& options,
                   Color color = colors::black, const std::string& label = "");

/// The basis function N_{index,p} of `knots` as a 1D B-spline over the whole
/// knot range [t_0, t_last]: coefficient 1 at `index`, 0 elsewhere, with the end
/// knots repeated (p+1 times in all) so that the domain covers the support of
/// every N_{i,p} even for unclamped knots; the added knots lie outside every
/// original support, so N_{index,p} is unchanged. `index` = -1 gives sum_i N_{i,p}
/// (all coefficients 1): 1 on [t_p, t_{n+1}], less outside. Knots as validate_knots requires.
BSplineCurve basis_function_curve(std::span<const double> knots, int degree, int index);

/// A panel with the graphs of every N_{i,p}(u) on [t_0, t_last] (tab10 colours,
/// each labelled N_i at its peak), their sum dashed gray, the knots as black
/// dots on the u axis ("×m" beside a knot of multiplicity m > 1), and the
/// parts outside the domain [t_p, t_{n+1}], where the sum is below 1, shaded.
/// Errors: a degree outside [0, tolerances::kMaxBSplineDegree], more than
/// tolerances::kMaxPlottedBasisDegree + 1 functions, knots that validate_knots refuses
/// for `degree` (with the count of control points they imply).
Expected<Panel> bspline_basis_panel(std::span<const double> knots, int degree);

/// Distinct knots a plot may want to name: "0 0 0 1 2 2 3 3 3" with {:g}
/// numbers, "…" after `max_count` knots.
std::string knots_text(std::span<const double> knots, std::size_t max_count = 16);

}  // namespace casteljau::render

#pragma once
// Figures of Bézier curves and of the Bernstein basis: the pictures of the
// seed notebook (seed 004: plot_bernstein, plot_bezier2, demo_casteljau) as
// functions that fill Panels. The CLI's `plot` and `bernstein` and the
// gallery are built from these; no geometry lives in the front ends.

#include <optional>
#include <string>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/render/figure.hpp"

namespace casteljau::render {

/// What to draw with a Bézier curve besides the curve itself.
struct BezierPlotOptions {
  bool control_polygon = false;  ///< the polygon P_0..P_n, dashed gray
  bool control_points = false;   ///< P_0..P_n as red dots (the notebook's 'or')
  bool end_tangents = false;     ///< the segments P_0P_1 and P_{n-1}P_n in blue (plot_bezier2)
  /// The de Casteljau construction at this t: every intermediate polygon
  /// dashed black with black dots, the point C(t) in red (demo_casteljau).
  std::optional<double> construction{};
  bool curvature_comb = false;  ///< teeth along the normal, length proportional to the curvature
};

/// `text` when no item of the panel has it as legend text yet, else empty:
/// decorations of several curves (control points, tangents) are listed once.
std::string label_once(const Panel& panel, const std::string& text);

/// Adds one curve (already in the plane, see plane_curve()) with its options
/// to a panel. Labels go to the legend when `label` is not empty.
void add_bezier(Panel& panel, const BezierCurve& plane, const BezierPlotOptions& options,
                Color color = colors::black, const std::string& label = "");

/// The curvature comb of a plane curve of any kind: on each Bézier piece
/// `teeth` segments from C(t_i) to C(t_i) - s kappa(t_i) N(t_i) at evenly
/// spaced t_i, both ends included (N the left normal, kappa signed, so teeth
/// stand on the outside of each bend), one scale s for all pieces, chosen so
/// the longest tooth is `length` model units, and per piece the polyline
/// through their tips: where the curvature jumps at a joint (a C¹ curve),
/// two teeth of different lengths stand there. Cusps (infinite curvature)
/// are skipped. With `reference_curvature` > 0, s is length / reference
/// instead (so that combs of different curves compare), and teeth longer
/// than twice `length` are cut there.
void add_curvature_comb(Panel& panel, CurveView plane, double length, int teeth = 96, Color color = colors::gray,
                        double reference_curvature = 0.0);

/// The graph t -> B_{n,k}(t) on [0,1] as a Bézier curve: control points
/// (j/n, delta_jk), exact by linear precision. n >= 1, 0 <= k <= n. Figures
/// of the basis draw BernsteinGraphItems instead (the closed form, O(n) per
/// vertex), since this curve costs O(n^2) per evaluation, O(n^3) for the basis.
BezierCurve bernstein_graph(int n, int k);

/// Whether a plot of the Bernstein basis draws its two end functions B_{n,0}
/// and B_{n,n} (the notebook's plot_bernstein draws them; its second figure
/// leaves them out to show the inner ones).
enum class BasisEnds { included, omitted };

/// A panel with B_{n,k} for k = 0..n (or k = 1..n-1 with BasisEnds::omitted),
/// black like the notebook's plot_bernstein, as BernsteinGraphItems (drawn
/// from their closed form, bernstein_graph.hpp). Errors: n < 1, n beyond
/// tolerances::kMaxPlottedBasisDegree, the ends omitted with n < 2 (nothing left to draw).
Expected<Panel> bernstein_basis_panel(int n, BasisEnds ends = BasisEnds::included);

/// A whole figure of the basis (title "Bernstein basis, n = ...").
Expected<Figure> bernstein_basis_figure(int n, BasisEnds ends = BasisEnds::included);

/// One input of the `plot` command: curves (model JSON, or a CSV point set
/// read as one Bézier curve's control polygon), or a point set drawn as data:
/// its points as diamonds (markers) and/or the polyline through them.
struct PlotSource {
  std::string name{};           ///< the file, for the legend and error messages
  std::vector<Model> models{};  ///< curves; when empty, `points` is a point set
  PointArray points{};
  bool markers = true;    ///< a point set: its points as filled diamonds (MarkerShape::diamond)
  bool polyline = false;  ///< a point set: the polyline through its points, in order
  /// A drawing (SVG, DXF): its curves share one color and one legend entry,
  /// the file's name (issue 39: a drawing of 19 subpaths made 19 entries).
  bool drawing = false;
};

/// What `plot` draws: the options for every curve, and a second panel with the
/// basis of the first curve: the Bernstein basis of its degree, or for a
/// B-spline (bspline model) its B-spline basis N_{i,p} on its knots
/// (bspline_basis_panel; weights are not applied).
struct PlotOptions {
  BezierPlotOptions bezier{};
  bool basis = false;
};

/// The figure of `plot`: every curve (black when there is one, the tab10
/// cycle otherwise, named in the legend when there are several), in the plane
/// (plane_curve: 3D curves projected on x, y; 1D curves as graphs), and every
/// point set as data (tab10 cycle; diamonds, which the legend calls "data
/// points" beside curves, where control points are red discs). A
/// piecewise curve gets the options piece by piece; its construction is drawn
/// on the piece holding the global parameter T in [0, m], its end tangents at
/// its two ends. A B-spline or NURBS curve is drawn by add_bspline
/// (bspline_plots.hpp): its own control polygon and points, the de Boor net
/// as its construction at u in its domain. Every error names the file (and
/// the model, "file[i]", when it holds several); so do layout errors about
/// its curves (CurveItem::source). Errors: no source; a construction
/// parameter outside a curve's domain, or asked of a curve (piece) of degree
/// beyond tolerances::kMaxConstructionDegree; a rational curve of dimension 1; a
/// curve piece of degree beyond tolerances::kMaxPlottedCurveDegree (check_plotted_degree);
/// control points (or data points) wider than tolerances::kMaxPlottedWidth, alone or together.
Expected<Figure> plot_figure(const std::vector<PlotSource>& sources, const PlotOptions& options);

/// An error "<subject> x from a to b, too wide to plot ..." (or the diagonal,
/// naming both ranges) when the points' box is wider than tolerances::kMaxPlottedWidth,
/// beyond what a figure can map to pixels, else nothing. `subject` names what
/// spans it ("head.json: the points span").
Status check_plottable_extent(const std::vector<Vec2>& points, const std::string& subject);

/// The smallest box around a curve's control points, widened by 1 % of its
/// size: the curve lies in it (convex hull property).
std::array<double, 4> control_box(const BezierCurve& plane);

}  // namespace casteljau::render

#pragma once
// A curve made of Bézier pieces end to end (the model JSON's
// `piecewise_bezier`; seed 000's C1 interpolant): piece i covers [i, i+1].
// It meets the curve concept (curves/curve.hpp) with the same operations, the
// same names and the same errors as BezierCurve and BSplineCurve; each one
// runs the Bézier algorithm on the pieces it touches.

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "casteljau/bezier/affine.hpp"
#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"

namespace casteljau {

/// m Bézier pieces of one dimension, any degrees; domain [0, m], piece i on [i, i+1].
class PiecewiseBezierCurve {
 public:
  /// At least one piece, all of the same dimension ("piece 2 has dimension 3,
  /// piece 0 has 2"). Pieces need not join: continuity is a property to check.
  static Expected<PiecewiseBezierCurve> make(std::vector<BezierCurve> pieces);
  const std::vector<BezierCurve>& pieces() const& noexcept { return pieces_; }
  std::vector<BezierCurve> pieces() && noexcept { return std::move(pieces_); }
  int dimension() const noexcept { return pieces_.front().dimension(); }
  /// m, the number of pieces (the domain is [0, m]).
  int size() const noexcept { return static_cast<int>(pieces_.size()); }
  /// The highest degree of the pieces.
  int degree() const noexcept;
  /// True when some piece is rational.
  bool is_rational() const noexcept;
  /// [0, m].
  Interval domain() const noexcept { return {0.0, static_cast<double>(pieces_.size())}; }
  friend bool operator==(const PiecewiseBezierCurve&, const PiecewiseBezierCurve&) = default;

 private:
  explicit PiecewiseBezierCurve(std::vector<BezierCurve> pieces) : pieces_(std::move(pieces)) {}
  std::vector<BezierCurve> pieces_;
};

/// The piece and local parameter of u in [0, m]: piece floor(u) (the last
/// piece for u = m), local u - i. Outside [0, m] the first or last piece extrapolates.
std::pair<int, double> locate(const PiecewiseBezierCurve& curve, double u);

/// C(u) for u in [0, m] (de Casteljau on the piece that holds u).
Point point_at(const PiecewiseBezierCurve& curve, double u);
/// The same point written into `out` (dimension() values, checked in every build), without allocating.
void point_at(const PiecewiseBezierCurve& curve, double u, std::span<double> out);

/// The k-th derivative with respect to the global parameter u (= the local t).
/// At a junction u = i, that of piece i (the one to the right); at u = m, the last piece's.
Point derivative_at(const PiecewiseBezierCurve& curve, double u, int order);

/// C(u), C'(u), ..., C^(max_order)(u) of the piece that holds u (as derivative_at).
std::vector<Point> derivatives_up_to(const PiecewiseBezierCurve& curve, double u, int max_order);

/// Batch evaluation over a span of u (any order) into out (size us.size() * d).
void points_at(const PiecewiseBezierCurve& curve, std::span<const double> us, std::span<double> out);

/// points_at that stops at the first parameter outside `allowed` (NaN is
/// outside every interval) and returns its index, us.size() when all are inside.
std::size_t points_at_within(const PiecewiseBezierCurve& curve, std::span<const double> us, Interval allowed,
                             std::span<double> out);

/// Batch k-th derivatives: out[i*d ..] = derivative_at(curve, us[i], order).
void derivatives_at(const PiecewiseBezierCurve& curve, std::span<const double> us, int order, std::span<double> out);

/// Batch points and first derivatives (both of size us.size() * d).
void points_and_derivatives_at(const PiecewiseBezierCurve& curve, std::span<const double> us,
                               std::span<double> points, std::span<double> derivatives);

/// 0, 1, ..., m: the junctions, where the curve may be less smooth.
std::vector<double> breakpoints(const PiecewiseBezierCurve& curve);

/// The two parts at u in (0, m): pieces 0..i-1 and the left half of piece i
/// (split at u - i), then the right half and pieces i+1..m-1; at a junction
/// u = i the pieces are only shared out. Each part has the unit pieces of its
/// kind, so the second starts at parameter 0 (the shape is kept, as for a
/// Bézier curve's split_at). Errors: u not finite or not inside (0, m).
Expected<std::pair<PiecewiseBezierCurve, PiecewiseBezierCurve>> split_at(const PiecewiseBezierCurve& curve,
                                                                         double u);

/// The curve between u0 < u1, both in [0, m]: the pieces they cross, the two
/// end ones cut (Bézier segment). Errors: not finite, outside [0, m], u0 >= u1.
Expected<PiecewiseBezierCurve> segment(const PiecewiseBezierCurve& curve, double u0, double u1);

/// The same curve traversed backwards: the pieces in reverse order, each reversed.
PiecewiseBezierCurve reversed(const PiecewiseBezierCurve& curve);

/// Every piece mapped by the affine map (Bézier transformed). Error when the
/// dimensions differ or a mapped point leaves the valid coordinates.
Expected<PiecewiseBezierCurve> transformed(const PiecewiseBezierCurve& curve, const AffineMap& map);

/// The k-th derivative curve, piece by piece (each piece's derivative_curve;
/// Farin §4.3). Refuses rational pieces and negative orders.
Expected<PiecewiseBezierCurve> derivative_curve(const PiecewiseBezierCurve& curve, int order = 1);

}  // namespace casteljau

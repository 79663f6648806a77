#pragma once
// A curve made of Bézier pieces end to end (the model JSON's
// `piecewise_bezier`; seed 000's C1 interpolant): piece i covers [i, i+1].

#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"

namespace casteljau {

/// m Bézier pieces of one dimension, any degrees; domain [0, m], piece i on [i, i+1].
class PiecewiseBezierCurve {
 public:
  /// At least one piece, all of the same dimension ("piece 2 has dimension 3,
  /// piece 0 has 2"). Pieces need not join: continuity is a property to check.
  static Expected<PiecewiseBezierCurve> make(std::vector<BezierCurve> pieces);
  const std::vector<BezierCurve>& pieces() const noexcept { return pieces_; }
  int dimension() const noexcept { return pieces_.front().dimension(); }
  /// m, the number of pieces (the domain is [0, m]).
  int size() const noexcept { return static_cast<int>(pieces_.size()); }
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

/// The k-th derivative with respect to the global parameter u (= the local t).
Point derivative_at(const PiecewiseBezierCurve& curve, double u, int order);

/// Batch evaluation over a span of u (any order) into out (size us.size() * d).
void points_at(const PiecewiseBezierCurve& curve, std::span<const double> us, std::span<double> out);

}  // namespace casteljau

#pragma once
// Coons patches: the surface spanned by four boundary curves (Coons 1967;
// seed 001 §2 with the corrected blending f_0 = 2t^3 - 3t^2 + 1; Farin ch. 22),
//   P(u,v) = f0(u) P(0,v) + f1(u) P(1,v) + f0(v) P(u,0) + f1(v) P(u,1)
//          - [f0(u) f0(v) P00 + f0(u) f1(v) P01 + f1(u) f0(v) P10 + f1(u) f1(v) P11],
// with f0(t) = 1 - t, f1(t) = t (bilinearly blended) or the cubic Hermite
// blending f0(t) = 2t^3 - 3t^2 + 1, f1(t) = 3t^2 - 2t^3. Either patch
// reproduces its four boundaries.
#include <array>
#include <span>
#include <utility>
#include <vector>
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"

namespace casteljau {

/// The blending functions of a Coons patch.
enum class CoonsBlending { linear, cubic };

/// A Coons patch on [0,1]^2 from four boundary curves: u0 = P(0,v),
/// u1 = P(1,v), v0 = P(u,0), v1 = P(u,1) (model JSON's names). Each boundary
/// is stored reparameterized to [0,1] (a Bézier or piecewise Bézier curve is
/// first written as a B-spline: bspline/bezier_pieces.hpp, to_bspline).
class CoonsPatch {
 public:
  /// Validates and builds: all four curves of one dimension, and meeting at
  /// the corners within tolerances::kJointRelativeGap of the boundaries'
  /// scale: u0(0) = v0(0) = P00, u0(1) = v1(0) = P01, u1(0) = v0(1) = P10,
  /// u1(1) = v1(1) = P11. The error names the corner, the curves and the gap:
  /// "the boundaries u1 and v0 do not meet at the corner P(1,0): u1 starts at
  /// (1, 0, 0), v0 ends at (1, 0.5, 0), 0.5 apart".
  static Expected<CoonsPatch> make(BSplineCurve u0, BSplineCurve u1, BSplineCurve v0, BSplineCurve v1,
                                   CoonsBlending blending = CoonsBlending::linear);
  /// P(0,v), P(1,v), P(u,0), P(u,1), each on [0,1].
  const BSplineCurve& u0() const& noexcept { return u0_; }
  BSplineCurve u0() && noexcept { return std::move(u0_); }
  const BSplineCurve& u1() const& noexcept { return u1_; }
  BSplineCurve u1() && noexcept { return std::move(u1_); }
  const BSplineCurve& v0() const& noexcept { return v0_; }
  BSplineCurve v0() && noexcept { return std::move(v0_); }
  const BSplineCurve& v1() const& noexcept { return v1_; }
  BSplineCurve v1() && noexcept { return std::move(v1_); }
  CoonsBlending blending() const noexcept { return blending_; }
  int dimension() const noexcept { return u0_.dimension(); }

  friend bool operator==(const CoonsPatch&, const CoonsPatch&) = default;

 private:
  CoonsPatch(BSplineCurve u0, BSplineCurve u1, BSplineCurve v0, BSplineCurve v1, CoonsBlending blending)
      : u0_(std::move(u0)), u1_(std::move(u1)), v0_(std::move(v0)), v1_(std::move(v1)), blending_(blending) {}
  BSplineCurve u0_, u1_, v0_, v1_;
  CoonsBlending blending_ = CoonsBlending::linear;
};

/// The blending name in model JSON ("linear", "cubic").
const char* blending_name(CoonsBlending blending);

/// The k-th derivatives {f0^(k)(t), f1^(k)(t)} of the blending functions,
/// order k >= 0: linear f0 = 1 - t, f1 = t; cubic (Hermite, seed 001 §2
/// corrected) f0 = 2t^3 - 3t^2 + 1 = (1 - t)^2 (1 + 2t), f1 = 3t^2 - 2t^3 =
/// t^2 (3 - 2t), computed in those factored forms so that f0(0) = f1(1) = 1
/// and f0(1) = f1(0) = 0 exactly. Derivatives above 1 (linear) or 3 (cubic)
/// are 0. O(1).
std::array<double, 2> blending_functions(CoonsBlending blending, double t, int order = 0);

/// P(u,v) by the formula above; the corners P00.. are the ends of the u0 and
/// u1 curves, so P(0,v) = u0(v) and P(1,v) = u1(v) to rounding, and P(u,0),
/// P(u,1) reproduce v0, v1 up to the corner gap allowed by make().
Point point_at(const CoonsPatch& patch, double u, double v);
/// d^(k+l) P / du^k dv^l, from the derivatives of the boundaries and of the
/// blending functions.
Point partial_derivative_at(const CoonsPatch& patch, double u, double v, int order_u, int order_v);
/// The unit normal of a patch in R^3 (as normal_at for B-spline surfaces).
Point normal_at(const CoonsPatch& patch, double u, double v);
/// Scattered and grid batches, laid out as in surfaces/evaluate.hpp.
void points_at(const CoonsPatch& patch, std::span<const double> us, std::span<const double> vs,
               std::span<double> out);
void grid_points_at(const CoonsPatch& patch, std::span<const double> us, std::span<const double> vs,
                    std::span<double> out);
/// The patch as an exact B-spline surface when its boundaries are polynomial:
/// the sum of the two ruled (or, with cubic blending, Hermite-blended)
/// surfaces minus the bilinear (bicubic) corner surface, made compatible by
/// degree elevation and knot refinement (The NURBS Book §10.5 for the
/// bilinear case). Error for rational boundaries ("a Coons patch with
/// rational boundaries has no B-spline form of the same degree; boundary v1
/// is rational").
Expected<BSplineSurface> to_bspline_surface(const CoonsPatch& patch);

}  // namespace casteljau

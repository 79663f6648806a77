#pragma once
// BSplineCurve: a B-spline curve of degree p >= 0 in R^d (d >= 1),
//   C(u) = sum_{i=0..n} N_{i,p}(u) P_i,   u in [t_p, t_{n+1}],
// or, when it carries one weight w_i > 0 per control point, a NURBS curve
//   C(u) = sum w_i P_i N_{i,p}(u) / sum w_i N_{i,p}(u)
// (The NURBS Book eq. 4.1; seed 001 §1.2.4 with the corrected σ(u)).
// Rational algorithms run the polynomial ones on the homogeneous control
// points (w_i P_i, w_i) and project back (The NURBS Book §4.2).

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// A B-spline or NURBS curve: degree p, knots t_0..t_{n+p+1}, control points
/// P_0..P_n and (NURBS) weights w_0..w_n. A regular value; built from outside
/// data only through make().
class BSplineCurve {
 public:
  /// Validates and builds: 0 <= p <= tolerances::kMaxBSplineDegree, at least
  /// p+1 control points (at most tolerances::kMaxControlPoints), every
  /// coordinate valid (finite, within tolerances::kMaxCoordinate:
  /// check_coordinates), knots as validate_knots requires, and `weights`
  /// empty (polynomial) or one valid weight per control point (within
  /// [kMinWeight, kMaxWeight]: check_weight). Such a curve's points and first
  /// derivatives are finite on its domain (core/tolerance.hpp says why).
  /// Errors name the field: "weight 2 is -1, weights must be > 0".
  static Expected<BSplineCurve> make(int degree, std::vector<double> knots, PointArray control_points,
                                     std::vector<double> weights = {});

  /// For data computed by casteljau itself (asserts the shape and
  /// check_knot_structure; computed curves, such as a derivative curve or a
  /// curve with a knot inserted next to another, may go beyond the ranges
  /// make() accepts from outside).
  static BSplineCurve from_trusted(int degree, std::vector<double> knots, PointArray control_points,
                                   std::vector<double> weights = {});

  /// p.
  int degree() const noexcept { return degree_; }
  /// d.
  int dimension() const noexcept { return control_points_.dimension(); }
  /// t_0 .. t_{n+p+1}.
  std::span<const double> knots() const& noexcept { return knots_; }
  std::span<const double> knots() const&& = delete;  // a view into a temporary dangles
  /// P_0 .. P_n.
  const PointArray& control_points() const& noexcept { return control_points_; }
  PointArray control_points() && noexcept { return std::move(control_points_); }
  /// w_0 .. w_n, empty for a polynomial curve.
  std::span<const double> weights() const& noexcept { return weights_; }
  std::span<const double> weights() const&& = delete;  // a view into a temporary dangles
  /// True when the curve carries weights (even if all equal): a NURBS curve.
  bool is_rational() const noexcept { return !weights_.empty(); }
  /// [t_p, t_{n+1}], where the basis functions sum to one.
  Interval domain() const noexcept {
    return {knots_[static_cast<std::size_t>(degree_)], knots_[control_points_.size()]};
  }

  friend bool operator==(const BSplineCurve&, const BSplineCurve&) = default;

 private:
  BSplineCurve(int degree, std::vector<double> knots, PointArray points, std::vector<double> weights)
      : degree_(degree), knots_(std::move(knots)), control_points_(std::move(points)),
        weights_(std::move(weights)) {}
  int degree_ = 0;
  std::vector<double> knots_;
  PointArray control_points_;
  std::vector<double> weights_;
};

/// The homogeneous control points (w_i P_i, w_i) in R^(d+1) of a NURBS curve,
/// (P_i, 1) for a polynomial one (The NURBS Book eq. 4.2).
PointArray homogeneous_points(const BSplineCurve& curve);

/// The NURBS curve of degree p on `knots` whose homogeneous control points
/// are `points` (last coordinate the weight, asserted > 0).
BSplineCurve from_homogeneous(int degree, std::vector<double> knots, const PointArray& points);

/// The same curve as a B-spline: degree n, knots 0^(n+1) 1^(n+1) (a clamped
/// B-spline with no interior knot is a Bézier curve; seed 001 §1.2.3).
BSplineCurve to_bspline(const BezierCurve& curve);

/// A closed (periodic) uniform B-spline of degree p through the control
/// polygon P_0..P_{m-1} taken cyclically: the control points P_0..P_{m-1},
/// P_0..P_{p-1} on periodic_knots(p, m, domain). C(lower) = C(upper) with
/// C^(p-1) continuity there. Requires m >= p+1 control points and passes
/// the checks of make() (errors name the given points and weights).
Expected<BSplineCurve> make_periodic(int degree, PointArray control_points,
                                     std::vector<double> weights = {}, Interval domain = {});

}  // namespace casteljau

#pragma once
// BezierCurve: a Bézier curve of any degree n >= 0 in R^d (d >= 1),
// polynomial, or rational when it carries one positive weight per control
// point: C(t) = sum w_k P_k B_{n,k}(t) / sum w_k B_{n,k}(t), t in [0,1].

#include <span>
#include <utility>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// A Bézier curve: its control polygon P_0..P_n and, if rational, weights w_0..w_n.
/// A regular value; built from outside data only through make().
class BezierCurve {
 public:
  /// Validates and builds: at least one control point and at most
  /// tolerances::kMaxBezierDegree + 1, every coordinate a valid coordinate
  /// (finite, within tolerances::kMaxCoordinate: check_coordinates), and
  /// `weights` either empty (polynomial) or one valid weight per point
  /// (within [kMinWeight, kMaxWeight]: check_weight). Such a curve's points
  /// and first derivatives are finite on [0, 1] (core/tolerance.hpp says
  /// why). Errors name the field: "weight 2 is -1, weights must be > 0".
  static Expected<BezierCurve> make(PointArray control_points, std::vector<double> weights = {});

  /// For control points computed by casteljau itself (asserts the invariants).
  static BezierCurve from_trusted(PointArray control_points, std::vector<double> weights = {});

  /// n, the degree: the number of control points minus one.
  int degree() const noexcept { return static_cast<int>(control_points_.size()) - 1; }
  /// d, the dimension of the space the curve lives in.
  int dimension() const noexcept { return control_points_.dimension(); }
  /// P_0 .. P_n (moved out of a temporary curve, not referenced).
  const PointArray& control_points() const& noexcept { return control_points_; }
  PointArray control_points() && noexcept { return std::move(control_points_); }
  /// w_0 .. w_n, empty for a polynomial curve (a view: deleted on a temporary).
  std::span<const double> weights() const& noexcept { return weights_; }
  std::span<const double> weights() const&& = delete;  // a view into a temporary dangles
  /// True when the curve carries weights (even if they are all equal).
  bool is_rational() const noexcept { return !weights_.empty(); }
  /// [0, 1], the parameter domain (the curve concept's domain(), curves/curve.hpp).
  Interval domain() const noexcept { return {0.0, 1.0}; }

  friend bool operator==(const BezierCurve&, const BezierCurve&) = default;

 private:
  BezierCurve(PointArray points, std::vector<double> weights)
      : control_points_(std::move(points)), weights_(std::move(weights)) {}
  PointArray control_points_;
  std::vector<double> weights_;
};

/// The homogeneous control points (w_k P_k, w_k) in R^(d+1) of a rational curve,
/// (P_k, 1) for a polynomial one. Rational algorithms run the polynomial ones on
/// these and project back (The NURBS Book, §4.2).
PointArray homogeneous_points(const BezierCurve& curve);

/// The rational curve whose homogeneous control points are `points` (last
/// coordinate the weight, asserted > 0): P_k = (first d coordinates) / w_k.
BezierCurve from_homogeneous(const PointArray& points);

}  // namespace casteljau

#pragma once
// BSplineSurface: a tensor-product B-spline surface of degrees (p, q) in R^d,
//   S(u,v) = sum_i sum_j N_{i,p}(u) N_{j,q}(v) P_ij,
// (u,v) in [s_p, s_{n+1}] x [t_q, t_{m+1}], or with one weight w_ij > 0 per
// control point a NURBS surface
//   S(u,v) = sum w_ij P_ij N_i N_j / sum w_ij N_i N_j
// (The NURBS Book eqs. 3.11 and 4.15; seed 001 §2). Like BSplineCurve, one
// type for both: rational algorithms run on the homogeneous net (w P, w).
//
// The tensor product is how casteljau reuses its curve algorithms: seen
// along u, the surface is a B-spline curve whose control point i is row i of
// the (homogeneous) net; knot insertion, degree elevation and splitting in
// one direction are the curve algorithms applied to those rows (The NURBS
// Book §5.2, A5.3: "apply the curve algorithm to each column").
#include <cstddef>
#include <span>
#include <utility>
#include <vector>
#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/surfaces/control_net.hpp"

namespace casteljau {

/// One of the two parameter directions of a surface.
enum class Direction { u, v };

/// A B-spline or NURBS surface; a regular value built from outside data only
/// through make().
class BSplineSurface {
 public:
  /// Validates and builds: each degree in [0, tolerances::kMaxBSplineDegree];
  /// at least p+1 rows and q+1 columns; every coordinate valid (finite,
  /// within tolerances::kMaxCoordinate: "coordinate 2 of control point [1][3]
  /// is 1e+308, outside [-1e+100, 1e+100], the range of coordinates"); each
  /// knot vector as validate_knots requires for its count (errors say which:
  /// "knots_v: knot 4 (0.5) is smaller than knot 3 (0.7), knots must be
  /// non-decreasing"); `weights` empty or one valid weight (within
  /// [kMinWeight, kMaxWeight]) per control point, row by row ("weight
  /// [2][1] is -1, weights must be > 0"; "the weights have 11 entries, the
  /// control net has 12 points"). Such a surface's points and first partial
  /// derivatives are finite on its domain (core/tolerance.hpp says why).
  static Expected<BSplineSurface> make(int degree_u, int degree_v, std::vector<double> knots_u,
                                       std::vector<double> knots_v, ControlNet net,
                                       std::vector<double> weights = {});
  /// For data computed by casteljau itself (asserts the shape and
  /// check_knot_structure of both knot vectors).
  static BSplineSurface from_trusted(int degree_u, int degree_v, std::vector<double> knots_u,
                                     std::vector<double> knots_v, ControlNet net,
                                     std::vector<double> weights = {});

  /// p (u) or q (v).
  int degree(Direction direction) const noexcept { return direction == Direction::u ? degree_u_ : degree_v_; }
  int degree_u() const noexcept { return degree_u_; }
  int degree_v() const noexcept { return degree_v_; }
  /// s_0..s_{n+p+1} (u) or t_0..t_{m+q+1} (v).
  /// (Views: deleted on a temporary surface, whose knots they would outlive.)
  std::span<const double> knots(Direction direction) const& noexcept {
    return direction == Direction::u ? std::span<const double>(knots_u_) : std::span<const double>(knots_v_);
  }
  std::span<const double> knots(Direction direction) const&& = delete;  // a view into a temporary dangles
  std::span<const double> knots_u() const& noexcept { return knots_u_; }
  std::span<const double> knots_u() const&& = delete;  // a view into a temporary dangles
  std::span<const double> knots_v() const& noexcept { return knots_v_; }
  std::span<const double> knots_v() const&& = delete;  // a view into a temporary dangles
  /// The control net P_ij (i along u).
  const ControlNet& control_net() const& noexcept { return net_; }
  ControlNet control_net() && noexcept { return std::move(net_); }
  /// w_ij row by row (w_ij at i*(m+1)+j), empty for a polynomial surface.
  std::span<const double> weights() const& noexcept { return weights_; }
  std::span<const double> weights() const&& = delete;  // a view into a temporary dangles
  /// True when the surface carries weights: a NURBS surface.
  bool is_rational() const noexcept { return !weights_.empty(); }
  /// d.
  int dimension() const noexcept { return net_.dimension(); }
  /// [s_p, s_{n+1}] or [t_q, t_{m+1}].
  Interval domain(Direction direction) const noexcept;
  Interval domain_u() const noexcept { return domain(Direction::u); }
  Interval domain_v() const noexcept { return domain(Direction::v); }

  friend bool operator==(const BSplineSurface&, const BSplineSurface&) = default;

 private:
  BSplineSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                 ControlNet net, std::vector<double> weights)
      : degree_u_(degree_u), degree_v_(degree_v), knots_u_(std::move(knots_u)),
        knots_v_(std::move(knots_v)), net_(std::move(net)), weights_(std::move(weights)) {}
  int degree_u_ = 0;
  int degree_v_ = 0;
  std::vector<double> knots_u_;
  std::vector<double> knots_v_;
  ControlNet net_;
  std::vector<double> weights_;
};

/// The homogeneous net (w_ij P_ij, w_ij) in R^(d+1) of a NURBS surface,
/// (P_ij, 1) for a polynomial one (The NURBS Book eq. 4.16).
ControlNet homogeneous_net(const BSplineSurface& surface);
/// The NURBS surface whose homogeneous net is `net` (last coordinate the
/// weight, asserted > 0).
BSplineSurface from_homogeneous(int degree_u, int degree_v, std::vector<double> knots_u,
                                std::vector<double> knots_v, const ControlNet& net);
/// The same surface with u and v exchanged: T(v,u) = S(u,v).
BSplineSurface transposed(const BSplineSurface& surface);

}  // namespace casteljau

#pragma once
// BezierSurface: a tensor-product Bézier patch of degrees (n, m) in R^d,
//   S(u,v) = sum_i sum_j B_i^n(u) B_j^m(v) P_ij,  (u,v) in [0,1]^2,
// and its rational form with weights w_ij > 0 (seed 003 §III.3 and figure 6,
// seed 001 §2; Farin ch. 14-15; The NURBS Book eq. 1.12).
#include <span>
#include <utility>
#include <vector>
#include "casteljau/core/expected.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/control_net.hpp"

namespace casteljau {

/// A Bézier patch: an (n+1) x (m+1) control net and optional weights.
class BezierSurface {
 public:
  /// Validates and builds: degrees up to tolerances::kMaxBezierDegree in each
  /// direction; every coordinate valid and weights empty or one valid weight
  /// per control point, row by row (errors as BSplineSurface::make).
  static Expected<BezierSurface> make(ControlNet net, std::vector<double> weights = {});
  /// For data computed by casteljau itself (asserts the invariants).
  static BezierSurface from_trusted(ControlNet net, std::vector<double> weights = {});

  /// n = rows - 1.
  int degree_u() const noexcept { return static_cast<int>(net_.rows()) - 1; }
  /// m = columns - 1.
  int degree_v() const noexcept { return static_cast<int>(net_.columns()) - 1; }
  const ControlNet& control_net() const& noexcept { return net_; }
  ControlNet control_net() && noexcept { return std::move(net_); }
  /// w_ij row by row, empty for a polynomial patch.
  std::span<const double> weights() const& noexcept { return weights_; }
  std::span<const double> weights() const&& = delete;  // a view into a temporary dangles
  bool is_rational() const noexcept { return !weights_.empty(); }
  int dimension() const noexcept { return net_.dimension(); }

  friend bool operator==(const BezierSurface&, const BezierSurface&) = default;

 private:
  BezierSurface(ControlNet net, std::vector<double> weights)
      : net_(std::move(net)), weights_(std::move(weights)) {}
  ControlNet net_;
  std::vector<double> weights_;
};

/// The same patch as a B-spline surface on knots 0^(n+1) 1^(n+1) and
/// 0^(m+1) 1^(m+1) (exact: the Bernstein polynomials are the B-splines of
/// those knots).
BSplineSurface to_bspline_surface(const BezierSurface& surface);

}  // namespace casteljau

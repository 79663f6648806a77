#pragma once
// SurfaceView: a non-owning reference to any surface of casteljau, for the
// algorithms that only evaluate a surface (tessellation, figures). Like a
// span, it does not own what it shows: the surface must outlive the view.
// It is the one place that dispatches on the surface kind below io/.
#include <span>
#include <vector>
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/coons.hpp"

namespace casteljau {

/// A view of a Bézier, B-spline/NURBS surface or Coons patch.
class SurfaceView {
 public:
  /// Views of the three surface kinds (implicit, like span from a vector).
  SurfaceView(const BSplineSurface& surface) noexcept;  // NOLINT: implicit by design
  SurfaceView(const BezierSurface& surface) noexcept;   // NOLINT
  SurfaceView(const CoonsPatch& patch) noexcept;        // NOLINT
  /// Never of a temporary (`SurfaceView v = *make_sphere(...)` would dangle):
  /// name the surface first (docs/cpp.md, "Lifetimes").
  SurfaceView(const BSplineSurface&&) = delete;  // a view of a temporary dangles: name it first
  SurfaceView(const BezierSurface&&) = delete;  // a view of a temporary dangles: name it first
  SurfaceView(const CoonsPatch&&) = delete;  // a view of a temporary dangles: name it first

  /// The parameter domain in u and in v ([0,1] for Bézier and Coons patches).
  Interval domain_u() const noexcept;
  Interval domain_v() const noexcept;
  /// d.
  int dimension() const noexcept;
  /// S(u,v) (surfaces/evaluate.hpp, surfaces/coons.hpp).
  Point point_at(double u, double v) const;
  /// d^(k+l) S / du^k dv^l.
  Point partial_derivative_at(double u, double v, int order_u, int order_v) const;
  /// The unit normal (d == 3), with the limit at degenerate points (normal_at).
  Point normal_at(double u, double v) const;
  /// Grid batch, laid out as grid_points_at.
  void grid_points_at(std::span<const double> us, std::span<const double> vs, std::span<double> out) const;
  /// The distinct knots of the u (v) direction inside the domain, both ends
  /// included and increasing: the lines across which the surface may be less
  /// smooth, where tessellation starts its quadtree. {0, 1} for a Bézier
  /// patch; for a Coons patch, the knots of the two boundaries that run along
  /// that direction (v0 and v1 for u, u0 and u1 for v), merged.
  std::vector<double> breakpoints_u() const;
  std::vector<double> breakpoints_v() const;

 private:
  enum class Kind { bspline, bezier, coons };
  Kind kind_;
  const void* surface_;
};

}  // namespace casteljau

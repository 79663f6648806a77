// SurfaceView: the one dispatch on the surface kind below io/. Each member
// forwards to the free function of surfaces/evaluate.hpp or surfaces/coons.hpp
// for the kind it was built from; the view stores only a tag and an address.
#include "casteljau/surfaces/surface_view.hpp"

#include <algorithm>
#include <cassert>

#include "casteljau/surfaces/coons.hpp"
#include "casteljau/surfaces/evaluate.hpp"

namespace casteljau {
namespace {

/// The distinct knots of `knots` inside [domain.lower, domain.upper], ends
/// included (a clamped knot vector repeats its ends; an unclamped one has
/// knots outside the domain, which do not split it).
void append_breakpoints(std::span<const double> knots, Interval domain, std::vector<double>& out) {
  out.push_back(domain.lower);
  out.push_back(domain.upper);
  for (const double knot : knots) {
    if (knot > domain.lower && knot < domain.upper) out.push_back(knot);
  }
}

std::vector<double> sorted_unique(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

/// The breakpoints of a Coons patch along one direction: the knots of the
/// two boundary curves that run along it, each already on [0,1].
std::vector<double> coons_breakpoints(const BSplineCurve& first, const BSplineCurve& second) {
  std::vector<double> values;
  append_breakpoints(first.knots(), Interval{0.0, 1.0}, values);
  append_breakpoints(second.knots(), Interval{0.0, 1.0}, values);
  return sorted_unique(std::move(values));
}

}  // namespace

SurfaceView::SurfaceView(const BSplineSurface& surface) noexcept : kind_(Kind::bspline), surface_(&surface) {}
SurfaceView::SurfaceView(const BezierSurface& surface) noexcept : kind_(Kind::bezier), surface_(&surface) {}
SurfaceView::SurfaceView(const CoonsPatch& patch) noexcept : kind_(Kind::coons), surface_(&patch) {}

// The three kinds behind the stored address; each member switches on kind_.
#define CASTELJAU_SURFACE_DISPATCH(call)                                            \
  switch (kind_) {                                                                  \
    case Kind::bspline: return call(*static_cast<const BSplineSurface*>(surface_)); \
    case Kind::bezier: return call(*static_cast<const BezierSurface*>(surface_));   \
    case Kind::coons: break;                                                        \
  }                                                                                 \
  return call(*static_cast<const CoonsPatch*>(surface_))

Interval SurfaceView::domain_u() const noexcept {
  if (kind_ == Kind::bspline) return static_cast<const BSplineSurface*>(surface_)->domain_u();
  return Interval{0.0, 1.0};
}

Interval SurfaceView::domain_v() const noexcept {
  if (kind_ == Kind::bspline) return static_cast<const BSplineSurface*>(surface_)->domain_v();
  return Interval{0.0, 1.0};
}

int SurfaceView::dimension() const noexcept {
  const auto call = [](const auto& surface) { return surface.dimension(); };
  CASTELJAU_SURFACE_DISPATCH(call);
}

Point SurfaceView::point_at(double u, double v) const {
  const auto call = [u, v](const auto& surface) { return casteljau::point_at(surface, u, v); };
  CASTELJAU_SURFACE_DISPATCH(call);
}

Point SurfaceView::partial_derivative_at(double u, double v, int order_u, int order_v) const {
  const auto call = [u, v, order_u, order_v](const auto& surface) {
    return casteljau::partial_derivative_at(surface, u, v, order_u, order_v);
  };
  CASTELJAU_SURFACE_DISPATCH(call);
}

Point SurfaceView::normal_at(double u, double v) const {
  const auto call = [u, v](const auto& surface) { return casteljau::normal_at(surface, u, v); };
  CASTELJAU_SURFACE_DISPATCH(call);
}

void SurfaceView::grid_points_at(std::span<const double> us, std::span<const double> vs,
                                 std::span<double> out) const {
  const auto call = [us, vs, out](const auto& surface) { casteljau::grid_points_at(surface, us, vs, out); };
  CASTELJAU_SURFACE_DISPATCH(call);
}

#undef CASTELJAU_SURFACE_DISPATCH

std::vector<double> SurfaceView::breakpoints_u() const {
  switch (kind_) {
    case Kind::bspline: {
      const auto& surface = *static_cast<const BSplineSurface*>(surface_);
      std::vector<double> values;
      append_breakpoints(surface.knots_u(), surface.domain_u(), values);
      return sorted_unique(std::move(values));
    }
    case Kind::bezier: return {0.0, 1.0};
    case Kind::coons: break;
  }
  const auto& patch = *static_cast<const CoonsPatch*>(surface_);
  return coons_breakpoints(patch.v0(), patch.v1());
}

std::vector<double> SurfaceView::breakpoints_v() const {
  switch (kind_) {
    case Kind::bspline: {
      const auto& surface = *static_cast<const BSplineSurface*>(surface_);
      std::vector<double> values;
      append_breakpoints(surface.knots_v(), surface.domain_v(), values);
      return sorted_unique(std::move(values));
    }
    case Kind::bezier: return {0.0, 1.0};
    case Kind::coons: break;
  }
  const auto& patch = *static_cast<const CoonsPatch*>(surface_);
  return coons_breakpoints(patch.u0(), patch.u1());
}

}  // namespace casteljau

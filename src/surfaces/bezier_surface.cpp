// BezierSurface: validation and the B-spline form.
#include "casteljau/surfaces/bezier_surface.hpp"

#include <cassert>
#include <string>
#include <utility>

#include "casteljau/core/tolerance.hpp"
#include "surface_checks.hpp"

namespace casteljau {

Expected<BezierSurface> BezierSurface::make(ControlNet net, std::vector<double> weights) {
  if (net.rows() == 0 || net.columns() == 0) return Error{"the control net is empty"};
  const std::size_t limit = static_cast<std::size_t>(tolerances::kMaxBezierDegree) + 1;
  if (net.rows() > limit) {
    return Error{"the control net has " + std::to_string(net.rows()) + " rows, degree " +
                 std::to_string(net.rows() - 1) + " in u is above the limit " +
                 std::to_string(tolerances::kMaxBezierDegree)};
  }
  if (net.columns() > limit) {
    return Error{"the control net has " + std::to_string(net.columns()) + " columns, degree " +
                 std::to_string(net.columns() - 1) + " in v is above the limit " +
                 std::to_string(tolerances::kMaxBezierDegree)};
  }
  if (auto ok = detail::check_net_coordinates(net); !ok) return ok.error();
  if (auto ok = detail::check_surface_weights(weights, net); !ok) return ok.error();
  return BezierSurface(std::move(net), std::move(weights));
}

BezierSurface BezierSurface::from_trusted(ControlNet net, std::vector<double> weights) {
  assert(net.rows() >= 1 && net.columns() >= 1);
  assert(weights.empty() || weights.size() == net.rows() * net.columns());
  return BezierSurface(std::move(net), std::move(weights));
}

BSplineSurface to_bspline_surface(const BezierSurface& surface) {
  const auto bernstein_knots = [](std::size_t count) {
    std::vector<double> knots(2 * count, 0.0);
    for (std::size_t i = count; i < 2 * count; ++i) knots[i] = 1.0;
    return knots;
  };
  const ControlNet& net = surface.control_net();
  return BSplineSurface::from_trusted(surface.degree_u(), surface.degree_v(), bernstein_knots(net.rows()),
                                      bernstein_knots(net.columns()), net,
                                      std::vector<double>(surface.weights().begin(), surface.weights().end()));
}

}  // namespace casteljau

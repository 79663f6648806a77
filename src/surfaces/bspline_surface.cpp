// BSplineSurface: validation, the homogeneous net, the transpose.
#include "casteljau/surfaces/bspline_surface.hpp"

#include <cassert>
#include <cmath>
#include <string>
#include <utility>

#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/homogeneous.hpp"
#include "surface_checks.hpp"

namespace casteljau {

namespace detail {

Status check_surface_weights(std::span<const double> weights, const ControlNet& net) {
  if (weights.empty()) return {};
  const std::size_t count = net.rows() * net.columns();
  if (weights.size() != count) {
    return Error{"the weights have " + std::to_string(weights.size()) + " entries, the control net has " +
                 std::to_string(count) + " points (" + std::to_string(net.rows()) + " x " +
                 std::to_string(net.columns()) + "), there must be one weight per control point"};
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (is_valid_weight(weights[k])) continue;  // the name is built only for a weight that fails
    return check_weight(weights[k], "weight [" + std::to_string(k / net.columns()) + "][" +
                                        std::to_string(k % net.columns()) + "]");
  }
  return {};
}

Status check_net_coordinates(const ControlNet& net) {
  const std::span<const double> coordinates = net.points().coordinates();
  const std::size_t d = static_cast<std::size_t>(net.dimension());
  for (std::size_t k = 0; k < coordinates.size(); ++k) {
    if (is_valid_coordinate(coordinates[k])) continue;
    const std::size_t point = k / d;
    return check_coordinate(coordinates[k], "coordinate " + std::to_string(k % d) + " of control point [" +
                                                std::to_string(point / net.columns()) + "][" +
                                                std::to_string(point % net.columns()) + "]");
  }
  return {};
}

}  // namespace detail

Expected<BSplineSurface> BSplineSurface::make(int degree_u, int degree_v, std::vector<double> knots_u,
                                              std::vector<double> knots_v, ControlNet net,
                                              std::vector<double> weights) {
  const int degrees[2] = {degree_u, degree_v};
  const std::size_t counts[2] = {net.rows(), net.columns()};
  const char* names[2] = {"u", "v"};
  const char* lines[2] = {"rows", "columns"};
  if (net.rows() == 0 || net.columns() == 0) return Error{"the control net is empty"};
  for (int k = 0; k < 2; ++k) {
    if (degrees[k] < 0 || degrees[k] > tolerances::kMaxBSplineDegree) {
      return Error{std::string("degree_") + names[k] + " " + std::to_string(degrees[k]) + " is outside [0, " +
                   std::to_string(tolerances::kMaxBSplineDegree) + "]"};
    }
    if (counts[k] < static_cast<std::size_t>(degrees[k]) + 1) {
      return Error{"the control net has " + std::to_string(counts[k]) + " " + lines[k] + ", a surface of degree " +
                   std::to_string(degrees[k]) + " in " + names[k] + " needs at least " +
                   std::to_string(degrees[k] + 1)};
    }
  }
  if (auto ok = detail::check_net_coordinates(net); !ok) return ok.error();
  if (auto ok = validate_knots(knots_u, degree_u, net.rows()); !ok) {
    return with_context(ok.error(), "knots_u");
  }
  if (auto ok = validate_knots(knots_v, degree_v, net.columns()); !ok) {
    return with_context(ok.error(), "knots_v");
  }
  if (auto ok = detail::check_surface_weights(weights, net); !ok) return ok.error();
  return BSplineSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net),
                        std::move(weights));
}

BSplineSurface BSplineSurface::from_trusted(int degree_u, int degree_v, std::vector<double> knots_u,
                                            std::vector<double> knots_v, ControlNet net,
                                            std::vector<double> weights) {
  assert(degree_u >= 0 && degree_v >= 0);
  assert(net.rows() >= static_cast<std::size_t>(degree_u) + 1);
  assert(net.columns() >= static_cast<std::size_t>(degree_v) + 1);
  assert(check_knot_structure(knots_u, degree_u, net.rows()).has_value());
  assert(check_knot_structure(knots_v, degree_v, net.columns()).has_value());
  assert(weights.empty() || weights.size() == net.rows() * net.columns());
  return BSplineSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net),
                        std::move(weights));
}

Interval BSplineSurface::domain(Direction direction) const noexcept {
  const std::span<const double> t = knots(direction);
  const std::size_t p = static_cast<std::size_t>(degree(direction));
  const std::size_t count = direction == Direction::u ? net_.rows() : net_.columns();
  return {t[p], t[count]};
}

ControlNet homogeneous_net(const BSplineSurface& surface) {
  const ControlNet& net = surface.control_net();
  return ControlNet::from_trusted(net.rows(), net.columns(),
                                  detail::weighted_rows(net.points(), surface.weights()));
}

BSplineSurface from_homogeneous(int degree_u, int degree_v, std::vector<double> knots_u,
                                std::vector<double> knots_v, const ControlNet& net) {
  auto [points, weights] = detail::projected_rows(net.points());
  return BSplineSurface::from_trusted(degree_u, degree_v, std::move(knots_u), std::move(knots_v),
                                      ControlNet::from_trusted(net.rows(), net.columns(), std::move(points)),
                                      std::move(weights));
}

BSplineSurface transposed(const BSplineSurface& surface) {
  std::vector<double> weights;
  if (surface.is_rational()) {
    const ControlNet& net = surface.control_net();
    weights.resize(surface.weights().size());
    for (std::size_t i = 0; i < net.rows(); ++i)
      for (std::size_t j = 0; j < net.columns(); ++j)
        weights[j * net.rows() + i] = surface.weights()[i * net.columns() + j];
  }
  const auto ku = surface.knots_u(), kv = surface.knots_v();
  return BSplineSurface::from_trusted(surface.degree_v(), surface.degree_u(), std::vector<double>(kv.begin(), kv.end()),
                                      std::vector<double>(ku.begin(), ku.end()), transposed(surface.control_net()),
                                      std::move(weights));
}

}  // namespace casteljau

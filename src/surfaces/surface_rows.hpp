#pragma once
// A tensor-product surface seen along one direction as a curve whose
// control points are whole rows of the net (The NURBS Book §5.2, A5.3:
// "apply the curve algorithm to each column"). Along u, control point i of
// the wide curve is row i of the net flattened: the (m+1) points P_i0..P_im,
// homogeneous (w P, w) for a NURBS surface, so the wide curve is always
// polynomial and every linear curve algorithm (knot insertion, refinement,
// degree elevation, splitting, evaluation) acts on all rows at once, exactly
// as if run column by column. Along v the transposed net is used.
// Internal to src/surfaces.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "../core/homogeneous.hpp"

namespace casteljau::detail {

/// (w P, w) rows of the net, or the net's own points when there are no weights.
inline PointArray weighted_or_plain(const ControlNet& net, std::span<const double> weights) {
  return weights.empty() ? net.points() : weighted_rows(net.points(), weights);
}

/// The net as rows along `direction` (transposed for v), homogeneous if `weights` is not empty.
inline PointArray wide_rows(const ControlNet& net, std::span<const double> weights, Direction direction) {
  const PointArray h = weighted_or_plain(net, weights);
  const std::size_t w = static_cast<std::size_t>(h.dimension());
  const std::size_t rows = net.rows(), columns = net.columns();
  const bool along_u = direction == Direction::u;
  const std::size_t other = along_u ? columns : rows;
  std::vector<double> c(rows * columns * w);
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < columns; ++j) {
      const auto point = h[i * columns + j];
      const std::size_t k = along_u ? i * columns + j : j * rows + i;
      for (std::size_t x = 0; x < w; ++x) c[k * w + x] = point[x];
    }
  return PointArray::from_trusted(static_cast<int>(w * other), std::move(c));
}

/// Rebuilds a net (and weights) from wide rows along `direction`: each wide
/// point holds `other` points of width w (d+1 with the weight last if rational).
inline std::pair<ControlNet, std::vector<double>> net_from_wide(const PointArray& wide, std::size_t other,
                                                                 Direction direction, bool rational) {
  const std::size_t width = static_cast<std::size_t>(wide.dimension()) / other;
  const std::size_t count = wide.size();
  const std::size_t rows = direction == Direction::u ? count : other;
  const std::size_t columns = direction == Direction::u ? other : count;
  std::vector<double> h(rows * columns * width);
  for (std::size_t k = 0; k < count; ++k)
    for (std::size_t o = 0; o < other; ++o) {
      const std::size_t i = direction == Direction::u ? k : o, j = direction == Direction::u ? o : k;
      for (std::size_t x = 0; x < width; ++x) h[(i * columns + j) * width + x] = wide[k][o * width + x];
    }
  PointArray points = PointArray::from_trusted(static_cast<int>(width), std::move(h));
  if (!rational) return {ControlNet::from_trusted(rows, columns, std::move(points)), {}};
  auto [projected, weights] = projected_rows(points);
  return {ControlNet::from_trusted(rows, columns, std::move(projected)), std::move(weights)};
}

/// The surface along `direction` as a polynomial B-spline curve of wide points.
inline BSplineCurve wide_curve(const BSplineSurface& surface, Direction direction) {
  const auto knots = surface.knots(direction);
  return BSplineCurve::from_trusted(surface.degree(direction), std::vector<double>(knots.begin(), knots.end()),
                                    wide_rows(surface.control_net(), surface.weights(), direction));
}

/// The surface whose `direction` is the wide curve and whose other direction is `like`'s.
inline BSplineSurface surface_from_wide(const BSplineCurve& curve, Direction direction, const BSplineSurface& like) {
  const Direction other_direction = direction == Direction::u ? Direction::v : Direction::u;
  const std::size_t other = direction == Direction::u ? like.control_net().columns() : like.control_net().rows();
  auto [net, weights] = net_from_wide(curve.control_points(), other, direction, like.is_rational());
  const auto along = curve.knots();
  const auto across = like.knots(other_direction);
  std::vector<double> knots_along(along.begin(), along.end()), knots_across(across.begin(), across.end());
  if (direction == Direction::u) {
    return BSplineSurface::from_trusted(curve.degree(), like.degree_v(), std::move(knots_along),
                                        std::move(knots_across), std::move(net), std::move(weights));
  }
  return BSplineSurface::from_trusted(like.degree_u(), curve.degree(), std::move(knots_across),
                                      std::move(knots_along), std::move(net), std::move(weights));
}

/// A Bézier patch along `direction` as a polynomial Bézier curve of wide points.
inline BezierCurve wide_curve(const BezierSurface& surface, Direction direction) {
  return BezierCurve::from_trusted(wide_rows(surface.control_net(), surface.weights(), direction));
}

/// The patch whose `direction` is the wide Bézier curve.
inline BezierSurface surface_from_wide(const BezierCurve& curve, Direction direction, const BezierSurface& like) {
  const std::size_t other = direction == Direction::u ? like.control_net().columns() : like.control_net().rows();
  auto [net, weights] = net_from_wide(curve.control_points(), other, direction, like.is_rational());
  return BezierSurface::from_trusted(std::move(net), std::move(weights));
}

/// "u" or "v".
inline const char* direction_name(Direction direction) { return direction == Direction::u ? "u" : "v"; }

/// Refuses results beyond tolerances::kMaxControlPoints points in all.
inline Status check_net_size(std::size_t rows, std::size_t columns) {
  if (rows > tolerances::kMaxControlPoints / columns) {
    return Error{"the result would have " + std::to_string(rows) + " x " + std::to_string(columns) +
                 " control points, above the limit " + std::to_string(tolerances::kMaxControlPoints)};
  }
  return {};
}

}  // namespace casteljau::detail

// Interpolation of a grid of points by a B-spline surface (The NURBS Book A9.4).
#include "casteljau/surfaces/grid_interpolation.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/interpolation/spline_interpolation.hpp"
#include "construction_support.hpp"

namespace casteljau {
namespace {

/// The grid's columns (along u) or rows (along v) as polylines.
std::vector<PointArray> lines_of(const ControlNet& points, Direction direction) {
  const bool along_u = direction == Direction::u;
  const std::size_t lines = along_u ? points.columns() : points.rows();
  const std::size_t count = along_u ? points.rows() : points.columns();
  std::vector<PointArray> out;
  out.reserve(lines);
  for (std::size_t l = 0; l < lines; ++l) {
    PointArray line = PointArray::zeros(points.dimension(), 0);
    for (std::size_t k = 0; k < count; ++k) line.push_back(along_u ? points(k, l) : points(l, k));
    out.push_back(std::move(line));
  }
  return out;
}

Status check_size(std::size_t count, int degree, const char* degree_name, const char* noun) {
  if (degree < 1) return Error{std::string(degree_name) + " is " + std::to_string(degree) + ", it must be >= 1"};
  if (count < 2 || static_cast<std::size_t>(degree) + 1 > count) {
    return Error{"a grid of " + std::to_string(count) + " " + noun + "s cannot be interpolated with " + degree_name +
                 " " + std::to_string(degree) + ", it needs at least " + std::to_string(std::max(degree + 1, 2)) + " " +
                 noun + "s"};
  }
  return {};
}

}  // namespace

Expected<GridParameters> grid_parameters(const ControlNet& points, Parameterization parameterization) {
  if (points.rows() < 2 || points.columns() < 2) {
    return Error{"a grid of " + std::to_string(points.rows()) + " x " + std::to_string(points.columns()) +
                 " points has no parameters, it needs at least 2 rows and 2 columns"};
  }
  auto u = detail::averaged_parameters(lines_of(points, Direction::u), parameterization, "row");
  if (!u) return u.error();
  auto v = detail::averaged_parameters(lines_of(points, Direction::v), parameterization, "column");
  if (!v) return v.error();
  return GridParameters{std::move(*u), std::move(*v)};
}

Expected<BSplineSurface> interpolate_grid(const ControlNet& points, int degree_u, int degree_v,
                                          Parameterization parameterization) {
  if (auto ok = check_size(points.rows(), degree_u, "degree_u", "row"); !ok) return ok.error();
  if (auto ok = check_size(points.columns(), degree_v, "degree_v", "column"); !ok) return ok.error();
  auto parameters = grid_parameters(points, parameterization);
  if (!parameters) return parameters.error();
  const std::size_t columns = points.columns();
  const std::size_t d = static_cast<std::size_t>(points.dimension());

  // Along u: row k of the grid is one wide point; the interpolant's control
  // point i is the row R_i0..R_im of the intermediate net.
  const PointArray grid_rows = PointArray::from_trusted(static_cast<int>(columns * d),
                                                        std::vector<double>(points.points().coordinates().begin(),
                                                                            points.points().coordinates().end()));
  auto along_u = interpolate_bspline(grid_rows, parameters->u, degree_u);
  if (!along_u) return with_context(along_u.error(), "interpolating the columns");
  const std::size_t net_rows = along_u->control_points().size();

  // Along v: column l of R (R_0l..R_{n'}l) is one wide point.
  std::vector<double> transposed_r(net_rows * columns * d);
  for (std::size_t i = 0; i < net_rows; ++i) {
    const auto row = along_u->control_points()[i];
    for (std::size_t l = 0; l < columns; ++l)
      for (std::size_t c = 0; c < d; ++c) transposed_r[(l * net_rows + i) * d + c] = row[l * d + c];
  }
  auto along_v = interpolate_bspline(PointArray::from_trusted(static_cast<int>(net_rows * d), std::move(transposed_r)),
                                     parameters->v, degree_v);
  if (!along_v) return with_context(along_v.error(), "interpolating the rows");
  const std::size_t net_columns = along_v->control_points().size();
  std::vector<double> coordinates(net_rows * net_columns * d);
  for (std::size_t j = 0; j < net_columns; ++j) {
    const auto column = along_v->control_points()[j];
    for (std::size_t i = 0; i < net_rows; ++i)
      for (std::size_t c = 0; c < d; ++c) coordinates[(i * net_columns + j) * d + c] = column[i * d + c];
  }
  return BSplineSurface::from_trusted(
      degree_u, degree_v, std::vector<double>(along_u->knots().begin(), along_u->knots().end()),
      std::vector<double>(along_v->knots().begin(), along_v->knots().end()),
      ControlNet::from_trusted(net_rows, net_columns, PointArray::from_trusted(static_cast<int>(d), std::move(coordinates))));
}

}  // namespace casteljau

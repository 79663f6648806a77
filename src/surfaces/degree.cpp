// Degree elevation of surfaces in one direction, through the curve
// algorithms on the rows of the homogeneous net (surface_rows.hpp).
#include "casteljau/surfaces/degree.hpp"

#include <string>

#include "casteljau/bezier/degree.hpp"
#include "casteljau/bspline/degree.hpp"
#include "casteljau/core/tolerance.hpp"
#include "surface_rows.hpp"

namespace casteljau {

Expected<BSplineSurface> elevate_degree(const BSplineSurface& surface, Direction direction, int times) {
  const std::string where = std::string("direction ") + detail::direction_name(direction) + ": ";
  if (times < 0) return Error{where + "cannot elevate the degree " + std::to_string(times) + " times, times must be >= 0"};
  if (times == 0) return surface;
  auto curve = elevate_degree(detail::wide_curve(surface, direction), times);
  if (!curve) return Error{where + curve.error().message, curve.error().kind};
  const std::size_t other = direction == Direction::u ? surface.control_net().columns() : surface.control_net().rows();
  if (auto ok = detail::check_net_size(curve->control_points().size(), other); !ok) return ok.error();
  return detail::surface_from_wide(*curve, direction, surface);
}

Expected<BezierSurface> elevate_degree(const BezierSurface& surface, Direction direction, int times) {
  const std::string where = std::string("direction ") + detail::direction_name(direction) + ": ";
  if (times < 0) return Error{where + "cannot elevate the degree " + std::to_string(times) + " times, times must be >= 0"};
  const int degree = direction == Direction::u ? surface.degree_u() : surface.degree_v();
  if (times > tolerances::kMaxBezierDegree - degree) {
    return Error{where + "degree " + std::to_string(degree) + " + " + std::to_string(times) +
                 " is above the limit " + std::to_string(tolerances::kMaxBezierDegree)};
  }
  if (times == 0) return surface;
  const std::size_t other = direction == Direction::u ? surface.control_net().columns() : surface.control_net().rows();
  if (auto ok = detail::check_net_size(static_cast<std::size_t>(degree + times) + 1, other); !ok) return ok.error();
  return detail::surface_from_wide(elevate_degree(detail::wide_curve(surface, direction), times), direction, surface);
}

}  // namespace casteljau

// Splitting surfaces along one direction, through the curves' split_at on
// the rows of the homogeneous net (surface_rows.hpp).
#include "casteljau/surfaces/split.hpp"

#include <cmath>
#include <string>

#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/transform.hpp"
#include "../core/number_text.hpp"
#include "surface_rows.hpp"

namespace casteljau {

Expected<std::pair<BSplineSurface, BSplineSurface>> split_at(const BSplineSurface& surface, Direction direction,
                                                             double value) {
  auto parts = split_at(detail::wide_curve(surface, direction), value);
  if (!parts) return with_context(parts.error(), std::string("direction ") + detail::direction_name(direction));
  return std::pair<BSplineSurface, BSplineSurface>(detail::surface_from_wide(parts->first, direction, surface),
                                                   detail::surface_from_wide(parts->second, direction, surface));
}

Expected<std::pair<BezierSurface, BezierSurface>> split_at(const BezierSurface& surface, Direction direction,
                                                           double t) {
  const std::string name = detail::direction_name(direction);
  if (auto ok = check_finite(t, "the split parameter " + name); !ok) return ok.error();
  if (!(t > 0.0 && t < 1.0)) {
    return Error{"the split parameter " + name + " = " + detail::number_text(t) +
                 " is not strictly inside the domain (0, 1)", ErrorKind::out_of_domain};
  }
  auto [first, second] = split_at(detail::wide_curve(surface, direction), t).value();  // t checked above
  return std::pair<BezierSurface, BezierSurface>(detail::surface_from_wide(first, direction, surface),
                                                 detail::surface_from_wide(second, direction, surface));
}

}  // namespace casteljau

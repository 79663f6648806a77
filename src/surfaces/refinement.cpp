// Knot insertion and refinement of surfaces in one direction, through the
// curve algorithms on the rows of the homogeneous net (surface_rows.hpp).
#include "casteljau/surfaces/refinement.hpp"

#include <string>

#include "casteljau/bspline/knot_insertion.hpp"
#include "casteljau/bspline/transform.hpp"
#include "surface_rows.hpp"

namespace casteljau {
namespace {

Expected<BSplineSurface> rebuilt(Expected<BSplineCurve> curve, const BSplineSurface& surface, Direction direction) {
  if (!curve) return with_context(curve.error(), std::string("direction ") + detail::direction_name(direction));
  const std::size_t other = direction == Direction::u ? surface.control_net().columns() : surface.control_net().rows();
  if (auto ok = detail::check_net_size(curve->control_points().size(), other); !ok) return ok.error();
  return detail::surface_from_wide(*curve, direction, surface);
}

}  // namespace

Expected<BSplineSurface> insert_knot(const BSplineSurface& surface, Direction direction, double value, int times) {
  // times = 0 still checks the value (the curve's insert_knot does).
  return rebuilt(insert_knot(detail::wide_curve(surface, direction), value, times), surface, direction);
}

Expected<BSplineSurface> refine_knots(const BSplineSurface& surface, Direction direction,
                                      std::span<const double> new_knots) {
  if (new_knots.empty()) return surface;
  return rebuilt(refine_knots(detail::wide_curve(surface, direction), new_knots), surface, direction);
}

BSplineSurface clamped(const BSplineSurface& surface, Direction direction) {
  return detail::surface_from_wide(clamped(detail::wide_curve(surface, direction)), direction, surface);
}

}  // namespace casteljau

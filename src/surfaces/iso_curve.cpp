// Iso-parametric curves: the surface along the fixed direction (a curve of
// whole rows of the homogeneous net) evaluated at the fixed value gives the
// control points of the curve of the other direction (surface_rows.hpp).
#include "casteljau/surfaces/iso_curve.hpp"

#include <string>
#include <utility>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "../core/homogeneous.hpp"
#include "../core/number_text.hpp"
#include "surface_rows.hpp"

namespace casteljau {
namespace {

Status check_value(double value, Interval domain, Direction fixed) {
  const std::string name = std::string("the iso-curve parameter ") + detail::direction_name(fixed);
  if (auto ok = check_finite(value, name); !ok) return ok;
  if (!domain.contains(value)) {
    return Error{name + " = " + detail::number_text(value) + " is outside the domain [" +
                 detail::number_text(domain.lower) + ", " + detail::number_text(domain.upper) + "]", ErrorKind::out_of_domain};
  }
  return {};
}

/// The wide point (the control points of the iso-curve side by side) as points of width w.
PointArray split_wide_point(const Point& wide, std::size_t width) {
  return PointArray::from_trusted(static_cast<int>(width), std::vector<double>(wide.begin(), wide.end()));
}

}  // namespace

Expected<BSplineCurve> iso_curve(const BSplineSurface& surface, Direction fixed, double value) {
  if (auto ok = check_value(value, surface.domain(fixed), fixed); !ok) return ok.error();
  const Point wide = point_at(detail::wide_curve(surface, fixed), value);
  const Direction free = fixed == Direction::u ? Direction::v : Direction::u;
  const auto knots = surface.knots(free);
  std::vector<double> free_knots(knots.begin(), knots.end());
  const std::size_t width = static_cast<std::size_t>(surface.dimension() + (surface.is_rational() ? 1 : 0));
  PointArray points = split_wide_point(wide, width);
  if (surface.is_rational()) return from_homogeneous(surface.degree(free), std::move(free_knots), points);
  return BSplineCurve::from_trusted(surface.degree(free), std::move(free_knots), std::move(points));
}

Expected<BezierCurve> iso_curve(const BezierSurface& surface, Direction fixed, double value) {
  if (auto ok = check_value(value, Interval{0.0, 1.0}, fixed); !ok) return ok.error();
  const Point wide = point_at(detail::wide_curve(surface, fixed), value);
  const std::size_t width = static_cast<std::size_t>(surface.dimension() + (surface.is_rational() ? 1 : 0));
  PointArray points = split_wide_point(wide, width);
  if (surface.is_rational()) return from_homogeneous(points);
  return BezierCurve::from_trusted(std::move(points));
}

}  // namespace casteljau

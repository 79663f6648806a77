// Curves made compatible: one domain, one degree, one knot vector
// (The NURBS Book §10.3).
#include "casteljau/surfaces/compatible_curves.hpp"

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "casteljau/bspline/degree.hpp"
#include "casteljau/bspline/knot_insertion.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/bspline/transform.hpp"
#include "construction_support.hpp"

namespace casteljau {
namespace detail {

Expected<std::vector<BSplineCurve>> unify_curves(std::vector<BSplineCurve> curves) {
  int degree = 0;
  for (const auto& curve : curves) degree = std::max(degree, curve.degree());
  for (auto& curve : curves) {
    auto elevated = elevate_degree(curve, degree - curve.degree());
    if (!elevated) return elevated.error();
    curve = std::move(*elevated);
  }
  // The highest multiplicity of every knot value over all curves (exact
  // comparison: the curves share their domain ends exactly).
  std::map<double, int> highest;
  for (const auto& curve : curves) {
    for (const auto& knot : knot_multiplicities(curve.knots())) {
      int& m = highest[knot.value];
      m = std::max(m, knot.multiplicity);
    }
  }
  for (auto& curve : curves) {
    std::vector<double> missing;
    for (const auto& [value, multiplicity] : highest) {
      const int have = multiplicity_of(curve.knots(), value);
      missing.insert(missing.end(), static_cast<std::size_t>(multiplicity - have), value);
    }
    if (missing.empty()) continue;
    auto refined = refine_knots(curve, missing);
    if (!refined) return refined.error();
    curve = std::move(*refined);
  }
  return curves;
}

Expected<std::vector<BSplineCurve>> make_compatible_named(std::span<const BSplineCurve> curves, const char* noun) {
  if (curves.empty()) return Error{std::string("no ") + noun + " to make compatible"};
  const int dimension = curves[0].dimension();
  bool any_rational = false;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    if (curves[k].dimension() != dimension) {
      return Error{std::string(noun) + " " + std::to_string(k) + " has " + std::to_string(curves[k].dimension()) +
                   " coordinates, " + noun + " 0 has " + std::to_string(dimension) + "; compatible " + noun +
                   "s need one dimension"};
    }
    any_rational = any_rational || curves[k].is_rational();
  }
  std::vector<BSplineCurve> prepared;
  prepared.reserve(curves.size());
  const Interval unit{0.0, 1.0};
  for (const auto& curve : curves) {
    BSplineCurve c = clamped(curve);
    if (c.domain() != unit) c = *reparameterized(c, unit);  // a valid domain maps without error
    if (any_rational && !c.is_rational()) {
      const std::size_t count = c.control_points().size();
      const auto knots = c.knots();
      c = BSplineCurve::from_trusted(c.degree(), std::vector<double>(knots.begin(), knots.end()), c.control_points(),
                                     std::vector<double>(count, 1.0));
    }
    prepared.push_back(std::move(c));
  }
  return unify_curves(std::move(prepared));
}

}  // namespace detail

Expected<std::vector<BSplineCurve>> make_compatible(std::span<const BSplineCurve> curves) {
  return detail::make_compatible_named(curves, "curve");
}

}  // namespace casteljau

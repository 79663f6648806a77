// Natural splines of order q in the B-spline basis (see natural_spline.hpp).
#include "casteljau/interpolation/natural_spline.hpp"
#include "casteljau/interpolation/tolerance.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "collocation.hpp"

namespace casteljau {

Expected<BSplineCurve> interpolate_natural(const PointArray& points, std::span<const double> parameters, int order) {
  const int q = order;
  if (q < 1 || q > tolerances::kMaxNaturalSplineOrder) {
    return Error{"natural spline order " + std::to_string(q) + " is outside 1.." +
                 std::to_string(tolerances::kMaxNaturalSplineOrder)};
  }
  const std::size_t m1 = points.size();
  const std::string method = "the natural spline of order " + std::to_string(q);
  if (auto ok = detail::check_interpolation_input(points, parameters, m1, std::max<std::size_t>(2, static_cast<std::size_t>(q)),
                                                  method);
      !ok) {
    return ok.error();
  }
  // Degree 2q-1, a simple knot at each interior parameter (C^(2q-2) there),
  // and the q-1 natural conditions s^(j) = 0, j = q..2q-2, at each end: they
  // say the minimizer continues as a polynomial of degree q-1 outside
  // [t_0, t_m] (de Boor, A Practical Guide to Splines, ch. XIII).
  const int p = 2 * q - 1;
  std::vector<double> knots;
  knots.reserve(m1 + 2 * static_cast<std::size_t>(p));
  knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, parameters.front());
  knots.insert(knots.end(), parameters.begin() + 1, parameters.end() - 1);
  knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, parameters.back());
  std::vector<detail::EndConstraint> constraints;
  for (int j = q; j <= 2 * q - 2; ++j) {
    constraints.push_back({false, j, {}});
    constraints.push_back({true, j, {}});
  }
  auto control = detail::solve_collocation(p, knots, parameters, points, constraints);
  if (!control) return control.error();
  return BSplineCurve::from_trusted(p, std::move(knots), std::move(*control));
}

}  // namespace casteljau

// Derivative and antiderivative curves of polynomial B-splines, and the
// definite integral through the antiderivative.
#include "casteljau/bspline/hodograph.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"

namespace casteljau {

namespace {

using detail::number_text;

Error rational_refused(const char* what) {
  return Error{std::string("the ") + what +
               " of a rational (NURBS) curve is not a B-spline curve of that form: only polynomial curves are "
               "accepted"};
}

/// Drops the basis functions that vanish identically: in a run of equal
/// knots t_a = ... = t_b longer than p+1, N_{i,p} for a <= i <= b-p-1 has an
/// empty support; removing those control points and b-a-p knots of the run
/// leaves every other basis function's knots, hence the curve, unchanged
/// and every multiplicity at most p+1 (as validate_knots requires).
void drop_null_basis_functions(int degree, std::vector<double>& knots, std::vector<double>& coordinates,
                               std::size_t d) {
  const std::size_t p = static_cast<std::size_t>(degree);
  std::vector<double> kept_knots, kept_coordinates;
  kept_knots.reserve(knots.size());
  kept_coordinates.reserve(coordinates.size());
  const std::size_t count = coordinates.size() / d;  // n + 1
  std::size_t next_point = 0;  // points before it are copied or dropped
  std::size_t a = 0;
  while (a < knots.size()) {
    std::size_t b = a;
    while (b + 1 < knots.size() && knots[b + 1] == knots[a]) ++b;
    const std::size_t run = b - a + 1;
    if (run > p + 1) {
      // Points a .. b-p-1 vanish: copy those before a, skip these.
      for (; next_point < a && next_point < count; ++next_point)
        kept_coordinates.insert(kept_coordinates.end(), coordinates.begin() + static_cast<std::ptrdiff_t>(next_point * d),
                                coordinates.begin() + static_cast<std::ptrdiff_t>((next_point + 1) * d));
      next_point = b - p;
      kept_knots.insert(kept_knots.end(), p + 1, knots[a]);
    } else {
      kept_knots.insert(kept_knots.end(), run, knots[a]);
    }
    a = b + 1;
  }
  if (kept_knots.size() == knots.size()) return;
  for (; next_point < count; ++next_point)
    kept_coordinates.insert(kept_coordinates.end(), coordinates.begin() + static_cast<std::ptrdiff_t>(next_point * d),
                            coordinates.begin() + static_cast<std::ptrdiff_t>((next_point + 1) * d));
  knots = std::move(kept_knots);
  coordinates = std::move(kept_coordinates);
}

/// One differentiation of a polynomial curve of degree p >= 1 (A3.3).
BSplineCurve differentiated(const BSplineCurve& curve) {
  const int p = curve.degree();
  const auto t = curve.knots();
  const PointArray& points = curve.control_points();
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  const std::size_t n = points.size() - 1;
  std::vector<double> coordinates(n * d, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double step = t[i + static_cast<std::size_t>(p) + 1] - t[i + 1];
    if (step == 0.0) continue;  // N_{i+1,p-1} is identically zero: dropped below
    for (std::size_t c = 0; c < d; ++c)
      coordinates[i * d + c] = (points[i + 1][c] - points[i][c]) * p / step;
  }
  std::vector<double> knots(t.begin() + 1, t.end() - 1);
  drop_null_basis_functions(p - 1, knots, coordinates, d);
  return BSplineCurve::from_trusted(p - 1, std::move(knots),
                                    PointArray::from_trusted(static_cast<int>(d), std::move(coordinates)));
}

/// One integration of a polynomial curve (the running sum of splantider).
BSplineCurve integrated(const BSplineCurve& curve) {
  const std::size_t p = static_cast<std::size_t>(curve.degree());
  const auto t = curve.knots();
  const PointArray& points = curve.control_points();
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  const std::size_t count = points.size();  // n + 1
  std::vector<double> coordinates((count + 1) * d, 0.0);
  std::vector<double> sum(d, 0.0);
  const double order = static_cast<double>(p + 1);
  for (std::size_t j = 0; j < count; ++j) {
    const double width = t[j + p + 1] - t[j];
    for (std::size_t c = 0; c < d; ++c) {
      sum[c] += points[j][c] * width;
      coordinates[(j + 1) * d + c] = sum[c] / order;
    }
  }
  std::vector<double> knots;
  knots.reserve(t.size() + 2);
  knots.push_back(t.front());
  knots.insert(knots.end(), t.begin(), t.end());
  knots.push_back(t.back());
  return BSplineCurve::from_trusted(static_cast<int>(p) + 1, std::move(knots),
                                    PointArray::from_trusted(static_cast<int>(d), std::move(coordinates)));
}

}  // namespace

Expected<BSplineCurve> derivative_curve(const BSplineCurve& curve, int order) {
  if (order < 0) return Error{"derivative order " + std::to_string(order) + " is negative"};
  if (curve.is_rational()) return rational_refused("derivative");
  if (order > curve.degree()) {
    const Interval domain = curve.domain();
    return BSplineCurve::from_trusted(0, {domain.lower, domain.upper}, PointArray::zeros(curve.dimension(), 1));
  }
  BSplineCurve result = curve;
  for (int k = 0; k < order; ++k) result = differentiated(result);
  return result;
}

Expected<BSplineCurve> antiderivative_curve(const BSplineCurve& curve, int order) {
  if (order < 0) return Error{"antiderivative order " + std::to_string(order) + " is negative"};
  if (curve.is_rational()) return rational_refused("antiderivative");
  if (order > tolerances::kMaxBSplineDegree - curve.degree())
    return Error{"antiderivative order " + std::to_string(order) + " of a curve of degree " +
                 std::to_string(curve.degree()) + " gives a degree above the limit " +
                 std::to_string(tolerances::kMaxBSplineDegree)};
  if (static_cast<std::size_t>(order) > tolerances::kMaxControlPoints - curve.control_points().size())
    return Error{"antiderivative order " + std::to_string(order) + " gives more control points than the limit " +
                 std::to_string(tolerances::kMaxControlPoints), ErrorKind::limit};
  BSplineCurve result = curve;
  for (int k = 0; k < order; ++k) result = integrated(result);
  return result;
}

Expected<Point> integral(const BSplineCurve& curve, double a, double b) {
  if (!std::isfinite(a)) return Error{"the lower integration limit " + number_text(a) + " is not finite"};
  if (!std::isfinite(b)) return Error{"the upper integration limit " + number_text(b) + " is not finite"};
  if (curve.is_rational()) return rational_refused("integral");
  const Expected<BSplineCurve> antiderivative = antiderivative_curve(curve, 1);
  if (!antiderivative) return antiderivative.error();
  Point upper = point_at(*antiderivative, b);
  const Point lower = point_at(*antiderivative, a);
  for (std::size_t c = 0; c < upper.size(); ++c) upper[c] -= lower[c];
  return upper;
}

}  // namespace casteljau

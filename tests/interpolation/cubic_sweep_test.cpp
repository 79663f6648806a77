// The tridiagonal sweeps of the cubic interpolant (src/interpolation/
// cubic_sweep.hpp) against the general banded solver with partial pivoting
// (collocation.hpp), an independent factorization of the same collocation
// system: random point sets, dimensions 1 to 4, parameter steps whose ratios
// span six orders of magnitude, every end condition. The general solver is
// itself checked against exact rational arithmetic and scipy elsewhere
// (spline_interpolation_test.cpp, tests/python/test_interpolate_scipy.py).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../../src/interpolation/collocation.hpp"
#include "../../src/interpolation/cubic_sweep.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

struct Data {
  PointArray points;
  std::vector<double> parameters;  // strictly increasing, one more than the points when closed
};

Data random_data(bool closed, int spread) {
  const int count = *rc::gen::inRange(5, 60);
  const int d = *rc::gen::inRange(1, 5);
  std::vector<double> coordinates;
  for (int i = 0; i < count * d; ++i) coordinates.push_back(*test::coordinate());
  std::vector<double> parameters{*rc::gen::inRange(-100, 100) * 0.1};
  const int steps = closed ? count : count - 1;
  for (int i = 0; i < steps; ++i) {
    // spread 30: steps from 1e-3 to 1e3, neighbouring spans of very different
    // lengths; spread 3: steps within a factor 4 of each other.
    parameters.push_back(parameters.back() + std::pow(10.0, *rc::gen::inRange(-spread, spread + 1) * 0.1));
  }
  return {PointArray::make(d, std::move(coordinates)).value(), std::move(parameters)};
}

std::vector<double> clamped_knots(std::span<const double> parameters, std::size_t first, std::size_t end) {
  std::vector<double> knots(4, parameters.front());
  knots.insert(knots.end(), parameters.begin() + static_cast<std::ptrdiff_t>(first),
               parameters.begin() + static_cast<std::ptrdiff_t>(end));
  knots.insert(knots.end(), 4, parameters.back());
  return knots;
}

double largest_difference(std::span<const double> a, std::span<const double> b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(a[i] - b[i]));
  return largest;
}

// Neighbouring steps that differ by 1e6 make the collocation matrix badly
// conditioned (1e8 and more on the worst draws), so two correct
// factorizations may differ by that factor times the rounding in their
// control points. What a solver owes is a small residual (backward
// stability): the curve must pass through the points as closely as the
// pivoted solver's does; that is checked on every draw. The control points
// themselves are compared when the steps stay within a factor 4 of each
// other (condition below 10).
const int kWildSteps = 30;
const int kTameSteps = 3;
double tolerance_for(const PointArray& points, int spread) {
  return spread == kTameSteps ? 1e-12 * std::max(scale_of(points), 1.0) : HUGE_VAL;
}

/// max_i |C(t_i) - P_i| for the curve of the given control points.
double residual(int degree, std::vector<double> knots, std::span<const double> control, const PointArray& points,
                std::span<const double> sites) {
  const int d = points.dimension();
  const auto curve = BSplineCurve::make(degree, std::move(knots),
                                        PointArray::make(d, std::vector<double>(control.begin(), control.end())).value());
  double largest = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point at = point_at(curve.value(), sites[i]);
    largest = std::max(largest, distance(at, points[i]));
  }
  return largest;
}

// The sweep's residual is within a small factor of the pivoted solver's.
bool as_accurate(double sweep, double reference, const PointArray& points) {
  return sweep <= 4.0 * reference + 1e-13 * std::max(scale_of(points), 1.0);
}

RC_GTEST_PROP(CubicSweep, NaturalAndClampedEqualTheBandedSolver, ()) {
  const int spread = *rc::gen::element(kWildSteps, kTameSteps);
  const Data data = random_data(false, spread);
  const std::size_t m = data.points.size() - 1;
  const auto d = static_cast<std::size_t>(data.points.dimension());
  const auto knots = clamped_knots(data.parameters, 1, m);
  for (const bool clamped : {false, true}) {
    CubicEnds ends{clamped ? EndCondition::clamped : EndCondition::natural, {}, {}};
    std::vector<detail::EndConstraint> constraints;
    if (clamped) {
      for (std::size_t k = 0; k < d; ++k) {
        ends.start_tangent.push_back(*test::coordinate());
        ends.end_tangent.push_back(*test::coordinate());
      }
      constraints = {{false, 1, ends.start_tangent}, {true, 1, ends.end_tangent}};
    } else {
      constraints = {{false, 2, {}}, {true, 2, {}}};
    }
    std::vector<double> control((m + 3) * d);
    RC_ASSERT(detail::sweep_cubic_at_knots(knots, data.points, ends, control));
    const auto reference = detail::solve_collocation(3, knots, data.parameters, data.points, constraints);
    RC_ASSERT(reference.has_value());
    RC_ASSERT(largest_difference(control, reference->coordinates()) <= tolerance_for(data.points, spread));
    RC_ASSERT(as_accurate(residual(3, knots, control, data.points, data.parameters),
                          residual(3, knots, reference->coordinates(), data.points, data.parameters), data.points));
  }
}

RC_GTEST_PROP(CubicSweep, NotAKnotEqualsTheBandedSolver, ()) {
  const int spread = *rc::gen::element(kWildSteps, kTameSteps);
  const Data data = random_data(false, spread);
  const std::size_t m = data.points.size() - 1;
  const auto d = static_cast<std::size_t>(data.points.dimension());
  const auto knots = clamped_knots(data.parameters, 2, m - 1);
  std::vector<double> control((m + 1) * d);
  RC_ASSERT(detail::sweep_cubic_not_a_knot(knots, data.parameters, data.points, control));
  const auto reference = detail::solve_collocation(3, knots, data.parameters, data.points, {});
  RC_ASSERT(reference.has_value());
  RC_ASSERT(largest_difference(control, reference->coordinates()) <= tolerance_for(data.points, spread));
  RC_ASSERT(as_accurate(residual(3, knots, control, data.points, data.parameters),
                        residual(3, knots, reference->coordinates(), data.points, data.parameters), data.points));
}

RC_GTEST_PROP(CubicSweep, PeriodicEqualsTheWoodburySolver, ()) {
  const int spread = *rc::gen::element(kWildSteps, kTameSteps);
  const Data data = random_data(true, spread);
  const std::size_t count = data.points.size();
  const auto d = static_cast<std::size_t>(data.points.dimension());
  // The periodic knots of interpolate_cubic: the parameter steps continued cyclically.
  const double period = data.parameters[count] - data.parameters[0];
  std::vector<double> knots(count + 7);
  for (std::size_t i = 0; i <= count; ++i) knots[3 + i] = data.parameters[i];
  for (std::size_t i = 0; i < 3; ++i) {
    knots[i] = data.parameters[count - 3 + i] - period;
    knots[count + 4 + i] = data.parameters[1 + i] + period;
  }
  std::vector<double> control((count + 3) * d);
  RC_ASSERT(detail::sweep_cubic_periodic(knots, data.points, control));
  const auto reference = detail::solve_periodic_collocation(3, knots, data.points);
  RC_ASSERT(reference.has_value());
  const std::span<const double> all(control);
  RC_ASSERT(largest_difference(all.first(count * d), reference->coordinates()) <= tolerance_for(data.points, spread));
  for (std::size_t k = 0; k < 3 * d; ++k) RC_ASSERT(control[count * d + k] == control[k]);  // Q_0, Q_1, Q_2 wrap
  std::vector<double> wrapped(reference->coordinates().begin(), reference->coordinates().end());
  wrapped.insert(wrapped.end(), reference->coordinates().begin(), reference->coordinates().begin() + 3 * d);
  const std::span<const double> sites(knots.data() + 3, count);
  RC_ASSERT(as_accurate(residual(3, knots, control, data.points, sites), residual(3, knots, wrapped, data.points, sites),
                        data.points));
}

TEST(CubicSweep, GivesUpOnCoincidentParametersAndNonFinitePoints) {
  const auto points = PointArray::make(2, {0, 0, 1, 1, 2, 0, 3, 1, 4, 0, 5, 1}).value();
  const std::vector<double> repeated{0, 1, 1, 2, 3, 4};
  std::vector<double> control(8 * 2);
  EXPECT_FALSE(detail::sweep_cubic_at_knots(clamped_knots(repeated, 1, 5), points, {EndCondition::natural, {}, {}}, control));
  const auto bad = PointArray::from_trusted(2, {0, 0, 1, 1, 2, std::nan(""), 3, 1, 4, 0, 5, 1});
  const std::vector<double> good{0, 1, 2, 3, 4, 5};
  EXPECT_FALSE(detail::sweep_cubic_at_knots(clamped_knots(good, 1, 5), bad, {EndCondition::natural, {}, {}}, control));
  std::vector<double> six(6 * 2);
  EXPECT_FALSE(detail::sweep_cubic_not_a_knot(clamped_knots(good, 2, 4), good, bad, six));
}

}  // namespace
}  // namespace casteljau

// Natural splines of order q (natural_spline.hpp). References: the seed's
// truncated-power system solved exactly in rationals
// (support/exact_natural_spline.hpp), the minimum property of the energy
// ∫ (s^(q))² (Schoenberg 1964; de Boor, A Practical Guide to Splines, ch. XIII)
// by Gauss–Legendre quadrature, and the cubic and polyline special cases.
#include "casteljau/interpolation/natural_spline.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bspline/continuity.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "casteljau/interpolation/tolerance.hpp"
#include "support/exact.hpp"
#include "support/exact_natural_spline.hpp"
#include "support/generators.hpp"
#include "support/splitmix.hpp"

namespace casteljau {
namespace {

PointArray column(const std::vector<double>& values) { return PointArray::from_trusted(1, values); }

/// Nodes that are multiples of 1/8 with steps 1/8..2, values multiples of
/// 1/16 in [-4, 4]: exact in double, so the rational reference sees the same data.
void dyadic_data(test::SplitMix& random, std::size_t count, std::vector<double>& x, std::vector<double>& y) {
  x.assign(1, random.below(9) / 8.0 - 0.5);
  for (std::size_t i = 1; i < count; ++i) x.push_back(x.back() + (1 + random.below(16)) / 8.0);
  y.clear();
  for (std::size_t i = 0; i < count; ++i) y.push_back((random.below(129) - 64) / 16.0);
}

TEST(InterpolateNatural, MatchesTheExactTruncatedPowerSolution) {
  test::SplitMix random{20261122};
  for (int q = 2; q <= 4; ++q) {
    for (std::size_t count = static_cast<std::size_t>(q); count <= 8; ++count) {
      std::vector<double> x, y;
      dyadic_data(random, std::max<std::size_t>(count, 2), x, y);
      std::vector<mpq_class> ex(x.begin(), x.end()), ey(y.begin(), y.end());
      const auto exact = test::ExactNaturalSpline::solve(q, ex, ey);
      // The reference itself: it interpolates and meets the natural end
      // conditions exactly (the side conditions sum d_i x_i^k = 0 imply them).
      for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(exact.value(ex[i]), ey[i]);
      for (int j = q; j <= 2 * q - 2; ++j) {
        ASSERT_EQ(exact.derivative(ex.front(), j), 0) << "q " << q << " order " << j;
        ASSERT_EQ(exact.derivative(ex.back(), j), 0) << "q " << q << " order " << j;
      }
      const auto curve = interpolate_natural(column(y), x, q);
      ASSERT_TRUE(curve.has_value()) << curve.error().message;
      ASSERT_EQ(curve->degree(), 2 * q - 1);
      // Every derivative up to 2q-2 at 65 dyadic points (nodes included when
      // they fall on the grid) and at the nodes, relative to its own scale.
      std::vector<double> samples(x.begin(), x.end());
      for (int k = 0; k <= 64; ++k) samples.push_back(x.front() + (x.back() - x.front()) * k / 64.0);
      for (int r = 0; r <= 2 * q - 2; ++r) {
        double scale = 0.0;
        for (double u : samples) scale = std::max(scale, std::abs(exact.derivative(mpq_class(u), r).get_d()));
        // Rounding in a derivative of order r is relative to the data's
        // scale over the shortest step to the power r: the floor when the
        // exact derivative vanishes (a line through two points).
        double step = x.back() - x.front(), largest = 1e-300;
        for (std::size_t i = 0; i + 1 < x.size(); ++i) step = std::min(step, x[i + 1] - x[i]);
        for (double v : y) largest = std::max(largest, std::abs(v));
        scale = std::max(scale, largest / std::pow(step, r));
        for (double u : samples) {
          const double computed = derivative_at(*curve, u, r)[0];
          EXPECT_LE(test::error_of(computed, exact.derivative(mpq_class(u), r)), 1e-10 * scale)
              << "q " << q << ", " << count << " points, derivative " << r << " at " << u;
        }
      }
    }
  }
}

TEST(InterpolateNatural, OrderTwoIsTheNaturalCubicSpline) {
  const std::vector<double> t{0.0, 0.5, 1.75, 2.0, 3.5, 4.0};
  const auto points = PointArray::from_trusted(2, {0, 0, 1, 2, 2, -1, 3, 0.5, 4, 4, 5, 1});
  const auto natural = interpolate_natural(points, t, 2);
  const auto cubic = interpolate_cubic(points, t, CubicEnds{EndCondition::natural, {}, {}});
  ASSERT_TRUE(natural && cubic);
  // Same knots and system; interpolate_cubic solves it by its tridiagonal
  // sweep, interpolate_natural by the banded LU: equal up to rounding.
  EXPECT_TRUE(std::equal(natural->knots().begin(), natural->knots().end(), cubic->knots().begin(), cubic->knots().end()));
  const auto a = natural->control_points().coordinates(), b = cubic->control_points().coordinates();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-14 * 5) << i;
}

TEST(InterpolateNatural, OrderOneIsThePolyline) {
  const std::vector<double> t{0.0, 1.0, 1.5, 4.0};
  const auto points = PointArray::from_trusted(2, {0, 0, 1, 2, 2, -1, 3, 0.5});
  const auto curve = interpolate_natural(points, t, 1);
  ASSERT_TRUE(curve.has_value());
  EXPECT_EQ(curve->degree(), 1);
  EXPECT_EQ(curve->control_points(), points);
  EXPECT_EQ(std::vector<double>(curve->knots().begin(), curve->knots().end()),
            (std::vector<double>{0.0, 0.0, 1.0, 1.5, 4.0, 4.0}));
}

TEST(InterpolateNatural, CoordinatesAreIndependentFunctions) {
  const std::vector<double> t{0.0, 0.25, 1.0, 1.5, 2.75, 3.0, 4.0};
  const std::vector<double> xs{1, 3, -2, 0.5, 7, 2, 1}, ys{0, 1, 4, 9, 16, 25, 36};
  std::vector<double> both;
  for (std::size_t i = 0; i < t.size(); ++i) both.insert(both.end(), {xs[i], ys[i]});
  const auto curve = interpolate_natural(PointArray::from_trusted(2, both), t, 3);
  const auto first = interpolate_natural(column(xs), t, 3);
  const auto second = interpolate_natural(column(ys), t, 3);
  ASSERT_TRUE(curve && first && second);
  for (std::size_t i = 0; i < curve->control_points().size(); ++i) {
    EXPECT_EQ(curve->control_points()[i][0], first->control_points()[i][0]);
    EXPECT_EQ(curve->control_points()[i][1], second->control_points()[i][0]);
  }
}

/// Gauss–Legendre nodes and weights on [-1, 1] (Newton on P_n from the
/// three-term recurrence; Golub & Welsch would do as well).
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    nodes[static_cast<std::size_t>(i)] = x;
    weights[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
}

TEST(InterpolateNatural, MinimizesTheEnergyAmongInterpolants) {
  // phi(x) = prod (x - x_i) vanishes at every node, so s + a phi interpolates
  // the same data; the natural spline's energy must be the smallest, and the
  // cross term ∫ s^(q) phi^(q) must vanish (the orthogonality behind it).
  std::vector<double> gl_nodes, gl_weights;
  gauss_legendre(16, gl_nodes, gl_weights);  // exact for degree 31 per span
  test::SplitMix random{7};
  for (int q = 2; q <= 3; ++q) {
    std::vector<double> x, y;
    dyadic_data(random, 6, x, y);
    const auto curve = interpolate_natural(column(y), x, q);
    ASSERT_TRUE(curve.has_value());
    // phi's coefficients in the monomial basis (degree 6).
    std::vector<double> phi{1.0};
    for (double node : x) {
      std::vector<double> next(phi.size() + 1, 0.0);
      for (std::size_t k = 0; k < phi.size(); ++k) {
        next[k + 1] += phi[k];
        next[k] -= node * phi[k];
      }
      phi = next;
    }
    const auto phi_derivative = [&](double u) {
      double value = 0.0;
      for (std::size_t k = static_cast<std::size_t>(q); k < phi.size(); ++k) {
        double falling = 1.0;
        for (int i = 0; i < q; ++i) falling *= static_cast<double>(k) - i;
        value += phi[k] * falling * std::pow(u, static_cast<double>(k) - q);
      }
      return value;
    };
    double energy = 0.0, cross = 0.0, phi_energy = 0.0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
      const double half = (x[i + 1] - x[i]) / 2, middle = (x[i + 1] + x[i]) / 2;
      for (std::size_t k = 0; k < gl_nodes.size(); ++k) {
        const double u = middle + half * gl_nodes[k];
        const double s = derivative_at(*curve, u, q)[0], f = phi_derivative(u);
        energy += gl_weights[k] * half * s * s;
        cross += gl_weights[k] * half * s * f;
        phi_energy += gl_weights[k] * half * f * f;
      }
    }
    ASSERT_GT(energy, 0.0);
    EXPECT_LE(std::abs(cross), 1e-9 * std::sqrt(energy * phi_energy)) << "q " << q;
    for (double a : {-10.0, -1.0, -1e-3, 1e-3, 1.0, 10.0}) {
      const double scaled = a * std::sqrt(energy / phi_energy);  // comparable sizes
      const double perturbed = energy + 2 * scaled * cross + scaled * scaled * phi_energy;
      EXPECT_GT(perturbed, energy) << "q " << q << ", a " << a;
    }
  }
}

RC_GTEST_PROP(InterpolateNatural, ReproducesPolynomialsOfDegreeBelowQ, ()) {
  const int q = *rc::gen::inRange(1, 5);
  const int count = *rc::gen::inRange(std::max(q, 2), 12);
  std::vector<double> t{static_cast<double>(*rc::gen::inRange(-20, 20))};
  for (int i = 1; i < count; ++i) t.push_back(t.back() + *rc::gen::inRange(1, 40) / 8.0);
  const std::vector<double> c = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(q), test::coordinate());
  const auto poly = [&](double u) {
    double v = 0.0;
    for (std::size_t k = c.size(); k-- > 0;) v = v * u + c[k];
    return v;
  };
  std::vector<double> y;
  for (double u : t) y.push_back(poly(u));
  const auto curve = interpolate_natural(column(y), t, q);
  RC_ASSERT(curve.has_value());
  double scale = 1e-300;
  for (int k = 0; k <= 32; ++k) scale = std::max(scale, std::abs(poly(t.front() + (t.back() - t.front()) * k / 32.0)));
  for (int k = 0; k <= 32; ++k) {
    const double u = t.front() + (t.back() - t.front()) * k / 32.0;
    // Degree up to 7 with step ratios up to 40: the collocation system's
    // condition reaches ~1e5, so 1e-8 of the scale (seen: 1.3e-9).
    RC_ASSERT(std::abs(point_at(*curve, u)[0] - poly(u)) <= 1e-8 * scale);
  }
}

RC_GTEST_PROP(InterpolateNatural, InterpolatesAndIsSmoothAtTheNodes, ()) {
  const int q = *rc::gen::inRange(1, 5);
  const int count = *rc::gen::inRange(std::max(q, 2), 14);
  const int d = *rc::gen::inRange(1, 4);
  std::vector<double> t{0.0};
  for (int i = 1; i < count; ++i) t.push_back(t.back() + *rc::gen::inRange(1, 40) / 16.0);
  const auto coordinates = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(count * d), test::coordinate());
  const PointArray points = PointArray::from_trusted(d, coordinates);
  const auto curve = interpolate_natural(points, t, q);
  RC_ASSERT(curve.has_value());
  const double tolerance = 1e-10 * std::max(scale_of(points), 1e-300);
  for (std::size_t i = 0; i < t.size(); ++i) RC_ASSERT(distance(point_at(*curve, t[i]), points[i]) <= tolerance);
  for (const KnotContinuity& k : continuity_at_knots(*curve)) RC_ASSERT(k.measured.parametric >= 2 * q - 2);
}

TEST(InterpolateNatural, RefusesBadInput) {
  const std::vector<double> t{0.0, 1.0, 2.0};
  const PointArray points = column({1.0, 2.0, 0.0});
  EXPECT_FALSE(interpolate_natural(points, t, 0));
  EXPECT_FALSE(interpolate_natural(points, t, tolerances::kMaxNaturalSplineOrder + 1));
  const auto too_few = interpolate_natural(points, t, 4);  // 3 points, q = 4 needs 4
  ASSERT_FALSE(too_few);
  EXPECT_NE(too_few.error().message.find("needs at least 4"), std::string::npos) << too_few.error().message;
  EXPECT_FALSE(interpolate_natural(column({1.0}), std::vector<double>{0.0}, 1));
  EXPECT_FALSE(interpolate_natural(points, std::vector<double>{0.0, 1.0}, 2));
  const auto repeated = interpolate_natural(points, std::vector<double>{0.0, 1.0, 1.0}, 2);
  ASSERT_FALSE(repeated);
  EXPECT_NE(repeated.error().message.find("parameter 2"), std::string::npos) << repeated.error().message;
  EXPECT_FALSE(interpolate_natural(points, std::vector<double>{0.0, NAN, 2.0}, 2));
  EXPECT_FALSE(interpolate_natural(column({1.0, NAN, 0.0}), t, 2));
}

}  // namespace
}  // namespace casteljau

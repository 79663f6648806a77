// Scalar B-spline/NURBS evaluation against exact rational references
// (tests/support/exact_basis.hpp), the de Boor / basis-sum pair, exact ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "support/sanitizers.hpp"
#include "../support/exact.hpp"
#include "../support/exact_basis.hpp"

namespace casteljau {
namespace {

/// Deterministic curves: degrees 0..7, dimensions 1..3, knots with repeated
/// interior knots, clamped or not, NURBS or not; coordinates in [-100, 100].
std::vector<BSplineCurve> sample_curves() {
  std::mt19937 random(20261122);
  std::uniform_real_distribution<double> coordinate(-100, 100);
  std::uniform_real_distribution<double> weight(0.2, 5);
  std::uniform_int_distribution<int> step(0, 3);
  std::vector<BSplineCurve> curves;
  for (int p = 0; p <= 7; ++p) {
    for (int variant = 0; variant < 4; ++variant) {
      const bool clamped = variant % 2 == 0;
      const bool rational = variant >= 2;
      const int d = 1 + (p + variant) % 3;
      const int n = p + 1 + (p + variant) % 5;
      std::vector<double> knots;
      int run = 0;
      double t = -1.0;
      while (static_cast<int>(knots.size()) < n + p + 2) {
        const int size = static_cast<int>(knots.size());
        const bool end = clamped && (size <= p || size >= n + 1);
        double next = knots.empty() ? t : knots.back() + (end ? 0.0 : step(random) * 0.125);
        if (clamped && size == n + 1 && next == knots.back()) next += 0.125;  // domain end
        run = (!knots.empty() && next == knots.back()) ? run + 1 : 1;
        if (run > (end ? p + 1 : p)) { next += 0.125; run = 1; }
        knots.push_back(next);
      }
      std::vector<double> coords(static_cast<std::size_t>((n + 1) * d));
      for (double& c : coords) c = coordinate(random);
      std::vector<double> weights;
      if (rational) for (int i = 0; i <= n; ++i) weights.push_back(weight(random));
      auto curve = BSplineCurve::make(p, knots, *PointArray::make(d, coords), weights);
      EXPECT_TRUE(curve) << curve.error().message;
      if (curve) curves.push_back(*curve);
    }
  }
  return curves;
}

std::vector<double> parameters_of(const BSplineCurve& curve) {
  std::vector<double> us;
  const Interval domain = curve.domain();
  for (int k = 0; k <= 24; ++k) us.push_back(domain.lerp(k / 24.0));
  for (double t : curve.knots()) if (domain.contains(t)) us.push_back(t);
  return us;
}

TEST(BSplinePointAt, EqualsTheExactSumOfBasisFunctions) {
  double worst = 0;
  for (const BSplineCurve& curve : sample_curves()) {
    const double scale = scale_of(curve.control_points());
    for (double u : parameters_of(curve)) {
      const auto exact = test::exact_bspline_point(curve, u);
      const Point de_boor = point_at(curve, u);
      const Point sum = point_at_basis_sum(curve, u);
      for (int c = 0; c < curve.dimension(); ++c) {
        const double e1 = test::error_of(de_boor[c], exact[c]);
        const double e2 = test::error_of(sum[c], exact[c]);
        worst = std::max(worst, e1 / scale);
        EXPECT_LE(e1, 1e-14 * scale) << "p=" << curve.degree() << " u=" << u;
        EXPECT_LE(e2, 1e-14 * scale) << "p=" << curve.degree() << " u=" << u;
      }
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(BSplinePointAt, ClampedCurvesInterpolateTheirEndsExactly) {
  for (const BSplineCurve& curve : sample_curves()) {
    const auto k = curve.knots();
    const int p = curve.degree();
    const std::size_t n = curve.control_points().size() - 1;
    const bool clamped = k[0] == k[static_cast<std::size_t>(p)] && k[n + 1] == k.back();
    if (!clamped) continue;
    const Point start = point_at(curve, curve.domain().lower);
    const Point end = point_at(curve, curve.domain().upper);
    // Exact for polynomial curves; a NURBS curve divides w P by w (one rounding).
    const double slack = curve.is_rational() ? 2.3e-16 * scale_of(curve.control_points()) : 0.0;
    for (int c = 0; c < curve.dimension(); ++c) {
      EXPECT_NEAR(start[c], curve.control_points()[0][c], slack) << "p=" << p;
      EXPECT_NEAR(end[c], curve.control_points()[n][c], slack) << "p=" << p;
    }
  }
}

TEST(BSplineDerivativeAt, EqualsExactDerivativesUpToOrderThree) {
  const std::size_t stride = static_cast<std::size_t>(test::sample_count(1, 4));
  for (const BSplineCurve& curve : sample_curves()) {
    const double scale = scale_of(curve.control_points());
    // Derivatives grow like (p / shortest span)^k: measure against the
    // exact derivative's own size as well as the scale.
    const std::vector<double> us = parameters_of(curve);
    for (std::size_t i = 0; i < us.size(); i += stride) {
      const double u = us[i];
      for (int k = 1; k <= 3; ++k) {
        const auto exact = test::exact_bspline_derivative(curve, u, k);
        const Point computed = derivative_at(curve, u, k);
        double size = scale;
        for (const auto& c : exact) size = std::max(size, std::abs(c.get_d()));
        for (int c = 0; c < curve.dimension(); ++c) {
          EXPECT_LE(test::error_of(computed[c], exact[c]), 1e-12 * size)
              << "p=" << curve.degree() << " rational=" << curve.is_rational() << " u=" << u << " k=" << k;
        }
      }
    }
  }
}

TEST(BSplineDerivativeAt, VanishesAbovePForPolynomialCurves) {
  const auto curve = *BSplineCurve::make(2, {0, 0, 0, 0.5, 1, 1, 1}, *PointArray::make({{0, 0}, {1, 2}, {3, 2}, {4, 0}}));
  EXPECT_EQ(derivative_at(curve, 0.3, 3), (Point{0, 0}));
  EXPECT_EQ(derivatives_up_to(curve, 0.3, 5).size(), 6u);
}

TEST(BSplineBatch, EqualsTheScalarFunctions) {
  for (const BSplineCurve& curve : sample_curves()) {
    const auto us = parameters_of(curve);
    const std::size_t d = static_cast<std::size_t>(curve.dimension());
    std::vector<double> points(us.size() * d), first(us.size() * d), second(us.size() * d);
    points_at(curve, us, points);
    std::vector<double> points2(us.size() * d);
    points_and_derivatives_at(curve, us, points2, first);
    derivatives_at(curve, us, 2, second);
    const double scale = scale_of(curve.control_points());
    for (std::size_t i = 0; i < us.size(); ++i) {
      const Point p0 = point_at(curve, us[i]);
      const Point p1 = derivative_at(curve, us[i], 1);
      const Point p2 = derivative_at(curve, us[i], 2);
      for (std::size_t c = 0; c < d; ++c) {
        EXPECT_NEAR(points[i * d + c], p0[c], 4e-15 * scale);
        EXPECT_NEAR(points2[i * d + c], p0[c], 4e-15 * scale);
        EXPECT_NEAR(first[i * d + c], p1[c], 1e-13 * std::max(scale, std::abs(p1[c])));
        EXPECT_NEAR(second[i * d + c], p2[c], 1e-13 * std::max(scale, std::abs(p2[c])));
      }
    }
  }
}

TEST(DeBoorNet, LevelsShrinkToThePoint) {
  const auto curve = *BSplineCurve::make(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
                                         *PointArray::make({{0, 0}, {1, 3}, {3, 4}, {5, 1}, {7, 3}, {9, 0}}),
                                         {1, 2, 1, 0.5, 1, 1});
  const DeBoorNet net = de_boor_net(curve, 1.5);
  EXPECT_EQ(net.span, 4);
  ASSERT_EQ(net.levels.size(), 4u);
  for (int r = 0; r <= 3; ++r) EXPECT_EQ(net.levels[r].size(), static_cast<std::size_t>(4 - r));
  EXPECT_EQ(net.levels[0][0][0], 1.0);  // P_1, the first control point of span 4
  const Point point = point_at(curve, 1.5);
  EXPECT_EQ(net.levels[3][0][0], point[0]);
  EXPECT_EQ(net.levels[3][0][1], point[1]);
}

TEST(BSplinePointAt, ExtrapolatesTheEndPiecesOutsideTheDomain) {
  // Degree 2 uniform: the first piece is a parabola; its continuation just
  // below the domain must be continuous with the value at the start.
  const auto curve = *BSplineCurve::make(2, uniform_knots(2, 5, {0, 1}), *PointArray::make({{0, 0}, {1, 2}, {2, -1}, {3, 4}, {4, 0}}));
  const Point inside = point_at(curve, 0.0);
  const Point outside = point_at(curve, -1e-9);
  EXPECT_NEAR(inside[0], outside[0], 1e-7);
  EXPECT_NEAR(inside[1], outside[1], 1e-7);
  EXPECT_TRUE(std::isnan(point_at(curve, std::nan(""))[0]));
}

}  // namespace
}  // namespace casteljau

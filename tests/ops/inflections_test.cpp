// Inflections against curves whose inflections are known in closed form
// (x = t with y a cubic or quartic in t: the curvature has the sign of y''),
// the circle (none), every kind, and on random plane curves: the signed
// curvature changes sign across each reported inflection and keeps its sign
// between consecutive ones.
#include "casteljau/ops/inflections.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/curves/differential_geometry.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "support/bspline_generators.hpp"
#include "support/power_curves.hpp"

namespace casteljau {
namespace {

using test::polynomial_graph;

TEST(Inflections, OfCubicAndQuarticGraphs) {
  // y = (t - 1/2)^3 = t^3 - 1.5 t^2 + 0.75 t - 0.125: y'' = 6 (t - 1/2).
  const BezierCurve graph = polynomial_graph({-0.125, 0.75, -1.5, 1.0});
  const auto cubic = inflection_parameters(graph).value();
  ASSERT_EQ(cubic.size(), 1u);
  EXPECT_NEAR(cubic[0], 0.5, 1e-15);
  // y = (t - 1/2)^4 - 0.05 (t - 1/2)^2: y'' = 12 (t - 1/2)^2 - 0.1, zero at 1/2 +- sqrt(0.1 / 12).
  const double c = 0.5;
  const std::vector<double> quartic{std::pow(c, 4) - 0.05 * c * c, -4 * std::pow(c, 3) + 0.1 * c,
                                    6 * c * c - 0.05, -4 * c, 1.0};
  const BezierCurve quartic_graph = polynomial_graph(quartic);
  const auto two = inflection_parameters(quartic_graph).value();
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(two[0], 0.5 - std::sqrt(0.1 / 12), 1e-13);
  EXPECT_NEAR(two[1], 0.5 + std::sqrt(0.1 / 12), 1e-13);
  // y = (t - 1/2)^4: y'' = 12 (t - 1/2)^2 touches zero: a flat point, no inflection.
  const BezierCurve convex = polynomial_graph({0.0625, -0.5, 1.5, -2.0, 1.0});
  EXPECT_TRUE(inflection_parameters(convex).value().empty());
}

TEST(Inflections, OnEveryKindAndNoneOnTheCircle) {
  const BezierCurve cubic = polynomial_graph({-0.125, 0.75, -1.5, 1.0});
  const BSplineCurve as_bspline = to_bspline(cubic);
  EXPECT_NEAR(inflection_parameters(as_bspline).value().at(0), 0.5, 1e-15);
  const PiecewiseBezierCurve piecewise = PiecewiseBezierCurve::make({cubic, cubic}).value();
  const auto both = inflection_parameters(piecewise).value();
  ASSERT_EQ(both.size(), 2u);
  EXPECT_NEAR(both[0], 0.5, 1e-15);
  EXPECT_NEAR(both[1], 1.5, 1e-15);
  const BSplineCurve circle = make_circle(0.0, 0.0, 2.0).value();
  EXPECT_TRUE(inflection_parameters(circle).value().empty());
  const BezierCurve segment = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value()).value();
  EXPECT_TRUE(inflection_parameters(segment).value().empty());
  const auto space = BezierCurve::make(PointArray::make({{0, 0, 0}, {1, 1, 1}, {2, 0, 1}}).value()).value();
  EXPECT_EQ(inflection_parameters(space).error().message, "inflections need a plane curve, this one lives in R^3");
}

RC_GTEST_PROP(Inflections, TheCurvatureChangesSignThereAndOnlyThere, ()) {
  const BSplineCurve curve = *test::bspline_curve({.min_degree = 2, .max_degree = 5, .dimension = 2});
  const auto found = inflection_parameters(curve);
  RC_ASSERT(found.has_value());
  const Interval domain = curve.domain();
  const double h = 1e-6 * domain.length();
  for (const double u : *found) {
    RC_ASSERT(domain.lower < u && u < domain.upper);
    const double before = signed_curvature_at(curve, std::max(domain.lower, u - h));
    const double after = signed_curvature_at(curve, std::min(domain.upper, u + h));
    // Opposite signs, unless the curvature is too small to tell there.
    RC_PRE(std::abs(before) > 1e-9 && std::abs(after) > 1e-9);
    RC_ASSERT((before > 0) != (after > 0));
  }
  // Between consecutive inflections (and the ends) the sign is constant on
  // samples away from them, except across a corner or cusp of the curve.
  std::vector<double> cuts{domain.lower};
  cuts.insert(cuts.end(), found->begin(), found->end());
  cuts.push_back(domain.upper);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    int sign = 0;
    for (int i = 1; i < 50; ++i) {
      const double u = cuts[k] + (cuts[k + 1] - cuts[k]) * i / 50.0;
      const double kappa = signed_curvature_at(curve, u);
      if (std::abs(kappa) < 1e-6 || !std::isfinite(kappa)) continue;
      const int s = kappa > 0 ? 1 : -1;
      if (sign == 0) sign = s;
      if (sign != s) {
        // A sign change without a reported inflection is allowed only at a knot of
        // C1 continuity or less, where the curvature may jump across zero.
        bool knot_between = false;
        const double lower = cuts[k] + (cuts[k + 1] - cuts[k]) * (i - 1) / 50.0;
        for (double t : curve.knots())
          knot_between |= t > lower && t <= u && multiplicity_of(curve.knots(), t) >= curve.degree() - 1;
        RC_ASSERT(knot_between);
        sign = s;
      }
    }
  }
}

}  // namespace
}  // namespace casteljau

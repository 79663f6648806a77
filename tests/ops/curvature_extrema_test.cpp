// Curvature extrema and cusps against closed forms: y = x^3 (extrema at
// x = +-45^(-1/4), found by hand from kappa = 6x / (1 + 9x^4)^(3/2)), the
// parabola's vertex (kappa = 2c), the ellipse (a / b^2 at the ends of the
// major axis, b / a^2 at the minor one; at junctions of its rational pieces,
// and inside pieces for an arc cut elsewhere), none on lines and circles; the
// cusp of the cubic (0,0) (1,1) (0,1) (1,0) at t = 1/2 (C' = 3 ((1-2t)^2,
// 1-2t)), a stationary point that is not a cusp ((t-1/2)^3, (t-1/2)^5),
// cusps at junctions. On random curves of every kind, in the plane and in
// space: |kappa| sampled between consecutive reported points (extrema,
// inflections, cusps, breakpoints) is monotone, and a maximum is above its
// neighbours.
#include "casteljau/ops/curvature_extrema.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/bezier/affine.hpp"
#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/curves/differential_geometry.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/ops/inflections.hpp"
#include "support/bspline_generators.hpp"
#include "support/make.hpp"
#include "support/power_curves.hpp"

namespace casteljau {
namespace {

using test::bezier;
using test::polynomial_graph;
using test::power_curve;

/// The power coefficients of (t - c)^k.
std::vector<double> shifted_power(double c, int k) {
  std::vector<double> a(k + 1);
  for (int j = 0; j <= k; ++j) a[j] = binomial(k, j) * std::pow(-c, k - j);
  return a;
}

TEST(CurvatureExtrema, OfTheCubicGraphAndTheParabola) {
  // x = t, y = (t - 1/2)^3: the graph of y = s^3, s = t - 1/2.
  const BezierCurve graph = polynomial_graph(shifted_power(0.5, 3));
  const auto cubic = curvature_extrema(graph).value();
  ASSERT_EQ(cubic.size(), 2u);
  const double s = std::pow(45.0, -0.25);
  const double kappa = 6 * s / std::pow(1 + 9 * std::pow(s, 4), 1.5);
  EXPECT_NEAR(cubic[0].parameter, 0.5 - s, 1e-14);
  EXPECT_NEAR(cubic[1].parameter, 0.5 + s, 1e-14);
  EXPECT_NEAR(cubic[0].curvature, -kappa, 1e-13 * kappa);  // turning right below the inflection
  EXPECT_NEAR(cubic[1].curvature, kappa, 1e-13 * kappa);
  EXPECT_TRUE(cubic[0].maximum);
  EXPECT_TRUE(cubic[1].maximum);
  // y = 3 (t - 1/2)^2: its vertex, kappa = 6.
  std::vector<double> parabola = shifted_power(0.5, 2);
  for (double& a : parabola) a *= 3.0;
  const BezierCurve parabola_graph = polynomial_graph(parabola);
  const auto vertex = curvature_extrema(parabola_graph).value();
  ASSERT_EQ(vertex.size(), 1u);
  EXPECT_NEAR(vertex[0].parameter, 0.5, 1e-15);
  EXPECT_NEAR(vertex[0].curvature, 6.0, 1e-13);
  EXPECT_TRUE(vertex[0].maximum);
}

TEST(CurvatureExtrema, OfTheEllipseAtJunctionsAndInsidePieces) {
  const double a = 3.0, b = 1.0;
  const double major = a / (b * b), minor = b / (a * a);
  // The three axis ends after the start (a, 0): (0, b) flattest, (-a, 0)
  // sharpest, (0, -b) flattest; points within `accuracy` of a.
  const double expected_points[3][2] = {{0, b}, {-a, 0}, {0, -b}};
  const auto expect_axis_ends = [&](const BSplineCurve& curve, double accuracy) {
    const auto found = curvature_extrema(curve).value();
    ASSERT_EQ(found.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const Point p = point_at(curve, found[k].parameter);
      EXPECT_NEAR(p[0], expected_points[k][0], accuracy * a);
      EXPECT_NEAR(p[1], expected_points[k][1], accuracy * a);
      EXPECT_EQ(found[k].maximum, k == 1);
      EXPECT_NEAR(found[k].curvature, k == 1 ? major : minor, 10 * accuracy * major);
    }
  };
  // Rational quarter arcs from (a, 0): the other three axis ends are junctions.
  const BSplineCurve ellipse = make_ellipse(0.0, 0.0, a, b).value();
  expect_axis_ends(ellipse, 1e-14);
  const auto found = curvature_extrema(ellipse).value();
  // A circular arc from 0.3 rad nearly all the way round, stretched into an
  // ellipse: its axis ends now lie inside rational pieces.
  const BSplineCurve arc = make_arc(0.0, 0.0, 1.0, 0.3, 2 * std::numbers::pi - 0.6).value();
  expect_axis_ends(transformed(arc, AffineMap::make(2, {a, 0, 0, b}, {0, 0}).value()).value(), 1e-12);
  // The same ellipse in a tilted plane of R^3: unsigned curvature, same points.
  const double c = std::cos(0.4), s = std::sin(0.4);
  const ConicFrame tilted{{1.0, 2.0, 3.0}, {c, 0.0, s}, {0.0, 1.0, 0.0}};
  const BSplineCurve space = make_ellipse(tilted, a, b).value();
  const auto in_space = curvature_extrema(space).value();
  ASSERT_EQ(in_space.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(in_space[k].parameter, found[k].parameter, 1e-12);
    EXPECT_NEAR(in_space[k].curvature, k == 1 ? major : minor, 1e-13 * major);
    EXPECT_EQ(in_space[k].maximum, k == 1);
  }
}

TEST(CurvatureExtrema, NoneOnLinesAndCircles) {
  const BSplineCurve circle = make_circle(1.0, -2.0, 5.0).value();
  const BSplineCurve arc = make_arc(0.0, 0.0, 1e-3, 0.2, 2.0).value();
  EXPECT_TRUE(curvature_extrema(circle).value().empty());
  EXPECT_TRUE(curvature_extrema(arc).value().empty());
  const ConicFrame frame{{0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  const BSplineCurve tilted = make_circle(frame, 2.0).value();
  EXPECT_TRUE(curvature_extrema(tilted).value().empty());
  // A straight cubic with uneven speed: kappa = 0 throughout.
  const BezierCurve straight = bezier({{0, 0}, {1, 1}, {1.5, 1.5}, {3, 3}});
  EXPECT_TRUE(curvature_extrema(straight).value().empty());
  EXPECT_TRUE(cusp_parameters(circle).value().empty());
  const BezierCurve on_a_line = bezier({{0}, {1}, {3}});
  EXPECT_EQ(curvature_extrema(on_a_line).error().message,
            "curvature extrema need a curve in R^2 or more, this one lives in R^1");
  EXPECT_EQ(cusp_parameters(on_a_line).error().message,
            "curvature extrema need a curve in R^2 or more, this one lives in R^1");
}

TEST(Cusps, InsideAPieceAndAtJunctions) {
  // C' = 3 ((1 - 2t)^2, 1 - 2t): both vanish at 1/2, C'' = (0, -6) there.
  const BezierCurve cusp = bezier({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  const auto inside = cusp_parameters(cusp).value();
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_NEAR(inside[0], 0.5, 1e-15);
  // Its curvature grows towards the cusp from both sides: no extremum there.
  const std::vector<CurvatureExtremum> around = curvature_extrema(cusp).value();
  for (const CurvatureExtremum& e : around) EXPECT_GT(std::abs(e.parameter - 0.5), 1e-3);
  // In space too.
  const BezierCurve spatial = bezier({{0, 0, 1}, {1, 1, 1}, {0, 1, 1}, {1, 0, 1}});
  EXPECT_EQ(cusp_parameters(spatial).value().size(), 1u);
  // ((t - 1/2)^3, (t - 1/2)^5): stationary at 1/2 but the tangent goes on (order 3).
  const BezierCurve flat_point = power_curve({shifted_power(0.5, 3), shifted_power(0.5, 5)});
  EXPECT_TRUE(cusp_parameters(flat_point).value().empty());
  // The cusp cubic cut at its cusp: two pieces stationary at their junction.
  const auto [left, right] = split_at(cusp, 0.5).value();
  const PiecewiseBezierCurve joined = PiecewiseBezierCurve::make({left, right}).value();
  const auto halves = cusp_parameters(joined).value();
  ASSERT_EQ(halves.size(), 1u);
  EXPECT_EQ(halves[0], 1.0);
  // Two arcs meeting head-on: arriving along (1, -1), leaving along (-1, 1).
  const BezierCurve arriving = bezier({{0, 0}, {0.5, 0.5}, {1, 0}});
  const PiecewiseBezierCurve head_on = PiecewiseBezierCurve::make({arriving, bezier({{1, 0}, {0.5, 0.5}, {0, 1}})}).value();
  const auto spike = cusp_parameters(head_on);
  ASSERT_EQ(spike.value().size(), 1u);
  EXPECT_EQ(spike.value()[0], 1.0);
  // A sharp corner that does not turn back is not a cusp.
  const PiecewiseBezierCurve corner = PiecewiseBezierCurve::make({arriving, bezier({{1, 0}, {0.9, 0.2}, {0, 1}})}).value();
  EXPECT_TRUE(cusp_parameters(corner).value().empty());
}

/// |kappa| at u (the right piece's at a junction).
double magnitude(CurveView curve, double u) { return std::abs(curvature_at(curve, u)); }

/// Between consecutive cuts |kappa| is monotone on samples inside, and each
/// reported maximum (minimum) is above (below) the samples next to it.
void check_monotone_between(const BSplineCurve& curve) {
  const auto extrema = curvature_extrema(curve);
  RC_ASSERT(extrema.has_value());
  const auto cusps = cusp_parameters(curve);
  RC_ASSERT(cusps.has_value());
  const Interval domain = curve.domain();
  std::vector<double> cuts = breakpoints(curve);
  for (const CurvatureExtremum& e : *extrema) {
    RC_ASSERT(domain.lower < e.parameter && e.parameter < domain.upper);
    cuts.push_back(e.parameter);
  }
  cuts.insert(cuts.end(), cusps->begin(), cusps->end());
  if (curve.dimension() == 2) {
    const auto inflections = inflection_parameters(curve).value();
    cuts.insert(cuts.end(), inflections.begin(), inflections.end());
  }
  std::sort(cuts.begin(), cuts.end());
  constexpr int kSamples = 40;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (!(b - a > 1e-6 * domain.length())) continue;
    std::vector<double> values;
    for (int i = 1; i < kSamples; ++i) values.push_back(magnitude(curve, a + (b - a) * i / kSamples));
    const double largest = *std::max_element(values.begin(), values.end());
    if (!std::isfinite(largest)) continue;
    const double slack = 1e-8 * largest + 1e-300;
    bool rises = false, falls = false;
    for (std::size_t i = 0; i + 1 < values.size(); ++i) {
      rises |= values[i + 1] > values[i] + slack;
      falls |= values[i + 1] < values[i] - slack;
    }
    RC_ASSERT(!(rises && falls));
  }
  for (const CurvatureExtremum& e : *extrema) {
    const double h = 1e-5 * domain.length();
    const bool crowded = std::any_of(cuts.begin(), cuts.end(), [&](double c) {
      return c != e.parameter && std::abs(c - e.parameter) < 2 * h;
    });
    if (crowded) continue;  // another cut between the samples and the extremum
    const double here = std::abs(e.curvature);
    const double before = magnitude(curve, e.parameter - h), after = magnitude(curve, e.parameter + h);
    const double slack = 1e-9 * std::max({here, before, after});
    if (e.maximum) {
      RC_ASSERT(before <= here + slack);
      RC_ASSERT(after <= here + slack);
    } else {
      RC_ASSERT(before >= here - slack);
      RC_ASSERT(after >= here - slack);
    }
  }
}

RC_GTEST_PROP(CurvatureExtrema, MonotoneBetweenThemOnPlaneCurves, ()) {
  check_monotone_between(*test::bspline_curve({.min_degree = 2, .max_degree = 5, .dimension = 2}));
}

RC_GTEST_PROP(CurvatureExtrema, MonotoneBetweenThemOnSpaceCurves, ()) {
  check_monotone_between(*test::bspline_curve({.min_degree = 2, .max_degree = 5, .dimension = 3}));
}

}  // namespace
}  // namespace casteljau

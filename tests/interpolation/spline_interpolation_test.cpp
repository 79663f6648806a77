// B-spline interpolation (spline_interpolation.hpp). References: a natural
// cubic worked by hand, the collocation systems of each end condition built
// from the definition (exact Cox–de Boor basis values and derivatives,
// support/exact_basis.hpp) and solved in rationals, the closed cubic through a
// regular polygon solved by hand (a circulant system), knots from The NURBS
// Book eq. 9.8 / 9.22 worked by hand, and polynomial reproduction.
#include "casteljau/interpolation/spline_interpolation.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bspline/continuity.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "support/exact.hpp"
#include "support/exact_basis.hpp"
#include "support/exact_linear.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

std::vector<double> knots_of(const BSplineCurve& curve) { return {curve.knots().begin(), curve.knots().end()}; }

/// The control points of the clamped interpolant on `knots`, from the
/// definition: rows N_j(t_i) = P_i, and rows N_j^(k)(t) = D for the end
/// conditions, in exact rationals.
std::vector<std::vector<mpq_class>> exact_clamped(const std::vector<double>& knots, int p, const std::vector<double>& t,
                                                  const PointArray& points,
                                                  const std::vector<EndDerivative>& derivatives) {
  const std::size_t n = knots.size() - static_cast<std::size_t>(p) - 1, d = static_cast<std::size_t>(points.dimension());
  test::RationalMatrix a, b;
  for (std::size_t i = 0; i < t.size(); ++i) {
    a.emplace_back(n, 0);
    for (std::size_t j = 0; j < n; ++j) a.back()[j] = test::exact_basis(knots, static_cast<int>(j), p, t[i]);
    b.emplace_back(points[i].begin(), points[i].end());
  }
  for (const EndDerivative& e : derivatives) {
    a.emplace_back(n, 0);
    const double u = e.at_end ? t.back() : t.front();
    for (std::size_t j = 0; j < n; ++j) a.back()[j] = test::exact_basis_derivative(knots, static_cast<int>(j), p, e.order, u);
    b.emplace_back(d, 0);
    for (std::size_t k = 0; k < d && !e.value.empty(); ++k) b.back()[k] = e.value[k];
  }
  return test::solve_exactly(a, b);
}

void expect_control_points_near(const BSplineCurve& curve, const std::vector<std::vector<mpq_class>>& exact,
                                double relative) {
  ASSERT_EQ(curve.control_points().size(), exact.size());
  double scale = 1e-300;
  for (const auto& row : exact)
    for (const auto& v : row) scale = std::max(scale, std::abs(v.get_d()));
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (std::size_t k = 0; k < exact[i].size(); ++k)
      EXPECT_LE(test::error_of(curve.control_points()[i][k], exact[i][k]), relative * scale) << "control point " << i;
}

// Dyadic data: exact in double, so the rational references see the same numbers.
const std::vector<double> kT{0.0, 0.5, 1.25, 2.0, 2.125, 3.0, 4.5};
const PointArray kPoints = PointArray::from_trusted(2, {0, 0, 1, 2, 2.5, -1, 3, 0.5, 3.25, 0.75, 4, 4, 5.5, 1});

TEST(InterpolateCubic, NaturalByHand) {
  // Through (0,0), (1,1), (2,0) at t = 0, 1, 2: the second derivatives solve
  // M_0 + 4 M_1 + M_2 = 6 (y_0 - 2 y_1 + y_2) with M_0 = M_2 = 0, so M_1 = -3
  // and s(t) = 3t/2 - t^3/2 on [0, 1], mirrored on [1, 2].
  const auto curve = interpolate_cubic(PointArray::from_trusted(1, {0, 1, 0}), std::vector<double>{0, 1, 2},
                                       CubicEnds{EndCondition::natural, {}, {}});
  ASSERT_TRUE(curve.has_value());
  EXPECT_EQ(knots_of(*curve), (std::vector<double>{0, 0, 0, 0, 1, 2, 2, 2, 2}));
  for (int k = 0; k <= 16; ++k) {
    const double u = k / 8.0, v = u <= 1 ? u : 2 - u;
    EXPECT_NEAR(point_at(*curve, u)[0], 1.5 * v - 0.5 * v * v * v, 1e-15) << u;
  }
}

TEST(InterpolateCubic, NaturalAndClampedMatchTheirExactSystems) {
  const std::vector<double> start{1.0, -2.0}, end{0.5, 3.0};
  for (EndCondition condition : {EndCondition::natural, EndCondition::clamped}) {
    const CubicEnds ends{condition, start, end};
    const auto curve = interpolate_cubic(kPoints, kT, ends);
    ASSERT_TRUE(curve.has_value()) << curve.error().message;
    EXPECT_EQ(knots_of(*curve), (std::vector<double>{0, 0, 0, 0, 0.5, 1.25, 2.0, 2.125, 3.0, 4.5, 4.5, 4.5, 4.5}));
    const int order = condition == EndCondition::natural ? 2 : 1;
    const std::vector<EndDerivative> rows{{false, order, condition == EndCondition::natural ? Point{} : start},
                                          {true, order, condition == EndCondition::natural ? Point{} : end}};
    expect_control_points_near(*curve, exact_clamped(knots_of(*curve), 3, kT, kPoints, rows), 1e-14);
  }
}

TEST(InterpolateCubic, NotAKnotMatchesItsExactSystem) {
  const auto curve = interpolate_cubic(kPoints, kT, CubicEnds{EndCondition::not_a_knot, {}, {}});
  ASSERT_TRUE(curve.has_value());
  EXPECT_EQ(knots_of(*curve), (std::vector<double>{0, 0, 0, 0, 1.25, 2.0, 2.125, 4.5, 4.5, 4.5, 4.5}));
  expect_control_points_near(*curve, exact_clamped(knots_of(*curve), 3, kT, kPoints, {}), 1e-14);
  // C''' is continuous at t_1 and t_{m-1}: they are not knots.
  for (double u : {kT[1], kT[5]}) {
    const double h = 1e-3;
    const auto left = derivative_at(*curve, u - h, 3), right = derivative_at(*curve, u + h, 3);
    EXPECT_EQ(left, right);  // one cubic piece: the third derivative is constant
  }
}

TEST(InterpolateCubic, PeriodicMatchesItsExactCyclicSystem) {
  // Closing parameter 5.25 after the last point.
  std::vector<double> t = kT;
  t.push_back(5.25);
  const auto curve = interpolate_cubic(kPoints, t, CubicEnds{EndCondition::periodic, {}, {}});
  ASSERT_TRUE(curve.has_value()) << curve.error().message;
  const std::size_t m = kPoints.size();
  const double period = 5.25;
  // Knots: the parameters extended by the steps taken cyclically.
  EXPECT_EQ(knots_of(*curve), (std::vector<double>{2.125 - period, 3.0 - period, 4.5 - period, 0, 0.5, 1.25, 2.0, 2.125,
                                                    3.0, 4.5, 5.25, 0.5 + period, 1.25 + period, 2.0 + period}));
  ASSERT_EQ(curve->control_points().size(), m + 3);
  for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(curve->control_points()[m + j][0], curve->control_points()[j][0]);
  // The cyclic system from the definition: column j of the full knot vector
  // is control point j mod m.
  const auto knots = knots_of(*curve);
  test::RationalMatrix a, b;
  for (std::size_t i = 0; i < m; ++i) {
    a.emplace_back(m, 0);
    for (std::size_t j = 0; j < m + 3; ++j) a.back()[j % m] += test::exact_basis(knots, static_cast<int>(j), 3, t[i]);
    b.push_back({kPoints[i][0], kPoints[i][1]});
  }
  const auto exact = test::solve_exactly(a, b);
  double scale = 0;
  for (const auto& r : exact) scale = std::max({scale, std::abs(r[0].get_d()), std::abs(r[1].get_d())});
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t k = 0; k < 2; ++k)
      EXPECT_LE(test::error_of(curve->control_points()[i][k], exact[i][k]), 1e-14 * scale) << i;
}

TEST(InterpolateCubic, PeriodicThroughARegularPolygonByHand) {
  // Uniform parameters: row i reads (Q_i + 4 Q_{i+1} + Q_{i+2}) / 6 = P_i,
  // and for P_i on the unit circle at angles i θ the solution is
  // Q_{i+1} = P_i · 3 / (2 + cos θ) (the circulant's eigenvalue on that mode).
  for (std::size_t m : {3u, 5u, 12u}) {
    const double theta = 2 * std::acos(-1.0) / static_cast<double>(m);
    std::vector<double> coordinates, t;
    for (std::size_t i = 0; i <= m; ++i) {
      t.push_back(static_cast<double>(i));
      if (i < m) coordinates.insert(coordinates.end(), {std::cos(theta * i), std::sin(theta * i)});
    }
    const auto curve = interpolate_cubic(PointArray::from_trusted(2, coordinates), t, CubicEnds{EndCondition::periodic, {}, {}});
    ASSERT_TRUE(curve.has_value());
    const double factor = 3 / (2 + std::cos(theta));
    for (std::size_t i = 0; i < m; ++i) {
      const auto q = curve->control_points()[(i + 1) % m];
      EXPECT_NEAR(q[0], factor * std::cos(theta * i), 1e-14) << m << " " << i;
      EXPECT_NEAR(q[1], factor * std::sin(theta * i), 1e-14) << m << " " << i;
    }
  }
}

/// Random strictly increasing parameters (steps 1/16..4) and points.
struct Data {
  std::vector<double> t;
  PointArray points;
};
Data random_data(int min_count, int max_count, bool closing) {
  const int count = *rc::gen::inRange(min_count, max_count + 1);
  const int d = *rc::gen::inRange(1, 4);
  Data data;
  data.t.push_back(*rc::gen::inRange(-50, 50) / 4.0);
  for (int i = 1; i < count + (closing ? 1 : 0); ++i) data.t.push_back(data.t.back() + *rc::gen::inRange(1, 65) / 16.0);
  data.points = PointArray::from_trusted(
      d, *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(count * d), test::coordinate()));
  return data;
}

EndCondition random_condition() {
  return *rc::gen::element(EndCondition::natural, EndCondition::clamped, EndCondition::not_a_knot, EndCondition::periodic);
}

CubicEnds random_ends(EndCondition condition, int d) {
  CubicEnds ends{condition, {}, {}};
  if (condition == EndCondition::clamped) {
    ends.start_tangent = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(d), test::coordinate());
    ends.end_tangent = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(d), test::coordinate());
  }
  return ends;
}

RC_GTEST_PROP(InterpolateCubic, ReproducesTheDataAndIsTwiceContinuous, ()) {
  const EndCondition condition = random_condition();
  const Data data = random_data(condition == EndCondition::not_a_knot ? 4 : condition == EndCondition::periodic ? 3 : 2,
                                40, condition == EndCondition::periodic);
  const CubicEnds ends = random_ends(condition, data.points.dimension());
  const auto curve = interpolate_cubic(data.points, data.t, ends);
  RC_ASSERT(curve.has_value());
  const double scale = std::max({scale_of(data.points), 1e-300});
  for (std::size_t i = 0; i < data.points.size(); ++i)
    RC_ASSERT(distance(point_at(*curve, data.t[i]), data.points[i]) <= 1e-11 * scale);
  for (const KnotContinuity& k : continuity_at_knots(*curve)) RC_ASSERT(k.measured.parametric >= 2);
  if (condition == EndCondition::periodic) {
    // Closed with C² at the seam: C, C', C'' equal at both ends of the domain.
    const auto start = derivatives_up_to(*curve, curve->domain().lower, 2);
    const auto end = derivatives_up_to(*curve, curve->domain().upper, 2);
    RC_ASSERT(distance(start[0], data.points[0]) <= 1e-11 * scale);
    for (int k = 0; k <= 2; ++k) {
      double size = 1e-300;
      for (double v : start[static_cast<std::size_t>(k)]) size = std::max(size, std::abs(v));
      RC_ASSERT(distance(start[static_cast<std::size_t>(k)], end[static_cast<std::size_t>(k)]) <= 1e-9 * size + 1e-11 * scale);
    }
  }
  if (condition == EndCondition::clamped) {
    const double tangent_scale = std::max(scale_of(PointArray::from_trusted(data.points.dimension(), ends.start_tangent)),
                                          scale_of(PointArray::from_trusted(data.points.dimension(), ends.end_tangent)));
    const double step = std::min(data.t[1] - data.t[0], data.t.back() - data.t[data.t.size() - 2]);
    const double tolerance = 1e-11 * (tangent_scale + scale / step);
    RC_ASSERT(distance(derivative_at(*curve, data.t.front(), 1), ends.start_tangent) <= tolerance);
    RC_ASSERT(distance(derivative_at(*curve, data.t.back(), 1), ends.end_tangent) <= tolerance);
  }
  if (condition == EndCondition::natural) {
    const double step = std::min(data.t[1] - data.t[0], data.t.back() - data.t[data.t.size() - 2]);
    for (double v : derivative_at(*curve, data.t.front(), 2)) RC_ASSERT(std::abs(v) <= 1e-10 * scale / (step * step));
    for (double v : derivative_at(*curve, data.t.back(), 2)) RC_ASSERT(std::abs(v) <= 1e-10 * scale / (step * step));
  }
}

/// Coefficients c_0..c_degree of a polynomial per coordinate, its value and
/// derivative.
struct Polynomial {
  std::vector<std::vector<double>> c;  // c[k][j]: coordinate k, power j
  double value(std::size_t k, double u, int order = 0) const {
    double v = 0.0;
    for (std::size_t j = c[k].size(); j-- > static_cast<std::size_t>(order);) {
      double falling = 1.0;
      for (int i = 0; i < order; ++i) falling *= static_cast<double>(j) - i;
      v = v * u + c[k][j] * falling;
    }
    return v;
  }
};

RC_GTEST_PROP(InterpolateCubic, ReproducesPolynomialsItsEndConditionsAllow, ()) {
  // Cubics under clamped (with the cubic's tangents) and not-a-knot, lines
  // under natural: the interpolant is unique and the polynomial qualifies.
  const EndCondition condition = *rc::gen::element(EndCondition::natural, EndCondition::clamped, EndCondition::not_a_knot);
  const Data data = random_data(condition == EndCondition::not_a_knot ? 4 : 2, 30, false);
  const std::size_t d = static_cast<std::size_t>(data.points.dimension());
  const std::size_t degree = condition == EndCondition::natural ? 1 : 3;
  // Centred at the middle parameter so that the values stay O(scale).
  const double centre = (data.t.front() + data.t.back()) / 2, half = (data.t.back() - data.t.front()) / 2;
  Polynomial poly;
  for (std::size_t k = 0; k < d; ++k) poly.c.push_back(*rc::gen::container<std::vector<double>>(degree + 1, test::coordinate()));
  const auto at = [&](std::size_t k, double u, int order = 0) {
    return poly.value(k, (u - centre) / half, order) / std::pow(half, order);
  };
  std::vector<double> coordinates;
  for (double u : data.t)
    for (std::size_t k = 0; k < d; ++k) coordinates.push_back(at(k, u));
  CubicEnds ends{condition, {}, {}};
  for (std::size_t k = 0; k < d; ++k) {
    ends.start_tangent.push_back(at(k, data.t.front(), 1));
    ends.end_tangent.push_back(at(k, data.t.back(), 1));
  }
  const PointArray points = PointArray::from_trusted(static_cast<int>(d), coordinates);
  const auto curve = interpolate_cubic(points, data.t, ends);
  RC_ASSERT(curve.has_value());
  const double scale = std::max(scale_of(points), 400.0);  // |poly| <= 4 * 100 on [-1, 1]
  for (int s = 0; s <= 40; ++s) {
    const double u = data.t.front() + (data.t.back() - data.t.front()) * s / 40.0;
    const auto p = point_at(*curve, u);
    for (std::size_t k = 0; k < d; ++k) RC_ASSERT(std::abs(p[k] - at(k, u)) <= 1e-10 * scale);
  }
}

RC_GTEST_PROP(InterpolateCubic, IsAffineInvariant, ()) {
  // Interpolating A P + b gives the control points A Q + b (the system acts
  // on each coordinate alike and reproduces constants).
  const EndCondition condition = random_condition();
  const Data data = random_data(condition == EndCondition::not_a_knot ? 4 : 3, 25, condition == EndCondition::periodic);
  const int d = data.points.dimension();
  const auto matrix = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(d * d), test::coordinate());
  const auto offset = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(d), test::coordinate());
  const auto map = [&](std::span<const double> x, bool vector) {
    std::vector<double> y(static_cast<std::size_t>(d), 0.0);
    for (int r = 0; r < d; ++r) {
      for (int c = 0; c < d; ++c) y[static_cast<std::size_t>(r)] += matrix[static_cast<std::size_t>(r * d + c)] * x[static_cast<std::size_t>(c)];
      if (!vector) y[static_cast<std::size_t>(r)] += offset[static_cast<std::size_t>(r)];
    }
    return y;
  };
  const CubicEnds ends = random_ends(condition, d);
  CubicEnds mapped_ends = ends;
  if (condition == EndCondition::clamped) {
    mapped_ends.start_tangent = map(ends.start_tangent, true);  // tangents are vectors: no offset
    mapped_ends.end_tangent = map(ends.end_tangent, true);
  }
  PointArray mapped = PointArray::zeros(d, 0);
  for (std::size_t i = 0; i < data.points.size(); ++i) mapped.push_back(map(data.points[i], false));
  const auto curve = interpolate_cubic(data.points, data.t, ends);
  const auto image = interpolate_cubic(mapped, data.t, mapped_ends);
  RC_ASSERT(curve && image);
  RC_ASSERT(knots_of(*curve) == knots_of(*image));
  double matrix_norm = 0.0;
  for (double v : matrix) matrix_norm += std::abs(v);
  const double tolerance = 1e-11 * (matrix_norm * scale_of(curve->control_points()) + scale_of(mapped) + 100.0);
  for (std::size_t i = 0; i < curve->control_points().size(); ++i)
    RC_ASSERT(distance(map(curve->control_points()[i], false), image->control_points()[i]) <= tolerance);
}

TEST(InterpolateCubic, TwoPointsGiveAStraightSegment) {
  const auto points = PointArray::from_trusted(2, {1, 1, 3, 5});
  for (EndCondition condition : {EndCondition::natural, EndCondition::clamped}) {
    const auto curve = interpolate_cubic(points, std::vector<double>{0, 2}, CubicEnds{condition, {1, 2}, {1, 2}});
    ASSERT_TRUE(curve.has_value());
    for (int k = 0; k <= 8; ++k) {
      const auto p = point_at(*curve, k / 4.0);
      EXPECT_NEAR(p[0], 1 + k / 4.0, 1e-15);
      EXPECT_NEAR(p[1], 1 + k / 2.0, 1e-15);
    }
  }
}

TEST(InterpolateCubic, RefusesBadInput) {
  const auto message = [](const Expected<BSplineCurve>& e) { return e ? std::string("(accepted)") : e.error().message; };
  const CubicEnds natural{EndCondition::natural, {}, {}}, not_a_knot{EndCondition::not_a_knot, {}, {}},
      periodic{EndCondition::periodic, {}, {}};
  const auto one = PointArray::from_trusted(2, {0, 0});
  const auto three = PointArray::from_trusted(2, {0, 0, 1, 1, 2, 0});
  EXPECT_EQ(message(interpolate_cubic(one, std::vector<double>{0}, natural)),
            "cubic interpolation with natural ends needs at least 2 points, got 1");
  EXPECT_EQ(message(interpolate_cubic(three, std::vector<double>{0, 1, 2}, not_a_knot)),
            "cubic interpolation with not-a-knot ends needs at least 4 points, got 3");
  EXPECT_EQ(message(interpolate_cubic(PointArray::from_trusted(2, {0, 0, 1, 1}), std::vector<double>{0, 1, 2}, periodic)),
            "cubic interpolation with periodic ends needs at least 3 points, got 2");
  EXPECT_EQ(message(interpolate_cubic(three, std::vector<double>{0, 1, 2}, periodic)),
            "3 parameter values for 3 points, cubic interpolation with periodic ends needs 4");
  EXPECT_EQ(message(interpolate_cubic(three, std::vector<double>{0, 1}, natural)),
            "2 parameter values for 3 points, cubic interpolation with natural ends needs 3");
  EXPECT_EQ(message(interpolate_cubic(three, std::vector<double>{0, 1, 1}, natural)),
            "parameters must increase strictly: parameter 2 is 1, parameter 1 is 1");
  EXPECT_EQ(message(interpolate_cubic(three, std::vector<double>{0, NAN, 2}, natural)), "parameter 1 is NaN");
  EXPECT_EQ(message(interpolate_cubic(PointArray::from_trusted(2, {0, 0, 1, NAN, 2, 0}), std::vector<double>{0, 1, 2}, natural)),
            "coordinate 1 of point 1 is NaN");
  EXPECT_EQ(message(interpolate_cubic(three, std::vector<double>{0, 1, 2}, CubicEnds{EndCondition::clamped, {1}, {1, 0}})),
            "the start tangent has 1 coordinates, the points have 2");
  EXPECT_EQ(message(interpolate_cubic(three, std::vector<double>{0, 1, 2}, CubicEnds{EndCondition::clamped, {1, 0}, {1, INFINITY}})),
            "coordinate 1 of the end tangent is infinite");
}

TEST(EndCondition, NamesRoundTrip) {
  for (EndCondition c : {EndCondition::natural, EndCondition::clamped, EndCondition::not_a_knot, EndCondition::periodic})
    EXPECT_EQ(*end_condition_from_name(name_of(c)), c);
  EXPECT_EQ(*end_condition_from_name("not_a_knot"), EndCondition::not_a_knot);
  EXPECT_FALSE(end_condition_from_name("free"));
}

TEST(InterpolateBSpline, DegreeOneIsThePolyline) {
  const auto curve = interpolate_bspline(kPoints, kT, 1);
  ASSERT_TRUE(curve.has_value());
  EXPECT_EQ(curve->control_points(), kPoints);
  EXPECT_EQ(knots_of(*curve), (std::vector<double>{0, 0, 0.5, 1.25, 2.0, 2.125, 3.0, 4.5, 4.5}));
}

TEST(InterpolateBSpline, KnotsAverageTheParameters) {
  // p = 3, t = 0, 0.5, 1.25, 2, 2.125, 3, 4.5: interior knots (eq. 9.8)
  // (0.5 + 1.25 + 2)/3 = 1.25, (1.25 + 2 + 2.125)/3 = 1.791666..., (2 + 2.125 + 3)/3 = 2.375.
  const auto curve = interpolate_bspline(kPoints, kT, 3);
  ASSERT_TRUE(curve.has_value());
  const auto knots = knots_of(*curve);
  ASSERT_EQ(knots.size(), 11u);
  EXPECT_EQ(knots[4], 1.25);
  EXPECT_DOUBLE_EQ(knots[5], (1.25 + 2.0 + 2.125) / 3);
  EXPECT_DOUBLE_EQ(knots[6], 2.375);
  expect_control_points_near(*curve, exact_clamped(knots, 3, kT, kPoints, {}), 1e-14);
  // With a first derivative at each end (eq. 9.22): sites 0, 0, 0.5, 1.25, 2,
  // 2.125, 3, 4.5, 4.5 and knots averaging 3 consecutive ones from the second.
  const std::vector<EndDerivative> ends{{false, 1, {1.0, 0.0}}, {true, 1, {0.0, -2.0}}};
  const auto with_ends = interpolate_bspline(kPoints, kT, 3, ends);
  ASSERT_TRUE(with_ends.has_value()) << with_ends.error().message;
  const auto k2 = knots_of(*with_ends);
  const std::vector<double> sites{0, 0, 0.5, 1.25, 2, 2.125, 3, 4.5, 4.5};
  ASSERT_EQ(k2.size(), sites.size() + 4);
  for (std::size_t j = 1; j + 3 < sites.size(); ++j)
    EXPECT_DOUBLE_EQ(k2[j + 3], (sites[j] + sites[j + 1] + sites[j + 2]) / 3) << j;
  expect_control_points_near(*with_ends, exact_clamped(k2, 3, kT, kPoints, ends), 1e-14);
}

// More end derivatives than p + 1 in all: two points are enough (the
// point count needed was once computed unsigned and wrapped around). Degree 5
// with 4 derivatives at each end through 2 points: 10 conditions, 10 control
// points on the averaged knots 0.2, 0.4, 0.6, 0.8; checked against the data.
TEST(InterpolateBSpline, ManyEndDerivativesNeedOnlyTwoPoints) {
  const auto points = PointArray::make({{0.0, 0.0}, {3.0, 1.0}}).value();
  const std::vector<double> parameters{0.0, 1.0};
  std::vector<EndDerivative> ends;
  for (int k = 1; k <= 4; ++k) {
    ends.push_back({false, k, {static_cast<double>(k), 0.0}});
    ends.push_back({true, k, {0.0, -static_cast<double>(k)}});
  }
  const auto curve = interpolate_bspline(points, parameters, 5, ends);
  ASSERT_TRUE(curve.has_value()) << curve.error().message;
  EXPECT_EQ(curve->control_points().size(), 10u);
  EXPECT_LE(distance(point_at(*curve, 0.0), points[0]), 1e-14);
  EXPECT_LE(distance(point_at(*curve, 1.0), points[1]), 1e-14);
  for (const EndDerivative& e : ends) {
    EXPECT_LE(distance(derivative_at(*curve, e.at_end ? 1.0 : 0.0, e.order), e.value), 1e-9 * (1 << (3 * e.order)))
        << e.order << (e.at_end ? " at the end" : " at the start");
  }
}

RC_GTEST_PROP(InterpolateBSpline, MeetsTheDataAndTheDerivatives, ()) {
  const int p = *rc::gen::inRange(1, 7);
  std::vector<EndDerivative> derivatives;
  for (bool at_end : {false, true}) {
    // At most p - 1 per end (the limit), and at most 2: Hermite data of high
    // order on a few points is ill-conditioned in any basis.
    const int count = *rc::gen::inRange(0, std::min(p, 3));
    for (int order = 1; order <= count; ++order) derivatives.push_back({at_end, order, {}});
  }
  const int needed = std::max(2, p + 1 - static_cast<int>(derivatives.size()));
  const Data data = random_data(needed, needed + 20, false);
  const std::size_t d = static_cast<std::size_t>(data.points.dimension());
  for (auto& e : derivatives) e.value = *rc::gen::container<std::vector<double>>(d, test::coordinate());
  const auto curve = interpolate_bspline(data.points, data.t, p, derivatives);
  RC_ASSERT(curve.has_value());
  RC_ASSERT(curve->degree() == p);
  const double scale = std::max(scale_of(data.points), 1e-300);
  for (std::size_t i = 0; i < data.points.size(); ++i)
    RC_ASSERT(distance(point_at(*curve, data.t[i]), data.points[i]) <= 1e-9 * scale);
  for (const EndDerivative& e : derivatives) {
    const auto value = derivative_at(*curve, e.at_end ? data.t.back() : data.t.front(), e.order);
    double size = 100.0;
    for (int k = 0; k < e.order; ++k) size *= 16.0;  // steps >= 1/16: derivatives of O(scale 16^k)
    RC_ASSERT(distance(value, e.value) <= 1e-8 * size);
  }
  for (const KnotContinuity& k : continuity_at_knots(*curve)) RC_ASSERT(k.measured.parametric >= k.predicted);
}

TEST(InterpolateBSpline, RefusesBadInput) {
  const auto message = [](const Expected<BSplineCurve>& e) { return e ? std::string("(accepted)") : e.error().message; };
  EXPECT_EQ(message(interpolate_bspline(kPoints, kT, 0)), "degree 0 is outside 1..10000 for B-spline interpolation");
  EXPECT_EQ(message(interpolate_bspline(kPoints, kT, 7)),
            "degree-7 B-spline interpolation needs at least 8 points, got 7");
  const std::vector<EndDerivative> order_four{{false, 4, {0, 0}}};
  EXPECT_EQ(message(interpolate_bspline(kPoints, kT, 3, order_four)),
            "end derivative 0 has order 4, orders must be in 1..3 for degree 3");
  const std::vector<EndDerivative> twice{{true, 1, {0, 0}}, {true, 1, {1, 0}}};
  EXPECT_EQ(message(interpolate_bspline(kPoints, kT, 3, twice)),
            "end derivative 1 repeats the order-1 derivative at the end (end derivative 0)");
  const std::vector<EndDerivative> too_many{{false, 1, {0, 0}}, {false, 2, {0, 0}}, {false, 3, {0, 0}}};
  EXPECT_EQ(message(interpolate_bspline(kPoints, kT, 3, too_many)), "3 derivatives at the start, degree 3 takes at most 2 at each end");
  const std::vector<EndDerivative> wrong_size{{false, 1, {0}}};
  EXPECT_EQ(message(interpolate_bspline(kPoints, kT, 3, wrong_size)), "end derivative 0 has 1 coordinates, the points have 2");
  // With derivatives a degree above the point count is possible: 2 points,
  // p = 3, a first derivative at each end is the Hermite cubic.
  const std::vector<EndDerivative> hermite{{false, 1, {3, 0}}, {true, 1, {3, 0}}};
  const auto cubic = interpolate_bspline(PointArray::from_trusted(2, {0, 0, 3, 0}), std::vector<double>{0, 1}, 3, hermite);
  ASSERT_TRUE(cubic.has_value()) << cubic.error().message;
  const auto expected = PointArray::from_trusted(2, {0, 0, 1, 0, 2, 0, 3, 0});
  ASSERT_EQ(cubic->control_points().size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LE(distance(cubic->control_points()[i], expected[i]), 1e-15) << i;
}

}  // namespace
}  // namespace casteljau

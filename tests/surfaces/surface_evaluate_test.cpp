// Evaluation of B-spline, NURBS and Bézier surfaces: points and partial
// derivatives (mixed ones too) against exact rational references
// (support/exact_surface.hpp, GMP), and the properties every surface has:
// partition of unity (affine invariance), the convex hull, the tensor
// product equal to iso-curve evaluation, derivatives equal to finite
// differences, the batches equal to point_at, unit normals orthogonal to the
// tangents, and the limit normal at a collapsed row (a pole).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "casteljau/surfaces/iso_curve.hpp"
#include "support/exact_surface.hpp"
#include "support/surface_generators.hpp"

namespace casteljau {
namespace {

/// A 5 x 4 net of dyadic points with a bump, degrees (3, 2), an interior
/// double knot in u: every value is exact in binary.
BSplineSurface reference_surface(bool rational) {
  std::vector<double> c;
  std::vector<double> w;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      c.push_back(i * 0.75 - 1.5);
      c.push_back(j * 1.25 + 0.5 * (i % 2));
      c.push_back(((i * 5 + j * 3) % 7) * 0.5 - 1.0);
      w.push_back(0.5 + ((i * 3 + j) % 5) * 0.375);
    }
  auto net = ControlNet::make(5, 4, *PointArray::make(3, std::move(c)));
  auto s = BSplineSurface::make(3, 2, {0, 0, 0, 0, 0.625, 2, 2, 2, 2}, {-1, -1, -1, 0.25, 1, 1, 1}, *net,
                                rational ? w : std::vector<double>{});
  return *s;
}

/// max over the coordinates of |x - exact| / max(1, max |exact| of that order's table).
struct Worst {
  double value = 0.0;
  void add(double e) { value = std::max(value, e); }
};

double table_scale(const std::vector<std::vector<std::vector<mpq_class>>>& table, int k, int l) {
  double s = 1.0;
  for (const mpq_class& x : table[k][l]) s = std::max(s, std::abs(x.get_d()));
  return s;
}

void check_exact(const BSplineSurface& s, double bound, const char* what) {
  const double us[] = {0, 0.1, 0.625, 1.3, 2};
  const double vs[] = {-1, -0.4, 0.25, 0.9, 1};
  Worst points, derivatives;
  for (double u : us)
    for (double v : vs) {
      const auto exact = test::exact_surface_derivatives(s, u, v, 3, 3);
      points.add(test::relative_error(point_at(s, u, v), exact[0][0], table_scale(exact, 0, 0)));
      const auto table = partial_derivatives_up_to(s, u, v, 3);
      for (int k = 0; k <= 3; ++k)
        for (int l = 0; k + l <= 3; ++l) {
          const double scale = table_scale(exact, k, l);
          const double e = test::relative_error(table[k][l], exact[k][l], scale);
          derivatives.add(e);
          const Point one = partial_derivative_at(s, u, v, k, l);
          derivatives.add(test::relative_error(one, exact[k][l], scale));
          EXPECT_LE(e, bound) << what << " S^(" << k << "," << l << ") at (" << u << ", " << v << ")";
        }
      // Partial derivatives of order 3 in one direction and mixed 3+3.
      const Point high = partial_derivative_at(s, u, v, 3, 3);
      derivatives.add(test::relative_error(high, exact[3][3], table_scale(exact, 3, 3)));
    }
  EXPECT_LE(points.value, bound) << what;
  EXPECT_LE(derivatives.value, bound) << what;
  std::cout << "[ exact    ] " << what << ": points " << points.value << ", derivatives up to (3,3) "
            << derivatives.value << " (relative)\n";
}

TEST(SurfaceEvaluate, PolynomialPointsAndDerivativesAreExactToRounding) {
  check_exact(reference_surface(false), 1e-14, "polynomial B-spline surface");
}

TEST(SurfaceEvaluate, RationalPointsAndDerivativesAreExactToRounding) {
  check_exact(reference_surface(true), 1e-13, "NURBS surface");
}

TEST(SurfaceEvaluate, ClampedCornersAreTheCornerControlPointsExactly) {
  for (bool rational : {false, true}) {
    const BSplineSurface s = reference_surface(rational);
    const ControlNet& net = s.control_net();
    const auto corner = [&](std::size_t i, std::size_t j) {
      return Point(net(i, j).begin(), net(i, j).end());
    };
    EXPECT_EQ(point_at(s, 0, -1), corner(0, 0));
    EXPECT_EQ(point_at(s, 2, -1), corner(4, 0));
    EXPECT_EQ(point_at(s, 0, 1), corner(0, 3));
    EXPECT_EQ(point_at(s, 2, 1), corner(4, 3));
  }
}

TEST(SurfaceEvaluate, PolynomialDerivativesAboveTheDegreeVanish) {
  const BSplineSurface s = reference_surface(false);
  EXPECT_EQ(partial_derivative_at(s, 0.3, 0.1, 4, 0), Point(3, 0.0));
  EXPECT_EQ(partial_derivative_at(s, 0.3, 0.1, 1, 3), Point(3, 0.0));
}

TEST(SurfaceEvaluate, BezierPatchEqualsTheExactBernsteinSum) {
  // Seed 003 figure 6's kind of patch: bicubic, with weights for the rational case.
  std::vector<std::vector<std::vector<double>>> rows;
  for (int i = 0; i < 4; ++i) {
    rows.emplace_back();
    for (int j = 0; j < 4; ++j) rows.back().push_back({i * 1.0, j * 1.0, ((i + 2 * j) % 3) * 0.75});
  }
  const ControlNet net = *ControlNet::make(rows);
  std::vector<double> weights;
  for (int k = 0; k < 16; ++k) weights.push_back(0.25 + (k % 5) * 0.5);
  Worst worst;
  for (const auto& patch : {*BezierSurface::make(net), *BezierSurface::make(net, weights)}) {
    for (double u : {0.0, 0.1, 0.5, 0.75, 1.0})
      for (double v : {0.0, 0.3, 0.625, 1.0}) {
        const auto exact = test::exact_surface_point(patch, u, v);
        const double e = test::relative_error(point_at(patch, u, v), exact, 3.0);
        worst.add(e);
        EXPECT_LE(e, 1e-15) << u << " " << v;
        const auto d = test::exact_surface_derivatives(to_bspline_surface(patch), u, v, 1, 2);
        EXPECT_LE(test::relative_error(partial_derivative_at(patch, u, v, 1, 2), d[1][2], table_scale(d, 1, 2)), 1e-13);
      }
  }
  std::cout << "[ exact    ] Bézier patches (de Casteljau): points " << worst.value << " (relative)\n";
}

RC_GTEST_PROP(SurfaceEvaluateProperties, RandomSurfacesMatchTheExactReference, ()) {
  const BSplineSurface s = *test::bspline_surface({.max_degree = 3, .max_extra_points = 2});
  const double u = *test::parameter_in(s, Direction::u), v = *test::parameter_in(s, Direction::v);
  const auto exact = test::exact_surface_derivatives(s, u, v, 1, 1);
  const double ratio = test::weight_ratio(s.weights());
  const double scale = std::max(1.0, scale_of(s.control_net().points()));
  RC_ASSERT(test::relative_error(point_at(s, u, v), exact[0][0], scale) <= 1e-14 * ratio);
  const auto table = partial_derivatives_up_to(s, u, v, 2);
  for (int k = 0; k <= 1; ++k)
    for (int l = 0; l <= 1; ++l)
      RC_ASSERT(test::relative_error(table[k][l], exact[k][l], table_scale(exact, k, l) + scale) <=
                1e-12 * ratio * ratio);
}

RC_GTEST_PROP(SurfaceEvaluateProperties, AffineInvariance, ()) {
  // Partition of unity makes S(A P + b) = A S(P) + b (weights unchanged).
  const BSplineSurface s = *test::bspline_surface();
  const double m[3][3] = {{0.5, -1.25, 2}, {1, 0.75, -0.5}, {-2, 0.25, 1.5}};
  const double shift[3] = {10, -20, 5};
  std::vector<double> moved;
  for (std::size_t k = 0; k < s.control_net().points().size(); ++k) {
    const auto p = s.control_net().points()[k];
    for (int r = 0; r < 3; ++r) moved.push_back(m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + shift[r]);
  }
  const ControlNet net = ControlNet::from_trusted(s.control_net().rows(), s.control_net().columns(),
                                                  PointArray::from_trusted(3, moved));
  const auto ku = s.knots_u(), kv = s.knots_v();
  const BSplineSurface t = BSplineSurface::from_trusted(s.degree_u(), s.degree_v(), {ku.begin(), ku.end()},
                                                        {kv.begin(), kv.end()}, net,
                                                        {s.weights().begin(), s.weights().end()});
  const double u = *test::parameter_in(s, Direction::u), v = *test::parameter_in(s, Direction::v);
  const Point a = point_at(s, u, v), b = point_at(t, u, v);
  Point mapped(3);
  for (int r = 0; r < 3; ++r) mapped[r] = m[r][0] * a[0] + m[r][1] * a[1] + m[r][2] * a[2] + shift[r];
  RC_ASSERT(distance(mapped, b) <= test::surface_tolerance(s, 1e-13) * 10);
}

RC_GTEST_PROP(SurfaceEvaluateProperties, ConvexHull, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const double u = *test::parameter_in(s, Direction::u), v = *test::parameter_in(s, Direction::v);
  const Point x = point_at(s, u, v);
  const double slack = test::surface_tolerance(s, 1e-14);
  // Every non-zero basis product is >= 0 and they sum to 1 on the domain:
  // the point lies in the box of the control points.
  for (int c = 0; c < 3; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k < s.control_net().points().size(); ++k) {
      lo = std::min(lo, s.control_net().points()[k][c]);
      hi = std::max(hi, s.control_net().points()[k][c]);
    }
    RC_ASSERT(x[c] >= lo - slack);
    RC_ASSERT(x[c] <= hi + slack);
  }
}

RC_GTEST_PROP(SurfaceEvaluateProperties, TensorProductEqualsIsoCurveEvaluation, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const double u = *test::parameter_in(s, Direction::u), v = *test::parameter_in(s, Direction::v);
  const Point direct = point_at(s, u, v);
  const auto along_v = iso_curve(s, Direction::u, u);  // v -> S(u, v)
  const auto along_u = iso_curve(s, Direction::v, v);  // u -> S(u, v)
  RC_ASSERT(along_v.has_value());
  RC_ASSERT(along_u.has_value());
  const double tol = test::surface_tolerance(s, 1e-13);
  RC_ASSERT(distance(direct, point_at(*along_v, v)) <= tol);
  RC_ASSERT(distance(direct, point_at(*along_u, u)) <= tol);
}

RC_GTEST_PROP(SurfaceEvaluateProperties, DerivativesMatchFiniteDifferences, ()) {
  const BSplineSurface s = *test::bspline_surface({.max_degree = 4});
  // A point in the middle of a non-empty span in each direction, so that
  // u +- h stays on one polynomial piece.
  auto inside = [&](Direction direction) {
    const auto t = s.knots(direction);
    const Interval domain = s.domain(direction);
    std::vector<std::pair<double, double>> spans;
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      if (t[i] < t[i + 1] && domain.contains(t[i]) && domain.contains(t[i + 1])) spans.emplace_back(t[i], t[i + 1]);
    const auto span = *rc::gen::elementOf(spans);
    const double f = *rc::gen::inRange(20, 81) / 100.0;
    return std::make_pair(span.first + f * (span.second - span.first), span.second - span.first);
  };
  const auto [u, hu_span] = inside(Direction::u);
  const auto [v, hv_span] = inside(Direction::v);
  const double hu = 1e-4 * hu_span, hv = 1e-4 * hv_span;
  const auto table = partial_derivatives_up_to(s, u, v, 2);
  const auto at = [&](double a, double b) { return point_at(s, a, b); };
  const Point pu = at(u + hu, v), mu = at(u - hu, v), pv = at(u, v + hv), mv = at(u, v - hv);
  const Point pp = at(u + hu, v + hv), pm = at(u + hu, v - hv), mp = at(u - hu, v + hv), mm = at(u - hu, v - hv);
  double su = 0, sv = 0, suv = 0;
  for (int c = 0; c < 3; ++c) {
    su = std::max(su, std::abs(table[1][0][c]));
    sv = std::max(sv, std::abs(table[0][1][c]));
    suv = std::max(suv, std::abs(table[1][1][c]));
  }
  // Central differences: error O(h^2 S''') plus rounding O(eps scale / h);
  // relative 1e-5 of the derivative's size (plus the scale over the span) covers both.
  const double scale = std::max(1.0, scale_of(s.control_net().points())) * test::weight_ratio(s.weights());
  for (int c = 0; c < 3; ++c) {
    RC_ASSERT(std::abs((pu[c] - mu[c]) / (2 * hu) - table[1][0][c]) <= 1e-5 * (su + scale / hu_span));
    RC_ASSERT(std::abs((pv[c] - mv[c]) / (2 * hv) - table[0][1][c]) <= 1e-5 * (sv + scale / hv_span));
    const double mixed = (pp[c] - pm[c] - mp[c] + mm[c]) / (4 * hu * hv);
    RC_ASSERT(std::abs(mixed - table[1][1][c]) <= 1e-4 * (suv + scale / (hu_span * hv_span)));
  }
}

/// Parameters for the batches: ends, knots and interior values, in drawn order.
std::vector<double> batch_parameters(const BSplineSurface& s, Direction direction) {
  return *rc::gen::container<std::vector<double>>(*rc::gen::inRange(1, 12), test::parameter_in(s, direction));
}

RC_GTEST_PROP(SurfaceEvaluateProperties, GridEqualsPointAt, ()) {
  const int d = *rc::gen::inRange(2, 4);
  const BSplineSurface s = *test::bspline_surface({.max_degree = 4, .dimension = d});
  const auto us = batch_parameters(s, Direction::u), vs = batch_parameters(s, Direction::v);
  std::vector<double> out(us.size() * vs.size() * static_cast<std::size_t>(d), NAN);
  grid_points_at(s, us, vs, out);
  const double tol = test::surface_tolerance(s, 1e-14);
  for (std::size_t a = 0; a < us.size(); ++a)
    for (std::size_t b = 0; b < vs.size(); ++b) {
      const Point expected = point_at(s, us[a], vs[b]);
      const std::span<const double> got(out.data() + (a * vs.size() + b) * static_cast<std::size_t>(d),
                                        static_cast<std::size_t>(d));
      RC_ASSERT(distance(expected, got) <= tol);
    }
}

RC_GTEST_PROP(SurfaceEvaluateProperties, ScatteredBatchEqualsPointAt, ()) {
  const BSplineSurface s = *test::bspline_surface({.max_degree = 5, .dimension = 0});
  const std::size_t count = static_cast<std::size_t>(*rc::gen::inRange(1, 20));
  std::vector<double> us, vs;
  for (std::size_t k = 0; k < count; ++k) {
    us.push_back(*test::parameter_in(s, Direction::u));
    vs.push_back(*test::parameter_in(s, Direction::v));
  }
  const std::size_t d = static_cast<std::size_t>(s.dimension());
  std::vector<double> out(count * d, NAN);
  points_at(s, us, vs, out);
  for (std::size_t k = 0; k < count; ++k) {
    const Point expected = point_at(s, us[k], vs[k]);
    for (std::size_t c = 0; c < d; ++c) RC_ASSERT(out[k * d + c] == expected[c]);  // the same operations
  }
}

RC_GTEST_PROP(SurfaceEvaluateProperties, BezierEqualsItsBSplineForm, ()) {
  const BezierSurface patch = *test::bezier_surface(6);
  const BSplineSurface s = to_bspline_surface(patch);
  const double tol = test::surface_tolerance(s, 1e-13);
  std::vector<double> us, vs;
  for (int k = 0; k < 5; ++k) {
    us.push_back(*test::unit_parameter());
    vs.push_back(*test::unit_parameter());
  }
  std::vector<double> grid(us.size() * vs.size() * 3), scattered(us.size() * 3);
  grid_points_at(patch, us, vs, grid);
  points_at(patch, us, vs, scattered);
  for (std::size_t a = 0; a < us.size(); ++a) {
    const Point x = point_at(patch, us[a], vs[a]);
    RC_ASSERT(distance(x, point_at(s, us[a], vs[a])) <= tol);
    RC_ASSERT(distance(x, std::span<const double>(scattered.data() + 3 * a, 3)) == 0.0);
    for (std::size_t b = 0; b < vs.size(); ++b)
      RC_ASSERT(distance(point_at(patch, us[a], vs[b]),
                         std::span<const double>(grid.data() + 3 * (a * vs.size() + b), 3)) <= tol);
  }
  // Derivatives and normals go through the B-spline form: the same numbers.
  RC_ASSERT(partial_derivative_at(patch, us[0], vs[0], 1, 1) == partial_derivative_at(s, us[0], vs[0], 1, 1));
}

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double length(const Point& a) { return std::sqrt(dot(a, a)); }

RC_GTEST_PROP(SurfaceEvaluateProperties, NormalIsUnitAndOrthogonalToTheTangents, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const double u = *test::parameter_in(s, Direction::u), v = *test::parameter_in(s, Direction::v);
  const Point su = partial_derivative_at(s, u, v, 1, 0), sv = partial_derivative_at(s, u, v, 0, 1);
  const Point n = normal_at(s, u, v);
  const double cross_size = length({su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2],
                                    su[0] * sv[1] - su[1] * sv[0]});
  // Random nets can have S_u parallel to S_v somewhere; skip the nearly singular ones.
  RC_PRE(cross_size > 1e-6 * length(su) * length(sv));
  RC_ASSERT(std::abs(length(n) - 1.0) <= 1e-14);
  RC_ASSERT(std::abs(dot(n, su)) <= 1e-9 * length(su));
  RC_ASSERT(std::abs(dot(n, sv)) <= 1e-9 * length(sv));
}

/// A cap z = 1 - u^2 over the disk of radius u: row 0 is the apex repeated
/// (S_v = 0 there), the columns turn counter-clockwise, so the outward
/// normal at the pole is (0, 0, 1). `upper` puts the pole at u = 1 instead.
BezierSurface cap(bool upper) {
  const double radius[3] = {0, 0.5, 1}, height[3] = {1, 1, 0};
  const double angle[4][2] = {{1, 0}, {1, 1}, {-1, 1}, {-1, 0}};  // a Bézier arc over the upper half
  std::vector<std::vector<std::vector<double>>> rows(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) rows[upper ? 2 - i : i].push_back({radius[i] * angle[j][0], radius[i] * angle[j][1], height[i]});
  return *BezierSurface::make(*ControlNet::make(rows));
}

TEST(SurfaceEvaluate, NormalAtAPoleIsTheLimitFromInside) {
  for (double v : {0.0, 0.3, 0.5, 1.0}) {
    const Point n = normal_at(cap(false), 0.0, v);
    EXPECT_NEAR(n[0], 0.0, 1e-15);
    EXPECT_NEAR(n[1], 0.0, 1e-15);
    EXPECT_NEAR(n[2], 1.0, 1e-15) << v;
    // The limit: the normal just inside the domain tends to it.
    const Point near = normal_at(cap(false), 1e-7, v);
    EXPECT_LE(distance(n, near), 1e-6);
    // The pole at the upper end of u: the sign follows the inside approach.
    const Point m = normal_at(cap(true), 1.0, v);
    const Point near_upper = normal_at(cap(true), 1.0 - 1e-7, v);
    EXPECT_LE(distance(m, near_upper), 1e-6) << v;
    EXPECT_NEAR(std::abs(m[2]), 1.0, 1e-15);
  }
  // Transposed (the collapsed side is a column): S_u vanishes instead.
  const BSplineSurface t = transposed(to_bspline_surface(cap(false)));
  const Point n = normal_at(t, 0.4, 0.0);
  const Point near = normal_at(t, 0.4, 1e-7);
  EXPECT_NEAR(std::abs(n[2]), 1.0, 1e-15);
  EXPECT_LE(distance(n, near), 1e-6);
}

TEST(SurfaceEvaluate, NormalOfAPlaneIsItsUnitNormal) {
  const ControlNet net = *ControlNet::make({{{0, 0, 0}, {0, 2, 0}}, {{3, 0, 0}, {3, 2, 0}}});
  const BezierSurface plane = *BezierSurface::make(net);
  EXPECT_EQ(normal_at(plane, 0.25, 0.5), (Point{0, 0, 1}));
  // A net collapsed to one point has no normal anywhere: the zero vector.
  const ControlNet dot_net = *ControlNet::make({{{1, 1, 1}, {1, 1, 1}}, {{1, 1, 1}, {1, 1, 1}}});
  EXPECT_EQ(normal_at(*BezierSurface::make(dot_net), 0.5, 0.5), (Point{0, 0, 0}));
}

}  // namespace
}  // namespace casteljau

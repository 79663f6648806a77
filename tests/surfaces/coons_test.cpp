// Coons patches: boundaries, blending functions, corners, derivatives and
// the B-spline form.
#include "casteljau/surfaces/coons.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

BSplineCurve line(std::vector<double> a, std::vector<double> b) {
  return BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({a, b}).value()).value();
}

BezierCurve bezier(const std::vector<std::vector<double>>& points) {
  return BezierCurve::make(PointArray::make(points).value()).value();
}

// Four curves of four kinds meeting at A = (0,0,0), B = (3,0,0),
// C = (0,2,0), D = (3,2,0.5), exactly:
//  u0 = P(0,v): a NURBS half circle from A to C (centre (0,1,0), radius 1, in the plane x = 0);
//  u1 = P(1,v): a cubic B-spline from B to D on the domain [2, 5] (reparameterized by make);
//  v0 = P(u,0): a cubic Bézier curve from A to B (to_bspline);
//  v1 = P(u,1): a piecewise Bézier curve (a quadratic and a cubic) from C to D.
struct Boundaries {
  BSplineCurve u0, u1, v0, v1;
};

Boundaries mixed_boundaries() {
  const ConicFrame frame{{0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  BSplineCurve u0 = make_arc(frame, 1.0, 0.0, std::numbers::pi).value();
  BSplineCurve u1 = BSplineCurve::make(3, {2, 2, 2, 2, 3, 5, 5, 5, 5},
                                       PointArray::make({{3, 0, 0}, {3.5, 0.5, 0.3}, {2.8, 1, 0.2}, {3.2, 1.5, 0.7}, {3, 2, 0.5}}).value())
                        .value();
  BSplineCurve v0 = to_bspline(bezier({{0, 0, 0}, {1, 0, 1}, {2, 0, -1}, {3, 0, 0}}));
  const auto pieces = PiecewiseBezierCurve::make({bezier({{0, 2, 0}, {0.7, 2.3, 0.4}, {1.5, 2, 0.2}}),
                                                  bezier({{1.5, 2, 0.2}, {2, 1.8, 0.1}, {2.6, 2.1, 0.6}, {3, 2, 0.5}})})
                          .value();
  BSplineCurve v1 = from_bezier_pieces(to_bezier_pieces(pieces)).value();
  return {u0, u1, v0, v1};
}

// Polynomial boundaries of three kinds (for the B-spline form): the arc
// replaced by a quadratic B-spline with an interior knot.
Boundaries polynomial_boundaries() {
  Boundaries b = mixed_boundaries();
  b.u0 = BSplineCurve::make(2, {0, 0, 0, 0.25, 1, 1, 1},
                            PointArray::make({{0, 0, 0}, {0.2, 0.3, 0.8}, {-0.1, 1.5, 0.6}, {0, 2, 0}}).value())
             .value();
  return b;
}

constexpr double kScale = 3.5;  // largest coordinate of the boundaries above

double largest_gap(const Point& a, const Point& b) { return distance(a, b); }

std::vector<double> dyadic_grid(int n) {
  std::vector<double> t;
  for (int i = 0; i <= n; ++i) t.push_back(static_cast<double>(i) / n);
  return t;
}

TEST(CoonsPatch, ReproducesItsFourBoundariesWithBothBlendings) {
  const Boundaries b = mixed_boundaries();
  for (CoonsBlending blending : {CoonsBlending::linear, CoonsBlending::cubic}) {
    const auto patch = CoonsPatch::make(b.u0, b.u1, b.v0, b.v1, blending).value();
    double worst = 0.0;
    for (double s : dyadic_grid(64)) {
      // The boundaries on their own domains: u1 is on [2, 5].
      worst = std::max(worst, largest_gap(point_at(patch, 0.0, s), point_at(b.u0, s)));
      worst = std::max(worst, largest_gap(point_at(patch, 1.0, s), point_at(b.u1, 2.0 + 3.0 * s)));
      worst = std::max(worst, largest_gap(point_at(patch, s, 0.0), point_at(b.v0, s)));
      worst = std::max(worst, largest_gap(point_at(patch, s, 1.0), point_at(b.v1, b.v1.domain().lerp(s))));
    }
    EXPECT_LE(worst, 1e-15 * kScale) << blending_name(blending);  // measured 1.4e-15: two roundings of O(3) numbers
  }
}

TEST(CoonsPatch, UBoundariesAreBitExactWhenTheCornersMatch) {
  // At u = 0, f0 = 1 and f1 = 0 exactly and the corner differences vanish.
  const Boundaries b = mixed_boundaries();
  const auto patch = CoonsPatch::make(b.u0, b.u1, b.v0, b.v1, CoonsBlending::cubic).value();
  for (double v : dyadic_grid(16)) EXPECT_EQ(point_at(patch, 0.0, v), point_at(patch.u0(), v)) << v;
}

TEST(CoonsPatch, FourStraightEdgesGiveTheBilinearPatch) {
  // Non-planar corners; P = (1-u)(1-v) P00 + (1-u) v P01 + u (1-v) P10 + u v P11.
  const std::vector<double> p00{0, 0, 0}, p01{0.5, 2, 1}, p10{3, -0.5, 0.25}, p11{2.5, 3, -1};
  const auto patch = CoonsPatch::make(line(p00, p01), line(p10, p11), line(p00, p10), line(p01, p11)).value();
  double worst = 0.0;
  for (double u : dyadic_grid(16)) {
    for (double v : dyadic_grid(16)) {
      const Point p = point_at(patch, u, v);
      for (int c = 0; c < 3; ++c) {
        const double exact = (1 - u) * (1 - v) * p00[c] + (1 - u) * v * p01[c] + u * (1 - v) * p10[c] + u * v * p11[c];
        worst = std::max(worst, std::abs(p[c] - exact));
      }
    }
  }
  EXPECT_LE(worst, 8e-16 * 3);
}

mpq_class exact_f0(const mpq_class& t) { return 2 * t * t * t - 3 * t * t + 1; }

TEST(CoonsBlending, CubicBlendingIsTheCorrectedHermiteBasis) {
  // Exact at t = k/256: f0 = 2t^3 - 3t^2 + 1 (seed 001 corrected), f1 = 1 - f0,
  // and the derivatives 6t^2 - 6t, 12t - 6, 12 (all exact in double there).
  for (int k = 0; k <= 256; ++k) {
    const double t = k / 256.0;
    mpq_class q(k, 256);
    q.canonicalize();
    const auto f = blending_functions(CoonsBlending::cubic, t);
    EXPECT_EQ(mpq_class(f[0]), exact_f0(q)) << t;
    EXPECT_EQ(mpq_class(f[1]), 1 - exact_f0(q)) << t;
    const auto d1 = blending_functions(CoonsBlending::cubic, t, 1);
    EXPECT_EQ(mpq_class(d1[0]), 6 * q * q - 6 * q) << t;
    EXPECT_EQ(d1[1], -d1[0]);
    const auto d2 = blending_functions(CoonsBlending::cubic, t, 2);
    EXPECT_EQ(mpq_class(d2[0]), 12 * q - 6) << t;
    EXPECT_EQ(blending_functions(CoonsBlending::cubic, t, 3)[0], 12.0);
    EXPECT_EQ(blending_functions(CoonsBlending::cubic, t, 4)[0], 0.0);
    const auto linear = blending_functions(CoonsBlending::linear, t);
    EXPECT_EQ(linear[0], 1 - t);
    EXPECT_EQ(linear[1], t);
  }
  // The seed's misprint 2t^3 - 2t^2 + 1 would give f0(1) = 1.
  EXPECT_EQ(blending_functions(CoonsBlending::cubic, 1.0)[0], 0.0);
  EXPECT_EQ(blending_functions(CoonsBlending::cubic, 0.5)[0], 0.5);
}

TEST(CoonsPatch, CubicBlendingOfStraightEdgesMatchesTheFormulaExactly) {
  // Reference: the header's formula in exact rationals at dyadic (u, v).
  const std::vector<double> p00{0, 0, 0}, p01{0.5, 2, 1}, p10{3, -0.5, 0.25}, p11{2.5, 3, -1};
  const auto patch =
      CoonsPatch::make(line(p00, p01), line(p10, p11), line(p00, p10), line(p01, p11), CoonsBlending::cubic).value();
  double worst = 0.0;
  for (int a = 0; a <= 8; ++a) {
    for (int b = 0; b <= 8; ++b) {
      mpq_class u(a, 8), v(b, 8);
      u.canonicalize();
      v.canonicalize();
      const mpq_class f0u = exact_f0(u), f1u = 1 - f0u, f0v = exact_f0(v), f1v = 1 - f0v;
      const Point p = point_at(patch, a / 8.0, b / 8.0);
      for (int c = 0; c < 3; ++c) {
        const mpq_class U0 = (1 - v) * p00[c] + v * p01[c], U1 = (1 - v) * p10[c] + v * p11[c];
        const mpq_class V0 = (1 - u) * p00[c] + u * p10[c], V1 = (1 - u) * p01[c] + u * p11[c];
        const mpq_class exact = f0u * U0 + f1u * U1 + f0v * V0 + f1v * V1 -
                                (f0u * f0v * p00[c] + f0u * f1v * p01[c] + f1u * f0v * p10[c] + f1u * f1v * p11[c]);
        worst = std::max(worst, std::abs(mpq_class(p[c] - exact).get_d()));
      }
    }
  }
  EXPECT_LE(worst, 8e-16 * 3);
}

TEST(CoonsPatch, RefusesBoundariesThatDoNotMeet) {
  const auto a = line({0, 0, 0}, {0, 1, 0});
  const auto b = line({1, 0, 0}, {1, 1, 0});
  const auto c = line({0, 0, 0}, {1, 0.5, 0});  // should end at (1, 0, 0)
  const auto d = line({0, 1, 0}, {1, 1, 0});
  const auto patch = CoonsPatch::make(a, b, c, d);
  ASSERT_FALSE(patch.has_value());
  EXPECT_EQ(patch.error().message,
            "the boundaries u1 and v0 do not meet at the corner P(1,0): u1 starts at (1, 0, 0), v0 ends at "
            "(1, 0.5, 0), 0.5 apart");
  const auto top = CoonsPatch::make(a, b, line({0, 0, 0}, {1, 0, 0}), line({0, 1, 0}, {1, 1, 2}));
  ASSERT_FALSE(top.has_value());
  EXPECT_EQ(top.error().message,
            "the boundaries u1 and v1 do not meet at the corner P(1,1): u1 ends at (1, 1, 0), v1 ends at (1, 1, 2), 2 "
            "apart");
  const auto flat = line({0, 0}, {1, 0});
  const auto mixed = CoonsPatch::make(a, b, flat, d);
  ASSERT_FALSE(mixed.has_value());
  EXPECT_EQ(mixed.error().message, "the boundaries have different dimensions: u0 has 3 coordinates, v0 has 2");
  // A gap within kJointRelativeGap of the scale is accepted (rounded data).
  EXPECT_TRUE(CoonsPatch::make(a, b, line({0, 0, 0}, {1, 1e-12, 0}), d).has_value());
}

TEST(CoonsPatch, PartialDerivativesMatchFiniteDifferences) {
  const Boundaries b = mixed_boundaries();
  for (CoonsBlending blending : {CoonsBlending::linear, CoonsBlending::cubic}) {
    const auto patch = CoonsPatch::make(b.u0, b.u1, b.v0, b.v1, blending).value();
    const double h = 1e-5;
    for (double u : {0.2, 0.45, 0.8}) {
      for (double v : {0.15, 0.6, 0.9}) {
        // Central differences: error O(h^2 |S'''|) + rounding O(eps |S| / h).
        auto diff = [&](double du, double dv) {
          const Point plus = point_at(patch, u + du, v + dv);
          const Point minus = point_at(patch, u - du, v - dv);
          Point out(3);
          for (int c = 0; c < 3; ++c) out[c] = (plus[c] - minus[c]) / (2 * h);
          return out;
        };
        const Point su = partial_derivative_at(patch, u, v, 1, 0);
        const Point sv = partial_derivative_at(patch, u, v, 0, 1);
        EXPECT_LE(distance(su, diff(h, 0.0)), 1e-7 * kScale) << u << " " << v;
        EXPECT_LE(distance(sv, diff(0.0, h)), 1e-7 * kScale) << u << " " << v;
        // Mixed and second derivatives from differences of the first ones.
        const Point suv = partial_derivative_at(patch, u, v, 1, 1);
        const Point suu = partial_derivative_at(patch, u, v, 2, 0);
        const Point svv2 = partial_derivative_at(patch, u, v, 0, 2);
        const Point su_up = partial_derivative_at(patch, u, v + h, 1, 0), su_down = partial_derivative_at(patch, u, v - h, 1, 0);
        const Point su_right = partial_derivative_at(patch, u + h, v, 1, 0), su_left = partial_derivative_at(patch, u - h, v, 1, 0);
        const Point sv_up = partial_derivative_at(patch, u, v + h, 0, 1), sv_down = partial_derivative_at(patch, u, v - h, 0, 1);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(suv[c], (su_up[c] - su_down[c]) / (2 * h), 1e-6 * kScale);
          EXPECT_NEAR(suu[c], (su_right[c] - su_left[c]) / (2 * h), 1e-6 * kScale);
          EXPECT_NEAR(svv2[c], (sv_up[c] - sv_down[c]) / (2 * h), 1e-6 * kScale);
        }
        EXPECT_EQ(partial_derivative_at(patch, u, v, 0, 0), point_at(patch, u, v));
      }
    }
  }
}

TEST(CoonsPatch, BatchesAgreeWithPointAt) {
  const Boundaries b = mixed_boundaries();
  const auto patch = CoonsPatch::make(b.u0, b.u1, b.v0, b.v1, CoonsBlending::cubic).value();
  const std::vector<double> us{0.0, 0.3, 0.55, 1.0}, vs{1.0, 0.1, 0.75};
  std::vector<double> grid(us.size() * vs.size() * 3), scattered(us.size() * 3);
  grid_points_at(patch, us, vs, grid);
  for (std::size_t a = 0; a < us.size(); ++a)
    for (std::size_t k = 0; k < vs.size(); ++k) {
      const Point p = point_at(patch, us[a], vs[k]);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(grid[(a * vs.size() + k) * 3 + c], p[c], 4e-16 * kScale);
    }
  const std::vector<double> scattered_vs{0.2, 0.0, 0.9, 1.0};
  points_at(patch, us, scattered_vs, scattered);
  for (std::size_t k = 0; k < us.size(); ++k) {
    const Point p = point_at(patch, us[k], scattered_vs[k]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(scattered[k * 3 + c], p[c], 4e-16 * kScale);
  }
}

TEST(CoonsPatch, NormalOfAPlanarPatchIsThePlaneNormal) {
  // Curved boundaries in the plane z = 0, oriented so that S_u x S_v = +z.
  const auto v0 = to_bspline(bezier({{0, 0, 0}, {1, -0.5, 0}, {2, 0.5, 0}, {3, 0, 0}}));
  const auto v1 = to_bspline(bezier({{0, 2, 0}, {1.5, 2.5, 0}, {3, 2, 0}}));
  const auto u0 = to_bspline(bezier({{0, 0, 0}, {-0.5, 1, 0}, {0, 2, 0}}));
  const auto u1 = line({3, 0, 0}, {3, 2, 0});
  const auto patch = CoonsPatch::make(u0, u1, v0, v1, CoonsBlending::cubic).value();
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.5, 1.0}) {
      const Point n = normal_at(patch, u, v);
      EXPECT_NEAR(n[0], 0.0, 1e-15);
      EXPECT_NEAR(n[1], 0.0, 1e-15);
      EXPECT_NEAR(n[2], 1.0, 1e-15);
    }
}

TEST(CoonsPatch, ToBSplineSurfaceEqualsThePatch) {
  const Boundaries b = polynomial_boundaries();
  for (CoonsBlending blending : {CoonsBlending::linear, CoonsBlending::cubic}) {
    const auto patch = CoonsPatch::make(b.u0, b.u1, b.v0, b.v1, blending).value();
    const auto surface = to_bspline_surface(patch).value();
    EXPECT_EQ(surface.domain_u(), (Interval{0, 1}));
    EXPECT_EQ(surface.domain_v(), (Interval{0, 1}));
    EXPECT_FALSE(surface.is_rational());
    double worst = 0.0;
    for (double u : dyadic_grid(32))
      for (double v : dyadic_grid(32)) worst = std::max(worst, distance(point_at(surface, u, v), point_at(patch, u, v)));
    EXPECT_LE(worst, 1e-14 * kScale) << blending_name(blending);
    // The degrees: the boundaries' (3 in u from v0, v1; 3 in v from u1), at least the blending's.
    EXPECT_EQ(surface.degree_u(), 3);
    EXPECT_EQ(surface.degree_v(), 3);
  }
}

TEST(CoonsPatch, ToBSplineSurfaceOfStraightEdgesIsBilinear) {
  const std::vector<double> p00{0, 0, 0}, p01{0.5, 2, 1}, p10{3, -0.5, 0.25}, p11{2.5, 3, -1};
  const auto patch = CoonsPatch::make(line(p00, p01), line(p10, p11), line(p00, p10), line(p01, p11)).value();
  const auto surface = to_bspline_surface(patch).value();
  ASSERT_EQ(surface.degree_u(), 1);
  ASSERT_EQ(surface.degree_v(), 1);
  ASSERT_EQ(surface.control_net().rows(), 2u);
  ASSERT_EQ(surface.control_net().columns(), 2u);
  // The net is the four corners, exactly (P + P - P of equal doubles).
  EXPECT_EQ(Point(surface.control_net()(0, 0).begin(), surface.control_net()(0, 0).end()), p00);
  EXPECT_EQ(Point(surface.control_net()(0, 1).begin(), surface.control_net()(0, 1).end()), p01);
  EXPECT_EQ(Point(surface.control_net()(1, 0).begin(), surface.control_net()(1, 0).end()), p10);
  EXPECT_EQ(Point(surface.control_net()(1, 1).begin(), surface.control_net()(1, 1).end()), p11);
}

TEST(CoonsPatch, ToBSplineSurfaceRefusesRationalBoundaries) {
  const Boundaries b = mixed_boundaries();
  const auto patch = CoonsPatch::make(b.u0, b.u1, b.v0, b.v1).value();
  const auto surface = to_bspline_surface(patch);
  ASSERT_FALSE(surface.has_value());
  EXPECT_EQ(surface.error().message,
            "a Coons patch with rational boundaries has no B-spline form of the same degree; boundary u0 is rational");
}

RC_GTEST_PROP(CoonsPatch, RandomPolynomialBoundariesReproduceAndConvert, ()) {
  // Random cubic Bézier boundaries through random corners (each boundary's
  // ends set to the corners), random blending.
  auto corner = [] { return *rc::gen::container<std::vector<double>>(3, test::coordinate()); };
  const auto p00 = corner(), p01 = corner(), p10 = corner(), p11 = corner();
  auto edge = [&](const std::vector<double>& a, const std::vector<double>& b) {
    const int degree = *rc::gen::inRange(1, 5);
    std::vector<std::vector<double>> points{a};
    for (int k = 1; k < degree; ++k) points.push_back(corner());
    points.push_back(b);
    return to_bspline(bezier(points));
  };
  const auto blending = *rc::gen::element(CoonsBlending::linear, CoonsBlending::cubic);
  const auto patch = CoonsPatch::make(edge(p00, p01), edge(p10, p11), edge(p00, p10), edge(p01, p11), blending).value();
  const auto surface = to_bspline_surface(patch).value();
  const double tol = 1e-13 * 100;
  for (int k = 0; k < 20; ++k) {
    const double u = *test::unit_parameter(), v = *test::unit_parameter();
    RC_ASSERT(distance(point_at(surface, u, v), point_at(patch, u, v)) <= tol);
    RC_ASSERT(distance(point_at(patch, u, 0.0), point_at(patch.v0(), u)) <= 1e-14 * 100);
    RC_ASSERT(distance(point_at(patch, u, 1.0), point_at(patch.v1(), u)) <= 1e-14 * 100);
    RC_ASSERT(distance(point_at(patch, 0.0, v), point_at(patch.u0(), v)) <= 1e-14 * 100);
    RC_ASSERT(distance(point_at(patch, 1.0, v), point_at(patch.u1(), v)) <= 1e-14 * 100);
  }
}

}  // namespace
}  // namespace casteljau

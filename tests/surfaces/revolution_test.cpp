// Surfaces of revolution, spheres and tori: exact NURBS shapes.
#include "casteljau/surfaces/revolution.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "support/bspline_generators.hpp"

namespace casteljau {
namespace {

constexpr double kPi = std::numbers::pi;

double dot3(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point minus3(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// The height along the unit axis t and the distance from the axis of p.
std::pair<double, double> cylindrical(const Point& p, const Point& s, const Point& t) {
  const Point d = minus3(p, s);
  const double h = dot3(d, t);
  const Point radial{d[0] - h * t[0], d[1] - h * t[1], d[2] - h * t[2]};
  return {h, std::sqrt(dot3(radial, radial))};
}

TEST(Sphere, IsASphere) {
  const std::vector<double> center{1.5, -2.25, 0.75};
  const double radius = 3.0;
  const auto sphere = make_sphere(center, radius).value();
  EXPECT_EQ(sphere.degree_u(), 2);
  EXPECT_EQ(sphere.degree_v(), 2);
  EXPECT_EQ(sphere.control_net().rows(), 9u);
  EXPECT_EQ(sphere.control_net().columns(), 5u);
  double worst = 0.0;
  const int n = 200;
  for (int a = 0; a <= n; ++a)
    for (int b = 0; b <= n; ++b) {
      const Point p = point_at(sphere, a / double(n), b / double(n));
      worst = std::max(worst, std::abs(distance(p, center) - radius));
    }
  EXPECT_LE(worst, 1e-14 * radius);
  // Poles: the columns v = 0 and v = 1 are one point each.
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_EQ(Point(sphere.control_net()(i, 0).begin(), sphere.control_net()(i, 0).end()),
              (Point{1.5, -2.25, 0.75 - 3.0}));
    EXPECT_EQ(Point(sphere.control_net()(i, 4).begin(), sphere.control_net()(i, 4).end()),
              (Point{1.5, -2.25, 0.75 + 3.0}));
  }
  // Outward normals, also at the poles (the limit from inside).
  for (double u : {0.0, 0.3, 0.8})
    for (double v : {0.0, 0.25, 0.5, 1.0}) {
      const Point p = point_at(sphere, u, v);
      const Point outward = minus3(p, center);
      const Point normal = normal_at(sphere, u, v);
      EXPECT_NEAR(dot3(normal, outward) / radius, 1.0, 1e-12) << u << " " << v;
    }
}

TEST(Sphere, FullTurnSeamIsSharedBitForBit) {
  const auto sphere = make_sphere(std::vector<double>{0, 0, 0}, 1.0).value();
  const auto& net = sphere.control_net();
  const std::size_t last = net.rows() - 1;
  const std::size_t columns = net.columns();
  for (std::size_t j = 0; j < columns; ++j) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(net(0, j)[c], net(last, j)[c]);
    EXPECT_EQ(sphere.weights()[j], sphere.weights()[last * columns + j]);
  }
  for (double v : {0.1, 0.5, 0.77}) EXPECT_EQ(point_at(sphere, 0.0, v), point_at(sphere, 1.0, v));
}

TEST(Torus, IsATorusAroundAnyAxis) {
  const std::vector<double> center{0.5, 1, -2};
  const std::vector<double> axis{1, 2, 2};  // length 3
  const Point t{1 / 3.0, 2 / 3.0, 2 / 3.0};
  const double major = 4.0, minor = 1.5;
  const auto torus = make_torus(center, axis, major, minor).value();
  EXPECT_EQ(torus.control_net().rows(), 9u);
  EXPECT_EQ(torus.control_net().columns(), 9u);
  double worst = 0.0;
  const int n = 120;
  for (int a = 0; a <= n; ++a)
    for (int b = 0; b <= n; ++b) {
      const Point p = point_at(torus, a / double(n), b / double(n));
      const auto [h, rho] = cylindrical(p, center, t);
      // (rho - R)^2 + h^2 = r^2: the distance to the core circle is r.
      worst = std::max(worst, std::abs(std::hypot(rho - major, h) - minor));
    }
  EXPECT_LE(worst, 1e-14 * (major + minor));
  // Outward normals: away from the core circle.
  for (double u : {0.0, 0.4})
    for (double v : {0.0, 0.3, 0.6}) {
      const Point p = point_at(torus, u, v);
      const auto [h, rho] = cylindrical(p, center, t);
      const Point d = minus3(p, center);
      const Point radial{(d[0] - h * t[0]) / rho, (d[1] - h * t[1]) / rho, (d[2] - h * t[2]) / rho};
      const Point core{center[0] + major * radial[0], center[1] + major * radial[1], center[2] + major * radial[2]};
      const Point outward = minus3(p, core);
      EXPECT_NEAR(dot3(normal_at(torus, u, v), outward) / minor, 1.0, 1e-12);
    }
}

RC_GTEST_PROP(Revolve, EveryProfilePointTurnsOnItsCircle, ()) {
  // Reference: the profile itself. S(0, v) = C(v); S(u, v) is at C(v)'s
  // height on the axis and distance from it, at the angle u * angle
  // (checked at the arcs' ends, where the parameter maps to the angle
  // exactly: u = a / arcs gives the angle a * dθ).
  const auto profile = *test::bspline_curve({.max_degree = 4, .dimension = 3, .max_extra_points = 5});
  const Point s = {*test::coordinate(), *test::coordinate(), *test::coordinate()};
  Point t = {*test::coordinate(), *test::coordinate(), *test::coordinate()};
  RC_PRE(std::sqrt(dot3(t, t)) > 1.0);
  const double angle = *rc::gen::element(kPi / 3, kPi / 2, 2.5, kPi, 4.0, 2 * kPi);
  const auto surface = revolve(profile, s, t, angle).value();
  const double length = std::sqrt(dot3(t, t));
  t = {t[0] / length, t[1] / length, t[2] / length};
  const int arcs = angle <= kPi / 2 ? 1 : angle <= kPi ? 2 : angle <= 3 * kPi / 2 ? 3 : 4;
  RC_ASSERT(static_cast<int>(surface.control_net().rows()) == 2 * arcs + 1);
  const double scale = std::max(1.0, scale_of(profile.control_points())) + 200.0;  // the axis point is O(100)
  const double tol = test::shape_tolerance(profile, 1e-13) + 1e-13 * scale;
  for (int k = 0; k < 8; ++k) {
    const double v = *test::parameter_in(profile);
    const Point c = point_at(profile, v);
    RC_ASSERT(distance(point_at(surface, 0.0, v), c) <= tol);
    const auto [h0, r0] = cylindrical(c, s, t);
    // The profile point's own frame around the axis.
    const Point d = minus3(c, s);
    Point x{d[0] - h0 * t[0], d[1] - h0 * t[1], d[2] - h0 * t[2]};
    for (int i = 0; i <= 16; ++i) {
      const double u = i / 16.0;
      const auto [h, r] = cylindrical(point_at(surface, u, v), s, t);
      RC_ASSERT(std::abs(h - h0) <= tol);
      RC_ASSERT(std::abs(r - r0) <= tol);
    }
    for (int a = 0; a <= arcs; ++a) {
      const double theta = a * (angle / arcs);
      const Point y{t[1] * x[2] - t[2] * x[1], t[2] * x[0] - t[0] * x[2], t[0] * x[1] - t[1] * x[0]};
      Point expected(3);
      for (int cc = 0; cc < 3; ++cc)
        expected[cc] = s[cc] + h0 * t[cc] + std::cos(theta) * x[cc] + std::sin(theta) * y[cc];
      RC_ASSERT(distance(point_at(surface, static_cast<double>(a) / arcs, v), expected) <= tol);
    }
  }
}

TEST(Revolve, AConeFromASegment) {
  // The segment from the apex (0,0,2) to (1,0,0) turned a quarter: the
  // apex column is one point, and S(1, 1) = (0, 1, 0) exactly.
  const auto segment = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0, 2}, {1, 0, 0}}).value()).value();
  const auto cone = revolve(segment, std::vector<double>{0, 0, 0}, std::vector<double>{0, 0, 5}, kPi / 2).value();
  EXPECT_EQ(cone.control_net().rows(), 3u);
  EXPECT_EQ(point_at(cone, 1.0, 1.0), (Point{0, 1, 0}));
  EXPECT_EQ(point_at(cone, 0.5, 0.0), (Point{0, 0, 2}));
  const Point middle = point_at(cone, 0.5, 1.0);  // 45° on the unit circle
  EXPECT_NEAR(middle[0], std::sqrt(0.5), 2.3e-16);
  EXPECT_NEAR(middle[1], std::sqrt(0.5), 2.3e-16);
}

TEST(Revolve, RefusesBadInput) {
  const auto flat = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 1}}).value()).value();
  const auto space = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{1, 0, 0}, {1, 0, 1}}).value()).value();
  const std::vector<double> origin{0, 0, 0}, z{0, 0, 1}, zero{0, 0, 0};
  auto message = [](const Expected<BSplineSurface>& s) { return s.has_value() ? std::string("ok") : s.error().message; };
  EXPECT_EQ(message(revolve(flat, origin, z, 1.0)), "the profile has 2 coordinates, a surface of revolution needs a 3D profile");
  EXPECT_EQ(message(revolve(space, origin, zero, 1.0)),
            "the axis direction is the zero vector (or too large to normalize), it must give a direction");
  EXPECT_EQ(message(revolve(space, std::vector<double>{0, 0}, z, 1.0)), "the axis point has 2 coordinates, it needs 3");
  EXPECT_EQ(message(revolve(space, origin, z, 0.0)), "the angle is 0, it must be > 0 and at most 2π (6.283185307179586)");
  EXPECT_EQ(message(revolve(space, origin, z, 7.0)), "the angle is 7, it must be > 0 and at most 2π (6.283185307179586)");
  EXPECT_EQ(message(revolve(space, origin, z, std::nan(""))), "the angle is NaN");
  EXPECT_EQ(message(make_sphere(origin, 0.0)), "the radius is 0, it must be finite and > 0");
  EXPECT_EQ(message(make_sphere(std::vector<double>{0, 0}, 1.0)), "the centre has 2 coordinates, it needs 3");
  EXPECT_EQ(message(make_torus(origin, z, 1.0, 1.0)),
            "the minor radius 1 is not smaller than the major radius 1: that torus touches or crosses itself on its "
            "axis (only ring tori are made)");
  EXPECT_EQ(message(make_torus(origin, zero, 2.0, 1.0)),
            "the axis is the zero vector (or too large to normalize), it must give a direction");
  EXPECT_EQ(message(make_torus(origin, z, -2.0, 1.0)), "the major radius is -2, it must be finite and > 0");
}

}  // namespace
}  // namespace casteljau

// Invariants of Bézier curves from the seeds: end interpolation, convex hull,
// and the refusal of bad input with messages that name what and where.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "casteljau/bezier/evaluate.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// Andrew's monotone chain convex hull (counter-clockwise), for the test only.
std::vector<Vec2> convex_hull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// Signed distance outside the hull (<= 0 inside), for hulls of >= 3 vertices.
double outside_distance(const std::vector<Vec2>& hull, const Vec2& q) {
  double worst = -INFINITY;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    const Vec2 e = b - a;
    worst = std::max(worst, -cross(e, q - a) / norm(e));
  }
  return worst;
}

RC_GTEST_PROP(BezierCurve, InterpolatesItsEndPoints, ()) {
  const auto curve = *test::any_bezier_curve(20);
  const auto& P = curve.control_points();
  const Point first(P[0].begin(), P[0].end()), last(P[P.size() - 1].begin(), P[P.size() - 1].end());
  if (!curve.is_rational()) {
    // Polynomial: exact, since (1-t) a + t b is a at t = 0 and b at t = 1.
    RC_ASSERT(point_at(curve, 0.0) == first);
    RC_ASSERT(point_at(curve, 1.0) == last);
  } else {
    // Rational: (w P) / w may differ from P by one rounding.
    RC_ASSERT(distance(point_at(curve, 0.0), first) <= 2.3e-16 * 2 * scale_of(P));
    RC_ASSERT(distance(point_at(curve, 1.0), last) <= 2.3e-16 * 2 * scale_of(P));
  }
}

RC_GTEST_PROP(BezierCurve, StaysInTheConvexHull, ()) {
  const bool rational = *rc::gen::arbitrary<bool>();
  const auto curve = *test::bezier_curve(0, 15, rational, 2);
  std::vector<Vec2> points;
  for (std::size_t i = 0; i < curve.control_points().size(); ++i) points.push_back(curve.control_points().vec<2>(i));
  const auto hull = convex_hull(points);
  RC_PRE(hull.size() >= 3);
  const double t = *test::unit_parameter();
  const Vec2 q = Vec2::from(point_at(curve, t));
  RC_ASSERT(outside_distance(hull, q) <= 1e-12 * std::max(1.0, scale_of(curve.control_points())));
}

TEST(BezierCurveMake, RefusesBadInputWithItsPlace) {
  const auto message = [](Expected<BezierCurve> r) { return r.has_value() ? std::string("(accepted)") : r.error().message; };
  EXPECT_EQ(message(BezierCurve::make(PointArray{})),
            "the control polygon is empty, a Bézier curve needs at least one control point");
  EXPECT_EQ(PointArray::make({{0, 0}, {1, NAN}}).error().message, "coordinate 1 of point 1 is NaN");
  EXPECT_EQ(PointArray::make({{0, 0}, {1, 1}, {INFINITY, 2}}, "control point").error().message,
            "coordinate 0 of control point 2 is infinite");
  EXPECT_EQ(PointArray::make({{0, 0}, {1, 1, 1}}).error().message, "point 1 has 3 coordinates, point 0 has 2");
  const auto polygon = PointArray::make({{0, 0}, {1, 1}, {2, 0}}).value();
  EXPECT_EQ(message(BezierCurve::make(polygon, {1, 0, 1})), "weight 1 is 0, weights must be > 0");
  EXPECT_EQ(message(BezierCurve::make(polygon, {1, 1, -2.5})), "weight 2 is -2.5, weights must be > 0");
  EXPECT_EQ(message(BezierCurve::make(polygon, {1, NAN, 1})), "weight 1 is NaN");
  EXPECT_EQ(message(BezierCurve::make(polygon, {1, 1})),
            "2 weights for 3 control points, there must be one weight per control point");
  EXPECT_EQ(PointArray::make(0, {}).error().message, "dimension 0 is not >= 1");
  EXPECT_NE(message(BezierCurve::make(PointArray::zeros(2, 10'002))).find("degree 10001, above the limit 10000"),
            std::string::npos);
  EXPECT_TRUE(BezierCurve::make(PointArray::zeros(2, 10'001)).has_value());
  EXPECT_EQ(PointArray::make(2, {1, 2, 3}).error().message, "3 coordinates do not make whole 2-dimensional points");
}

TEST(BezierCurve, AnyDimensionIsAccepted) {
  const auto c1 = BezierCurve::make(PointArray::make(1, {0, 3, 1}).value()).value();
  EXPECT_EQ(point_at(c1, 0.5), (Point{1.75}));
  std::vector<double> c7(7 * 3);
  for (std::size_t i = 0; i < c7.size(); ++i) c7[i] = static_cast<double>(i);
  const auto curve = BezierCurve::make(PointArray::make(7, c7).value()).value();
  const Point p = point_at(curve, 0.5);
  ASSERT_EQ(p.size(), 7u);
  for (int j = 0; j < 7; ++j) EXPECT_EQ(p[j], 7.0 + j);  // the middle point of an arithmetic progression
}

}  // namespace
}  // namespace casteljau

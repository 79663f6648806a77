// Degree elevation (exact: the same curve), least-squares reduction (with its
// reported error), and seed 003's repeated control point.
#include "casteljau/bezier/degree.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "casteljau/bezier/evaluate.hpp"
#include "support/exact.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

RC_GTEST_PROP(ElevateDegree, KeepsTheCurve, ()) {
  const auto curve = *test::any_bezier_curve(12);
  const int times = *rc::gen::inRange(0, 6);
  const auto elevated = elevate_degree(curve, times);
  RC_ASSERT(elevated.degree() == curve.degree() + times);
  const double tol = 1e-12 * std::max(1.0, scale_of(curve.control_points()));
  for (int i = 0; i <= 16; ++i) RC_ASSERT(distance(point_at(elevated, i / 16.0), point_at(curve, i / 16.0)) <= tol);
}

TEST(ElevateDegree, ControlPointsMatchExactFormula) {
  // Q_i = i/(n+1) P_{i-1} + (1 - i/(n+1)) P_i, computed in exact rationals.
  const auto curve = BezierCurve::make(PointArray::make({{0.1, 3}, {1.7, -2}, {2.2, 2.5}, {4, 1}}).value()).value();
  const auto elevated = elevate_degree(curve);
  const int n = 3;
  for (int i = 0; i <= n + 1; ++i)
    for (int j = 0; j < 2; ++j) {
      mpq_class a(i, n + 1);
      mpq_class exact = (i > 0 ? a * mpq_class(curve.control_points()[i - 1][j]) : mpq_class(0)) +
                        (i <= n ? (1 - a) * mpq_class(curve.control_points()[i][j]) : mpq_class(0));
      EXPECT_LE(test::error_of(elevated.control_points()[i][j], exact), 1e-15 * 4) << i << "," << j;
    }
}

RC_GTEST_PROP(ReduceDegree, UndoesAnElevationExactly, ()) {
  const auto curve = *test::bezier_curve(1, 8, false);
  const auto reduced = reduce_degree(elevate_degree(curve)).value();
  RC_ASSERT(reduced.curve.degree() == curve.degree());
  const double tol = 1e-9 * std::max(1.0, scale_of(curve.control_points()));
  RC_ASSERT(reduced.error_bound <= tol);
  for (std::size_t i = 0; i < curve.control_points().size(); ++i)
    RC_ASSERT(distance(reduced.curve.control_points()[i], curve.control_points()[i]) <= tol);
}

RC_GTEST_PROP(ReduceDegree, ReportedBoundHoldsAndEndsAreKept, ()) {
  const auto curve = *test::bezier_curve(2, 10, false, 2);
  const auto reduced = reduce_degree(curve).value();
  RC_ASSERT(reduced.sampled_error <= reduced.error_bound * (1 + 1e-12) + 1e-12);
  const int n = curve.degree();
  RC_ASSERT(distance(reduced.curve.control_points()[0], curve.control_points()[0]) == 0.0);
  RC_ASSERT(distance(reduced.curve.control_points()[n - 1], curve.control_points()[n]) == 0.0);
  for (int i = 0; i <= 64; ++i) {
    const double t = i / 64.0;
    RC_ASSERT(distance(point_at(curve, t), point_at(reduced.curve, t)) <= reduced.error_bound * (1 + 1e-9) + 1e-12);
  }
}

TEST(ReduceDegree, UnconstrainedIsTheL2Best) {
  // The L2-best line for the parabola t^2 on [0,1] is t - 1/6 (Legendre projection).
  const auto parabola = BezierCurve::make(PointArray::make({{0, 0}, {0.5, 0}, {1, 1}}).value()).value();
  const auto line = reduce_degree(parabola, {.keep_end_points = false}).value();
  EXPECT_NEAR(line.curve.control_points()[0][1], -1.0 / 6, 1e-14);
  EXPECT_NEAR(line.curve.control_points()[1][1], 5.0 / 6, 1e-14);
  EXPECT_NEAR(line.sampled_error, 1.0 / 6, 1e-6);
}

TEST(ReduceDegree, RefusesWhatItCannotDo) {
  const auto point = BezierCurve::make(PointArray::make({{1, 1}}).value()).value();
  EXPECT_FALSE(reduce_degree(point).has_value());
  const auto rational = BezierCurve::make(PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(), {1, 0.7, 1}).value();
  const auto r = reduce_degree(rational);
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().message.find("rational"), std::string::npos);
}

TEST(RepeatControlPoint, PullsTheCurveTowardThePoint) {
  // Seed 003 fig. 4 b): the more copies of P1, the closer the curve comes to it.
  const auto curve = BezierCurve::make(PointArray::make({{0, 0}, {1, 3}, {3, 3}, {4, 0}}).value()).value();
  double previous = INFINITY;
  for (int extra = 0; extra <= 4; ++extra) {
    const auto pulled = repeat_control_point(curve, 1, extra);
    EXPECT_EQ(pulled.degree(), 3 + extra);
    double closest = INFINITY;
    for (int i = 0; i <= 2000; ++i) closest = std::min(closest, distance(point_at(pulled, i / 2000.0), curve.control_points()[1]));
    EXPECT_LT(closest, previous) << extra;
    previous = closest;
  }
}

}  // namespace
}  // namespace casteljau

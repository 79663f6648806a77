// Differential geometry written once on CurveView, checked on every kind
// against closed forms: the twisted cubic (t, t^2, t^3), whose curvature and
// torsion are known exactly (do Carmo §1-6, exercise 2), written as a Bézier
// curve, as a B-spline and as a piecewise curve of its two halves (curvature
// and torsion are invariants: the reparameterization must not show); the
// NURBS circle (curvature 1/R, normal toward the centre); a parabola for the
// signed curvature; a repeated control point for the tangent's limit.
#include "casteljau/curves/differential_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/nurbs/conics.hpp"

namespace casteljau {
namespace {

/// (t, t^2, t^3) on [0, 1]: the power basis converted to Bernstein form exactly (up to rounding 1/3, 2/3).
BezierCurve twisted_cubic() {
  return BezierCurve::make(PointArray::make({{0, 0, 0}, {1.0 / 3, 0, 0}, {2.0 / 3, 1.0 / 3, 0}, {1, 1, 1}}).value())
      .value();
}

double twisted_curvature(double t) {
  // |C' x C''| / |C'|^3 with C' = (1, 2t, 3t^2), C'' = (0, 2, 6t): C' x C'' = (6t^2, -6t, 2).
  return 2.0 * std::sqrt(9 * t * t * t * t + 9 * t * t + 1) / std::pow(1 + 4 * t * t + 9 * t * t * t * t, 1.5);
}

double twisted_torsion(double t) { return 3.0 / (9 * t * t * t * t + 9 * t * t + 1); }

double norm(const Point& p) { return distance(p, Point(p.size(), 0.0)); }

double dot(const Point& a, const Point& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

TEST(DifferentialGeometry, TwistedCubicOnEveryKind) {
  const BezierCurve bezier = twisted_cubic();
  const BSplineCurve bspline = to_bspline(bezier);
  const auto halves = split_at(bezier, 0.5).value();
  const PiecewiseBezierCurve piecewise = PiecewiseBezierCurve::make({halves.first, halves.second}).value();
  for (int i = 0; i <= 16; ++i) {
    const double t = i / 16.0;
    const double u = t < 0.5 ? 2 * t : 1 + 2 * (t - 0.5);  // the same point on the piecewise curve
    for (const auto& [view, at] : {std::pair{CurveView(bezier), t}, std::pair{CurveView(bspline), t},
                                   std::pair{CurveView(piecewise), u}}) {
      EXPECT_NEAR(curvature_at(view, at), twisted_curvature(t), 1e-14 * 8) << t;
      EXPECT_NEAR(torsion_at(view, at), twisted_torsion(t), 1e-14 * 8) << t;
      const FrenetFrame frame = frenet_frame_at(view, at);
      EXPECT_EQ(frame.curvature, curvature_at(view, at));
      EXPECT_EQ(frame.torsion, torsion_at(view, at));
      EXPECT_EQ(frame.tangent, unit_tangent_at(view, at));
      EXPECT_EQ(frame.normal, unit_normal_at(view, at));
      EXPECT_EQ(frame.binormal, binormal_at(view, at));
      // An orthonormal, right-handed frame.
      EXPECT_NEAR(norm(frame.tangent), 1.0, 1e-15);
      EXPECT_NEAR(norm(frame.normal), 1.0, 1e-15);
      EXPECT_NEAR(norm(frame.binormal), 1.0, 1e-15);
      EXPECT_NEAR(dot(frame.tangent, frame.normal), 0.0, 1e-15);
      EXPECT_NEAR(dot(frame.tangent, frame.binormal), 0.0, 1e-15);
      EXPECT_NEAR(dot(frame.normal, frame.binormal), 0.0, 1e-15);
      // The tangent of (t, t^2, t^3) is (1, 2t, 3t^2) normalised.
      const Point exact{1, 2 * t, 3 * t * t};
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(frame.tangent[j], exact[j] / norm(exact), 1e-15) << t;
    }
  }
}

TEST(DifferentialGeometry, TheNurbsCircleHasConstantCurvatureTowardItsCentre) {
  const double radius = 2.5;
  const BSplineCurve circle = make_circle(1.0, -2.0, radius).value();
  const Interval domain = circle.domain();
  for (int i = 0; i <= 64; ++i) {
    const double u = domain.lerp(i / 64.0);
    EXPECT_NEAR(curvature_at(circle, u), 1.0 / radius, 1e-14 / radius);
    EXPECT_NEAR(signed_curvature_at(circle, u), 1.0 / radius, 1e-14 / radius);  // counter-clockwise
    const Point p = point_at(circle, u), n = unit_normal_at(circle, u);
    // p + R n is the centre.
    EXPECT_NEAR(p[0] + radius * n[0], 1.0, 1e-13);
    EXPECT_NEAR(p[1] + radius * n[1], -2.0, 1e-13);
    const FrenetFrame frame = frenet_frame_at(circle, u);
    EXPECT_TRUE(frame.binormal.empty());
    EXPECT_EQ(frame.torsion, 0.0);
  }
}

TEST(DifferentialGeometry, SignedCurvatureOfTheParabolaAsABSpline) {
  // (0,0), (1/2,0), (1,1): x = t, y = t^2, kappa = 2 / (1 + 4x^2)^(3/2), turning left.
  const BezierCurve parabola = BezierCurve::make(PointArray::make({{0, 0}, {0.5, 0}, {1, 1}}).value()).value();
  const BSplineCurve as_bspline = to_bspline(parabola);
  for (double t : {0.0, 0.3, 0.5, 1.0}) {
    const double expected = 2 / std::pow(1 + 4 * t * t, 1.5);
    EXPECT_NEAR(signed_curvature_at(as_bspline, t), expected, 1e-14);
    const BSplineCurve backwards = reversed(as_bspline);
    EXPECT_NEAR(signed_curvature_at(backwards, 1 - t), -expected, 1e-14);
  }
}

TEST(DifferentialGeometry, TangentLimitAtARepeatedControlPointOnEveryKind) {
  // C'(0) = 0 and C'(1) = 0: the tangent is the direction of C''.
  const BezierCurve cubic = BezierCurve::make(PointArray::make({{0, 0}, {0, 0}, {3, 4}, {3, 4}}).value()).value();
  const BSplineCurve bspline = to_bspline(cubic);
  const PiecewiseBezierCurve piecewise = PiecewiseBezierCurve::make({cubic}).value();
  for (const CurveView view : {CurveView(cubic), CurveView(bspline), CurveView(piecewise)}) {
    const Point start = unit_tangent_at(view, 0.0), end = unit_tangent_at(view, 1.0);
    EXPECT_NEAR(start[0], 0.6, 1e-15);
    EXPECT_NEAR(start[1], 0.8, 1e-15);
    // At the end the limit from inside the domain: along the travel, not against it.
    EXPECT_NEAR(end[0], 0.6, 1e-15);
    EXPECT_NEAR(end[1], 0.8, 1e-15);
    EXPECT_EQ(curvature_at(view, 0.5), 0.0);  // a straight segment
  }
  const BezierCurve point = BezierCurve::make(PointArray::make({{1, 1}, {1, 1}}).value()).value();
  EXPECT_EQ(unit_tangent_at(point, 0.5), (Point{0, 0}));
}

}  // namespace
}  // namespace casteljau

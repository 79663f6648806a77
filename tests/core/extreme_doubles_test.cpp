// Every make() of a curve, fed extreme doubles (subnormals, the edges of the
// accepted ranges and one ulp beyond, 1e308, DBL_MAX, inf, NaN, spans of one
// ulp, huge and tiny weights), either refuses with a message or builds a
// curve whose points and first derivatives are finite everywhere on its
// domain, by every evaluator: point_at, derivative_at (order 1), the batch
// kernels points_at (sorted and shuffled, which take different SIMD paths),
// points_at_within and points_and_derivatives_at (core/tolerance.hpp says
// why the ranges guarantee it). Surfaces: tests/surfaces/extreme_doubles_test.cpp.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/interpolation/c1_bezier.hpp"
#include "casteljau/interpolation/catmull_rom.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "support/extreme_doubles.hpp"

namespace casteljau {
namespace {

using test::all_finite;
using test::expect_message;

/// Evaluates a Bézier curve at the ends, one ulp inside them, the middle,
/// subnormal parameters and a random one: every point and first derivative
/// finite, and the batch equal to point_at.
void expect_finite(const BezierCurve& curve) {
  RC_TAG("evaluated");
  std::vector<double> ts{0.0, 1.0, 0.5, 5e-324, 1e-310, std::nextafter(1.0, 0.0), *test::mixed_double(0) / 32 + 0.5};
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  std::vector<double> batch(ts.size() * d);
  points_at(curve, ts, batch);
  RC_ASSERT(all_finite(batch));
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Point point = point_at(curve, ts[i]);
    RC_ASSERT(all_finite(point));
    RC_ASSERT(std::equal(point.begin(), point.end(), batch.begin() + static_cast<std::ptrdiff_t>(i * d)));
    RC_ASSERT(all_finite(derivative_at(curve, ts[i], 1)));
  }
}

/// The same over a B-spline's domain (every knot, beside every knot, every
/// span's middle), by the scalar functions and every batch kernel.
void expect_finite(const BSplineCurve& curve) {
  RC_TAG("evaluated");
  const Interval domain = curve.domain();
  std::vector<double> us = test::parameters_over(curve.knots(), domain.lower, domain.upper);
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  for (double u : us) {
    RC_ASSERT(all_finite(point_at(curve, u)));
    RC_ASSERT(all_finite(derivative_at(curve, u, 1)));
  }
  for (const bool sorted : {true, false}) {
    if (sorted) {
      std::sort(us.begin(), us.end());
    } else {
      std::reverse(us.begin(), us.end());
      if (us.size() > 2) std::swap(us[1], us[us.size() / 2]);
    }
    std::vector<double> points(us.size() * d), derivatives(us.size() * d);
    points_at(curve, us, points);
    RC_ASSERT(all_finite(points));
    RC_ASSERT(points_at_within(curve, us, domain, points) == us.size());
    RC_ASSERT(all_finite(points));
    points_and_derivatives_at(curve, us, points, derivatives);
    RC_ASSERT(all_finite(points));
    RC_ASSERT(all_finite(derivatives));
    derivatives_at(curve, us, 1, derivatives);
    RC_ASSERT(all_finite(derivatives));
  }
}

RC_GTEST_PROP(ExtremeDoubles, BezierCurveMakeRefusesOrEvaluatesFinitely, ()) {
  const int degree = *rc::gen::weightedOneOf<int>({{9, rc::gen::inRange(0, 6)}, {1, rc::gen::just(300)}});
  const int d = *rc::gen::inRange(1, 4);
  const std::size_t count = static_cast<std::size_t>(degree) + 1;
  const int share = degree > 10 ? 0 : 2;  // the long curve: ordinary points, extreme weights
  auto curve = BezierCurve::make(test::mixed_points(count, d, share), test::mixed_weights(count));
  if (!curve) return expect_message(curve);
  expect_finite(*curve);
}

RC_GTEST_PROP(ExtremeDoubles, PiecewiseBezierMakeRefusesOrEvaluatesFinitely, ()) {
  const int d = *rc::gen::inRange(1, 4);
  std::vector<BezierCurve> pieces;
  const int count = *rc::gen::inRange(1, 4);
  for (int i = 0; i < count; ++i) {
    const std::size_t points = static_cast<std::size_t>(*rc::gen::inRange(1, 5));
    auto piece = BezierCurve::make(test::mixed_points(points, d), test::mixed_weights(points));
    if (!piece) return expect_message(piece);
    pieces.push_back(*piece);
  }
  auto curve = PiecewiseBezierCurve::make(pieces);
  RC_ASSERT(curve.has_value());
  RC_TAG("evaluated");
  const std::size_t dd = static_cast<std::size_t>(d);
  std::vector<double> us;
  for (int i = 0; i <= count; ++i) {
    us.push_back(i);
    us.push_back(std::nextafter(static_cast<double>(i), -1.0));
    us.push_back(i + 0.5);
  }
  us.front() = 0.0;
  us.back() = count;
  std::vector<double> out(us.size() * dd);
  points_at(*curve, us, out);
  RC_ASSERT(all_finite(out));
  for (double u : us) {
    RC_ASSERT(all_finite(point_at(*curve, u)));
    RC_ASSERT(all_finite(derivative_at(*curve, u, 1)));
  }
}

/// A B-spline from extreme knots, coordinates and weights; degree 0..4 in
/// dimension 1..3 (the unrolled kernels) or degree 9 (the scalar path).
RC_GTEST_PROP(ExtremeDoubles, BSplineCurveMakeRefusesOrEvaluatesFinitely, ()) {
  const int degree = *rc::gen::weightedOneOf<int>({{9, rc::gen::inRange(0, 5)}, {1, rc::gen::just(9)}});
  const int d = *rc::gen::inRange(1, 4);
  const std::size_t count = static_cast<std::size_t>(degree) + 1 + static_cast<std::size_t>(*rc::gen::inRange(0, 4));
  std::vector<double> knots = test::extreme_knots(count + static_cast<std::size_t>(degree) + 1);
  const int share = *rc::gen::inRange(0, 3);  // some curves with ordinary points only, to reach the knots
  auto curve = BSplineCurve::make(degree, knots, test::mixed_points(count, d, share), test::mixed_weights(count));
  if (!curve) return expect_message(curve);
  expect_finite(*curve);
}

/// The Rhino/openNURBS convention goes through the same checks.
RC_GTEST_PROP(ExtremeDoubles, RhinoKnotsAreRefusedOrEvaluateFinitely, ()) {
  const int degree = *rc::gen::inRange(1, 4);
  const std::size_t count = static_cast<std::size_t>(degree) + 1 + static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  auto knots = knots_from_rhino(test::extreme_knots(count + static_cast<std::size_t>(degree) - 1), degree, count);
  if (!knots) return expect_message(knots);
  auto curve = BSplineCurve::make(degree, *knots, test::mixed_points(count, 2, 0));
  RC_ASSERT(curve.has_value());
  expect_finite(*curve);
}

RC_GTEST_PROP(ExtremeDoubles, PeriodicMakeRefusesOrEvaluatesFinitely, ()) {
  const int degree = *rc::gen::inRange(1, 4);
  const std::size_t count = static_cast<std::size_t>(degree) + 1 + static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  const double lower = *test::mixed_double(5);
  const double upper = *rc::gen::weightedOneOf<double>(
      {{1, rc::gen::just(std::nextafter(lower, test::kInf))}, {1, test::mixed_double(5)}});
  auto curve = make_periodic(degree, test::mixed_points(count, 2), test::mixed_weights(count), Interval{lower, upper});
  if (!curve) return expect_message(curve);
  expect_finite(*curve);
}

/// Conics: centre, radius (or semi-axes) and angles at the edges, in the
/// plane and in a frame of R^3.
RC_GTEST_PROP(ExtremeDoubles, ConicsRefuseOrEvaluateFinitely, ()) {
  const double cx = *test::mixed_double(4), cy = *test::mixed_double(4);
  const double r = *rc::gen::weightedOneOf<double>(
      {{1, test::edge_double()}, {1, rc::gen::map(rc::gen::inRange(1, 64), [](int i) { return i / 8.0; })}});
  const double b = *test::mixed_double(5);
  const double start = *test::mixed_double(3);
  const double sweep = *rc::gen::weightedOneOf<double>(
      {{2, rc::gen::map(rc::gen::inRange(-8, 9), [](int i) { return i * std::numbers::pi / 4; })},
       {1, test::edge_double()}});
  const ConicFrame frame{{cx, cy, *test::mixed_double(4)}, {0, 0, 1}, {1, 0, 0}};  // a plane of R^3
  for (const auto& curve : {make_arc(cx, cy, r, start, sweep), make_circle(cx, cy, r), make_ellipse(cx, cy, r, b),
                            make_arc(frame, r, start, sweep)}) {
    if (!curve) {
      expect_message(curve);
      continue;
    }
    expect_finite(*curve);
  }
}

/// Interpolation inputs go through check_coordinates (and parameters through
/// check_increasing): refused, or the interpolant evaluates finitely.
RC_GTEST_PROP(ExtremeDoubles, InterpolationInputsAreRefusedOrEvaluateFinitely, ()) {
  const std::size_t count = static_cast<std::size_t>(*rc::gen::inRange(2, 7));
  const PointArray points = test::mixed_points(count, 2);
  if (auto c1 = interpolate_c1_bezier(points)) {
    for (const BezierCurve& piece : c1->pieces()) expect_finite(piece);
  } else {
    expect_message(c1);
  }
  const std::vector<double> parameters = test::extreme_knots(count);
  for (const auto& curve : {interpolate_cubic(points, parameters, CubicEnds{EndCondition::natural, {}, {}}),
                            interpolate_catmull_rom(points, parameters)}) {
    if (!curve) {
      expect_message(curve);
      continue;
    }
    expect_finite(*curve);
  }
}

}  // namespace
}  // namespace casteljau

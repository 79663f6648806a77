// Catmull–Rom splines against the Barry–Goldman pyramid evaluated exactly
// (rational arithmetic with forward-mode derivatives), Yuksel's cusp and
// loop configurations, the closed form, errors.
#include "casteljau/interpolation/catmull_rom.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/interpolation/c1_bezier.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// A point of the pyramid with its derivative in t, exactly.
struct Jet {
  std::vector<mpq_class> value, derivative;
};

/// ((b − t) X + (t − a) Y)/(b − a) and its derivative (product rule).
Jet lerp(const Jet& x, const Jet& y, const mpq_class& a, const mpq_class& b, const mpq_class& t) {
  Jet out;
  const mpq_class length = b - a;
  for (std::size_t k = 0; k < x.value.size(); ++k) {
    out.value.push_back(((b - t) * x.value[k] + (t - a) * y.value[k]) / length);
    out.derivative.push_back((y.value[k] - x.value[k]) / length +
                             ((b - t) * x.derivative[k] + (t - a) * y.derivative[k]) / length);
  }
  return out;
}

Jet constant(const std::vector<mpq_class>& p) {
  return {p, std::vector<mpq_class>(p.size(), mpq_class(0))};
}

/// The Barry–Goldman pyramid (Barry & Goldman 1988; Yuksel et al. 2011 eq. 2)
/// over four points at four times, at t in [t1, t2]: value and derivative.
Jet barry_goldman(const std::vector<std::vector<mpq_class>>& p, const std::vector<mpq_class>& t,
                  const mpq_class& u) {
  const Jet a1 = lerp(constant(p[0]), constant(p[1]), t[0], t[1], u);
  const Jet a2 = lerp(constant(p[1]), constant(p[2]), t[1], t[2], u);
  const Jet a3 = lerp(constant(p[2]), constant(p[3]), t[2], t[3], u);
  const Jet b1 = lerp(a1, a2, t[0], t[2], u);
  const Jet b2 = lerp(a2, a3, t[1], t[3], u);
  return lerp(b1, b2, t[1], t[2], u);
}

/// The four points and times of segment i, with the documented end rule
/// (reflected phantom points) or cyclic neighbours when closed.
void segment_data(const PointArray& points, std::span<const double> parameters, bool closed, std::size_t i,
                  std::vector<std::vector<mpq_class>>& p, std::vector<mpq_class>& t) {
  const std::size_t count = points.size(), d = static_cast<std::size_t>(points.dimension());
  const std::size_t segments = closed ? count : count - 1;
  auto exact_point = [&](std::size_t j) {
    std::vector<mpq_class> q;
    for (std::size_t k = 0; k < d; ++k) q.emplace_back(points[j % count][k]);
    return q;
  };
  p.assign(4, {});
  t.assign(4, 0);
  p[1] = exact_point(i);
  p[2] = exact_point(i + 1);
  t[1] = parameters[i];
  t[2] = parameters[i + 1];
  if (i > 0) {
    p[0] = exact_point(i - 1);
    t[0] = parameters[i - 1];
  } else if (closed) {
    p[0] = exact_point(count - 1);
    t[0] = mpq_class(parameters[0]) - (mpq_class(parameters[segments]) - mpq_class(parameters[segments - 1]));
  } else {
    for (std::size_t k = 0; k < d; ++k) p[0].push_back(2 * p[1][k] - p[2][k]);
    t[0] = 2 * t[1] - t[2];
  }
  if (i + 1 < segments) {
    p[3] = exact_point(i + 2);
    t[3] = parameters[i + 2];
  } else if (closed) {
    p[3] = exact_point(1);
    t[3] = mpq_class(parameters[segments]) + (mpq_class(parameters[1]) - mpq_class(parameters[0]));
  } else {
    for (std::size_t k = 0; k < d; ++k) p[3].push_back(2 * p[2][k] - p[1][k]);
    t[3] = 2 * t[2] - t[1];
  }
}

/// Max over the segments and 9 parameters per segment of the distances
/// between the curve (and its derivative) and the exact pyramid, relative to
/// the scale of the points (and of the difference quotients).
void expect_barry_goldman(const PointArray& points, std::span<const double> parameters, bool closed,
                          const std::string& what) {
  const auto curve = interpolate_catmull_rom(points, parameters, closed ? Closure::closed : Closure::open);
  ASSERT_TRUE(curve) << curve.error().message;
  const std::size_t count = points.size(), d = static_cast<std::size_t>(points.dimension());
  const std::size_t segments = closed ? count : count - 1;
  EXPECT_EQ(curve->domain(), (Interval{parameters[0], parameters[segments]})) << what;
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < segments; ++i) shortest = std::min(shortest, parameters[i + 1] - parameters[i]);
  const double scale = scale_of(points);
  const double point_tolerance = 1e-13 * scale, derivative_tolerance = 1e-12 * scale / shortest;
  for (std::size_t i = 0; i < segments; ++i) {
    std::vector<std::vector<mpq_class>> p;
    std::vector<mpq_class> t;
    segment_data(points, parameters, closed, i, p, t);
    for (int j = 0; j <= 8; ++j) {
      const double u = j == 8 ? parameters[i + 1] : parameters[i] + (parameters[i + 1] - parameters[i]) * j / 8.0;
      const Jet exact = barry_goldman(p, t, mpq_class(u));
      const Point c = point_at(*curve, u);
      // At a knot derivative_at takes the span to the right; the pyramid of
      // segment i gives the left derivative at t_{i+1}, so take that span's
      // Bézier piece there: both must agree (C¹).
      const Point dc = j == 8 ? derivative_at(to_bezier_pieces(*curve).pieces[i], 1.0, 1)
                              : derivative_at(*curve, u, 1);
      const double h = parameters[i + 1] - parameters[i];
      for (std::size_t k = 0; k < d; ++k) {
        EXPECT_LE(std::abs(mpq_class(mpq_class(c[k]) - exact.value[k]).get_d()), point_tolerance)
            << what << " segment " << i << " u " << u;
        const double derivative = j == 8 ? dc[k] / h : dc[k];
        EXPECT_LE(std::abs(mpq_class(mpq_class(derivative) - exact.derivative[k]).get_d()), derivative_tolerance)
            << what << " segment " << i << " u " << u << " coordinate " << k;
      }
    }
  }
}

PointArray head_points() {
  // examples/head.csv (seed 000, 19 points), inlined: the points are data here.
  return PointArray::make(2, {9.5, 5, 5.5, 5, 1, 7, -3.5, 9.5, -9.5, 8, -9.5, -2.5, -8.5, -4.5,
                              -5, -5, -4.5, -2.5, -0.5, -9, 0, -7, -1, -4.5, 2, -5, 3, -1.5,
                              2.5, -5, 5, -4.5, 7.5, -5, 6.5, -0.5, 9.5, -0.5})
      .value();
}

TEST(CatmullRom, EqualsTheBarryGoldmanPyramidOnTheHead) {
  const PointArray head = head_points();
  for (auto kind : {Parameterization::uniform, Parameterization::chord_length, Parameterization::centripetal})
    for (bool closed : {false, true}) {
      const auto parameters = parameter_values(head, kind, closed ? Closure::closed : Closure::open).value();
      expect_barry_goldman(head, parameters, closed,
                           std::string(name_of(kind)) + (closed ? " closed" : " open"));
    }
}

TEST(CatmullRom, PassesThroughThePointsWithBarryGoldmanTangents) {
  const PointArray head = head_points();
  const auto parameters = parameter_values(head, Parameterization::centripetal).value();
  const auto curve = interpolate_catmull_rom(head, parameters).value();
  const double scale = scale_of(head);
  for (std::size_t i = 0; i < head.size(); ++i) {
    const Point c = point_at(curve, parameters[i]);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(c[k], head[i][k], 1e-14 * scale) << "point " << i;
  }
  // The tangent formula of the header, in exact arithmetic, at an interior point.
  const std::size_t i = 7;
  const Point tangent = derivative_at(curve, parameters[i], 1);
  for (int k = 0; k < 2; ++k) {
    const mpq_class t0(parameters[i - 1]), t1(parameters[i]), t2(parameters[i + 1]);
    const mpq_class p0(head[i - 1][k]), p1(head[i][k]), p2(head[i + 1][k]);
    const mpq_class exact = (p1 - p0) / (t1 - t0) - (p2 - p0) / (t2 - t0) + (p2 - p1) / (t2 - t1);
    EXPECT_NEAR(tangent[k], exact.get_d(), 1e-12 * std::abs(exact.get_d()) + 1e-12 * scale);
  }
}

TEST(CatmullRom, UniformClosedEqualsClosedC1BezierAlphaTwo) {
  const PointArray head = head_points();
  std::vector<double> parameters(head.size() + 1);
  for (std::size_t i = 0; i < parameters.size(); ++i) parameters[i] = static_cast<double>(i);
  const auto pieces = to_bezier_pieces(interpolate_catmull_rom(head, parameters, Closure::closed).value());
  const auto c1 = interpolate_c1_bezier(head, 2.0, Closure::closed).value();
  ASSERT_EQ(pieces.pieces.size(), c1.pieces().size());
  for (std::size_t i = 0; i < pieces.pieces.size(); ++i)
    for (std::size_t j = 0; j < 4; ++j)
      for (std::size_t k = 0; k < 2; ++k)
        EXPECT_NEAR(pieces.pieces[i].control_points()[j][k], c1.pieces()[i].control_points()[j][k],
                    1e-14 * scale_of(head));
}

/// Number of crossings between non-adjacent edges of a plane polyline.
int self_intersections(const std::vector<double>& xy) {
  const std::size_t n = xy.size() / 2;
  auto cross = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) -
           (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
  };
  int crossings = 0;
  for (std::size_t i = 0; i + 1 < n; ++i)
    for (std::size_t j = i + 2; j + 1 < n; ++j)
      if (cross(i, i + 1, j) * cross(i, i + 1, j + 1) < 0 && cross(j, j + 1, i) * cross(j, j + 1, i + 1) < 0)
        ++crossings;
  return crossings;
}

struct SegmentShape {
  int crossings = 0;
  double slowest = 0;  // min |C'| over the middle segment, relative to |P_2 − P_1| / h
};

SegmentShape middle_segment(const PointArray& points, Parameterization kind) {
  const auto parameters = parameter_values(points, kind).value();
  const auto curve = interpolate_catmull_rom(points, parameters).value();
  const double a = parameters[1], b = parameters[2];
  std::vector<double> us(801), xy(us.size() * 2), derivatives(us.size() * 2);
  for (std::size_t j = 0; j < us.size(); ++j) us[j] = a + (b - a) * static_cast<double>(j) / 800.0;
  points_and_derivatives_at(curve, us, xy, derivatives);
  SegmentShape shape;
  shape.crossings = self_intersections(xy);
  shape.slowest = std::numeric_limits<double>::infinity();
  const double chord_speed = distance(points[1], points[2]) / (b - a);
  for (std::size_t j = 0; j < us.size(); ++j)
    shape.slowest = std::min(shape.slowest, std::hypot(derivatives[2 * j], derivatives[2 * j + 1]) / chord_speed);
  return shape;
}

// Yuksel, Schaefer & Keyser 2011, fig. 1 and §4: two close middle points with
// far outer points. Uniform parameters make a loop (here: tangents of length
// 4 on a chord of 1) or, at the threshold, a cusp; centripetal ones never do.
TEST(CatmullRom, CentripetalHasNoLoopWhereUniformLoops) {
  const PointArray loop = PointArray::make(2, {-7, 1, 0, 0, 1, 0, 8, 1}).value();
  const SegmentShape uniform = middle_segment(loop, Parameterization::uniform);
  EXPECT_GE(uniform.crossings, 1);
  const SegmentShape centripetal = middle_segment(loop, Parameterization::centripetal);
  EXPECT_EQ(centripetal.crossings, 0);
  EXPECT_GT(centripetal.slowest, 0.5);
}

TEST(CatmullRom, CentripetalHasNoCuspWhereUniformHasOne) {
  // Uniform: C'(t) = 3(2s − 1)² e_x + (s − 1/2) e_y on the middle segment,
  // which vanishes at s = 1/2 (a cusp).
  const PointArray cusp = PointArray::make(2, {-5, 1, 0, 0, 1, 0, 6, 1}).value();
  EXPECT_LT(middle_segment(cusp, Parameterization::uniform).slowest, 1e-12);
  const SegmentShape centripetal = middle_segment(cusp, Parameterization::centripetal);
  EXPECT_GT(centripetal.slowest, 0.5);
  EXPECT_EQ(centripetal.crossings, 0);
}

RC_GTEST_PROP(CatmullRom, InterpolatesAndIsC1, ()) {
  const int count = *rc::gen::inRange(3, 10);
  const int d = *rc::gen::inRange(1, 4);
  const auto coordinates = *rc::gen::container<std::vector<double>>(count * d, test::coordinate());
  const PointArray points = PointArray::make(d, coordinates).value();
  const bool closed = *rc::gen::arbitrary<bool>();
  const auto kind = *rc::gen::element(Parameterization::uniform, Parameterization::chord_length,
                                      Parameterization::centripetal);
  const auto parameters = parameter_values(points, kind, closed ? Closure::closed : Closure::open);
  if (!parameters) return;  // two random consecutive points coincide
  const auto made = interpolate_catmull_rom(points, *parameters, closed ? Closure::closed : Closure::open);
  if (!made) {
    RC_ASSERT(closed && kind == Parameterization::uniform);  // the last point repeats the first
    return;
  }
  const double scale = std::max(1.0, scale_of(points));
  for (int i = 0; i < count; ++i) {
    const Point c = point_at(*made, (*parameters)[static_cast<std::size_t>(i)]);
    for (int k = 0; k < d; ++k) RC_ASSERT(std::abs(c[k] - points[i][k]) <= 1e-13 * scale);
  }
  const BezierPieces pieces = to_bezier_pieces(*made);
  for (std::size_t i = 0; i + 1 < pieces.pieces.size() + (closed ? 1 : 0); ++i) {
    const std::size_t next = (i + 1) % pieces.pieces.size();
    const double h0 = pieces.breakpoints[i + 1] - pieces.breakpoints[i];
    const double h1 = pieces.breakpoints[next + 1] - pieces.breakpoints[next];
    const Point a = derivative_at(pieces.pieces[i], 1.0, 1), b = derivative_at(pieces.pieces[next], 0.0, 1);
    for (int k = 0; k < d; ++k)
      RC_ASSERT(std::abs(a[k] / h0 - b[k] / h1) <= 1e-11 * scale / std::min(h0, h1));
  }
}

TEST(CatmullRom, RefusesBadInput) {
  const PointArray three = PointArray::make(2, {0, 0, 1, 0, 1, 1}).value();
  const std::vector<double> good{0, 0.5, 1};
  auto e = interpolate_catmull_rom(PointArray::make(2, {0, 0}).value(), std::vector<double>{0});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "Catmull-Rom spline needs at least 2 points, got 1");
  e = interpolate_catmull_rom(three, std::vector<double>{0, 1});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "a Catmull-Rom spline through 3 points needs 3 parameter values, got 2");
  e = interpolate_catmull_rom(three, good, Closure::closed);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "a Catmull-Rom spline through 3 points (closed) needs 4 parameter values, got 3");
  e = interpolate_catmull_rom(three, std::vector<double>{0, 0.5, 0.5});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "parameters must increase strictly: parameter 2 is 0.5, parameter 1 is 0.5");
  e = interpolate_catmull_rom(three, std::vector<double>{0, std::nan(""), 1});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "parameter 1 is NaN");
  e = interpolate_catmull_rom(PointArray::from_trusted(2, {0, 0, 1, std::nan(""), 1, 1}), good);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "coordinate 1 of point 1 is NaN");
  const PointArray repeated = PointArray::make(2, {0, 0, 1, 0, 1, 1, 0, 0}).value();
  e = interpolate_catmull_rom(repeated, std::vector<double>{0, 1, 2, 3, 4}, Closure::closed);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("repeats the first"), std::string::npos) << e.error().message;
  EXPECT_FALSE(interpolate_catmull_rom(PointArray::make(2, {0, 0, 1, 1}).value(), std::vector<double>{0, 1, 2}, Closure::closed));
}

}  // namespace
}  // namespace casteljau

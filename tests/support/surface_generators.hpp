#pragma once
// rapidcheck generators of valid B-spline, NURBS and Bézier surfaces.
// Degrees 1..4 (or as asked) in each direction, p+1..p+4 rows and q+1..q+4
// columns, coordinates from test::coordinate() (multiples of 1e-4 in
// [-100, 100]), knots on a 1/64 grid (exact dyadic values) built like
// bspline_generators.hpp's curves: clamped, or unclamped one time in three,
// interior multiplicities 1..p; weights in [0.2, 5] (multiples of 1e-3).
#include <rapidcheck.h>

#include <algorithm>
#include <vector>

#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "support/bspline_generators.hpp"
#include "support/generators.hpp"

namespace casteljau::test {

/// What bspline_surface generates.
struct SurfaceShape {
  int min_degree = 1;
  int max_degree = 4;
  /// 0: 2 or 3 at random; otherwise this dimension.
  int dimension = 3;
  int max_extra_points = 3;
  Rational rational = Rational::sometimes;
  bool allow_unclamped = true;
};

/// Knots of one direction: degree p, `count` control points, on [a, a + L].
inline std::vector<double> surface_knots(int p, int count, bool clamped) {
  const double a = *rc::gen::inRange(-4, 5);
  const double length = *rc::gen::inRange(1, 9);
  if (clamped) {
    std::vector<double> knots(static_cast<std::size_t>(p + 1), a);
    const auto inner = repeated_grid_knots(count - p - 1, p, a, length);
    knots.insert(knots.end(), inner.begin(), inner.end());
    knots.insert(knots.end(), static_cast<std::size_t>(p + 1), a + length);
    return knots;
  }
  return *rc::gen::suchThat(rc::gen::exec([&] { return repeated_grid_knots(count + p + 1, p, a, length); }),
                            [&](const std::vector<double>& k) {
                              return static_cast<int>(k.size()) == count + p + 1 &&
                                     k[static_cast<std::size_t>(p)] < k[static_cast<std::size_t>(count)];
                            });
}

inline std::vector<double> surface_weights(std::size_t count) {
  return *rc::gen::container<std::vector<double>>(
      count, rc::gen::map(rc::gen::inRange(200, 5001), [](int i) { return i * 1e-3; }));
}

inline bool draw_rational(Rational rational) {
  return rational == Rational::always || (rational == Rational::sometimes && *rc::gen::inRange(0, 2) == 1);
}

/// A random valid B-spline or NURBS surface.
inline rc::Gen<BSplineSurface> bspline_surface(SurfaceShape shape = {}) {
  return rc::gen::exec([shape] {
    const int p = *rc::gen::inRange(shape.min_degree, shape.max_degree + 1);
    const int q = *rc::gen::inRange(shape.min_degree, shape.max_degree + 1);
    const int d = shape.dimension > 0 ? shape.dimension : *rc::gen::inRange(2, 4);
    const int rows = p + 1 + *rc::gen::inRange(0, shape.max_extra_points + 1);
    const int columns = q + 1 + *rc::gen::inRange(0, shape.max_extra_points + 1);
    const bool clamped_u = !shape.allow_unclamped || *rc::gen::inRange(0, 3) != 0;
    const bool clamped_v = !shape.allow_unclamped || *rc::gen::inRange(0, 3) != 0;
    auto ku = surface_knots(p, rows, clamped_u);
    auto kv = surface_knots(q, columns, clamped_v);
    std::vector<double> coordinates =
        *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(rows * columns * d), coordinate());
    auto net = ControlNet::make(static_cast<std::size_t>(rows), static_cast<std::size_t>(columns),
                                *PointArray::make(d, std::move(coordinates)));
    std::vector<double> weights;
    if (draw_rational(shape.rational)) weights = surface_weights(static_cast<std::size_t>(rows * columns));
    auto surface = BSplineSurface::make(p, q, std::move(ku), std::move(kv), *net, std::move(weights));
    RC_ASSERT(surface.has_value());
    return *surface;
  });
}

/// A random Bézier patch of degrees 0..max_degree.
inline rc::Gen<BezierSurface> bezier_surface(int max_degree = 5, Rational rational = Rational::sometimes,
                                             int dimension = 3) {
  return rc::gen::exec([=] {
    const int n = *rc::gen::inRange(0, max_degree + 1);
    const int m = *rc::gen::inRange(0, max_degree + 1);
    const std::size_t count = static_cast<std::size_t>((n + 1) * (m + 1));
    std::vector<double> coordinates = *rc::gen::container<std::vector<double>>(count * dimension, coordinate());
    auto net = ControlNet::make(static_cast<std::size_t>(n + 1), static_cast<std::size_t>(m + 1),
                                *PointArray::make(dimension, std::move(coordinates)));
    std::vector<double> weights;
    if (draw_rational(rational)) weights = surface_weights(count);
    auto surface = BezierSurface::make(*net, std::move(weights));
    RC_ASSERT(surface.has_value());
    return *surface;
  });
}

/// A parameter of the domain: an end, a knot, or a 1e-6 grid fraction.
inline rc::Gen<double> parameter_in(const BSplineSurface& surface, Direction direction) {
  const Interval domain = surface.domain(direction);
  std::vector<double> inside;
  for (double t : surface.knots(direction))
    if (domain.contains(t)) inside.push_back(t);
  return rc::gen::weightedOneOf<double>(
      {{1, rc::gen::elementOf(inside)},
       {3, rc::gen::map(rc::gen::inRange(0, 1000001), [domain](int i) { return domain.lerp(i * 1e-6); })}});
}

/// max w / min w (1 for a polynomial surface): how much projection can
/// magnify the rounding of homogeneous sums.
inline double weight_ratio(std::span<const double> weights) {
  if (weights.empty()) return 1.0;
  return *std::max_element(weights.begin(), weights.end()) / *std::min_element(weights.begin(), weights.end());
}

/// `relative` times the net's scale (at least 1) times the weight ratio.
inline double surface_tolerance(const BSplineSurface& s, double relative = 1e-12) {
  return relative * std::max(1.0, scale_of(s.control_net().points())) * weight_ratio(s.weights());
}

}  // namespace casteljau::test

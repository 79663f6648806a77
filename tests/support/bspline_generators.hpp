#pragma once
// rapidcheck generators of valid B-spline and NURBS curves, for every test
// that needs random curves (knot insertion, removal, decomposition,
// evaluation, continuity...).
//
// What they produce: degree p in [min_degree, max_degree] (1..7 by default),
// dimension 2 or 3 (or fixed), n+1 = p+1+extra control points with
// coordinates from test::coordinate() (multiples of 1e-4 in [-100, 100], so
// the scale is known: scale_of <= 100), knots that are multiples of 1/64 on
// a domain [a, a + L] (a integer in [-8, 8], L in [1, 16]): exact dyadic
// values, so exact rational references see the same numbers. Interior knots
// are repeated on purpose (multiplicity 1..p, weighted toward 1), so that
// C^(p-m) joints of every kind appear; `allow_jumps` also allows
// multiplicity p+1 (a discontinuous curve). Clamped (end multiplicity p+1)
// or not (end knots spread out, the domain [t_p, t_{n+1}] strictly inside
// the knots). NURBS with weights in [0.2, 5] (multiples of 1e-3) when
// rational is allowed.
//
// Use:  const BSplineCurve curve = *test::bspline_curve();
//       const auto curve = *test::bspline_curve({.max_degree = 3, .rational = test::Rational::never});

#include <rapidcheck.h>

#include <algorithm>
#include <vector>

#include <cmath>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "support/generators.hpp"

namespace casteljau::test {

/// Whether generated curves carry weights.
enum class Rational { never, sometimes, always };

/// What bspline_curve generates (designated initializers welcome).
struct BSplineShape {
  int min_degree = 1;
  int max_degree = 7;
  /// 0: 2 or 3 at random; otherwise this dimension.
  int dimension = 0;
  /// Most control points beyond the minimum p+1.
  int max_extra_points = 10;
  Rational rational = Rational::sometimes;
  /// Also generate unclamped knot vectors (about one curve in three).
  bool allow_unclamped = true;
  /// Allow interior multiplicity p+1 (a jump in the curve).
  bool allow_jumps = false;
};

/// Sorted knot values: `count` knots that are multiples of 1/64 in
/// [a, a + L], grouped in distinct values of multiplicity 1..max_multiplicity.
inline std::vector<double> repeated_grid_knots(int count, int max_multiplicity, double a, double length) {
  std::vector<double> knots;
  const int steps = static_cast<int>(length * 64);
  // Distinct grid positions, more than enough, then multiplicities.
  std::vector<int> positions = *rc::gen::unique<std::vector<int>>(count, rc::gen::inRange(1, steps));
  std::sort(positions.begin(), positions.end());
  for (int position : positions) {
    if (static_cast<int>(knots.size()) >= count) break;
    const int left = count - static_cast<int>(knots.size());
    const int top = std::min(max_multiplicity, left);
    const int m = *rc::gen::weightedOneOf<int>({{6, rc::gen::just(1)}, {3, rc::gen::inRange(1, top + 1)}, {1, rc::gen::just(top)}});
    knots.insert(knots.end(), static_cast<std::size_t>(std::min(m, top)), a + position / 64.0);
  }
  return knots;
}

/// A random valid curve (see the file comment).
inline rc::Gen<BSplineCurve> bspline_curve(BSplineShape shape = {}) {
  return rc::gen::exec([shape] {
    const int p = *rc::gen::inRange(shape.min_degree, shape.max_degree + 1);
    const int d = shape.dimension > 0 ? shape.dimension : *rc::gen::inRange(2, 4);
    const int count = p + 1 + *rc::gen::inRange(0, shape.max_extra_points + 1);  // n + 1
    const double a = *rc::gen::inRange(-8, 9);
    const double length = *rc::gen::inRange(1, 17);
    const bool clamped = !shape.allow_unclamped || *rc::gen::inRange(0, 3) != 0;
    const int interior_max = shape.allow_jumps ? p + 1 : p;
    std::vector<double> knots;
    if (clamped) {
      knots.assign(static_cast<std::size_t>(p + 1), a);
      const auto inner = repeated_grid_knots(count - p - 1, interior_max, a, length);
      knots.insert(knots.end(), inner.begin(), inner.end());
      knots.insert(knots.end(), static_cast<std::size_t>(p + 1), a + length);
    } else {
      // Every knot strictly between a and a + L, multiplicity <= p at the
      // ends of the domain too; the domain [t_p, t_{n+1}] is then a proper
      // sub-interval (non-empty: retried until it is).
      knots = *rc::gen::suchThat(rc::gen::exec([&] { return repeated_grid_knots(count + p + 1, p, a, length); }),
                                 [&](const std::vector<double>& k) {
                                   return static_cast<int>(k.size()) == count + p + 1 &&
                                          k[static_cast<std::size_t>(p)] < k[static_cast<std::size_t>(count)];
                                 });
    }
    std::vector<double> coordinates =
        *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(count * d), coordinate());
    const bool rational = shape.rational == Rational::always ||
                          (shape.rational == Rational::sometimes && *rc::gen::inRange(0, 2) == 1);
    std::vector<double> weights;
    if (rational)
      weights = *rc::gen::container<std::vector<double>>(
          static_cast<std::size_t>(count), rc::gen::map(rc::gen::inRange(200, 5001), [](int i) { return i * 1e-3; }));
    auto curve = BSplineCurve::make(p, std::move(knots), *PointArray::make(d, std::move(coordinates)), std::move(weights));
    RC_ASSERT(curve.has_value());
    return *curve;
  });
}

/// A parameter in the curve's domain: often a knot or an end, else a 1e-6 grid fraction.
inline rc::Gen<double> parameter_in(const BSplineCurve& curve) {
  const Interval domain = curve.domain();
  std::vector<double> inside;
  for (double t : curve.knots())
    if (domain.contains(t)) inside.push_back(t);
  return rc::gen::weightedOneOf<double>(
      {{1, rc::gen::elementOf(inside)},
       {3, rc::gen::map(rc::gen::inRange(0, 1000001), [domain](int i) { return domain.lerp(i * 1e-6); })}});
}

/// A distance tolerance for comparing two computations of one curve:
/// `relative` times its scale (at least 1), times the weight ratio
/// max w / min w of a NURBS curve (projection divides by the weight sum, so
/// homogeneous rounding grows by that ratio at most).
inline double shape_tolerance(const BSplineCurve& curve, double relative = 1e-12) {
  double ratio = 1.0;
  if (curve.is_rational()) {
    const auto w = curve.weights();
    ratio = *std::max_element(w.begin(), w.end()) / *std::min_element(w.begin(), w.end());
  }
  return relative * std::max(1.0, scale_of(curve.control_points())) * ratio;
}

/// The largest distance between `reference` at u and `other` at map(u), for
/// `samples` + 1 evenly spaced u of the reference's domain and every knot in
/// it, with `other` evaluated both by point_at (de Boor) and by
/// point_at_basis_sum (basis functions), so that a shape check exercises
/// both evaluators. map defaults to the identity.
template <class Map>
double largest_distance(const BSplineCurve& reference, const BSplineCurve& other, Map map, int samples = 64) {
  const Interval domain = reference.domain();
  double worst = 0.0;
  auto check = [&](double u) {
    const Point expected = point_at(reference, u);
    worst = std::max(worst, distance(expected, point_at(other, map(u))));
    worst = std::max(worst, distance(expected, point_at_basis_sum(other, map(u))));
  };
  for (int i = 0; i <= samples; ++i) check(domain.lerp(static_cast<double>(i) / samples));
  for (double t : reference.knots())
    if (domain.contains(t)) check(t);
  return worst;
}
inline double largest_distance(const BSplineCurve& reference, const BSplineCurve& other, int samples = 64) {
  return largest_distance(reference, other, [](double u) { return u; }, samples);
}

/// The cubic of The NURBS Book Example 5.1: U = {0,0,0,0,1,2,3,4,5,5,5,5}
/// with eight control points of ours (the book leaves them symbolic).
inline BSplineCurve book_example_5_1() {
  return BSplineCurve::make(3, {0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5},
                            PointArray::make({{0, 0}, {1, 3}, {2.5, 4}, {4, 1}, {6, 2}, {7, 5}, {9, 4.5}, {10, 0}}).value())
      .value();
}

}  // namespace casteljau::test

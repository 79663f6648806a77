#pragma once
// rapidcheck generators of extreme doubles, for the properties that every
// make() either refuses a value with a message or builds an object that
// evaluates to finite values everywhere on its domain (tests/core and
// tests/surfaces extreme_doubles_test.cpp).
//
// What they produce: the values at and around every edge of double and of
// casteljau's ranges (core/tolerance.hpp "Valid model numbers"): 0 and -0,
// subnormals (5e-324, 1e-310), DBL_MIN, kScaleFloor (1e-300), the range
// bounds 1e-100, 1e-50, 1e50, 1e100 and their neighbours one ulp outside,
// 1e150, 1e300, 1e308, DBL_MAX, infinities and NaN, and ordinary values
// among them (so that objects mixing one extreme with ordinary data occur).
// Knot vectors are built from extreme gaps (0, subnormal, one ulp, the
// narrowest span and just below it, huge) on an extreme start, so that both
// accepted and refused vectors come out.

#include <rapidcheck.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau::test {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// One of the values at the edges of double and of casteljau's ranges, either sign.
inline rc::Gen<double> edge_double() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> magnitudes{0.0,
                                       5e-324,
                                       1e-310,
                                       DBL_MIN,
                                       tolerances::kScaleFloor,
                                       std::nextafter(tolerances::kMinKnotSpan, 0.0),
                                       tolerances::kMinKnotSpan,
                                       std::nextafter(tolerances::kMinWeight, 0.0),
                                       tolerances::kMinWeight,
                                       1e-16,
                                       1.0,
                                       std::nextafter(1.0, 2.0),
                                       tolerances::kMaxWeight,
                                       std::nextafter(tolerances::kMaxWeight, kInf),
                                       tolerances::kMaxCoordinate,
                                       std::nextafter(tolerances::kMaxCoordinate, kInf),
                                       1e150,
                                       1e300,
                                       1e308,
                                       DBL_MAX,
                                       kInf,
                                       nan};
  return rc::gen::apply([](double magnitude, bool negative) { return negative ? -magnitude : magnitude; },
                        rc::gen::elementOf(magnitudes), rc::gen::arbitrary<bool>());
}

/// An ordinary value: a multiple of 1/8 in [-16, 16].
inline rc::Gen<double> ordinary_double() {
  return rc::gen::map(rc::gen::inRange(-128, 129), [](int i) { return i / 8.0; });
}

/// Mostly ordinary, one value in `extreme_share` (of 10) at an edge.
inline rc::Gen<double> mixed_double(int extreme_share = 3) {
  return rc::gen::weightedOneOf<double>({{10 - extreme_share, ordinary_double()}, {extreme_share, edge_double()}});
}

/// n points of dimension d with mixed coordinates.
inline PointArray mixed_points(std::size_t count, int dimension, int extreme_share = 2) {
  std::vector<double> coordinates =
      *rc::gen::container<std::vector<double>>(count * static_cast<std::size_t>(dimension), mixed_double(extreme_share));
  return PointArray::from_trusted(dimension, std::move(coordinates));
}

/// A weight: ordinary (0.25..4), at or beyond the ends of the range, or an
/// edge double of either sign.
inline rc::Gen<double> mixed_weight() {
  const std::vector<double> edges{tolerances::kMinWeight, tolerances::kMaxWeight,
                                  std::nextafter(tolerances::kMinWeight, 0.0),
                                  std::nextafter(tolerances::kMaxWeight, kInf), 1e-300, 1e-320, 5e-324, DBL_MAX};
  return rc::gen::weightedOneOf<double>({{6, rc::gen::map(rc::gen::inRange(1, 17), [](int i) { return i / 4.0; })},
                                         {3, rc::gen::elementOf(edges)},
                                         {1, edge_double()}});
}

/// `count` weights (empty: polynomial, one time in three).
inline std::vector<double> mixed_weights(std::size_t count) {
  if (*rc::gen::inRange(0, 3) == 0) return {};
  return *rc::gen::container<std::vector<double>>(count, mixed_weight());
}

/// A gap between consecutive knots: 0 (a repeated knot), subnormal, one ulp
/// of the previous knot, the narrowest span or just below it, ordinary, huge.
inline rc::Gen<double> knot_gap() {
  const std::vector<double> edges{5e-324, 1e-310, 1e-300, std::nextafter(tolerances::kMinKnotSpan, 0.0),
                                  tolerances::kMinKnotSpan, 1e-16, 1e100, 1e300, 1e308};
  return rc::gen::weightedOneOf<double>({{3, rc::gen::just(0.0)},
                                         {3, rc::gen::map(rc::gen::inRange(1, 9), [](int i) { return i / 4.0; })},
                                         {1, rc::gen::just(-1.0)},  // one ulp of the previous knot
                                         {3, rc::gen::elementOf(edges)}});
}

/// `count` knots: an extreme or ordinary start, then gaps from knot_gap();
/// sorted unless a NaN or an overflow spoils them (refused, as it should).
/// One time in twenty, one knot is replaced by an edge double.
inline std::vector<double> extreme_knots(std::size_t count) {
  std::vector<double> knots;
  knots.reserve(count);
  double t = *mixed_double(3);
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) {
      const double gap = *knot_gap();
      t = gap < 0.0 ? std::nextafter(t, kInf) : t + gap;
    }
    knots.push_back(t);
  }
  if (count > 0 && *rc::gen::inRange(0, 20) == 0) {
    knots[*rc::gen::inRange<std::size_t>(0, count)] = *edge_double();
  }
  return knots;
}

/// Parameters at which to evaluate over [lower, upper]: both ends, every
/// knot inside, one ulp inside each end and beside each knot, and the
/// midpoint of every non-empty span (lower + (upper - lower) / 2, which
/// cannot overflow for valid knots).
inline std::vector<double> parameters_over(std::span<const double> knots, double lower, double upper) {
  std::vector<double> us{lower, upper, std::nextafter(lower, upper), std::nextafter(upper, lower)};
  for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
    const double a = knots[i], b = knots[i + 1];
    if (!(a >= lower && b <= upper && a < b)) continue;
    us.push_back(a);
    us.push_back(std::nextafter(a, b));
    us.push_back(a + (b - a) / 2);
    us.push_back(std::nextafter(b, a));
  }
  return us;
}

/// Whether every value is finite (and so the object evaluated without
/// overflow or NaN).
inline bool all_finite(std::span<const double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

/// A property's refusal branch: make() said why (front ends print the
/// message as it is); tagged so that the run shows how often each branch ran.
template <class T>
void expect_message(const Expected<T>& result) {
  RC_TAG("refused");
  RC_ASSERT(!result.error().message.empty());
}

}  // namespace casteljau::test

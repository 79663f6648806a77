#pragma once
// rapidcheck generators for the core types. Coordinates are multiples of 1e-4
// in [-100, 100] (so the scale is known), weights in [0.05, 20].

#include <rapidcheck.h>

#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"

namespace casteljau::test {

/// A coordinate in [-100, 100] on a 1e-4 grid.
inline rc::Gen<double> coordinate() {
  return rc::gen::map(rc::gen::inRange(-1000000, 1000001), [](int i) { return i * 1e-4; });
}

/// A coordinate in [-100, 100] on the grid of 1 / steps_per_unit, each value
/// k / steps_per_unit (a correctly rounded quotient).
inline rc::Gen<double> coordinate_on_grid(int steps_per_unit) {
  return rc::gen::map(rc::gen::inRange(-100 * steps_per_unit, 100 * steps_per_unit + 1),
                      [steps_per_unit](int k) { return k / static_cast<double>(steps_per_unit); });
}

/// A parameter in [0, 1] (both ends included, often).
inline rc::Gen<double> unit_parameter() {
  return rc::gen::weightedOneOf<double>({{1, rc::gen::just(0.0)},
                                         {1, rc::gen::just(1.0)},
                                         {8, rc::gen::map(rc::gen::inRange(0, 1000001), [](int i) { return i * 1e-6; })}});
}

/// A curve of degree in [min_degree, max_degree], dimension in [1, 4] or fixed.
inline rc::Gen<BezierCurve> bezier_curve(int min_degree, int max_degree, bool rational, int dimension = 0) {
  return rc::gen::exec([=] {
    const int n = *rc::gen::inRange(min_degree, max_degree + 1);
    const int d = dimension > 0 ? dimension : *rc::gen::inRange(1, 5);
    std::vector<double> coords = *rc::gen::container<std::vector<double>>((n + 1) * d, coordinate());
    std::vector<double> weights;
    if (rational)
      weights = *rc::gen::container<std::vector<double>>(
          n + 1, rc::gen::map(rc::gen::inRange(50, 20001), [](int i) { return i * 1e-3; }));
    return BezierCurve::make(*PointArray::make(d, std::move(coords)), std::move(weights)).value();
  });
}

/// Either kind.
inline rc::Gen<BezierCurve> any_bezier_curve(int max_degree = 12) {
  return rc::gen::oneOf(bezier_curve(0, max_degree, false), bezier_curve(0, max_degree, true));
}

}  // namespace casteljau::test

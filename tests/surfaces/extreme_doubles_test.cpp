// Every make() of a surface, fed extreme doubles (as tests/core/
// extreme_doubles_test.cpp feeds the curves): refused with a message, or a
// surface whose points and first partial derivatives are finite everywhere
// on its domain, by point_at, partial_derivative_at (orders (1,0) and (0,1))
// and the scattered and grid batches. Both knot directions, B-spline, Bézier
// and Coons patches (whose boundaries come from BSplineCurve::make).

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/control_net.hpp"
#include "casteljau/surfaces/coons.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "support/extreme_doubles.hpp"

namespace casteljau {
namespace {

using test::all_finite;
using test::expect_message;

/// Points and first partials at every pair of us x vs, and both batches.
template <class Surface>
void expect_finite(const Surface& surface, const std::vector<double>& us, const std::vector<double>& vs) {
  RC_TAG("evaluated");
  const std::size_t d = static_cast<std::size_t>(surface.dimension());
  std::vector<double> su, sv;  // the grid as scattered pairs
  for (double u : us) {
    for (double v : vs) {
      RC_ASSERT(all_finite(point_at(surface, u, v)));
      RC_ASSERT(all_finite(partial_derivative_at(surface, u, v, 1, 0)));
      RC_ASSERT(all_finite(partial_derivative_at(surface, u, v, 0, 1)));
      su.push_back(u);
      sv.push_back(v);
    }
  }
  std::vector<double> scattered(su.size() * d), grid(us.size() * vs.size() * d);
  points_at(surface, su, sv, scattered);
  RC_ASSERT(all_finite(scattered));
  grid_points_at(surface, us, vs, grid);
  RC_ASSERT(all_finite(grid));
}

RC_GTEST_PROP(ExtremeDoubles, BSplineSurfaceMakeRefusesOrEvaluatesFinitely, ()) {
  const int p = *rc::gen::inRange(0, 4), q = *rc::gen::inRange(0, 4);
  const std::size_t rows = static_cast<std::size_t>(p) + 1 + static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  const std::size_t columns = static_cast<std::size_t>(q) + 1 + static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  const int d = *rc::gen::inRange(2, 4);
  // One direction ordinary now and then, so that the other one's extremes are reached.
  const bool plain_u = *rc::gen::inRange(0, 4) == 0, plain_v = *rc::gen::inRange(0, 4) == 0;
  const auto knots = [](std::size_t count, bool plain) {
    if (!plain) return test::extreme_knots(count);
    std::vector<double> k(count);
    for (std::size_t i = 0; i < count; ++i) k[i] = static_cast<double>(i);
    return k;
  };
  std::vector<double> knots_u = knots(rows + static_cast<std::size_t>(p) + 1, plain_u);
  std::vector<double> knots_v = knots(columns + static_cast<std::size_t>(q) + 1, plain_v);
  auto net = ControlNet::make(rows, columns, test::mixed_points(rows * columns, d, *rc::gen::inRange(0, 2)));
  RC_ASSERT(net.has_value());
  auto surface = BSplineSurface::make(p, q, knots_u, knots_v, *net, test::mixed_weights(rows * columns));
  if (!surface) return expect_message(surface);
  const Interval du = surface->domain_u(), dv = surface->domain_v();
  expect_finite(*surface, test::parameters_over(knots_u, du.lower, du.upper),
                test::parameters_over(knots_v, dv.lower, dv.upper));
}

RC_GTEST_PROP(ExtremeDoubles, BezierSurfaceMakeRefusesOrEvaluatesFinitely, ()) {
  const std::size_t rows = static_cast<std::size_t>(*rc::gen::inRange(1, 5));
  const std::size_t columns = static_cast<std::size_t>(*rc::gen::inRange(1, 5));
  auto net = ControlNet::make(rows, columns, test::mixed_points(rows * columns, 3));
  RC_ASSERT(net.has_value());
  auto surface = BezierSurface::make(*net, test::mixed_weights(rows * columns));
  if (!surface) return expect_message(surface);
  const std::vector<double> ts{0.0, 1.0, 0.5, 5e-324, std::nextafter(1.0, 0.0)};
  expect_finite(*surface, ts, ts);
}

/// The nested-rows ControlNet::make of model JSON refuses non-finite values itself.
RC_GTEST_PROP(ExtremeDoubles, NestedControlNetRefusesOrBuildsFiniteNets, ()) {
  const std::size_t rows = static_cast<std::size_t>(*rc::gen::inRange(1, 4));
  const std::size_t columns = static_cast<std::size_t>(*rc::gen::inRange(1, 4));
  std::vector<std::vector<std::vector<double>>> nested(rows);
  for (auto& row : nested)
    for (std::size_t j = 0; j < columns; ++j) row.push_back({*test::mixed_double(), *test::mixed_double()});
  auto net = ControlNet::make(nested);
  if (!net) return expect_message(net);
  RC_TAG("built");
  RC_ASSERT(all_finite(net->points().coordinates()));
}

/// A boundary from a to b: a B-spline of degree 1..2 with (one time in
/// three) extreme knots, otherwise 0, 1, 2, ..., and mixed middle control
/// points, its ends exactly a and b (clamped).
Expected<BSplineCurve> boundary(const std::vector<double>& a, const std::vector<double>& b) {
  const int degree = *rc::gen::inRange(1, 3);
  const std::size_t count = static_cast<std::size_t>(degree) + 1 + static_cast<std::size_t>(*rc::gen::inRange(0, 2));
  const std::size_t distinct = count - static_cast<std::size_t>(degree) + 1;
  std::vector<double> knots(distinct);
  for (std::size_t i = 0; i < distinct; ++i) knots[i] = static_cast<double>(i);
  if (*rc::gen::inRange(0, 3) == 0) knots = test::extreme_knots(distinct);
  knots.insert(knots.begin(), static_cast<std::size_t>(degree), knots.front());
  knots.insert(knots.end(), static_cast<std::size_t>(degree), knots.back());
  PointArray points = test::mixed_points(count, 3, 1);
  std::copy(a.begin(), a.end(), points[0].begin());
  std::copy(b.begin(), b.end(), points[count - 1].begin());
  return BSplineCurve::make(degree, std::move(knots), std::move(points));
}

RC_GTEST_PROP(ExtremeDoubles, CoonsPatchOfValidBoundariesEvaluatesFinitely, ()) {
  std::vector<std::vector<double>> corners(4);
  for (auto& c : corners) c = {*test::mixed_double(1), *test::mixed_double(1), *test::mixed_double(1)};
  // P00, P01, P10, P11.
  const auto u0 = boundary(corners[0], corners[1]), u1 = boundary(corners[2], corners[3]);
  const auto v0 = boundary(corners[0], corners[2]), v1 = boundary(corners[1], corners[3]);
  for (const auto* c : {&u0, &u1, &v0, &v1})
    if (!*c) return expect_message(*c);
  const CoonsBlending blending = *rc::gen::element(CoonsBlending::linear, CoonsBlending::cubic);
  auto patch = CoonsPatch::make(*u0, *u1, *v0, *v1, blending);
  if (!patch) return expect_message(patch);
  const std::vector<double> ts{0.0, 1.0, 0.5, 5e-324, 0.25, std::nextafter(1.0, 0.0)};
  expect_finite(*patch, ts, ts);
}

/// The sphere and the torus (surfaces of revolution of conics): centre,
/// axis and radii at the edges.
RC_GTEST_PROP(ExtremeDoubles, SphereAndTorusRefuseOrEvaluateFinitely, ()) {
  const std::vector<double> center{*test::mixed_double(2), *test::mixed_double(2), *test::mixed_double(2)};
  const std::vector<double> axis{*test::mixed_double(2), *test::mixed_double(2), *test::mixed_double(2)};
  const auto radius = [] {
    return *rc::gen::weightedOneOf<double>(
        {{1, test::edge_double()}, {1, rc::gen::map(rc::gen::inRange(1, 64), [](int i) { return i / 8.0; })}});
  };
  const double major = radius(), minor = radius();
  const std::vector<double> ts{0.0, 1.0, 0.5, 0.25, std::nextafter(1.0, 0.0)};
  for (const auto& surface : {make_sphere(center, major), make_torus(center, axis, major, minor)}) {
    if (!surface) {
      expect_message(surface);
      continue;
    }
    const Interval du = surface->domain_u(), dv = surface->domain_v();
    std::vector<double> us, vs;
    for (double t : ts) {
      us.push_back(du.lower + t * (du.upper - du.lower));
      vs.push_back(dv.lower + t * (dv.upper - dv.lower));
    }
    expect_finite(*surface, us, vs);
  }
}

}  // namespace
}  // namespace casteljau

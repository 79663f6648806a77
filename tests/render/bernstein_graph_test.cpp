// The Bernstein graph polyline: its second-derivative bound holds (reference:
// the exact second derivative in dyadic arithmetic, tests/support/exact.hpp),
// the polyline stays within its tolerance of the graph (reference: the
// triangular recurrence bernstein_all, NURBS Book A1.3, at 2001 parameters),
// and the basis of degree 1000, the documented limit, costs tens of vertices
// per function (issue 15: it took hours through degree-1000 Bézier curves).
#include "casteljau/render/bernstein_graph.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/render/layout.hpp"
#include "casteljau/render/plots.hpp"
#include "support/exact.hpp"
#include "support/plane_geometry.hpp"

namespace casteljau::render {
namespace {

using test::distance_to_segment;

/// A parameter in [0, 1] on a 1e-6 grid.
rc::Gen<double> parameter() {
  return rc::gen::map(rc::gen::inRange(0, 1000001), [](int i) { return i * 1e-6; });
}

RC_GTEST_PROP(BernsteinGraph, SecondDerivativeBoundHolds, ()) {
  const int n = *rc::gen::inRange(2, 61);
  const int k = *rc::gen::inRange(0, n + 1);
  double a = *parameter(), b = *parameter();
  if (a > b) std::swap(a, b);
  const double bound = bernstein_second_derivative_bound(n, k, a, b);
  // B_{n,k} as the 1D Bézier curve with coefficients delta_jk.
  std::vector<double> coefficients(static_cast<std::size_t>(n + 1), 0.0);
  coefficients[static_cast<std::size_t>(k)] = 1.0;
  const auto graph = BezierCurve::make(PointArray::make(1, coefficients).value()).value();
  for (int i = 0; i <= 16; ++i) {
    const double t = a + (b - a) * i / 16.0;
    const mpq_class exact = abs(test::exact_derivative(graph, t, 2)[0].rational());
    RC_ASSERT(exact <= mpq_class(bound));
  }
}

RC_GTEST_PROP(BernsteinGraph, PolylineStaysWithinTolerance, ()) {
  const int n = *rc::gen::inRange(1, 61);
  const int k = *rc::gen::inRange(0, n + 1);
  const double tolerance = std::pow(10.0, -*rc::gen::inRange(2, 6));
  const auto line = bernstein_graph_polyline(n, k, Tolerance{tolerance});
  RC_ASSERT(line.has_value());
  RC_ASSERT(line->front()[0] == 0.0);
  RC_ASSERT(line->back()[0] == 1.0);
  std::vector<double> values(static_cast<std::size_t>(n + 1));
  const double rounding = 8.0 * n * 2.220446049250313e-16;
  for (std::size_t i = 0; i < line->size(); ++i) {
    if (i > 0) RC_ASSERT((*line)[i - 1][0] < (*line)[i][0]);
    bernstein_all(n, (*line)[i][0], values);
    RC_ASSERT(std::abs((*line)[i][1] - values[static_cast<std::size_t>(k)]) <= rounding);  // on the graph
  }
  // Every sampled point of the graph within the tolerance of the polyline.
  std::size_t segment = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0;
    bernstein_all(n, t, values);
    const Vec2 p{{t, values[static_cast<std::size_t>(k)]}};
    while (segment + 2 < line->size() && (*line)[segment + 1][0] < t) ++segment;
    double nearest = distance_to_segment(p, (*line)[segment], (*line)[segment + 1]);
    if (segment > 0) nearest = std::min(nearest, distance_to_segment(p, (*line)[segment - 1], (*line)[segment]));
    RC_ASSERT(nearest <= tolerance + rounding);
  }
}

TEST(BernsteinGraph, TheDegreeThousandBasisCostsTensOfVerticesPerFunction) {
  // The figure of `casteljau bernstein 1000`, laid out once: its 1001 graphs
  // at a quarter pixel, 22,811 vertices when measured, O(n) work each.
  const auto scene = layout(bernstein_basis_figure(1000).value());
  ASSERT_TRUE(scene) << scene.error().message;
  std::size_t vertices = 0, most = 0, graphs = 0;
  for (const auto& shape : scene->shapes)
    if (const auto* path = std::get_if<PathShape>(&shape); path && !path->closed && path->points.size() > 2) {
      vertices += path->points.size();
      most = std::max(most, path->points.size());
      ++graphs;
    }
  EXPECT_EQ(graphs, 1001u);
  EXPECT_LE(vertices, 30000u);
  EXPECT_LE(most, 40u);
}

TEST(BernsteinGraph, Errors) {
  EXPECT_FALSE(bernstein_graph_polyline(0, 0, Tolerance{1e-3}));
  EXPECT_FALSE(bernstein_graph_polyline(tolerances::kMaxBezierDegree + 1, 0, Tolerance{1e-3}));
  EXPECT_FALSE(bernstein_graph_polyline(5, 6, Tolerance{1e-3}));
  EXPECT_FALSE(bernstein_graph_polyline(5, -1, Tolerance{1e-3}));
  EXPECT_FALSE(bernstein_graph_polyline(5, 2, Tolerance{INFINITY}));
  EXPECT_FALSE(bernstein_graph_polyline(5, 2, Tolerance{0.0}));
  EXPECT_FALSE(bernstein_graph_polyline(5, 2, Tolerance{1e-16}));  // below the vertices' rounding
  // A line needs one segment.
  EXPECT_EQ(bernstein_graph_polyline(1, 0, Tolerance{1e-9}).value().size(), 2u);
}

}  // namespace
}  // namespace casteljau::render

// Layout: axis ranges contain the data, equal aspect gives equal scales,
// ticks are nice and inside the range (reference: matplotlib's MaxNLocator
// output for the same ranges), errors for bad figures, and the plot helpers
// (plane projection, Bernstein graphs) against independent evaluations.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/interpolation/lagrange.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/render/layout.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/tolerance.hpp"
#include "support/generators.hpp"

namespace casteljau::render {
namespace {

Figure points_figure(const std::vector<Vec2>& points, bool equal_aspect, int width = 800, int height = 600) {
  Figure figure;
  figure.width = width;
  figure.height = height;
  Panel panel;
  panel.equal_aspect = equal_aspect;
  panel.markers.push_back({points, colors::red, 6.0, ""});
  figure.panels.push_back(panel);
  return figure;
}

RC_GTEST_PROP(Layout, AxisRangesContainTheData, ()) {
  const auto coordinates = *rc::gen::container<std::vector<double>>(*rc::gen::inRange(2, 40), test::coordinate());
  std::vector<Vec2> points;
  for (std::size_t i = 0; i + 1 < coordinates.size(); i += 2) points.push_back(Vec2{{coordinates[i], coordinates[i + 1]}});
  const bool equal = *rc::gen::arbitrary<bool>();
  const int width = *rc::gen::inRange(200, 1200), height = *rc::gen::inRange(200, 1200);
  auto frames = panel_frames(points_figure(points, equal, width, height));
  RC_ASSERT(frames.has_value());
  const PanelFrame& f = (*frames)[0];
  for (auto p : points) {
    RC_ASSERT(f.x_lower <= p[0]);
    RC_ASSERT(p[0] <= f.x_upper);
    RC_ASSERT(f.y_lower <= p[1]);
    RC_ASSERT(p[1] <= f.y_upper);
    const Vec2 pixel = f.to_pixels(p);
    RC_ASSERT(pixel[0] >= f.area.left && pixel[0] <= f.area.left + f.area.width);
    RC_ASSERT(pixel[1] >= f.area.top && pixel[1] <= f.area.top + f.area.height);
    // from_pixels inverts to_pixels.
    const Vec2 back = f.from_pixels(pixel);
    RC_ASSERT(std::abs(back[0] - p[0]) <= 1e-9 * (1.0 + std::abs(p[0])));
    RC_ASSERT(std::abs(back[1] - p[1]) <= 1e-9 * (1.0 + std::abs(p[1])));
  }
  if (equal) {
    const double ux = (f.x_upper - f.x_lower) / f.area.width, uy = (f.y_upper - f.y_lower) / f.area.height;
    RC_ASSERT(std::abs(ux - uy) <= 1e-9 * std::max(ux, uy));
  }
}

TEST(Layout, CurveExtentNotControlPolygon) {
  // The cubic (0,0) (0,10) (1,10) (1,0) rises to y = 7.5 only: the range is
  // fitted to the curve (as matplotlib fits the plotted line), with 5 % margins.
  Figure figure;
  Panel panel;
  panel.curves.push_back(
      {{BezierCurve::make(*PointArray::make({{0, 0}, {0, 10}, {1, 10}, {1, 0}})).value()}, solid(colors::black), ""});
  figure.panels.push_back(panel);
  auto frames = panel_frames(figure);
  ASSERT_TRUE(frames);
  EXPECT_NEAR((*frames)[0].y_upper, 7.5 + 0.05 * 7.5, 0.01);
  EXPECT_NEAR((*frames)[0].y_lower, -0.05 * 7.5, 0.01);
  EXPECT_NEAR((*frames)[0].x_lower, -0.05, 1e-3);
  EXPECT_NEAR((*frames)[0].x_upper, 1.05, 1e-3);
}

TEST(Layout, ExtentBoundsTheRungePolynomialNotACoarsePass) {
  // Issue 15: 21 equispaced samples of 1/(1+25x^2), the Lagrange polynomial
  // as a Bézier curve (x, p(x)) of degree 20 whose control points reach 3e5.
  // The y range must hold the curve's dips (-59.78 near x = -0.975 and 0.975),
  // found here by the barycentric formula (an evaluation independent of the
  // Bézier form that is drawn) at 4001 points.
  std::vector<double> xy;
  for (int i = 0; i <= 20; ++i) {
    const double x = -1.0 + i / 10.0;
    xy.insert(xy.end(), {x, 1.0 / (1.0 + 25.0 * x * x)});
  }
  const PointArray points = PointArray::make(2, xy).value();
  const auto parameters = function_parameters(points).value();
  const auto polynomial = interpolate_lagrange(points, parameters).value();
  const BezierCurve curve = to_bezier(polynomial).value();
  double lowest = INFINITY, highest = -INFINITY;
  for (int i = 0; i <= 4000; ++i) {
    const Point p = point_at(polynomial, parameters.front() + (parameters.back() - parameters.front()) * i / 4000.0);
    lowest = std::min(lowest, p[1]), highest = std::max(highest, p[1]);
  }
  ASSERT_LT(lowest, -59.0);
  for (bool equal : {true, false}) {
    Figure figure;
    Panel panel;
    panel.equal_aspect = equal;
    panel.curves.push_back({{curve}, solid(colors::black), ""});
    figure.panels.push_back(panel);
    auto frames = panel_frames(figure);
    ASSERT_TRUE(frames) << frames.error().message;
    const PanelFrame& f = (*frames)[0];
    // The extent plus matplotlib's 5 % margins, and no more than a pixel beyond.
    const double margin = 0.05 * (highest - lowest), pixel = (f.y_upper - f.y_lower) / f.area.height;
    EXPECT_NEAR(f.y_lower, lowest - margin, pixel) << equal;
    EXPECT_NEAR(f.y_upper, highest + margin, pixel) << equal;
  }
}

RC_GTEST_PROP(Layout, CurveExtentHoldsEverySampledPointAndLittleMore, ()) {
  // Whatever the curve (rational ones, high degrees), the range fitted to it
  // holds every point of it (sampled at 2001 parameters) and is no wider than
  // its sampled extent with the 5 % margins, give or take a pixel.
  const BezierCurve curve = *test::bezier_curve(1, 24, *rc::gen::arbitrary<bool>(), 2);
  Figure figure;
  Panel panel;
  panel.curves.push_back({{curve}, solid(colors::black), ""});
  figure.panels.push_back(panel);
  auto frames = panel_frames(figure);
  if (!frames) {
    std::string text;
    for (std::size_t i = 0; i < curve.control_points().size(); ++i) text += fmt::format(" ({}, {})", curve.control_points()[i][0], curve.control_points()[i][1]);
    RC_FAIL(frames.error().message + text);
  }
  const PanelFrame& f = (*frames)[0];
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (int i = 0; i <= 2000; ++i) {
    const Point p = point_at(curve, i / 2000.0);
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  }
  RC_PRE(x1 - x0 > 1e-6 && y1 - y0 > 1e-6);  // a flat curve gets matplotlib's window around it instead
  const double px = (f.x_upper - f.x_lower) / f.area.width, py = (f.y_upper - f.y_lower) / f.area.height;
  RC_ASSERT(f.x_lower <= x0 - 0.05 * (x1 - x0) + px && f.x_lower >= x0 - 0.05 * (x1 - x0) - px);
  RC_ASSERT(f.x_upper >= x1 + 0.05 * (x1 - x0) - px && f.x_upper <= x1 + 0.05 * (x1 - x0) + px);
  RC_ASSERT(f.y_lower <= y0 - 0.05 * (y1 - y0) + py && f.y_lower >= y0 - 0.05 * (y1 - y0) - py);
  RC_ASSERT(f.y_upper >= y1 + 0.05 * (y1 - y0) - py && f.y_upper <= y1 + 0.05 * (y1 - y0) + py);
}

TEST(Layout, ProgressRisesToOneOverEveryPanelsCurves) {
  // Three panels (the second with Bernstein graphs, the third with nothing to
  // flatten): the fractions never fall and end at 1, and a layout with no
  // Progress draws the same scene.
  Figure figure;
  figure.columns = 3;
  Panel curves;
  for (int i = 0; i < 5; ++i)
    curves.curves.push_back({{BezierCurve::make(*PointArray::make({{0, 0}, {1, 2.0 + i}, {3, 0}})).value()}, solid(colors::black), ""});
  figure.panels.push_back(curves);
  figure.panels.push_back(bernstein_basis_panel(10).value());
  figure.panels.push_back(points_figure({Vec2{{0, 0}}, Vec2{{1, 1}}}, false).panels[0]);
  std::vector<double> seen;
  const Progress progress{[](void* self, double f) { static_cast<std::vector<double>*>(self)->push_back(f); }, &seen};
  const auto scene = layout(figure, progress);
  ASSERT_TRUE(scene);
  ASSERT_GE(seen.size(), 16u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LE(seen[i - 1], seen[i]) << i;
  EXPECT_EQ(scene->shapes.size(), layout(figure).value().shapes.size());
}

TEST(Layout, FixedAndLogarithmicRanges) {
  Figure figure = points_figure({Vec2{{0.5, 1e-12}}, Vec2{{2.0, 1e-3}}, Vec2{{3.0, 0.0}}}, false);
  figure.panels[0].x.range = std::array<double, 2>{0.0, 4.0};
  figure.panels[0].y.logarithmic = true;
  auto frames = panel_frames(figure);
  ASSERT_TRUE(frames) << frames.error().message;
  const PanelFrame& f = (*frames)[0];
  EXPECT_EQ(f.x_lower, 0.0);
  EXPECT_EQ(f.x_upper, 4.0);
  // Log range: the positive values with 5 % margins in log space (9 decades).
  EXPECT_NEAR(std::log10(f.y_lower), -12.0 - 0.45, 1e-9);
  EXPECT_NEAR(std::log10(f.y_upper), -3.0 + 0.45, 1e-9);
  // Zero cannot be drawn on a log axis: it is left out, not an error.
  EXPECT_TRUE(layout(figure));
}

TEST(Layout, Errors) {
  EXPECT_FALSE(layout(Figure{}));  // no panel
  Figure bad_size = points_figure({Vec2{{0, 0}}}, false, 10, 600);
  EXPECT_FALSE(layout(bad_size));
  Figure empty_range = points_figure({Vec2{{0, 0}}}, false);
  empty_range.panels[0].x.range = std::array<double, 2>{1.0, 1.0};
  auto e = layout(empty_range);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("empty"), std::string::npos);
  Figure log_negative = points_figure({Vec2{{1, 1}}}, false);
  log_negative.panels[0].y.logarithmic = true;
  log_negative.panels[0].y.range = std::array<double, 2>{-1.0, 1.0};
  EXPECT_FALSE(layout(log_negative));
  Figure not_finite = points_figure({Vec2{{0, NAN}}}, false);
  auto n = layout(not_finite);
  ASSERT_FALSE(n);
  EXPECT_NE(n.error().message.find("point 0 is not finite"), std::string::npos) << n.error().message;
  Figure three_d;
  three_d.panels.emplace_back();
  three_d.panels[0].curves.push_back(
      {{BezierCurve::make(*PointArray::make({{0, 0, 0}, {1, 1, 1}})).value()}, solid(colors::black), ""});
  EXPECT_FALSE(layout(three_d));
}

TEST(Ticks, LikeMatplotlib) {
  // matplotlib 3.6, plt.plot([0, 1]) on default axes (xlim -0.05..1.05):
  // ticks 0.0, 0.2, ..., 1.0 labelled with one decimal.
  const Ticks a = linear_ticks(-0.05, 1.05, 8);
  ASSERT_EQ(a.values.size(), 6u);
  EXPECT_EQ(a.labels.front(), "0.0");
  EXPECT_EQ(a.labels.back(), "1.0");
  // plt.plot([0, 4]) (xlim -0.2..4.2): 0.0, 0.5, ..., 4.0.
  const Ticks b = linear_ticks(-0.2, 4.2, 9);
  ASSERT_EQ(b.values.size(), 9u);
  EXPECT_EQ(b.labels[1], "0.5");
  // A step of 0.25 needs two decimals; negative labels use U+2212.
  const Ticks c = linear_ticks(-1.0, 1.0, 8);
  EXPECT_EQ(c.labels.front(), "\u22121.00");
  EXPECT_EQ(c.labels[4], "0.00");
  const Ticks d = logarithmic_ticks(1e-20, 2e-15, 10);
  ASSERT_EQ(d.values.size(), 6u);
  EXPECT_EQ(d.labels[0], "10");
  EXPECT_EQ(d.superscripts[0], "\u221220");
  EXPECT_EQ(d.superscripts.back(), "\u221215");
}

RC_GTEST_PROP(Ticks, InsideTheRangeAndEvenlySpaced, ()) {
  const double lower = *test::coordinate();
  const double width = 1e-3 + std::abs(*test::coordinate());
  const int max_count = *rc::gen::inRange(3, 11);
  const Ticks t = linear_ticks(lower, lower + width, max_count);
  RC_ASSERT(t.values.size() >= 2u);
  // At most max_count intervals, unless that would leave fewer than two ticks
  // (then the next smaller step, at most 2.5 times smaller: at most 7 ticks).
  RC_ASSERT(static_cast<int>(t.values.size()) <= std::max(max_count + 1, 7));
  const double step = t.values[1] - t.values[0];
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    RC_ASSERT(t.values[i] >= lower - 1e-9 * width);
    RC_ASSERT(t.values[i] <= lower + width + 1e-9 * width);
    if (i > 0) RC_ASSERT(std::abs(t.values[i] - t.values[i - 1] - step) <= 1e-9 * step);
  }
  // Labels are distinct (enough decimals for the step).
  for (std::size_t i = 1; i < t.labels.size(); ++i) RC_ASSERT(t.labels[i] != t.labels[i - 1]);
}

TEST(TextWidth, DejaVuSansAdvances) {
  // DejaVu Sans: every digit advances 1303/2048 em, the space 651/2048 em.
  EXPECT_NEAR(estimated_text_width("0123456789", 2048.0), 10 * 1303.0, 10.0);
  EXPECT_NEAR(estimated_text_width(" ", 2048.0), 651.0, 2.0);
  EXPECT_EQ(estimated_text_width("", 10.0), 0.0);
}

TEST(Plots, BernsteinGraphMatchesBernsteinAll) {
  for (int n : {1, 3, 20}) {
    std::vector<double> values(static_cast<std::size_t>(n + 1));
    for (int k = 0; k <= n; ++k) {
      const BezierCurve graph = bernstein_graph(n, k);
      for (int i = 0; i <= 50; ++i) {
        const double t = i / 50.0;
        bernstein_all(n, t, values);
        const Point p = point_at(graph, t);
        EXPECT_NEAR(p[0], t, 1e-15);  // linear precision
        EXPECT_NEAR(p[1], values[static_cast<std::size_t>(k)], 1e-15);
      }
    }
  }
}

TEST(Plots, BernsteinBasisPanel) {
  // Drawn from the closed form (bernstein_graph.hpp), not as Bézier curves of degree n.
  EXPECT_EQ(bernstein_basis_panel(20).value().bernstein_graphs.size(), 21u);
  EXPECT_TRUE(bernstein_basis_panel(20).value().curves.empty());
  EXPECT_EQ(bernstein_basis_panel(20, BasisEnds::omitted).value().bernstein_graphs.size(), 19u);
  EXPECT_EQ(bernstein_basis_panel(20, BasisEnds::omitted).value().bernstein_graphs.front().index, 1);
  EXPECT_FALSE(bernstein_basis_panel(0));
  EXPECT_FALSE(bernstein_basis_panel(1, BasisEnds::omitted));
  EXPECT_FALSE(bernstein_basis_panel(tolerances::kMaxPlottedBasisDegree + 1));
}

RC_GTEST_PROP(Plots, PlaneCurveProjectsTheCurve, ()) {
  const BezierCurve curve = *test::bezier_curve(1, 8, *rc::gen::arbitrary<bool>(), *rc::gen::inRange(2, 5));
  const auto plane = plane_curve(curve);
  RC_ASSERT(plane.has_value());
  RC_ASSERT(plane->dimension() == 2);
  const double t = *test::unit_parameter();
  const Point a = point_at(curve, t), b = point_at(*plane, t);
  const double tol = 1e-12 * (1.0 + scale_of(curve.control_points()));
  RC_ASSERT(std::abs(a[0] - b[0]) <= tol);
  RC_ASSERT(std::abs(a[1] - b[1]) <= tol);
}

RC_GTEST_PROP(Plots, OneDimensionalCurveIsDrawnAsItsGraph, ()) {
  const BezierCurve curve = *test::bezier_curve(1, 8, false, 1);
  const auto graph = plane_curve(curve);
  RC_ASSERT(graph.has_value());
  const double t = *test::unit_parameter();
  const Point p = point_at(*graph, t);
  const double tol = 1e-12 * (1.0 + scale_of(curve.control_points()));
  RC_ASSERT(std::abs(p[0] - t) <= 1e-12);
  RC_ASSERT(std::abs(p[1] - point_at(curve, t)[0]) <= tol);
}

TEST(Plots, RationalOneDimensionalCurveIsRefused) {
  const auto curve = BezierCurve::make(*PointArray::make({{0}, {1}}), {1.0, 2.0}).value();
  EXPECT_FALSE(plane_curve(curve));
}

TEST(Plots, ConstructionDrawsEveryLevel) {
  const auto curve = BezierCurve::make(*PointArray::make({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}})).value();
  Panel panel;
  BezierPlotOptions options;
  options.construction = 0.5;
  add_bezier(panel, curve, options);
  // Levels 0..3 as dashed polygons; C(0.5) = (2.25, 1.5), the notebook's value.
  EXPECT_EQ(panel.polylines.size(), 4u);
  bool found = false;
  for (const auto& m : panel.markers)
    for (auto p : m.points) found = found || (std::abs(p[0] - 2.25) < 1e-15 && std::abs(p[1] - 1.5) < 1e-15);
  EXPECT_TRUE(found);
}

TEST(Plots, PlotFigureChecksTheConstructionParameter) {
  PlotSource source;
  source.name = "c.json";
  source.models.push_back(BezierCurve::make(*PointArray::make({{0, 0}, {1, 1}})).value());
  PlotOptions options;
  options.bezier.construction = 1.5;
  auto figure = plot_figure({source}, options);
  ASSERT_FALSE(figure);
  EXPECT_NE(figure.error().message.find("c.json"), std::string::npos);
  options.bezier.construction = 0.25;
  options.basis = true;
  figure = plot_figure({source}, options);
  ASSERT_TRUE(figure);
  EXPECT_EQ(figure->panels.size(), 2u);
  EXPECT_FALSE(plot_figure({}, options));
}

}  // namespace
}  // namespace casteljau::render

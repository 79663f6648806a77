// SVG output: well-formed XML-ish text with the expected elements, no curve
// commands, deterministic bytes, and polylines that stay within the quarter
// pixel flattening tolerance of the true curve (reference: de Casteljau
// point_at sampled densely, independent of the flattening and the layout).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/render/layout.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/tolerance.hpp"
#include "casteljau/render/write.hpp"
#include "support/plane_geometry.hpp"

namespace casteljau::render {
namespace {

using test::distance_to_segment;

BezierCurve notebook_curve() {
  return BezierCurve::make(*PointArray::make({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}})).value();
}

/// Checks that every tag is closed in order (a small XML well-formedness
/// check: names of start and end tags match, self-closing tags allowed).
::testing::AssertionResult balanced_tags(const std::string& text) {
  std::vector<std::string> open;
  std::size_t i = 0;
  while ((i = text.find('<', i)) != std::string::npos) {
    const std::size_t end = text.find('>', i);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unterminated tag at " << i;
    const std::string tag = text.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.empty()) return ::testing::AssertionFailure() << "empty tag";
    if (tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name)
        return ::testing::AssertionFailure() << "</" << name << "> closes " << (open.empty() ? "nothing" : open.back());
      open.pop_back();
      continue;
    }
    if (tag.back() == '/') continue;
    open.push_back(tag.substr(0, tag.find_first_of(" \n\t")));
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> never closed";
  return ::testing::AssertionSuccess();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}

std::vector<Vec2> parse_points(const std::string& attribute) {
  std::vector<Vec2> points;
  std::istringstream in(attribute);
  std::string pair;
  while (in >> pair) {
    const auto comma = pair.find(',');
    points.push_back(Vec2{{std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1))}});
  }
  return points;
}

/// The points of the polyline stroked with `color` (e.g. "#010203").
std::vector<Vec2> polyline_with_stroke(const std::string& svg, const std::string& color) {
  const std::regex pattern("<polyline points=\"([^\"]*)\"[^>]*stroke=\"" + color + "\"");
  std::smatch match;
  if (!std::regex_search(svg, match, pattern)) return {};
  return parse_points(match[1].str());
}

double distance_to_polyline(Vec2 p, const std::vector<Vec2>& line) {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) best = std::min(best, distance_to_segment(p, line[i], line[i + 1]));
  return best;
}

Figure curve_figure(const BezierCurve& curve, bool equal_aspect) {
  Figure figure;
  figure.title = "test";
  Panel panel;
  panel.equal_aspect = equal_aspect;
  panel.curves.push_back({{curve}, Stroke{Color{1, 2, 3}, 1.0, {}}, "curve"});
  panel.markers.push_back({plane_points(curve.control_points()), colors::red, 6.0, "control points"});
  figure.panels.push_back(panel);
  return figure;
}

TEST(Svg, HasTheExpectedElementsAndNoCurveCommands) {
  const Figure figure = curve_figure(notebook_curve(), true);
  auto scene = layout(figure);
  ASSERT_TRUE(scene) << scene.error().message;
  const std::string svg = svg_document(*scene);
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  EXPECT_TRUE(balanced_tags(svg));
  EXPECT_EQ(count(svg, "<circle"), 5u + 1u);  // five control points, one legend marker
  EXPECT_GE(count(svg, "<text"), 10u);        // tick labels, title, legend
  EXPECT_EQ(count(svg, "<title>test</title>"), 1u);
  EXPECT_EQ(count(svg, "<clipPath"), 1u);
  EXPECT_EQ(count(svg, "<path"), 0u);  // curves are polylines, never 'C' commands
  EXPECT_NE(svg.find(">control points</text>"), std::string::npos);
}

TEST(Svg, EscapesText) {
  Figure figure;
  figure.title = "a < b & \"c\"";
  figure.panels.emplace_back();
  figure.panels[0].polylines.push_back({{Vec2{{0, 0}}, Vec2{{1, 1}}}, solid(colors::black), "x<y"});
  auto scene = layout(figure);
  ASSERT_TRUE(scene);
  const std::string svg = svg_document(*scene);
  EXPECT_NE(svg.find("a &lt; b &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(svg.find(">x&lt;y</text>"), std::string::npos);
  EXPECT_TRUE(balanced_tags(svg));
}

TEST(Svg, IsDeterministic) {
  const Figure figure = curve_figure(notebook_curve(), false);
  auto a = layout(figure), b = layout(figure);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(svg_document(*a), svg_document(*b));
}

// The drawn polyline must stay within tolerances::kCurveTolerancePixels of the curve, in
// pixels, after the SVG's rounding to 1/100 px: every densely sampled curve
// point lies within 0.25 px (+ rounding) of the polyline, and every vertex
// lies on the curve (within rounding + sampling error).
void expect_polyline_within_tolerance(const BezierCurve& curve, bool equal_aspect) {
  const Figure figure = curve_figure(curve, equal_aspect);
  auto frames = panel_frames(figure);
  ASSERT_TRUE(frames) << frames.error().message;
  auto scene = layout(figure);
  ASSERT_TRUE(scene);
  const auto line = polyline_with_stroke(svg_document(*scene), "#010203");
  ASSERT_GE(line.size(), 8u);
  const PanelFrame& frame = (*frames)[0];
  std::vector<Vec2> samples;
  constexpr int kSamples = 20000;
  for (int i = 0; i <= kSamples; ++i) {
    const Point p = point_at(curve, static_cast<double>(i) / kSamples);
    samples.push_back(frame.to_pixels(Vec2{{p[0], p[1]}}));
  }
  const double rounding = 0.005 * std::sqrt(2.0);
  double worst = 0.0;
  for (auto s : samples) worst = std::max(worst, distance_to_polyline(s, line));
  EXPECT_LE(worst, tolerances::kCurveTolerancePixels + rounding);
  // Vertices on the curve: nearest sample within rounding + half a sample step.
  double step = 0.0;
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) step = std::max(step, distance(samples[i], samples[i + 1]));
  for (auto v : line) {
    double nearest = INFINITY;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i)
      nearest = std::min(nearest, distance_to_segment(v, samples[i], samples[i + 1]));
    EXPECT_LE(nearest, rounding + 0.01);
  }
  // The first and last vertices are the curve's end points.
  EXPECT_LE(distance(line.front(), samples.front()), rounding);
  EXPECT_LE(distance(line.back(), samples.back()), rounding);
}

TEST(Svg, PolylineStaysWithinAQuarterPixelOfTheCurve) {
  expect_polyline_within_tolerance(notebook_curve(), true);
  expect_polyline_within_tolerance(notebook_curve(), false);
  // A tight spiral-like cubic with a loop, and a flat wide one (unequal scales).
  expect_polyline_within_tolerance(
      BezierCurve::make(*PointArray::make({{0, 0}, {10, 10}, {0, 10}, {10, 0}})).value(), true);
  expect_polyline_within_tolerance(
      BezierCurve::make(*PointArray::make({{0, 0}, {100, 0.5}, {200, -0.5}, {300, 0}})).value(), false);
}

TEST(Svg, RationalCurveWithinTolerance) {
  // A quarter circle, exactly (rational quadratic with weight cos 45°).
  const auto arc = BezierCurve::make(*PointArray::make({{1, 0}, {1, 1}, {0, 1}}), {1.0, std::sqrt(0.5), 1.0}).value();
  const Figure figure = curve_figure(arc, true);
  auto frames = panel_frames(figure);
  auto scene = layout(figure);
  ASSERT_TRUE(frames && scene);
  const auto line = polyline_with_stroke(svg_document(*scene), "#010203");
  ASSERT_GE(line.size(), 8u);
  // Every vertex on the unit circle; every sampled arc point near the polyline.
  for (auto v : line) {
    const Vec2 p = (*frames)[0].from_pixels(v);
    const double pixels_per_unit = (*frames)[0].area.width / ((*frames)[0].x_upper - (*frames)[0].x_lower);
    EXPECT_NEAR(norm(p), 1.0, 0.01 / pixels_per_unit);
  }
  for (int i = 0; i <= 2000; ++i) {
    const double a = 0.5 * std::numbers::pi * i / 2000.0;
    const Vec2 q = (*frames)[0].to_pixels(Vec2{{std::cos(a), std::sin(a)}});
    EXPECT_LE(distance_to_polyline(q, line), tolerances::kCurveTolerancePixels + 0.01);
  }
}

}  // namespace
}  // namespace casteljau::render

// SVG drawings (io/svg_drawing.hpp): transforms (each of the six forms, lists,
// groups), the basic shapes as SVG 2 §10 defines their paths, viewports
// (nested <svg>, viewBox with preserveAspectRatio, <use> and <symbol>),
// lengths with units, millimetres, style and metadata, and the errors: what
// is in error is reported with its line and element, the rest is drawn.
// Expected coordinates are worked out by hand from the SVG specification.
#include "casteljau/io/svg_drawing.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/svg_writer.hpp"

namespace casteljau {
namespace {

using Flat = std::vector<double>;

SvgDrawing read_drawing(const std::string& body, const std::string& root = "<svg xmlns='http://www.w3.org/2000/svg'>",
                      DrawingUnits units = DrawingUnits::user) {
  const std::string text = root + body + "</svg>";
  auto drawing = parse_svg_drawing(text, "t.svg", units);
  EXPECT_TRUE(drawing.has_value()) << text << ": " << drawing.error().message;
  if (!drawing) return {};
  for (const Error& problem : drawing->problems) ADD_FAILURE() << text << ": " << problem.message;
  return std::move(*drawing);
}

/// The problems of a drawing (each one line).
std::vector<std::string> problems_of(const std::string& body) {
  auto drawing = parse_svg_drawing("<svg xmlns='http://www.w3.org/2000/svg'>\n" + body + "</svg>", "t.svg");
  EXPECT_TRUE(drawing.has_value());
  std::vector<std::string> messages;
  if (drawing)
    for (const Error& problem : drawing->problems) messages.push_back(problem.message);
  return messages;
}

/// A piece's control points in the file's user space (y down): the tests'
/// roots have no viewBox or height unless they say, so the page's bottom is
/// y = 0 and the file's y is -y (exactly).
Flat drawing_points(const SvgCurve& curve, std::size_t piece = 0, double page_bottom = 0.0) {
  const auto c = curve.curve.pieces().at(piece).control_points().coordinates();
  Flat file(c.begin(), c.end());
  for (std::size_t i = 1; i < file.size(); i += 2) file[i] = page_bottom - file[i];
  return file;
}

void expect_near(const Flat& actual, const Flat& expected, double tolerance = 1e-12) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "value " << i;
}

TEST(SvgDrawing, EachTransformFormMovesThePoint) {
  // (1, 1) and (2, 0) under each form, worked from SVG 1.1 §7.6's matrices.
  const auto moved = [](const std::string& transform) {
    const auto drawing = read_drawing(fmt::format("<path transform='{}' d='M1 1L2 0'/>", transform));
    return drawing.curves.empty() ? Flat{} : drawing_points(drawing.curves[0]);
  };
  expect_near(moved("matrix(1 2 3 4 5 6)"), {9, 12, 7, 10});
  expect_near(moved("translate(5)"), {6, 1, 7, 0});
  expect_near(moved("translate(5,-1)"), {6, 0, 7, -1});
  expect_near(moved("scale(2)"), {2, 2, 4, 0});
  expect_near(moved("scale(2 3)"), {2, 3, 4, 0});
  EXPECT_EQ(moved("rotate(90)"), (Flat{-1, 1, 0, 2}));  // exactly: quarter turns are exact
  EXPECT_EQ(moved("rotate(180)"), (Flat{-1, -1, -2, 0}));
  expect_near(moved("rotate(90 1 0)"), {0, 0, 1, 1});
  expect_near(moved("rotate(30)"), {std::cos(M_PI / 6) - std::sin(M_PI / 6), std::sin(M_PI / 6) + std::cos(M_PI / 6),
                                    2 * std::cos(M_PI / 6), 2 * std::sin(M_PI / 6)});
  expect_near(moved("skewX(45)"), {2, 1, 2, 0});
  expect_near(moved("skewY(45)"), {1, 2, 2, 2});
  // A list is applied right to left: scale first, then translate.
  expect_near(moved("translate(10) scale(2)"), {12, 2, 14, 0});
  expect_near(moved(" translate(10),scale(2) "), {12, 2, 14, 0});
  expect_near(moved("scale(2)translate(10)"), {22, 2, 24, 0});
}

TEST(SvgDrawing, GroupTransformsComposeOutsideIn) {
  const auto drawing = read_drawing(
      "<g transform='translate(10 20)'><g transform='scale(2)'><path transform='translate(1)' d='M0 0L1 1'/>"
      "</g></g>");
  ASSERT_EQ(drawing.curves.size(), 1u);
  EXPECT_EQ(drawing_points(drawing.curves[0]), (Flat{12, 20, 14, 22}));
}

TEST(SvgDrawing, BadTransformsAreProblemsAndTheElementIsNotDrawn) {
  const auto problem = [](const std::string& transform) {
    const auto messages = problems_of(fmt::format("<path id='p' transform='{}' d='M0 0L1 1'/>", transform));
    return messages.empty() ? std::string("(none)") : messages[0];
  };
  EXPECT_EQ(problem("rotate(30"), "t.svg, line 2, <path id='p'>: transform, at its end: rotate is not closed by ')'");
  EXPECT_EQ(problem("rotate(1 2)"),
            "t.svg, line 2, <path id='p'>: transform, character 11 (')'): rotate takes 1 or 3 numbers, found 2");
  EXPECT_EQ(problem("spin(1)"), "t.svg, line 2, <path id='p'>: transform, character 1 ('s'): 'spin' is not a "
                                "transform (matrix, translate, scale, rotate, skewX, skewY)");
  EXPECT_EQ(problem("matrix(1 2 3)"),
            "t.svg, line 2, <path id='p'>: transform, character 13 (')'): matrix takes 6 numbers, found 3");
  EXPECT_EQ(problem("scale(2),"), "t.svg, line 2, <path id='p'>: transform, at its end: a transform list does not "
                                  "end with a comma");
  EXPECT_EQ(problem("scale(x)"),
            "t.svg, line 2, <path id='p'>: transform, character 7 ('x'): expected a number or ')' in scale");
  auto drawing = parse_svg_drawing("<svg><path transform='rotate(' d='M0 0L1 1'/><path d='M0 0L2 2'/></svg>", "t.svg");
  ASSERT_TRUE(drawing);
  ASSERT_EQ(drawing->curves.size(), 1u);  // the second path only
  EXPECT_EQ(drawing_points(drawing->curves[0]), (Flat{0, 0, 2, 2}));
}

TEST(SvgDrawing, RectWithoutCornersIsFourLines) {
  const auto drawing = read_drawing("<rect id='r' x='1' y='2' width='3' height='4'/>");
  ASSERT_EQ(drawing.curves.size(), 1u);
  const SvgCurve& rect = drawing.curves[0];
  EXPECT_TRUE(rect.closed);
  EXPECT_EQ(rect.element, "rect");
  EXPECT_EQ(rect.id, "r");
  ASSERT_EQ(rect.curve.pieces().size(), 4u);
  EXPECT_EQ(drawing_points(rect, 0), (Flat{1, 2, 4, 2}));
  EXPECT_EQ(drawing_points(rect, 1), (Flat{4, 2, 4, 6}));
  EXPECT_EQ(drawing_points(rect, 2), (Flat{4, 6, 1, 6}));
  EXPECT_EQ(drawing_points(rect, 3), (Flat{1, 6, 1, 2}));
}

/// Every point of the pieces at parameters k/64 lies on the ellipse
/// ((x - cx) / rx)² + ((y - cy) / ry)² = 1 within `tolerance` (a few ulps:
/// the arc is exact, its evaluation rounds).
void expect_on_ellipse(const BezierCurve& piece, double cx, double cy, double rx, double ry, double tolerance) {
  for (int k = 0; k <= 64; ++k) {
    const Point p = point_at(piece, k / 64.0);
    const double x = (p[0] - cx) / rx, y = (-p[1] - cy) / ry;  // the file's y: -y (page bottom 0)
    EXPECT_NEAR(std::hypot(x, y), 1.0, tolerance) << "at " << k << "/64";
  }
}

TEST(SvgDrawing, RoundedRectCornersAreExactQuarterEllipses) {
  const auto drawing = read_drawing("<rect x='0' y='0' width='10' height='6' rx='2' ry='1'/>");
  ASSERT_EQ(drawing.curves.size(), 1u);
  const auto& pieces = drawing.curves[0].curve.pieces();
  ASSERT_EQ(pieces.size(), 8u);  // four edges, four corners
  EXPECT_EQ(drawing_points(drawing.curves[0], 0), (Flat{2, 0, 8, 0}));
  EXPECT_TRUE(pieces[1].is_rational());
  expect_on_ellipse(pieces[1], 8, 1, 2, 1, 4e-15);  // top right
  expect_on_ellipse(pieces[3], 8, 5, 2, 1, 4e-15);  // bottom right
  expect_on_ellipse(pieces[5], 2, 5, 2, 1, 4e-15);
  expect_on_ellipse(pieces[7], 2, 1, 2, 1, 4e-15);
  // One radius given: the other takes it (SVG 2 "auto"); too large: clamped to half the side.
  const auto one = read_drawing("<rect width='10' height='6' rx='2'/>");
  expect_on_ellipse(one.curves.at(0).curve.pieces().at(1), 8, 2, 2, 2, 4e-15);
  const auto clamped = read_drawing("<rect width='10' height='6' rx='20' ry='1'/>");
  const auto& round = clamped.curves.at(0).curve.pieces();
  ASSERT_EQ(round.size(), 8u);
  EXPECT_EQ(drawing_points(clamped.curves[0], 0), (Flat{5, 0, 5, 0}));  // the edge shrinks to a point
  expect_on_ellipse(round[1], 5, 1, 5, 1, 4e-15);
}

TEST(SvgDrawing, CirclesAndEllipsesAreFourExactArcsClockwiseFromTheRight) {
  const auto drawing = read_drawing("<circle cx='3' cy='4' r='5'/><ellipse cx='-1' cy='2' rx='4' ry='0.5'/>");
  ASSERT_EQ(drawing.curves.size(), 2u);
  const auto& circle = drawing.curves[0];
  EXPECT_TRUE(circle.closed);
  ASSERT_EQ(circle.curve.pieces().size(), 4u);
  EXPECT_EQ(drawing_points(circle, 0).front(), 8.0);
  // SVG 2 §10.3: starts at (cx + r, cy), then (cx, cy + r): clockwise on
  // screen, and in the model (y up), where the file's (3, 9) is (3, -9).
  const Point quarter = point_at(circle.curve.pieces()[0], 1.0);
  EXPECT_NEAR(quarter[0], 3.0, 4e-15);
  EXPECT_NEAR(quarter[1], -9.0, 4e-15);
  for (const auto& piece : circle.curve.pieces()) expect_on_ellipse(piece, 3, 4, 5, 5, 4e-15);
  for (const auto& piece : drawing.curves[1].curve.pieces()) expect_on_ellipse(piece, -1, 2, 4, 0.5, 4e-15);
}

TEST(SvgDrawing, LinesPolylinesAndPolygons) {
  const auto drawing = read_drawing(
      "<line x1='1' y1='2' x2='3' y2='4'/><polyline points='0,0 1,1 2,0'/><polygon points='0 0,4 0 4 3'/>");
  ASSERT_EQ(drawing.curves.size(), 3u);
  EXPECT_EQ(drawing_points(drawing.curves[0]), (Flat{1, 2, 3, 4}));
  EXPECT_FALSE(drawing.curves[1].closed);
  EXPECT_EQ(drawing.curves[1].curve.pieces().size(), 2u);
  EXPECT_TRUE(drawing.curves[2].closed);
  ASSERT_EQ(drawing.curves[2].curve.pieces().size(), 3u);
  EXPECT_EQ(drawing_points(drawing.curves[2], 2), (Flat{4, 3, 0, 0}));
}

TEST(SvgDrawing, ShapesOfZeroSizeDrawNothingAndNegativeSizesAreProblems) {
  const auto none = read_drawing("<rect width='0' height='5'/><circle r='0'/><ellipse rx='1' ry='0'/>");
  EXPECT_TRUE(none.curves.empty());
  EXPECT_EQ(problems_of("<rect width='-1' height='5'/>"),
            std::vector<std::string>{"t.svg, line 2, <rect>: a negative width (-1)"});
  EXPECT_EQ(problems_of("<circle r='-2'/>"), std::vector<std::string>{"t.svg, line 2, <circle>: r: a negative radius (-2)"});
  EXPECT_EQ(problems_of("<polyline points='0 0 1 1 2'/>"),
            std::vector<std::string>{"t.svg, line 2, <polyline>: points, at its end: an odd count of numbers (5), "
                                     "points are x,y pairs"});
}

TEST(SvgDrawing, PathDataIsDrawnUpToItsFirstError) {
  auto drawing = parse_svg_drawing("<svg>\n\n<path id='a' d='M0 0 L1 1 L2 x'/></svg>", "t.svg");
  ASSERT_TRUE(drawing);
  ASSERT_EQ(drawing->problems.size(), 1u);
  EXPECT_EQ(drawing->problems[0].message,
            "t.svg, line 3, <path id='a'>: path data, character 14 ('x'): expected a number, 'L' takes x y");
  ASSERT_EQ(drawing->curves.size(), 1u);
  EXPECT_EQ(drawing->curves[0].curve.pieces().size(), 1u);
  EXPECT_EQ(drawing->curves[0].line, 3u);
}

TEST(SvgDrawing, LengthUnitsAndPercentages) {
  const auto drawing = read_drawing("<rect width='1in' height='2.54cm'/><line x2='72pt' y2='6pc'/>"
                                  "<line x1='25.4mm' x2='101.6Q'/>");
  ASSERT_EQ(drawing.curves.size(), 3u);
  EXPECT_EQ(drawing_points(drawing.curves[0], 1), (Flat{96, 0, 96, 96}));
  expect_near(drawing_points(drawing.curves[1]), {0, 0, 96, 96}, 1e-13);
  expect_near(drawing_points(drawing.curves[2]), {96, 0, 96, 0}, 1e-13);
  const auto percent = read_drawing("<rect width='50%' height='25%'/><circle r='10%'/>",
                                  "<svg viewBox='0 0 200 100'>");
  EXPECT_EQ(drawing_points(percent.curves.at(0), 1, percent.page_bottom), (Flat{100, 0, 100, 25}));
  // r: 10% of sqrt((200² + 100²) / 2).
  EXPECT_NEAR(drawing_points(percent.curves.at(1), 0)[0], 0.1 * std::sqrt((200.0 * 200 + 100 * 100) / 2), 1e-12);
  EXPECT_EQ(problems_of("<rect width='2em' height='1'/>"),
            std::vector<std::string>{"t.svg, line 2, <rect>: width, character 2 ('e'): '2em': em and ex lengths "
                                     "depend on fonts, casteljau reads px, in, cm, mm, Q, pt, pc and %"});
  EXPECT_EQ(problems_of("<rect width='50%' height='1'/>"),
            std::vector<std::string>{"t.svg, line 2, <rect>: width: '50%' needs a viewport size (the root's "
                                     "viewBox, or its width and height in absolute units)"});
}

TEST(SvgDrawing, ModelsAreUprightWithYUpFromThePagesBottom) {
  // Issue 39: SVG is y down, every other format and plot y up; a drawing read
  // as its numbers came out mirrored. y is now measured up from the page's
  // bottom edge: the viewBox's min-y + height, else the root's height, else 0.
  const std::string body = "<path d='M0 10L20 30'/>";
  const auto boxed = read_drawing(body, "<svg viewBox='5 -20 200 100'>");
  EXPECT_EQ(boxed.page_bottom, 80.0);
  EXPECT_EQ(boxed.curves.at(0).curve.pieces()[0].control_points().coordinates()[1], 70.0);
  EXPECT_EQ(boxed.curves.at(0).curve.pieces()[0].control_points().coordinates()[3], 50.0);
  const auto sized = read_drawing(body, "<svg width='100' height='1in'>");
  EXPECT_EQ(sized.page_bottom, 96.0);
  EXPECT_EQ(sized.curves.at(0).curve.pieces()[0].control_points().coordinates()[1], 86.0);
  const auto unsized = read_drawing(body);
  EXPECT_EQ(unsized.page_bottom, 0.0);
  EXPECT_EQ(unsized.curves.at(0).curve.pieces()[0].control_points().coordinates()[1], -10.0);
  // An "F" keeps its handedness: drawn on screen with its bar at the top and
  // its arms to the right, it has them at the top and to the right in the
  // model, and its outline, clockwise on screen, is clockwise in the model
  // too: a negative signed area with y up (the file's own numbers, y down,
  // give +68, which read as y up is the mirrored F).
  const auto letter = read_drawing("<path d='M0 0H6V2H2V4H5V6H2V10H0Z'/>", "<svg viewBox='0 0 10 10'>");
  const auto& f = letter.curves.at(0).curve;
  double area = 0.0, top_right = 0.0;
  for (const BezierCurve& piece : f.pieces()) {
    const auto c = piece.control_points().coordinates();
    area += c[0] * c[3] - c[2] * c[1];
    if (c[1] == 10.0) top_right = std::max(top_right, c[0]);  // the bar along the top
  }
  EXPECT_EQ(area / 2, -34.0);   // clockwise with y up
  EXPECT_EQ(top_right, 6.0);    // the bar is at the top, reaching right
}

TEST(SvgDrawing, MillimetresThroughTheRootsSizeAndViewBox) {
  const std::string body = "<path d='M0 0L200 100'/>";
  const auto user = read_drawing(body, "<svg width='100mm' height='50mm' viewBox='0 0 200 100'>");
  EXPECT_EQ(drawing_points(user.curves.at(0), 0, user.page_bottom), (Flat{0, 0, 200, 100}));  // user units: the root's map not applied
  const auto mm = read_drawing(body, "<svg width='100mm' height='50mm' viewBox='0 0 200 100'>", DrawingUnits::millimetres);
  // Millimetres measure y up from the page's bottom edge, 50 mm below its top.
  expect_near(drawing_points(mm.curves.at(0), 0, 50.0), {0, 0, 100, 50});
  EXPECT_EQ(mm.units, DrawingUnits::millimetres);
  // A square viewport: xMidYMid meet scales by 0.5 and centres vertically.
  const auto meet = read_drawing(body, "<svg width='100mm' height='100mm' viewBox='0 0 200 100'>",
                               DrawingUnits::millimetres);
  expect_near(drawing_points(meet.curves.at(0), 0, 100.0), {0, 25, 100, 75});
  const auto none = read_drawing(body, "<svg width='100mm' height='100mm' viewBox='0 0 200 100' "
                                     "preserveAspectRatio='none'>", DrawingUnits::millimetres);
  expect_near(drawing_points(none.curves.at(0), 0, 100.0), {0, 0, 100, 100});
  const auto slice = read_drawing(body, "<svg width='100mm' height='100mm' viewBox='0 0 200 100' "
                                      "preserveAspectRatio='xMinYMin slice'>", DrawingUnits::millimetres);
  expect_near(drawing_points(slice.curves.at(0), 0, 100.0), {0, 0, 200, 100});
  // No viewBox: a user unit is a CSS pixel, 25.4 / 96 mm.
  const auto pixels = read_drawing(body, "<svg width='960' height='480'>", DrawingUnits::millimetres);
  expect_near(drawing_points(pixels.curves.at(0), 0, 480 * 25.4 / 96), {0, 0, 200 * 25.4 / 96, 100 * 25.4 / 96});
  auto unsized = parse_svg_drawing("<svg viewBox='0 0 10 10'><path d='M0 0L1 1'/></svg>", "t.svg",
                                   DrawingUnits::millimetres);
  ASSERT_FALSE(unsized);
  EXPECT_EQ(unsized.error().message, "t.svg: millimetres need the root <svg>'s width and height as absolute "
                                     "lengths (mm, cm, in, pt, pc, px or a number), and it has neither");
  auto relative = parse_svg_drawing("<svg width='100%' height='5cm'><path d='M0 0L1 1'/></svg>", "t.svg",
                                    DrawingUnits::millimetres);
  ASSERT_FALSE(relative);
  EXPECT_NE(relative.error().message.find("width '100%', height '5cm'"), std::string::npos);
}

TEST(SvgDrawing, NestedViewportsAndUse) {
  const auto nested = read_drawing("<svg x='10' y='10' width='20' height='20' viewBox='0 0 2 2'><path d='M0 0L2 2'/></svg>");
  expect_near(drawing_points(nested.curves.at(0)), {10, 10, 30, 30});
  // In a root of unknown size, a nested svg without a size only moves its content.
  const auto unsized = read_drawing("<svg x='2' y='3'><path d='M0 0L1 1'/></svg>");
  EXPECT_EQ(drawing_points(unsized.curves.at(0)), (Flat{2, 3, 3, 4}));
  EXPECT_EQ(problems_of("<svg viewBox='0 0 1 1'><path d='M0 0L1 1'/></svg>"),
            std::vector<std::string>{"t.svg, line 2, <svg>: a viewBox needs the viewport's width and height, which "
                                     "neither this element nor its viewport gives"});
  const auto use = read_drawing(
      "<defs><path id='p' d='M0 0L1 0'/></defs><use href='#p' x='5' y='6'/>"
      "<use xlink:href='#p' transform='scale(2)' x='1'/>",
      "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink'>");
  ASSERT_EQ(use.curves.size(), 2u);  // the path in <defs> itself is not drawn
  EXPECT_EQ(drawing_points(use.curves[0]), (Flat{5, 6, 6, 6}));
  EXPECT_EQ(drawing_points(use.curves[1]), (Flat{2, 0, 4, 0}));  // transform, then x: scale(2) translate(1)
  EXPECT_EQ(use.curves[0].id, "p");
  const auto symbol = read_drawing(
      "<symbol id='s' viewBox='0 0 1 1'><path d='M0 0L1 1'/></symbol><use href='#s' x='3' width='10' height='10'/>");
  ASSERT_EQ(symbol.curves.size(), 1u);
  expect_near(drawing_points(symbol.curves[0]), {3, 0, 13, 10});
  EXPECT_EQ(problems_of("<g id='g'><use href='#g'/></g>"),
            std::vector<std::string>{"t.svg, line 2, <use>: refers to '#g', which contains this <use> (a cycle)"});
  EXPECT_EQ(problems_of("<use href='#nothing'/>"),
            std::vector<std::string>{"t.svg, line 2, <use>: refers to '#nothing', which no element has as its id"});
}

TEST(SvgDrawing, HiddenAndSkippedElements) {
  const auto drawing = read_drawing(
      "<path display='none' d='M0 0L1 1'/><g style='display:none'><path d='M0 0L1 1'/></g>"
      "<g visibility='hidden'><path d='M0 0L1 1'/><path visibility='visible' d='M0 0L3 3'/></g>"
      "<text>hello</text><image href='x.png'/><clipPath><rect width='1' height='1'/></clipPath>"
      "<unknown><path d='M9 9L1 1'/></unknown>");
  ASSERT_EQ(drawing.curves.size(), 1u);
  EXPECT_EQ(drawing_points(drawing.curves[0]), (Flat{0, 0, 3, 3}));
  ASSERT_EQ(drawing.skipped.size(), 2u);
  EXPECT_EQ(drawing.skipped[0], "line 1: <text> (text is not read: convert it to paths)");
  EXPECT_EQ(drawing.skipped[1], "line 1: <image> (not vector geometry)");
}

TEST(SvgDrawing, StyleAndMetadata) {
  const auto drawing = read_drawing(
      "<g stroke-width='2' fill-rule='evenodd' transform='scale(3)'>"
      "<path id='a' d='M0 0L1 1'/><path style='fill-rule: nonzero; stroke-width:0.5px' fill-rule='evenodd' "
      "d='M0 0L1 1'/></g><path stroke-width='1mm' d='M0 0L1 1'/>");
  ASSERT_EQ(drawing.curves.size(), 3u);
  EXPECT_EQ(drawing.curves[0].fill_rule, FillRule::evenodd);
  EXPECT_DOUBLE_EQ(drawing.curves[0].stroke_width, 6.0);  // inherited, scaled by the group
  EXPECT_EQ(drawing.curves[1].fill_rule, FillRule::nonzero);  // style wins over the attribute
  EXPECT_DOUBLE_EQ(drawing.curves[1].stroke_width, 1.5);
  EXPECT_DOUBLE_EQ(drawing.curves[2].stroke_width, 96.0 / 25.4);
  EXPECT_EQ(drawing.curves[2].fill_rule, FillRule::nonzero);
}

TEST(SvgDrawing, DocumentErrors) {
  const auto message = [](const std::string& text) {
    auto drawing = parse_svg_drawing(text, "t.svg");
    return drawing ? std::string("(read)") : drawing.error().message;
  };
  EXPECT_EQ(message("<svg>\n  <path d='M0 0'>\n</svg>"),
            "t.svg, line 3, column 3: not well-formed XML: Start-end tags mismatch");
  EXPECT_EQ(message(""), "t.svg, line 1, column 1: not well-formed XML: No document element found");
  EXPECT_EQ(message("<html><path d='M0 0L1 1'/></html>"), "t.svg: the root element is <html>, an SVG drawing's is <svg>");
  EXPECT_EQ(message("<svg viewBox='0 0 -1 1'/>"), "t.svg, line 1, <svg>: viewBox: a negative width (-1)");
  std::string deep = "<svg>";
  for (int i = 0; i < 300; ++i) deep += "<g>";
  for (int i = 0; i < 300; ++i) deep += "</g>";
  EXPECT_EQ(message(deep + "</svg>"),
            "t.svg, line 1, <g>: elements nested deeper than 256 levels (<use> references counted)");
  // A <use> chain that doubles at each level is cut by the element limit, not by memory or time.
  std::string bomb = "<svg><g id='l0'/>";
  for (int i = 1; i <= 40; ++i)
    bomb += fmt::format("<g id='l{}'><use href='#l{}'/><use href='#l{}'/></g>", i, i - 1, i - 1);
  EXPECT_NE(message(bomb + "</svg>").find("more than 1000000 elements to draw (<use> instances counted)"),
            std::string::npos);
}

// What a drawing may get wrong besides its path data, each refused with its
// line and element while the rest is drawn (found by `make coverage`: no
// test fed these; docs/coverage.md).
TEST(SvgDrawing, MalformedAttributesAreProblemsAndTheRestIsDrawn) {
  EXPECT_EQ(problems_of("<path fill-rule='sideways' d='M0 0L1 1'/>"),
            std::vector<std::string>{"t.svg, line 2, <path>: fill-rule: 'sideways' is not nonzero or evenodd"});
  EXPECT_EQ(problems_of("<svg width='-1' height='2'><path d='M0 0L1 1'/></svg>"),
            std::vector<std::string>{"t.svg, line 2, <svg>: a negative width or height"});
  EXPECT_EQ(problems_of("<svg width='2' height='2' viewBox='0 0 x 1'><path d='M0 0L1 1'/></svg>"),
            std::vector<std::string>{"t.svg, line 2, <svg>: viewBox, character 5 ('x'): expected a number, a viewBox "
                                     "is min-x min-y width height"});
  EXPECT_EQ(problems_of("<svg width='2' height='2' viewBox='0 0 1 1' preserveAspectRatio='sideways'>"
                        "<path d='M0 0L1 1'/></svg>"),
            std::vector<std::string>{"t.svg, line 2, <svg>: preserveAspectRatio: 'sideways' is not none or "
                                     "x{Min,Mid,Max}Y{Min,Mid,Max} with meet or slice"});
  EXPECT_EQ(problems_of("<polyline points='0 0 1 x'/>"),
            std::vector<std::string>{"t.svg, line 2, <polyline>: points, character 7 ('x'): expected a number, points "
                                     "are x,y pairs"});
  EXPECT_EQ(problems_of("<polyline points='0 0 1 1e999'/>"),
            std::vector<std::string>{"t.svg, line 2, <polyline>: points, character 7 ('1'): '1e999' overflows to "
                                     "infinity, numbers must be finite"});
  // Each scale is below the coordinate limit; their product takes the points beyond it.
  EXPECT_EQ(problems_of("<g transform='scale(1e60)'><path transform='scale(1e60)' d='M0 0L1 1'/></g>"),
            std::vector<std::string>{"t.svg, line 2, <path>: its transforms take a point beyond 1e+100, the largest "
                                     "coordinate casteljau takes"});
  const auto root_style = parse_svg_drawing("<svg xmlns='http://www.w3.org/2000/svg' fill-rule='x'>\n<path d='M0 0L1 1'/></svg>", "t.svg");
  ASSERT_TRUE(root_style);
  ASSERT_EQ(root_style->problems.size(), 1u);
  EXPECT_EQ(root_style->problems[0].message, "t.svg, line 1, <svg>: fill-rule: 'x' is not nonzero or evenodd");
  EXPECT_EQ(root_style->curves.size(), 1u);
}

// Accepted forms: a namespace prefix on the elements, !important in a style,
// a nested viewport of zero size (not drawn, as SVG says), a <use> of another
// file (skipped: only this file is read).
TEST(SvgDrawing, PrefixedElementsImportantStylesAndEmptyViewports) {
  const auto prefixed =
      parse_svg_drawing("<svg:svg xmlns:svg='http://www.w3.org/2000/svg'><svg:path d='M0 0L1 1'/></svg:svg>", "t.svg");
  ASSERT_TRUE(prefixed);
  EXPECT_EQ(prefixed->curves.size(), 1u);
  EXPECT_TRUE(prefixed->problems.empty());
  const auto important = read_drawing("<path style='fill-rule: evenodd !important' d='M0 0L1 1'/>");
  ASSERT_EQ(important.curves.size(), 1u);
  EXPECT_EQ(important.curves[0].fill_rule, FillRule::evenodd);
  EXPECT_TRUE(read_drawing("<svg width='0' height='2'><path d='M0 0L1 1'/></svg>").curves.empty());
  EXPECT_TRUE(read_drawing("<svg width='2' height='2' viewBox='0 0 0 1'><path d='M0 0L1 1'/></svg>").curves.empty());
  const auto external = read_drawing("<use href='other.svg#p'/>");
  EXPECT_TRUE(external.curves.empty());
  ASSERT_EQ(external.skipped.size(), 1u);
  EXPECT_EQ(external.skipped[0], "line 1: <use> (refers to 'other.svg#p' outside this file, which is not read)");
}

// In millimetres the root's size must be a usable length.
TEST(SvgDrawing, MillimetresRefuseANegativeRootSizeOrAnEmptyViewBox) {
  const auto message = [](const std::string& root) {
    auto drawing = parse_svg_drawing(root + "<path d='M0 0L1 1'/></svg>", "t.svg", DrawingUnits::millimetres);
    return drawing ? std::string("(read)") : drawing.error().message;
  };
  EXPECT_EQ(message("<svg xmlns='http://www.w3.org/2000/svg' width='-3mm' height='2mm'>"),
            "t.svg, line 1, <svg>: a negative width (-3mm)");
  EXPECT_EQ(message("<svg xmlns='http://www.w3.org/2000/svg' width='3mm' height='2mm' viewBox='0 0 0 5'>"),
            "t.svg: the root's viewBox has a zero width or height, its size in mm is undefined");
  EXPECT_EQ(message("<svg xmlns='http://www.w3.org/2000/svg' width='3q' height='2mm'>"),
            "t.svg, line 1, <svg>: width, character 2 ('q'): 'q' is not a unit of length (px, in, cm, mm, Q, pt, pc, %)");
}

TEST(SvgDrawing, ReadModelsTakesDrawings) {
  const auto folder = std::filesystem::temp_directory_path() / "casteljau_svg_drawing_test";
  std::filesystem::create_directories(folder);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(folder / name) << text;
    return folder / name;
  };
  auto models = read_models(write("d.svg", "<svg><path d='M0 0L1 1M5 5L6 6'/><circle r='1'/></svg>"));
  ASSERT_TRUE(models) << models.error().message;
  EXPECT_EQ(models->size(), 3u);
  auto sniffed = read_models(write("d.txt", "\n <?xml version='1.0'?><svg><path d='M0 0L1 1'/></svg>"));
  ASSERT_TRUE(sniffed) << sniffed.error().message;
  EXPECT_EQ(sniffed->size(), 1u);
  auto bad = read_models(write("bad.svg", "<svg><path d='M0 0L1 1'/><path d='M0 0 Lx'/><rect width='-1'/></svg>"));
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().message, fmt::format("{}, line 1, <path>: path data, character 7 ('x'): expected a number, "
                                             "'L' takes x y (and 1 more problem)",
                                             (folder / "bad.svg").string()));
  auto empty = read_models(write("e.svg", "<svg><text>x</text></svg>"));
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().message,
            fmt::format("{}: the drawing has no path or shape to read (line 1: <text> (text is not read: convert it "
                        "to paths))",
                        (folder / "e.svg").string()));
  auto unitless = read_models(write("p.csv", "0,0\n1,1\n"), DrawingUnits::millimetres);
  ASSERT_FALSE(unitless);
  EXPECT_EQ(unitless.error().message, fmt::format("{}: millimetres are asked of a CSV point set, whose numbers have "
                                                  "no unit (--units applies to drawings: SVG, DXF)",
                                                  (folder / "p.csv").string()));
  std::filesystem::remove_all(folder);
}

// Any prefix of a valid drawing, and any bytes, read without a crash: either
// an error or a drawing.
RC_GTEST_PROP(SvgDrawing, AnyPrefixOrBytesReadWithoutACrash, ()) {
  const std::string valid =
      "<?xml version='1.0'?><svg xmlns='http://www.w3.org/2000/svg' width='10mm' height='10mm' viewBox='0 0 10 10'>"
      "<g transform='rotate(30 5 5) scale(0.5)'><rect x='1' y='1' width='8' height='8' rx='2'/>"
      "<path id='p' d='M1 1 C2 2 3 2 4 1 A3 2 30 1 0 8 8 Z'/><use href='#p' x='1'/></g>"
      "<polygon points='0,0 5,5 10,0'/></svg>";
  const auto cut = *rc::gen::inRange<std::size_t>(0, valid.size() + 1);
  auto drawing = parse_svg_drawing(valid.substr(0, cut), "t.svg", DrawingUnits::millimetres);
  if (cut == valid.size()) RC_ASSERT(drawing.has_value());
  const auto bytes = *rc::gen::container<std::string>(rc::gen::element<char>('<', '>', '/', '=', '\'', 'g', 's', 'v',
                                                                            ' ', 'd', 'M', '1', 'x', 'L', '#'));
  (void)parse_svg_drawing("<svg>" + bytes, "t.svg");
}

}  // namespace
}  // namespace casteljau

namespace casteljau {
namespace {

// Lines, quadratics and cubics written by write_svg_drawing read back as the
// same doubles, piece by piece (shortest round-trip numbers, absolute commands).
RC_GTEST_PROP(SvgWriter, PolynomialPiecesOfDegreeAtMostThreeRoundTripExactly, ()) {
  // Drawings above y = 0 (the page's bottom edge stays there: y in [230, 1770]).
  const int count = *rc::gen::inRange(1, 6);
  std::vector<BezierCurve> pieces;
  std::vector<double> start = {*rc::gen::inRange(-1000000, 1000000) * 1e-3,
                               1000.0 + *rc::gen::inRange(-1000000, 1000000) * 0.77e-3};
  for (int i = 0; i < count; ++i) {
    const int degree = *rc::gen::inRange(1, 4);
    std::vector<double> c = start;
    for (int k = 0; k < degree; ++k) {
      c.push_back(*rc::gen::inRange(-1000000, 1000000) * 1.37e-3);
      c.push_back(1000.0 + *rc::gen::inRange(-1000000, 1000000) * 0.77e-3);
    }
    start = {c[c.size() - 2], c.back()};
    pieces.push_back(BezierCurve::make(PointArray::make(2, std::move(c)).value()).value());
  }
  const std::vector<SvgCurve> curves{SvgCurve{PiecewiseBezierCurve::make(pieces).value(), false, "path", "c", 1,
                                              FillRule::nonzero, 1.0}};
  const auto written = write_svg_drawing(curves, Tolerance{1e-6});
  RC_ASSERT(written.has_value());
  RC_ASSERT(written->approximated_pieces == 0u);
  const auto back = parse_svg_drawing(written->text, "w.svg");
  RC_ASSERT(back.has_value());
  RC_ASSERT(back->problems.empty());
  RC_ASSERT(back->curves.size() == 1u);
  RC_ASSERT(back->curves[0].curve == curves[0].curve);
  RC_ASSERT(back->curves[0].id == std::string("c"));
}

TEST(SvgWriter, DrawingsAreWrittenUprightOnAPageFromYZero) {
  // Models are y up, SVG y down: the written file has -y, and its viewBox
  // reaches down to y = 0 (the page's bottom edge, where reading measures y
  // from) when no curve goes below it, else to the drawing's lowest point
  // less half the stroke.
  const auto written_box = [](double low, double high) {
    const std::vector<SvgCurve> curves{SvgCurve{
        PiecewiseBezierCurve::make({BezierCurve::make(PointArray::make({{1, low}, {3, high}}).value()).value()})
            .value(),
        false, "path", "", 0, FillRule::nonzero, 2.0}};
    const std::string text = write_svg_drawing(curves, Tolerance{1e-6}).value().text;
    const auto start = text.find("viewBox=\"") + 9;
    return std::make_pair(text.substr(start, text.find('"', start) - start), parse_svg_drawing(text, "w.svg").value());
  };
  const auto [above, read_above] = written_box(5, 8);
  EXPECT_EQ(above, "0 -9 4 9");  // x from 1 - 1, y from -(8 + 1) down to 0
  EXPECT_EQ(read_above.curves.at(0).curve.pieces()[0].control_points().coordinates()[1], 5.0);
  const auto [below, read_below] = written_box(-5, 8);
  EXPECT_EQ(below, "0 -9 4 15");  // down to -5 - 1: read back moved up by 6
  EXPECT_EQ(read_below.curves.at(0).curve.pieces()[0].control_points().coordinates()[1], 1.0);
  const auto [touching, read_touching] = written_box(0, 8);
  EXPECT_EQ(touching, "0 -9 4 9");  // a curve along y = 0 keeps the page's bottom there
  EXPECT_EQ(read_touching.curves.at(0).curve.pieces()[0].control_points().coordinates()[1], 0.0);
}

}  // namespace
}  // namespace casteljau

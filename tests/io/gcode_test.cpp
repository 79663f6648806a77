// G-code programs (io/gcode.hpp): the exact text of a small toolpath worked
// by hand (a line and a half circle: the order, the reversal, IJK from the
// written start, the feeds), arc centres, the radius rule after rounding
// (checked on the numbers as written, arcs of every size from seeded random
// data), tiny and flat arcs as chords, no whole circle, the rotation of
// closed contours, passes, inches, decimals, the dialects and the errors.
// The motion as an interpreter we did not write reads it: tests/gcode/.
#include "casteljau/io/gcode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/ops/arc_spline.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/version.hpp"
#include "io_test_support.hpp"
#include "support/make.hpp"

namespace casteljau {
namespace {

/// One motion line of a program: its G word and the values of its other words.
struct Block {
  int g = -1;
  double x = NAN, y = NAN, z = NAN, i = NAN, j = NAN, f = NAN;
};

using test::lines_of;
using test::points_of;

/// The motion blocks (G0-G3) of a program; comments and set-up skipped.
std::vector<Block> motion_of(const std::string& text) {
  std::vector<Block> blocks;
  for (const std::string& line : lines_of(text)) {
    if (line.empty() || line[0] != 'G') continue;
    std::istringstream words(line);
    Block block;
    for (std::string word; words >> word;) {
      const double value = std::strtod(word.c_str() + 1, nullptr);
      switch (word[0]) {
        case 'G': block.g = static_cast<int>(value); break;
        case 'X': block.x = value; break;
        case 'Y': block.y = value; break;
        case 'Z': block.z = value; break;
        case 'I': block.i = value; break;
        case 'J': block.j = value; break;
        case 'F': block.f = value; break;
        default: break;
      }
    }
    if (block.g >= 0 && block.g <= 3) blocks.push_back(block);
  }
  return blocks;
}

/// Every G2/G3's start and end radius from its written centre, the start
/// being the position the program's moves reached.
struct ArcRadii {
  double start, end;
};
std::vector<ArcRadii> arc_radii(const std::string& text) {
  std::vector<ArcRadii> radii;
  double x = 0, y = 0;
  for (const Block& b : motion_of(text)) {
    if (b.g >= 2) {
      const double cx = x + b.i, cy = y + b.j;
      radii.push_back({std::hypot(x - cx, y - cy), std::hypot(b.x - cx, b.y - cy)});
    }
    if (!std::isnan(b.x)) x = b.x;
    if (!std::isnan(b.y)) y = b.y;
  }
  return radii;
}

ArcSegment arc_through(Vec2 center, double radius, double from, double sweep) {
  const Vec2 start{{center[0] + radius * std::cos(from), center[1] + radius * std::sin(from)}};
  const Vec2 end{{center[0] + radius * std::cos(from + sweep), center[1] + radius * std::sin(from + sweep)}};
  return ArcSegment{start, end, std::tan(sweep / 4.0)};
}

Toolpath toolpath_of(std::vector<GcodeContour> contours, double tolerance = 0.01) {
  return Toolpath{std::move(contours), {"test"}, Tolerance{tolerance}};
}

GcodeProgram written(const Toolpath& toolpath, const GcodeOptions& options = {}) {
  auto program = write_gcode(toolpath, options);
  EXPECT_TRUE(program.has_value()) << program.error().message;
  return program ? *program : GcodeProgram{};
}

std::string error_of(const Toolpath& toolpath, const GcodeOptions& options) {
  auto program = write_gcode(toolpath, options);
  return program ? std::string("no error") : program.error().message;
}

// A line from (1, 2) to (4, 6) and the half circle from (10, 0) to (0, 0)
// turning left (bulge 1, centre (5, 0), through (5, 5)). From the origin the
// half circle's end is nearest (0 away): it is run reversed, clockwise, G2
// with I J = (5, 0) - (0, 0). The tool is then at (10, 0): the line's end
// (4, 6) is sqrt(72) away, its start sqrt(85): the line is run reversed too.
TEST(GcodeWriter, ALineAndAHalfCircleExactly) {
  const Toolpath toolpath =
      toolpath_of({{ArcSegment{{{1, 2}}, {{4, 6}}, 0.0}}, {ArcSegment{{{10, 0}}, {{0, 0}}, 1.0}}});
  const GcodeProgram program = written(toolpath);
  const std::string expected = std::string("(casteljau ") + CASTELJAU_VERSION_STRING +
                               ": RS-274/NGC program for GRBL)\n"
                               "(source: test)\n"
                               "(tolerance 0.01 mm: the path within it of the curves; the rounding of its numbers "
                               "to 4 decimals takes at most 0.0005 of it)\n"
                               "(units mm [G21], absolute [G90], XY plane [G17], feed per minute [G94])\n"
                               "(depth 1.0000 in 1 pass, safe height 5.0000, feed 600.0000, plunge feed 200.0000)\n"
                               "(2 contours: 1 arc [G2 G3], 1 line [G1])\n"
                               // The half circle reaches y = 5 at x = 5; the line's end (4, 6) is higher.
                               "(box of the cuts: X 0.0000 to 10.0000, Y 0.0000 to 6.0000)\n"
                               // 5 pi + 5 of cuts, two plunges of 6, rapid moves sqrt(72); in the
                               // input's order sqrt(5) to the line, then sqrt(72) from its end;
                               // (5 pi + 5) / 600 + 12 / 200 minutes: 5.67 s.
                               "(cuts 20.7080 mm, plunges 12.0000, rapid moves 8.4853 in the plane [10.7213 in the "
                               "input's order]; about 6 s at the feeds, rapid moves not counted)\n"
                               "G21 G90 G17 G94\n"
                               "G0 Z5.0000\n"
                               "G0 X0.0000 Y0.0000\n"
                               "G1 Z-1.0000 F200.0000\n"
                               "G2 X10.0000 Y0.0000 I5.0000 J0.0000 F600.0000\n"
                               "G0 Z5.0000\n"
                               "G0 X4.0000 Y6.0000\n"
                               "G1 Z-1.0000 F200.0000\n"
                               "G1 X1.0000 Y2.0000 F600.0000\n"
                               "G0 Z5.0000\n"
                               "M2\n";
  EXPECT_EQ(program.text, expected);
  EXPECT_EQ(program.arcs, 1u);
  EXPECT_EQ(program.lines, 1u);
  EXPECT_EQ(program.arcs_as_lines, 0u);
  EXPECT_EQ(program.contours, 2u);
  EXPECT_DOUBLE_EQ(program.rapid_length, 0.0 + std::sqrt(72.0));
  EXPECT_DOUBLE_EQ(program.rapid_length_unordered, std::sqrt(5.0) + std::sqrt(72.0));
  EXPECT_NEAR(program.cut_length, 5 * std::numbers::pi + 5, 1e-12);
  EXPECT_EQ(program.plunge_length, 12.0);
  EXPECT_EQ(program.decimals, 4);
}

// The decimals a tolerance needs: the unit's default until rounding (5 units
// of the last decimal) would take more than a tenth of the budget.
TEST(GcodeDecimals, TheFewestThatLeaveNineTenthsOfTheTolerance) {
  const auto decimals = [](double tolerance, GcodeUnits units, int requested = 0) {
    auto d = gcode_decimals(Tolerance{tolerance}, units, requested);
    return d ? *d : -1;
  };
  EXPECT_EQ(decimals(0.1, GcodeUnits::millimetres), 4);
  EXPECT_EQ(decimals(0.005, GcodeUnits::millimetres), 4);   // 5e-4 is a tenth of it
  EXPECT_EQ(decimals(0.0049, GcodeUnits::millimetres), 5);
  EXPECT_EQ(decimals(0.001, GcodeUnits::millimetres), 5);
  EXPECT_EQ(decimals(0.0001, GcodeUnits::millimetres), 6);
  EXPECT_EQ(decimals(0.001, GcodeUnits::inches), 5);
  EXPECT_EQ(decimals(1.0, GcodeUnits::inches), 5);
  EXPECT_EQ(decimals(1e-7, GcodeUnits::millimetres), 8);    // 5e-8: half of it, still under it
  EXPECT_EQ(decimals(0.01, GcodeUnits::millimetres, 7), 7);
  EXPECT_EQ(gcode_rounding_allowance(4), 5e-4);
  EXPECT_EQ(gcode_decimals(Tolerance{4e-8}, GcodeUnits::millimetres).error().message,
            "tolerance 4e-08 mm is below what 8 decimals can carry (rounding moves the path by up to 5e-08 mm)");
  EXPECT_EQ(gcode_decimals(Tolerance{0.0004}, GcodeUnits::millimetres, 4).error().message,
            "tolerance 0.0004 mm is not above what rounding to 4 decimals may move the path (0.0005 mm)");
  EXPECT_EQ(gcode_decimals(Tolerance{-1}, GcodeUnits::inches).error().message, "tolerance -1 is not a distance > 0");
}

// contour_of a curve spends the tolerance minus the rounding allowance: the
// exact half circle of radius 3 is one arc; a cubic's arcs and lines are
// within 0.01 - 0.0005 of it (fit_arcs' own bound says so).
TEST(GcodeContours, CurvesAreFittedWithinWhatTheRoundingLeaves) {
  const auto half = BezierCurve::make(points_of(2, {-3, 0, -3, 6, 3, 6, 3, 0}), std::vector<double>{1, 1.0 / 3, 1.0 / 3, 1});
  ASSERT_TRUE(half.has_value());
  auto arcs = contour_of(CurveView(*half), Tolerance{0.01}, 4, GcodeMotion::arcs);
  ASSERT_TRUE(arcs.has_value()) << arcs.error().message;
  EXPECT_EQ(arcs->size(), 1u);
  const auto cubic = BezierCurve::make(points_of(2, {0, 0, 10, 30, 20, -10, 30, 0}));
  ASSERT_TRUE(cubic.has_value());
  for (const GcodeMotion motion : {GcodeMotion::arcs, GcodeMotion::lines}) {
    auto contour = contour_of(CurveView(*cubic), Tolerance{0.01}, 4, motion);
    ASSERT_TRUE(contour.has_value());
    const auto fitted = motion == GcodeMotion::arcs ? fit_arcs(CurveView(*cubic), Tolerance{0.0095}).value().segments.size()
                                                    : flatten(CurveView(*cubic), Tolerance{0.0095}).value().points.size() - 1;
    EXPECT_EQ(contour->size(), fitted);
  }
  const auto space = BezierCurve::make(points_of(3, {0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(contour_of(CurveView(*space), Tolerance{0.01}, 4, GcodeMotion::arcs).error().message,
            "G-code cuts plane curves, this one lives in R^3");
  EXPECT_EQ(contour_of(CurveView(*cubic), Tolerance{0.0005}, 4, GcodeMotion::lines).error().message,
            "tolerance 0.0005 is not above what rounding to 4 decimals may move the path (0.0005)");
}

TEST(GcodeWriter, CentresInTheIjkFormFromTheStart) {
  // A quarter circle of radius 3 about (2, 1), from angle 0 counterclockwise
  // (G3, I J = (-3, 0)), then a quarter turning right (G2) about (2, 7).
  const GcodeContour contour{arc_through({{2, 1}}, 3, 0, std::numbers::pi / 2),
                             arc_through({{2, 7}}, 3, -std::numbers::pi / 2, -std::numbers::pi / 2)};
  const GcodeProgram program = written(toolpath_of({contour}));
  const auto blocks = motion_of(program.text);
  ASSERT_EQ(blocks.size(), 6u);  // G0 Z, G0 XY, G1 Z, the two arcs, G0 Z
  EXPECT_EQ(blocks[3].g, 3);
  EXPECT_EQ(blocks[3].x, 2.0);
  EXPECT_EQ(blocks[3].y, 4.0);
  EXPECT_EQ(blocks[3].i, -3.0);
  EXPECT_EQ(blocks[3].j, 0.0);
  EXPECT_EQ(blocks[4].g, 2);
  EXPECT_EQ(blocks[4].x, -1.0);
  EXPECT_EQ(blocks[4].y, 7.0);
  EXPECT_EQ(blocks[4].i, 0.0);
  EXPECT_EQ(blocks[4].j, 3.0);
  for (const std::string& line : lines_of(program.text)) {
    EXPECT_TRUE(line[0] == '(' || line.find('R') == std::string::npos) << line;  // never the R form
  }
}

TEST(GcodeWriter, StartAndEndRadiiAgreeAfterRoundingForArcsOfEverySize) {
  std::mt19937_64 random(18);  // fixed seed
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int decimals : {4, 5, 6}) {
    GcodeContour contour;
    Vec2 at{{0, 0}};
    for (int k = 0; k < 400; ++k) {
      const double radius = std::pow(10.0, -4.0 + 7.0 * unit(random));  // 1e-4 to 1e3
      const double sweep = (unit(random) < 0.5 ? -1 : 1) * (0.001 + 1.9 * std::numbers::pi * unit(random));
      const double from = 2 * std::numbers::pi * unit(random);
      const Vec2 center{{at[0] - radius * std::cos(from), at[1] - radius * std::sin(from)}};
      ArcSegment arc = arc_through(center, radius, from, sweep);
      arc.start = at;
      contour.push_back(arc);
      at = arc.end;
    }
    GcodeOptions options;
    options.decimals = decimals;
    const GcodeProgram program = written(toolpath_of({contour}, 1e-3), options);
    const auto radii = arc_radii(program.text);
    EXPECT_EQ(radii.size(), program.arcs);
    EXPECT_GT(program.arcs, 300u) << "most arcs stay arcs";
    for (const ArcRadii& r : radii) EXPECT_LE(std::abs(r.start - r.end), tolerances::kGcodeRadiusAgreement);
    // No whole circle: every arc's written end differs from its start.
    double x = NAN, y = NAN;
    for (const Block& b : motion_of(program.text)) {
      if (b.g >= 2) {
        EXPECT_FALSE(b.x == x && b.y == y);
      }
      if (!std::isnan(b.x)) x = b.x, y = b.y;
    }
  }
}

TEST(GcodeWriter, TinyArcsBecomeChordsWithinTheRounding) {
  // LinuxCNC refuses arcs of radius below 0.00127 mm as "zero-radius arcs"
  // (its rs274 found them at the head's tightest turns): below 0.00254 mm
  // the writer cuts chords instead. A half circle of radius 0.002 sags by
  // 20 units of the last decimal: halved three times, 8 chords, each within
  // the rounding allowance. One of radius 1e-5 ends where it starts once
  // rounded: no G2/G3 (a whole circle), nothing to cut.
  const GcodeProgram tiny = written(toolpath_of({{ArcSegment{{{0, 0}}, {{0.004, 0}}, 1.0}}}));
  EXPECT_EQ(tiny.arcs, 0u) << tiny.text;
  EXPECT_EQ(tiny.lines, 8u) << tiny.text;
  EXPECT_EQ(tiny.arcs_as_lines, 8u);
  for (const Block& b : motion_of(tiny.text)) {
    if (b.g == 1 && !std::isnan(b.x)) {
      EXPECT_LE(std::abs(std::hypot(b.x - 0.002, b.y) - 0.002), 0.71e-4 + 1e-12) << b.x << ' ' << b.y;
    }
  }
  // Radius 0.003 (above 0.00254): one arc.
  const GcodeProgram small = written(toolpath_of({{ArcSegment{{{0, 0}}, {{0.006, 0}}, 1.0}}}));
  EXPECT_EQ(small.arcs, 1u) << small.text;
  for (const ArcRadii& r : arc_radii(small.text)) EXPECT_LE(std::abs(r.start - r.end), tolerances::kGcodeRadiusAgreement);
  const GcodeProgram point = written(toolpath_of({{ArcSegment{{{0, 0}}, {{2e-5, 0}}, 1.0}}}));
  EXPECT_EQ(point.arcs + point.lines, 0u) << point.text;
}

/// An arc of radius r about (0.123, 0.456) from the angle 0.7 + k 1.37e-5
/// through `sweep` (the angles tried to find the cases below).
GcodeContour arc_about(double r, int k, double sweep) {
  return {arc_through({{0.123, 0.456}}, r, 0.7 + k * 0.0000137, sweep)};
}

TEST(GcodeWriter, NearlyStraightArcsWithoutAGoodCentreBecomeChords) {
  // Radius 100, sweep 0.001: the centre's position barely changes the
  // difference of the radii (its gradient is 2 sin(sweep / 2) = 0.001), so
  // when the rounding of the ends makes it 1e-4 or more no centre mends it;
  // the sagitta, 1.25e-5, is within the rounding: one G1 chord (found among
  // start angles near 0.7 by trying them; about 1 in 100 fails).
  const GcodeProgram program = written(toolpath_of({arc_about(100, 18, 0.001)}));
  EXPECT_EQ(program.arcs, 0u);
  EXPECT_EQ(program.arcs_as_lines, 1u);
  EXPECT_NE(program.text.find("\nG0 X76.5913 Y64.8966\nG1 Z-1.0000 F200.0000\nG1 X76.5269 Y64.9731 F600.0000\n"),
            std::string::npos)
      << program.text;
  EXPECT_NE(program.text.find("1 of them chords of arcs too small or flat for G2 G3 once rounded"), std::string::npos);
  // The same arc a little further on is an arc: the rule is met.
  EXPECT_EQ(written(toolpath_of({arc_about(100, 19, 0.001)})).arcs, 1u);
}

TEST(GcodeWriter, ArcsWithoutAGoodCentreAreHalvedUntilThePartsPass) {
  // Radius 1000, sweep 0.002: sagitta 5e-4, too large for a chord; halved,
  // one quarter a chord (sagitta 3.1e-5), the other parts arcs that pass.
  const GcodeProgram program = written(toolpath_of({arc_about(1000, 5981, 0.002)}));
  EXPECT_EQ(program.arcs, 2u);
  EXPECT_EQ(program.arcs_as_lines, 1u);
  EXPECT_EQ(program.lines, 1u);
  for (const ArcRadii& r : arc_radii(program.text)) EXPECT_LE(std::abs(r.start - r.end), tolerances::kGcodeRadiusAgreement);
}

TEST(GcodeWriter, FlatArcsBecomeChords) {
  // Radius 1.25e9 over a chord of 100, far beyond 1e4 x the drawing's size
  // (its centre beyond any machine): a G1, its sagitta 1e-6.
  const GcodeProgram program = written(toolpath_of({{ArcSegment{{{0, 1}}, {{100, 1}}, 2e-8}}}));
  EXPECT_EQ(program.arcs, 0u);
  EXPECT_EQ(program.arcs_as_lines, 1u);
  EXPECT_NE(program.text.find("G1 X100.0000 Y1.0000 F600.0000\n"), std::string::npos) << program.text;
}

TEST(GcodeWriter, ClosedContoursStartAtTheJointNearestTheTool) {
  // A square from (10, 10) counterclockwise; its corner (5, 5) is nearest to
  // the origin: the contour is rotated to start there and ends there.
  const GcodeContour square{ArcSegment{{{10, 10}}, {{5, 10}}, 0}, ArcSegment{{{5, 10}}, {{5, 5}}, 0},
                            ArcSegment{{{5, 5}}, {{10, 5}}, 0}, ArcSegment{{{10, 5}}, {{10, 10}}, 0}};
  const auto blocks = motion_of(written(toolpath_of({square})).text);
  ASSERT_EQ(blocks.size(), 8u);
  EXPECT_EQ(blocks[1].g, 0);
  EXPECT_EQ(blocks[1].x, 5.0);
  EXPECT_EQ(blocks[1].y, 5.0);
  const double corners[4][2] = {{10, 5}, {10, 10}, {5, 10}, {5, 5}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(blocks[3 + k].g, 1);
    EXPECT_EQ(blocks[3 + k].x, corners[k][0]);
    EXPECT_EQ(blocks[3 + k].y, corners[k][1]);
  }
  // A contour whose ends are only within the tolerance is closed too; its
  // gap is cut by a G1, here where the rotation put it, inside the contour.
  GcodeContour nearly = square;
  nearly.back().end = {{10, 10.005}};
  const auto gap = motion_of(written(toolpath_of({nearly})).text);
  ASSERT_EQ(gap.size(), 9u);
  EXPECT_EQ(gap[1].x, 5.0);
  EXPECT_EQ(gap[4].y, 10.005);  // the end of the last side, then the G1 to the first side's start
  EXPECT_EQ(gap[5].y, 10.0);
}

TEST(GcodeWriter, NearestNeighbourOrderShortensRapids) {
  // Four short lines along the x axis given in a scrambled order: cut from
  // the origin outwards, each entered at its end nearest the tool.
  std::vector<GcodeContour> contours;
  for (double x : {30.0, 10.0, 40.0, 20.0}) contours.push_back({ArcSegment{{{x + 5, 0}}, {{x, 0}}, 0}});
  const GcodeProgram program = written(toolpath_of(contours));
  std::vector<double> entries;
  for (const Block& b : motion_of(program.text))
    if (b.g == 0 && !std::isnan(b.x)) entries.push_back(b.x);
  EXPECT_EQ(entries, (std::vector<double>{10, 20, 30, 40}));
  EXPECT_DOUBLE_EQ(program.rapid_length, 10 + 5 + 5 + 5);
}

// 2-opt after nearest neighbour: 300 small closed squares at seeded random
// places in a 100 x 100 field (entry = exit, so the order is a path through
// points). The rapid moves are shorter than nearest neighbour's, computed
// here on its own, and than the input's order; every square is cut once.
TEST(GcodeWriter, TwoOptShortensTheNearestNeighbourOrder) {
  std::mt19937_64 random(20261206);
  std::uniform_real_distribution<double> place(0.0, 100.0);
  std::vector<GcodeContour> contours;
  std::vector<Vec2> corners;
  for (int k = 0; k < 300; ++k) {
    const Vec2 c{{std::round(place(random) * 100) / 100, std::round(place(random) * 100) / 100}};
    const Vec2 b = c + Vec2{{0.5, 0}}, d = c + Vec2{{0.5, 0.5}}, e = c + Vec2{{0, 0.5}};
    contours.push_back({ArcSegment{c, b, 0}, ArcSegment{b, d, 0}, ArcSegment{d, e, 0}, ArcSegment{e, c, 0}});
    corners.push_back(c);
  }
  // Nearest neighbour through the squares' joints (the writer's first step).
  double greedy = 0.0;
  Vec2 tool{};
  std::vector<bool> done(contours.size());
  for (std::size_t step = 0; step < contours.size(); ++step) {
    double best = INFINITY;
    std::size_t chosen = 0;
    Vec2 entry{};
    for (std::size_t k = 0; k < contours.size(); ++k)
      for (const ArcSegment& joint : contours[k])
        if (!done[k] && distance(tool, joint.start) < best) {
          best = distance(tool, joint.start);
          chosen = k;
          entry = joint.start;
        }
    done[chosen] = true;
    greedy += best;
    tool = entry;
  }
  const GcodeProgram program = written(toolpath_of(contours));
  std::cout << "[measured] 300 squares: rapid moves " << program.rapid_length_unordered << " in the input's order, "
            << greedy << " nearest neighbour, " << program.rapid_length << " after 2-opt\n";
  EXPECT_LT(program.rapid_length, greedy);
  EXPECT_LT(program.rapid_length, program.rapid_length_unordered);
  EXPECT_EQ(program.contours, 300u);
  std::size_t entries = 0;
  for (const Block& b : motion_of(program.text)) entries += b.g == 0 && !std::isnan(b.x);
  EXPECT_EQ(entries, 300u);
}

TEST(GcodeWriter, PassesDownToTheDepth) {
  // Depth 1 in steps of at most 0.4: three equal passes. The open line runs
  // back and forth, the closed triangle round again; 0.3 in steps of 0.1 is
  // three passes (not four, whatever 0.3 / 0.1 is in doubles).
  const GcodeContour line{ArcSegment{{{1, 0}}, {{2, 0}}, 0}};
  GcodeOptions options;
  options.step_down = 0.4;
  const GcodeProgram program = written(toolpath_of({line}), options);
  EXPECT_EQ(program.passes, 3);
  const std::string body = program.text.substr(program.text.find("\nG21 ") + 1);
  EXPECT_EQ(body,
            "G21 G90 G17 G94\n"
            "G0 Z5.0000\n"
            "G0 X1.0000 Y0.0000\n"
            "G1 Z-0.3333 F200.0000\n"
            "G1 X2.0000 Y0.0000 F600.0000\n"
            "G1 Z-0.6667 F200.0000\n"
            "G1 X1.0000 Y0.0000 F600.0000\n"
            "G1 Z-1.0000 F200.0000\n"
            "G1 X2.0000 Y0.0000 F600.0000\n"
            "G0 Z5.0000\n"
            "M2\n");
  EXPECT_NE(program.text.find("(depth 1.0000 in 3 passes,"), std::string::npos);
  const GcodeContour triangle{ArcSegment{{{0, 0}}, {{1, 0}}, 0}, ArcSegment{{{1, 0}}, {{0, 1}}, 0},
                              ArcSegment{{{0, 1}}, {{0, 0}}, 0}};
  options.depth = 0.3;
  options.step_down = 0.1;
  const GcodeProgram closed = written(toolpath_of({triangle}), options);
  EXPECT_EQ(closed.passes, 3);
  EXPECT_EQ(closed.lines, 9u);
  int plunges = 0;
  for (const Block& b : motion_of(closed.text)) plunges += b.g == 1 && !std::isnan(b.z);
  EXPECT_EQ(plunges, 3);
}

TEST(GcodeWriter, InchesWithTheirDefaults) {
  const GcodeContour line{ArcSegment{{{0.5, 0.25}}, {{1, 0.25}}, 0}};
  const GcodeProgram program = written(toolpath_of({line}, 0.001), default_gcode_options(GcodeUnits::inches));
  EXPECT_NE(program.text.find("(tolerance 0.001 inch:"), std::string::npos);
  EXPECT_NE(program.text.find("(units inch [G20],"), std::string::npos);
  EXPECT_NE(program.text.find("\nG20 G90 G17 G94\nG0 Z0.20000\nG0 X0.50000 Y0.25000\nG1 Z-0.04000 F8.00000\n"
                              "G1 X1.00000 Y0.25000 F24.00000\n"),
            std::string::npos)
      << program.text;
}

TEST(GcodeWriter, DecimalsAndNumbers) {
  // A centre offset of -4e-7 writes as 0.0000, never -0.0000; 6 decimals
  // when asked; no exponent even for the largest coordinates.
  const GcodeContour arc{ArcSegment{{{1, 0}}, {{-1, 0.0000004}}, 1.0}};
  const GcodeProgram four = written(toolpath_of({arc}));
  EXPECT_EQ(four.text.find("-0.0000"), std::string::npos) << four.text;
  EXPECT_NE(four.text.find("G3 X-1.0000 Y0.0000 I-1.0000 J0.0000"), std::string::npos) << four.text;
  GcodeOptions options;
  options.decimals = 6;
  const GcodeProgram six = written(toolpath_of({arc}), options);
  EXPECT_NE(six.text.find("G3 X-1.000000 Y0.000000 I-1.000000 J0.000000"), std::string::npos) << six.text;
  const GcodeContour far{ArcSegment{{{-999999.5, 0}}, {{999999.5, 0}}, 0}};
  const GcodeProgram large = written(toolpath_of({far}));
  // Both ends are as near the origin: either may be the entry.
  EXPECT_NE(large.text.find("X999999.5000 Y0.0000"), std::string::npos) << large.text;
  EXPECT_NE(large.text.find("X-999999.5000 Y0.0000"), std::string::npos) << large.text;
  for (const std::string& line : lines_of(large.text))
    if (line[0] == 'G') {
      EXPECT_EQ(line.find_first_of("eE"), std::string::npos) << line;
    }
}

TEST(GcodeWriter, Dialects) {
  const GcodeContour line{ArcSegment{{{0, 0}}, {{1, 0}}, 0}};
  const GcodeProgram grbl = written(toolpath_of({line}));
  EXPECT_EQ(grbl.text.find("G64"), std::string::npos);
  EXPECT_EQ(grbl.text.find("G91.1"), std::string::npos);
  EXPECT_EQ(grbl.text.find("G5"), std::string::npos);
  EXPECT_TRUE(grbl.text.ends_with("M2\n"));
  GcodeOptions options;
  options.dialect = GcodeDialect::linuxcnc;
  const GcodeProgram linuxcnc = written(toolpath_of({line}), options);
  EXPECT_NE(linuxcnc.text.find("\nG21 G90 G17 G94\nG91.1 G64 P0.0001\n"), std::string::npos) << linuxcnc.text;
  EXPECT_NE(linuxcnc.text.find("RS-274/NGC program for LinuxCNC"), std::string::npos);
  EXPECT_TRUE(linuxcnc.text.ends_with("M2\n"));
}

TEST(GcodeWriter, HeaderIsAsciiWithoutNestedParentheses) {
  Toolpath toolpath = toolpath_of({{ArcSegment{{{0, 0}}, {{1, 0}}, 0}}});
  toolpath.sources = {"dessin (copie) \xc3\xa9t\xc3\xa9.svg"};
  const GcodeProgram program = written(toolpath);
  EXPECT_NE(program.text.find("(source: dessin [copie] ??t??.svg)\n"), std::string::npos) << program.text;
  for (const std::string& line : lines_of(program.text)) {
    for (const char c : line) EXPECT_TRUE(c >= 0x20 && c < 0x7F) << line;
    if (line[0] == '(') {
      EXPECT_EQ(line.back(), ')');
      EXPECT_EQ(line.find_first_of("()", 1), line.size() - 1) << line;
    }
  }
}

TEST(GcodeWriter, ContoursOfPolylines) {
  Polyline plane{PointArray::from_trusted(2, {0, 0, 1, 0, 1, 1}), {0, 0.5, 1}};
  auto contour = contour_of(plane);
  ASSERT_TRUE(contour.has_value());
  ASSERT_EQ(contour->size(), 2u);
  EXPECT_EQ((*contour)[1].start, (Vec2{{1, 0}}));
  EXPECT_EQ((*contour)[1].bulge, 0.0);
  Polyline space{PointArray::from_trusted(3, {0, 0, 0, 1, 0, 1}), {0, 1}};
  auto refused = contour_of(space);
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().message, "G-code contours are plane, this polyline lives in R^3");
}

TEST(GcodeWriter, Errors) {
  const Toolpath toolpath = toolpath_of({{ArcSegment{{{0, 0}}, {{1, 0}}, 0}}});
  GcodeOptions options;
  options.decimals = 3;
  EXPECT_EQ(error_of(toolpath, options), "decimals 3 is outside 4..8");
  options.decimals = 9;
  EXPECT_EQ(error_of(toolpath, options), "decimals 9 is outside 4..8");
  options = {};
  options.depth = 0;
  EXPECT_EQ(error_of(toolpath, options), "depth 0 is not a length > 0 and at most 1000000");
  options = {};
  options.safe_height = -2;
  EXPECT_EQ(error_of(toolpath, options), "safe height -2 is not a length > 0 and at most 1000000");
  options = {};
  options.feed = NAN;
  EXPECT_EQ(error_of(toolpath, options), "feed nan is not a length > 0 and at most 1000000");
  options = {};
  options.step_down = -0.1;
  EXPECT_EQ(error_of(toolpath, options), "step down -0.1 is not a length >= 0 and at most 1000000");
  options = {};
  options.step_down = 1e-5;
  EXPECT_EQ(error_of(toolpath, options), "depth 1 in steps of 1e-05 takes more than 10000 passes");
  EXPECT_EQ(error_of(toolpath_of(toolpath.contours, 0), {}), "tolerance 0 is not a distance > 0");
  const Toolpath far = toolpath_of({{ArcSegment{{{0, 0}}, {{2e6, 0}}, 0}}});
  EXPECT_EQ(error_of(far, {}), "contour 1, segment 1: point (2000000, 0) is beyond the 1000000 a G-code coordinate may reach");
}

TEST(GcodeWriter, EmptyContoursAreLeftOut) {
  const GcodeProgram program = written(toolpath_of({{}, {ArcSegment{{{0, 0}}, {{1, 0}}, 0}}, {}}));
  EXPECT_EQ(program.contours, 1u);
  EXPECT_NE(program.text.find("(1 contour: 0 arcs [G2 G3], 1 line [G1])"), std::string::npos) << program.text;
}

// --origin: a quarter circle of radius 2 about (10, 20) from angle 0 to pi/2
// (box 10..12 x 20..22, its extreme points included) and a line below it.
TEST(GcodeWriter, OriginMovesTheBoxCornerOrCentreToZero) {
  const GcodeContour arc = {arc_through({{10, 20}}, 2.0, 0.0, std::numbers::pi / 2)};
  const GcodeContour line = {ArcSegment{{{9, 19}}, {{13, 19}}, 0.0}};
  GcodeOptions options;
  options.origin = GcodeOrigin::lower_left;
  const GcodeProgram corner = written(toolpath_of({arc, line}), options);
  EXPECT_NE(corner.text.find("(the drawing moved by X -9.0000 Y -19.0000: its box's lower-left corner at X0 Y0)"),
            std::string::npos) << corner.text;
  EXPECT_NE(corner.text.find("(box of the cuts: X 0.0000 to 4.0000, Y 0.0000 to 3.0000)"), std::string::npos);
  options.origin = GcodeOrigin::centre;
  const GcodeProgram centre = written(toolpath_of({arc, line}), options);
  EXPECT_NE(centre.text.find("(box of the cuts: X -2.0000 to 2.0000, Y -1.5000 to 1.5000)"), std::string::npos)
      << centre.text;
  // The same cuts, moved (the order may differ: it starts from the machine's zero).
  EXPECT_EQ(corner.arcs, centre.arcs);
  EXPECT_EQ(corner.lines, centre.lines);
  EXPECT_NEAR(corner.cut_length, centre.cut_length, 1e-12);
  EXPECT_NE(corner.text.find("G1 X4.0000 Y0.0000"), std::string::npos) << corner.text;  // the line's end (13, 19)
  EXPECT_EQ(written(toolpath_of({arc, line})).text.find("moved by"), std::string::npos);
}

// --- reading programs back (read_gcode) ------------------------------------------

// What write_gcode wrote of the line and the half circle, read back: the
// moves a controller makes, worked by hand from the program of
// ALineAndAHalfCircleExactly.
TEST(GcodeReader, ReadsBackWhatTheWriterWrote) {
  const Toolpath toolpath =
      toolpath_of({{ArcSegment{{{1, 2}}, {{4, 6}}, 0.0}}, {ArcSegment{{{10, 0}}, {{0, 0}}, 1.0}}});
  auto reading = read_gcode(written(toolpath).text);
  ASSERT_TRUE(reading.has_value()) << reading.error().message;
  EXPECT_EQ(reading->units, GcodeUnits::millimetres);
  using Kind = GcodeMove::Kind;
  const std::vector<std::pair<Kind, std::array<double, 3>>> expected = {
      {Kind::rapid, {0, 0, 5}},  {Kind::rapid, {0, 0, 5}},  {Kind::line, {0, 0, -1}},
      {Kind::clockwise_arc, {10, 0, -1}}, {Kind::rapid, {10, 0, 5}}, {Kind::rapid, {4, 6, 5}},
      {Kind::line, {4, 6, -1}},  {Kind::line, {1, 2, -1}},  {Kind::rapid, {1, 2, 5}}};
  ASSERT_EQ(reading->moves.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(reading->moves[k].kind, expected[k].first) << k;
    EXPECT_EQ(reading->moves[k].to, expected[k].second) << k;
    if (k > 0) {
      EXPECT_EQ(reading->moves[k].from, reading->moves[k - 1].to) << k;
    }
  }
  EXPECT_EQ(reading->moves[3].centre, (Vec2{{5, 0}}));
  EXPECT_EQ(reading->moves[3].line, 13u);  // 8 comment lines, the set-up, G0 Z, G0 X Y, G1 Z
}

TEST(GcodeReader, TheSubsetOfOtherPrograms) {
  // Inches, N words, ';' comments, lower case, modal motion, F S M3 ignored, M30 ends.
  auto reading = read_gcode("%\nN10 g20 g17 g90 (set-up)\nN20 M3 S12000\nG0 X1 Y1 ; to the start\nG1 Z-0.1 F10\n"
                            "X2\nG3 X3 Y2 J1\nM30\nG0 X9\n");
  ASSERT_TRUE(reading.has_value()) << reading.error().message;
  EXPECT_EQ(reading->units, GcodeUnits::inches);
  ASSERT_EQ(reading->moves.size(), 4u);
  EXPECT_EQ(reading->moves[2].kind, GcodeMove::Kind::line);
  EXPECT_EQ(reading->moves[2].to, (std::array<double, 3>{2, 1, -0.1}));
  EXPECT_EQ(reading->moves[3].kind, GcodeMove::Kind::counterclockwise_arc);
  EXPECT_EQ(reading->moves[3].centre, (Vec2{{2, 2}}));
}

TEST(GcodeReader, WhatItDoesNotReadIsRefusedWithItsLine) {
  const auto error_of_reading = [](const std::string& text) {
    auto reading = read_gcode(text);
    return reading ? std::string("no error") : reading.error().message;
  };
  EXPECT_EQ(error_of_reading("G21\nG91\nG1 X1"),
            "line 2: G91 is not read (read: G0 G1 G2 G3, G17, G20 G21, G90, G91.1, G94, G61, G64)");
  EXPECT_EQ(error_of_reading("G18"), "line 1: G18 is not read (read: G0 G1 G2 G3, G17, G20 G21, G90, G91.1, G94, G61, G64)");
  EXPECT_EQ(error_of_reading("G2 X1 Y1 R1"), "line 1: an arc in the R form is not read (only I J centres)");
  EXPECT_EQ(error_of_reading("G2 X1 Y1"), "line 1: an arc without its centre (I J)");
  EXPECT_EQ(error_of_reading("G1 X1 I2"), "line 1: I or J without an arc (G2 or G3)");
  EXPECT_EQ(error_of_reading("G1 X"), "line 1: X is not a word (a letter and a finite number)");
  EXPECT_EQ(error_of_reading("G1 X1.5.5"), "line 1: X1.5.5 is not a word (a letter and a finite number)");
  EXPECT_NE(error_of_reading("G1 X" + std::string(400, '9')).find("is not a word"), std::string::npos);  // infinite
  EXPECT_EQ(error_of_reading("G1 X1 (open"), "line 1: a comment '(' without its ')'");
  EXPECT_EQ(error_of_reading("G21 G1 X1\nG20"), "line 2: the units change after the first move");
  EXPECT_EQ(error_of_reading("M6 T1"), "line 1: M6 is not read (read: M2 M30, and M3 M4 M5 M7 M8 M9 ignored)");
  EXPECT_EQ(error_of_reading("G1 X1 #1"), "line 1: '#' where a word's letter belongs");
  EXPECT_EQ(error_of_reading("G1 X1 A2"), "line 1: the word A2 is not read");
}

}  // namespace
}  // namespace casteljau

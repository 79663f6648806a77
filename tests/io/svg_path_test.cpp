// SVG path data (io/svg_path.hpp): every command, absolute and relative,
// implicit repeats, the number and flag grammar, the reflections of S and T,
// closepath, arcs against SVG's own definition, and the error rule (what
// comes before the first error is kept). Expected control points are worked
// out by hand from SVG 1.1 §8.3; the arc reference is the spec's centre
// formulas (implementation notes B.2.4) written out plainly here.
#include "casteljau/io/svg_path.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/ops/arc_length.hpp"

namespace casteljau {
namespace {

/// The control points of piece `piece` of subpath `subpath`, flat.
std::vector<double> path_points(const SvgPathData& path, std::size_t subpath, std::size_t piece) {
  const auto& pieces = path.subpaths.at(subpath).curve.pieces();
  const auto coordinates = pieces.at(piece).control_points().coordinates();
  return {coordinates.begin(), coordinates.end()};
}

std::size_t pieces_of(const SvgPathData& path, std::size_t subpath) {
  return path.subpaths.at(subpath).curve.pieces().size();
}

SvgPathData read_path(std::string_view data) {
  SvgPathData path = read_svg_path(data);
  EXPECT_FALSE(path.error.has_value()) << data << ": " << path.error->message;
  return path;
}

using Flat = std::vector<double>;

TEST(SvgPath, LinesAbsoluteAndRelative) {
  const auto path = read_path("M10 20 L30 40 l5 -5 H0 h1 V2 v-2");
  ASSERT_EQ(path.subpaths.size(), 1u);
  ASSERT_EQ(pieces_of(path, 0), 6u);
  EXPECT_EQ(path_points(path, 0, 0), (Flat{10, 20, 30, 40}));
  EXPECT_EQ(path_points(path, 0, 1), (Flat{30, 40, 35, 35}));
  EXPECT_EQ(path_points(path, 0, 2), (Flat{35, 35, 0, 35}));
  EXPECT_EQ(path_points(path, 0, 3), (Flat{0, 35, 1, 35}));
  EXPECT_EQ(path_points(path, 0, 4), (Flat{1, 35, 1, 2}));
  EXPECT_EQ(path_points(path, 0, 5), (Flat{1, 2, 1, 0}));
  EXPECT_FALSE(path.subpaths[0].closed);
}

TEST(SvgPath, ImplicitRepeatsAfterAMovetoAreLinetos) {
  const auto absolute = read_path("M0 0 1 1 2 0");
  ASSERT_EQ(pieces_of(absolute, 0), 2u);
  EXPECT_EQ(path_points(absolute, 0, 1), (Flat{1, 1, 2, 0}));
  const auto relative = read_path("m1 1 2 2 1 0");  // a first m is relative to the origin
  ASSERT_EQ(pieces_of(relative, 0), 2u);
  EXPECT_EQ(path_points(relative, 0, 0), (Flat{1, 1, 3, 3}));
  EXPECT_EQ(path_points(relative, 0, 1), (Flat{3, 3, 4, 3}));
  const auto cubics = read_path("M0 0 c1 1 2 1 3 0 1 -1 2 -1 3 0");
  ASSERT_EQ(pieces_of(cubics, 0), 2u);
  EXPECT_EQ(path_points(cubics, 0, 1), (Flat{3, 0, 4, -1, 5, -1, 6, 0}));
}

TEST(SvgPath, NumbersAsTheGrammarReadsThem) {
  EXPECT_EQ(path_points(read_path("M1.5.5L-1e2-1E-1"), 0, 0), (Flat{1.5, 0.5, -100, -0.1}));
  EXPECT_EQ(path_points(read_path("M.5-.5L+1,+2"), 0, 0), (Flat{0.5, -0.5, 1, 2}));
  EXPECT_EQ(path_points(read_path("M0,0L1.e1,2E+1"), 0, 0), (Flat{0, 0, 10, 20}));
  EXPECT_EQ(path_points(read_path("\tM 0 0\n\r\fL 3 , 4 "), 0, 0), (Flat{0, 0, 3, 4}));
}

TEST(SvgPath, SmoothCubicsReflectThePreviousSecondControlPoint) {
  const auto path = read_path("M0 0 C1 2 3 2 4 0 S7 -2 8 0 s3 2 4 0");
  ASSERT_EQ(pieces_of(path, 0), 3u);
  EXPECT_EQ(path_points(path, 0, 1), (Flat{4, 0, 5, -2, 7, -2, 8, 0}));
  EXPECT_EQ(path_points(path, 0, 2), (Flat{8, 0, 9, 2, 11, 2, 12, 0}));
  // After another command the first control point is the current point.
  EXPECT_EQ(path_points(read_path("M0 0 L1 1 S2 2 3 3"), 0, 1), (Flat{1, 1, 1, 1, 2, 2, 3, 3}));
  EXPECT_EQ(path_points(read_path("M0 0 Q1 1 2 0 S3 1 4 0"), 0, 1), (Flat{2, 0, 2, 0, 3, 1, 4, 0}));
}

TEST(SvgPath, SmoothQuadraticsChainTheirReflections) {
  const auto path = read_path("M0 0 Q1 1 2 0 T4 0 t2 0");
  ASSERT_EQ(pieces_of(path, 0), 3u);
  EXPECT_EQ(path_points(path, 0, 0), (Flat{0, 0, 1, 1, 2, 0}));
  EXPECT_EQ(path_points(path, 0, 1), (Flat{2, 0, 3, -1, 4, 0}));
  EXPECT_EQ(path_points(path, 0, 2), (Flat{4, 0, 5, 1, 6, 0}));
  EXPECT_EQ(path_points(read_path("M0 0 L1 0 T2 2"), 0, 1), (Flat{1, 0, 1, 0, 2, 2}));
  EXPECT_EQ(path_points(read_path("M0 0 C1 1 2 1 3 0 T5 0"), 0, 1), (Flat{3, 0, 3, 0, 5, 0}));
}

TEST(SvgPath, ClosepathDrawsBackAndTheNextSubpathStartsThere) {
  const auto path = read_path("M0 0 L1 0 L1 1 Z L0 1 m2 2 l1 0 z");
  ASSERT_EQ(path.subpaths.size(), 3u);
  EXPECT_TRUE(path.subpaths[0].closed);
  ASSERT_EQ(pieces_of(path, 0), 3u);
  EXPECT_EQ(path_points(path, 0, 2), (Flat{1, 1, 0, 0}));
  EXPECT_FALSE(path.subpaths[1].closed);
  EXPECT_EQ(path_points(path, 1, 0), (Flat{0, 0, 0, 1}));
  // m after the open subpath is relative to its end (0, 1).
  EXPECT_EQ(path_points(path, 2, 0), (Flat{2, 3, 3, 3}));
  EXPECT_EQ(path_points(path, 2, 1), (Flat{3, 3, 2, 3}));
  // A closepath at the start point adds no line; a lone moveto draws nothing.
  const auto square = read_path("M0 0 H1 V1 H0 V0 Z M5 5");
  ASSERT_EQ(square.subpaths.size(), 1u);
  EXPECT_EQ(pieces_of(square, 0), 4u);
  EXPECT_TRUE(square.subpaths[0].closed);
  EXPECT_TRUE(read_path("").subpaths.empty());
  EXPECT_TRUE(read_path("  M1 2  ").subpaths.empty());
}

/// The largest |distance from `center` - radius| over samples of every piece.
double off_circle(const SvgSubpath& subpath, double cx, double cy, double radius) {
  double worst = 0.0;
  for (const BezierCurve& piece : subpath.curve.pieces()) {
    for (int k = 0; k <= 32; ++k) {
      const Point p = point_at(piece, k / 32.0);
      worst = std::max(worst, std::abs(std::hypot(p[0] - cx, p[1] - cy) - radius));
    }
  }
  return worst;
}

TEST(SvgPath, TheSpecificationsThreeQuarterArc) {
  // SVG 1.1 §8.3.8's arcs01: centre (300, 200), radius 150, large arc, sweep 0.
  const auto path = read_path("M300,200 h-150 a150,150 0 1,0 150,-150 z");
  ASSERT_EQ(path.subpaths.size(), 1u);
  const SvgSubpath& shape = path.subpaths[0];
  EXPECT_TRUE(shape.closed);
  ASSERT_EQ(pieces_of(path, 0), 5u);  // the line, three quarter arcs, the closing line
  SvgSubpath arc{PiecewiseBezierCurve::make({shape.curve.pieces()[1], shape.curve.pieces()[2],
                                             shape.curve.pieces()[3]}).value()};
  EXPECT_LE(off_circle(arc, 300, 200, 150), 1e-12 * 300);
  // Sweep 0 turns the negative way: from (150, 200) through (300, 350) and (450, 200).
  const auto joint = [&](std::size_t piece) { return path_points(path, 0, piece); };
  EXPECT_NEAR(joint(2)[0], 300, 1e-12 * 300);
  EXPECT_NEAR(joint(2)[1], 350, 1e-12 * 300);
  EXPECT_NEAR(joint(3)[0], 450, 1e-12 * 300);
  EXPECT_NEAR(joint(3)[1], 200, 1e-12 * 300);
  EXPECT_EQ(joint(1)[0], 150);  // the ends are the path's points exactly
  EXPECT_EQ(joint(3)[4], 300);
  EXPECT_EQ(joint(3)[5], 50);
  for (std::size_t p = 1; p <= 3; ++p)
    EXPECT_NEAR(shape.curve.pieces()[p].weights()[1], std::sqrt(0.5), 1e-15);
}

TEST(SvgPath, ArcFlagsNeedNoSeparatorsAndSmallRadiiGrow) {
  // rx = ry = 1 is too small for ends 10 apart: scaled to 5, a half circle
  // around (5, 0); sweep 1 turns the positive way, through (5, -5).
  const auto path = read_path("M0 0a1 1 0 1110 0");
  ASSERT_EQ(pieces_of(path, 0), 2u);
  EXPECT_LE(off_circle(path.subpaths[0], 5, 0, 5), 1e-12 * 10);
  const Flat middle = path_points(path, 0, 1);
  EXPECT_NEAR(middle[0], 5, 1e-14);
  EXPECT_NEAR(middle[1], -5, 1e-14);
  EXPECT_EQ(middle[4], 10);
  // Negative radii count by their size.
  EXPECT_EQ(path_points(read_path("M0 0a-1 -1 0 1110 0"), 0, 1), middle);
}

TEST(SvgPath, DegenerateArcs) {
  // A zero radius is a straight line; ends that coincide omit the arc.
  const auto line = read_path("M0 0 A0 5 0 0 1 10 0");
  ASSERT_EQ(pieces_of(line, 0), 1u);
  EXPECT_EQ(path_points(line, 0, 0), (Flat{0, 0, 10, 0}));
  const auto omitted = read_path("M0 0 A5 5 0 0 1 0 0 L1 1");
  ASSERT_EQ(pieces_of(omitted, 0), 1u);
  EXPECT_EQ(path_points(omitted, 0, 0), (Flat{0, 0, 1, 1}));
}

TEST(SvgPath, ArcsOfHugeRadiiKeepTheirSagittaAndTinyRadiiGrow) {
  // Issue 39: M0 0 A R R 0 0 1 10 0 put the middle of the arc 6e-5 off at
  // R = 1e12 (a centre 1e12 away rounds to 1e-4) and made a length of 16384
  // at R = 1e20. The arc bulges by the sagitta R - sqrt(R^2 - 25) =
  // 25 / (R + sqrt(R^2 - 25)) to the right of the chord (sweep 1: the
  // positive way), its length is 2 R asin(5 / R).
  for (const double r : {1e3, 1e10, 1e12, 1e15, 1e20, 1e99}) {
    const auto path = read_path(fmt::format("M0 0 A{0} {0} 0 0 1 10 0", r));
    ASSERT_EQ(pieces_of(path, 0), 1u) << r;
    const BezierCurve& arc = path.subpaths[0].curve.pieces()[0];
    const double sagitta = 25.0 / (r + std::sqrt(r * r - 25.0));
    const Point middle = point_at(arc, 0.5);
    EXPECT_NEAR(middle[0], 5.0, 1e-15 * 5.0) << r;
    EXPECT_NEAR(middle[1], -sagitta, 1e-13 * sagitta) << r;
    const double length = arc_length(arc, Tolerance{1e-12}).value();
    EXPECT_NEAR(length, 2.0 * r * std::asin(5.0 / r), 2e-12) << r;
  }
  // The same arc the other way bulges to the left.
  const auto left = read_path("M0 0 A1e12 1e12 0 0 0 10 0");
  EXPECT_NEAR(point_at(left.subpaths[0].curve.pieces()[0], 0.5)[1], 1.25e-11, 1e-24);
  // An ellipse of radii 1e12 and 3e12 turned by 30 degrees, the chord of 10
  // along its first axis: near the end of its second axis the ellipse falls
  // away from the chord by 3e12 (1 - sqrt(1 - 25 / 1e24)), to the chord's
  // right (sin 30, -cos 30); the chord's end is 30 degrees to rounding
  // (1e-16 of 10), which leaves the sagitta right to ~1e-5.
  const auto tilted = read_path("M0 0 A1e12 3e12 30 0 1 8.660254037844387 5");
  ASSERT_EQ(pieces_of(tilted, 0), 1u);
  const Point bulge = point_at(tilted.subpaths[0].curve.pieces()[0], 0.5);
  const double ellipse_sagitta = 3e12 * (25.0 / 1e24) / (1.0 + std::sqrt(1.0 - 25.0 / 1e24));
  const double along = (bulge[0] - 4.330127018922193) * std::sqrt(0.75) + (bulge[1] - 2.5) * 0.5;
  const double across = (bulge[0] - 4.330127018922193) * 0.5 - (bulge[1] - 2.5) * std::sqrt(0.75);
  EXPECT_NEAR(along, 0.0, 1e-14);
  EXPECT_NEAR(across, ellipse_sagitta, 1e-4 * ellipse_sagitta);
  // Radii of 1e-160 and below (their squares underflow; 5e-324 is the least
  // double) grow to the half circle of radius 5 around (5, 0), through (5, -5).
  for (const char* r : {"1e-160", "1e-300", "5e-324"}) {
    const auto path = read_path(fmt::format("M0 0 A{0} {0} 0 0 1 10 0", r));
    ASSERT_FALSE(path.error.has_value()) << r << ": " << path.error->message;
    ASSERT_EQ(pieces_of(path, 0), 2u) << r;
    EXPECT_LE(off_circle(path.subpaths[0], 5, 0, 5), 1e-12 * 10) << r;
    const Flat joint = path_points(path, 0, 1);
    EXPECT_NEAR(joint[0], 5, 1e-14) << r;
    EXPECT_NEAR(joint[1], -5, 1e-14) << r;
  }
}

/// SVG's centre parameterization (implementation notes B.2.4 and B.2.5),
/// written out with the spec's own unnormalized formulas.
struct Ellipse {
  double cx, cy, rx, ry, phi, theta, delta;
};
Ellipse reference_arc(double x1, double y1, double rx, double ry, double degrees, bool fa, bool fs, double x2,
                      double y2) {
  const double phi = degrees * std::numbers::pi / 180.0, c = std::cos(phi), s = std::sin(phi);
  const double xp = c * (x1 - x2) / 2 + s * (y1 - y2) / 2, yp = -s * (x1 - x2) / 2 + c * (y1 - y2) / 2;
  rx = std::abs(rx), ry = std::abs(ry);
  const double lambda = xp * xp / (rx * rx) + yp * yp / (ry * ry);
  if (lambda >= 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
  const double num = rx * rx * ry * ry - rx * rx * yp * yp - ry * ry * xp * xp;
  const double den = rx * rx * yp * yp + ry * ry * xp * xp;
  // Radii scaled to fit make the radicand 0 exactly (rounding would leave
  // noise whose square root moves the centre).
  double root = lambda >= 1 ? 0.0 : std::sqrt(std::max(0.0, num / den));
  if (fa == fs) root = -root;
  const double cxp = root * rx * yp / ry, cyp = -root * ry * xp / rx;
  const double cx = c * cxp - s * cyp + (x1 + x2) / 2, cy = s * cxp + c * cyp + (y1 + y2) / 2;
  const auto angle = [](double ux, double uy, double vx, double vy) {
    const double a = std::acos(std::clamp((ux * vx + uy * vy) / std::hypot(ux, uy) / std::hypot(vx, vy), -1.0, 1.0));
    return ux * vy - uy * vx < 0 ? -a : a;
  };
  const double theta = angle(1, 0, (xp - cxp) / rx, (yp - cyp) / ry);
  double delta = std::fmod(angle((xp - cxp) / rx, (yp - cyp) / ry, (-xp - cxp) / rx, (-yp - cyp) / ry),
                           2 * std::numbers::pi);
  if (!fs && delta > 0) delta -= 2 * std::numbers::pi;
  if (fs && delta < 0) delta += 2 * std::numbers::pi;
  return {cx, cy, rx, ry, phi, theta, delta};
}

RC_GTEST_PROP(SvgPath, ArcsLieOnSvgsEllipseAndTurnAsTheFlagsSay, ()) {
  const auto coordinate = [] { return *rc::gen::inRange(-1000, 1001) / 10.0; };
  const double x1 = coordinate(), y1 = coordinate(), x2 = coordinate(), y2 = coordinate();
  RC_PRE(std::hypot(x2 - x1, y2 - y1) > 1.0);
  const double rx = *rc::gen::inRange(1, 2000) / 10.0, ry = *rc::gen::inRange(1, 2000) / 10.0;
  const double degrees = *rc::gen::inRange(-720, 721) / 2.0;
  const bool fa = *rc::gen::arbitrary<bool>(), fs = *rc::gen::arbitrary<bool>();
  const std::string data = fmt::format("M{} {} A{} {} {} {} {} {} {}", x1, y1, rx, ry, degrees, fa ? 1 : 0,
                                       fs ? 1 : 0, x2, y2);
  const auto path = read_svg_path(data);
  RC_ASSERT(!path.error.has_value());
  RC_ASSERT(path.subpaths.size() == 1u);
  const Ellipse e = reference_arc(x1, y1, rx, ry, degrees, fa, fs, x2, y2);
  const double size = std::max({std::abs(x1), std::abs(y1), std::abs(x2), std::abs(y2), e.rx, e.ry});
  // Every point is on the ellipse, and the parametric angle moves as the
  // sweep flag says, over the reference's total turn.
  double turned = 0.0, previous = e.theta;
  const auto& pieces = path.subpaths[0].curve.pieces();
  for (const BezierCurve& piece : pieces) {
    for (int k = 1; k <= 16; ++k) {
      const Point p = point_at(piece, k / 16.0);
      const double dx = p[0] - e.cx, dy = p[1] - e.cy;
      const double u = (std::cos(e.phi) * dx + std::sin(e.phi) * dy) / e.rx;
      const double v = (-std::sin(e.phi) * dx + std::cos(e.phi) * dy) / e.ry;
      RC_ASSERT(std::abs(std::hypot(u, v) - 1.0) <= 1e-9 * size / std::min(e.rx, e.ry));
      double step = std::atan2(v, u) - previous;
      step = std::remainder(step, 2 * std::numbers::pi);
      RC_ASSERT((fs ? step >= -1e-9 : step <= 1e-9));
      turned += step;
      previous = std::atan2(v, u);
    }
  }
  RC_ASSERT(std::abs(turned - e.delta) <= 1e-6);
  const auto first = pieces.front().control_points()[0];
  RC_ASSERT(first[0] == x1 && first[1] == y1);
}

TEST(SvgPathErrors, EverythingBeforeTheFirstErrorIsKept) {
  const auto cut = read_svg_path("M0 0 L1 1 L2");
  ASSERT_EQ(cut.subpaths.size(), 1u);
  EXPECT_EQ(pieces_of(cut, 0), 1u);
  ASSERT_TRUE(cut.error.has_value());
  EXPECT_EQ(cut.error->message, "path data, at its end: expected a number, 'L' takes x y");
  EXPECT_EQ(cut.error->kind, ErrorKind::parse);
  // An incomplete implicit repeat is its own segment: the complete one stays.
  const auto repeat = read_svg_path("M0 0 L1 1 2");
  EXPECT_EQ(pieces_of(repeat, 0), 1u);
  EXPECT_EQ(repeat.error->message, "path data, at its end: expected a number, 'L' takes x y");
  const auto later = read_svg_path("M0 0 L1 1 Z M5 5 L6 6 x L7 7");
  ASSERT_EQ(later.subpaths.size(), 2u);
  EXPECT_EQ(later.error->message,
            "path data, character 23 ('x'): expected a command letter (M L H V C S Q T A Z, or m l h ...)");
}

TEST(SvgPathErrors, EachMistakeNamesItsPlace) {
  const auto message = [](std::string_view data) {
    const auto path = read_svg_path(data);
    return path.error ? path.error->message : std::string("(no error)");
  };
  EXPECT_EQ(message("L0 0"), "path data, character 1 ('L'): path data must begin with a moveto, 'M' or 'm'");
  EXPECT_EQ(message("M0 0 L nan 0"), "path data, character 8 ('n'): expected a number, 'L' takes x y");
  EXPECT_EQ(message("M0 0 L1e999 0"), "path data, character 7 ('1'): '1e999' overflows to infinity, numbers must be finite");
  EXPECT_EQ(message("M 1e101 0"), "path data, character 3 ('1'): '1e101' is beyond 1e+100, the largest coordinate casteljau takes");
  EXPECT_EQ(message("M0 0 A1 1 0 2 0 1 1"),
            "path data, character 13 ('2'): expected a flag (0 or 1), 'A' takes rx ry x-axis-rotation "
            "large-arc-flag sweep-flag x y");
  // A comma after the last number of a command is read past, as Chromium does.
  EXPECT_EQ(message("M0 0 L1,1, L2 2"), "(no error)");
  EXPECT_EQ(pieces_of(read_svg_path("M0 0 L1,1, L2 2"), 0), 2u);
  EXPECT_EQ(message("M0 0 L1,1,,L2 2"),
            "path data, character 11 (','): expected a command letter (M L H V C S Q T A Z, or m l h ...)");
  EXPECT_EQ(message("M0 0 Z 1 1"),
            "path data, character 8 ('1'): expected a command letter (M L H V C S Q T A Z, or m l h ...)");
  EXPECT_EQ(message("M,0 0"), "path data, character 2 (','): expected a number, 'M' takes x y");
  EXPECT_EQ(message("M0 0 L1 1\x01"),
            "path data, character 10 (byte 0x01): expected a command letter (M L H V C S Q T A Z, or m l h ...)");
  // A relative step past the largest coordinate is refused at its segment.
  const auto far = read_svg_path("M0 0 l1e100 0 l1e100 0");
  EXPECT_EQ(pieces_of(far, 0), 1u);
  ASSERT_TRUE(far.error.has_value());
  EXPECT_EQ(far.error->message.substr(0, 29), "path data, character 15 ('l')");
}

RC_GTEST_PROP(SvgPathErrors, AnyBytesGiveValidSubpathsOrAnError, ()) {
  const std::string alphabet = "MmLlHhVvCcSsQqTtAaZz0123456789.,-+eE \n";
  const auto length = *rc::gen::inRange(0, 80);
  std::string data;
  for (int i = 0; i < length; ++i)
    data += *rc::gen::oneOf(rc::gen::elementOf(alphabet), rc::gen::arbitrary<char>());
  const auto path = read_svg_path(data);
  for (const SvgSubpath& subpath : path.subpaths) {
    RC_ASSERT(!subpath.curve.pieces().empty());
    RC_ASSERT(subpath.curve.dimension() == 2);
  }
}

}  // namespace
}  // namespace casteljau

// DXF drawings (io/dxf.hpp): each curve entity read exactly (values worked by
// hand from the DXF reference: ARC angles counter-clockwise in degrees, bulge
// = tan(θ/4), the arbitrary axis algorithm for extrusion (0, 0, -1)), the
// plane/space choice, $INSUNITS, the file's errors with their line and the
// entity problems, and the writer's round trip (the same doubles back).
// ezdxf's own reading and writing are compared in tests/python/test_dxf_ezdxf.py.
#include "casteljau/io/dxf.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "io_test_support.hpp"

namespace casteljau {
namespace {

/// A DXF file of the entities' group lines ("0\nLINE\n10\n1\n..."), in ENTITIES.
std::string dxf(const std::string& entities, const std::string& header = "") {
  return "0\nSECTION\n2\nHEADER\n" + header + "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" + entities +
         "0\nENDSEC\n0\nEOF\n";
}

DxfDrawing read_dxf(const std::string& text) {
  auto drawing = parse_dxf_drawing(text, "t.dxf");
  EXPECT_TRUE(drawing.has_value()) << drawing.error().message;
  if (!drawing) return {};
  for (const Error& problem : drawing->problems) ADD_FAILURE() << problem.message;
  return std::move(*drawing);
}

void expect_point(const Point& p, std::vector<double> expected, double tolerance = 1e-14) {
  ASSERT_EQ(p.size(), expected.size());
  for (std::size_t k = 0; k < p.size(); ++k) EXPECT_NEAR(p[k], expected[k], tolerance) << "coordinate " << k;
}

TEST(DxfRead, LinesInThePlaneAndInSpace) {
  const auto plane = read_dxf(dxf("0\nLINE\n5\n1F\n8\nparts\n10\n1\n20\n2\n11\n4\n21\n6\n"));
  ASSERT_EQ(plane.curves.size(), 1u);
  EXPECT_EQ(plane.curves[0].entity, "LINE");
  EXPECT_EQ(plane.curves[0].handle, "1F");
  EXPECT_EQ(plane.curves[0].layer, "parts");
  EXPECT_EQ(dimension_of(plane.curves[0].curve), 2);  // every z is 0
  expect_point(point_at(curve_view(plane.curves[0].curve), 0.5), {2.5, 4});
  const auto space = read_dxf(dxf("0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n0\nLINE\n10\n0\n20\n0\n30\n1\n11\n1\n21\n0\n"));
  ASSERT_EQ(space.curves.size(), 2u);
  EXPECT_EQ(dimension_of(space.curves[0].curve), 3);  // one z is not 0: all in R^3
}

TEST(DxfRead, ArcsRunCounterClockwiseFromStartToEndAngle) {
  // Centre (1, 2), radius 2, from 90 to 180 degrees: (1, 4) to (-1, 2).
  const auto drawing = read_dxf(dxf("0\nARC\n10\n1\n20\n2\n40\n2\n50\n90\n51\n180\n"
                                      "0\nARC\n10\n0\n20\n0\n40\n1\n50\n270\n51\n45\n"));
  ASSERT_EQ(drawing.curves.size(), 2u);
  const CurveView quarter = curve_view(drawing.curves[0].curve);
  expect_point(point_at(quarter, 0.0), {1, 4});
  expect_point(point_at(quarter, 1.0), {-1, 2});
  const Point middle = point_at(quarter, 0.5);
  EXPECT_NEAR(std::hypot(middle[0] - 1, middle[1] - 2), 2.0, 1e-15);
  // 270 to 45 crosses 0: a sweep of 135 degrees, ending at (√½, √½).
  const CurveView crossing = curve_view(drawing.curves[1].curve);
  expect_point(point_at(crossing, 0.0), {0, -1});
  expect_point(point_at(crossing, 1.0), {std::sqrt(0.5), std::sqrt(0.5)});
}

// Issue 42 (the dxf fuzzer): an ARC from 4e21 to 210 degrees. The sweep was
// the remainder of their difference, in which 210 is lost to rounding; the
// start angle in radians, 7e19, kept nothing either: four pieces each running
// out and back along one chord (and 4 s in the self-intersection search).
// Each angle is reduced modulo 360 on its own, exactly.
TEST(DxfRead, HugeArcAnglesAreReducedExactly) {
  // 45 * 2^63 degrees is 2^60 turns: the arc runs from 0 to 90 degrees.
  const double turns = std::ldexp(45.0, 63);
  const auto drawing = read_dxf(dxf(fmt::format("0\nARC\n10\n0\n20\n0\n40\n1\n50\n{}\n51\n90\n"
                                                  "0\nELLIPSE\n10\n0\n20\n0\n11\n2\n21\n0\n40\n0.5\n41\n{}\n42\n{}\n",
                                                  turns, 1e21 * std::numbers::pi, 1e21 * std::numbers::pi)));
  ASSERT_EQ(drawing.curves.size(), 2u);
  const CurveView quarter = curve_view(drawing.curves[0].curve);
  expect_point(point_at(quarter, 0.0), {1, 0});
  expect_point(point_at(quarter, 1.0), {0, 1});
  // Equal start and end parameters, however large: the whole ellipse.
  const CurveView whole = curve_view(drawing.curves[1].curve);
  const Point start = point_at(whole, 0.0), end = point_at(whole, 1.0);
  EXPECT_NEAR(std::hypot(start[0] - end[0], start[1] - end[1]), 0.0, 1e-15);
  EXPECT_NEAR(point_at(whole, 0.5)[0], -start[0], 1e-14);  // the opposite point halfway
}

TEST(DxfRead, ExtrusionDownwardsMirrorsX) {
  // Arbitrary axis algorithm for N = (0, 0, -1): Ax = (-1, 0, 0), Ay = (0, 1, 0).
  const auto drawing = read_dxf(dxf("0\nCIRCLE\n10\n3\n20\n0\n40\n1\n210\n0\n220\n0\n230\n-1\n"));
  const CurveView circle = curve_view(drawing.curves.at(0).curve);
  expect_point(point_at(circle, 0.0), {-4, 0});  // OCS (3 + 1, 0) is WCS (-4, 0)
  const Point quarter = point_at(circle, 0.25);
  expect_point(quarter, {-3, 1});
}

TEST(DxfRead, EllipsesAndTheirArcs) {
  // Centre (0, 0), major axis (4, 0), ratio 0.5: minor axis (0, 2); from 0 to π/2.
  const auto drawing = read_dxf(dxf(fmt::format("0\nELLIPSE\n10\n0\n20\n0\n11\n4\n21\n0\n40\n0.5\n41\n0\n42\n{}\n",
                                                  std::numbers::pi / 2)));
  const CurveView arc = curve_view(drawing.curves.at(0).curve);
  expect_point(point_at(arc, 0.0), {4, 0});
  expect_point(point_at(arc, 1.0), {0, 2}, 1e-14);
  for (int k = 0; k <= 16; ++k) {
    const Point p = point_at(arc, k / 16.0);
    EXPECT_NEAR(std::hypot(p[0] / 4, p[1] / 2), 1.0, 1e-15);
  }
}

TEST(DxfRead, PolylineBulgesAreExactArcs) {
  // Bulge 1 from (0, 0) to (2, 0): a half circle of radius 1 about (1, 0),
  // counter-clockwise, so through (1, -1); then a line back, closed.
  const auto drawing =
      read_dxf(dxf("0\nLWPOLYLINE\n90\n2\n70\n1\n10\n0\n20\n0\n42\n1\n10\n2\n20\n0\n"));
  const auto& curve = std::get<PiecewiseBezierCurve>(drawing.curves.at(0).curve);
  const CurveView view(curve);
  expect_point(point_at(view, 0.0), {0, 0});
  const Interval domain = view.domain();
  double lowest = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double u = domain.lower + (domain.upper - domain.lower) * k / 200;
    const Point p = point_at(view, u);
    if (p[1] < 0) {
      EXPECT_NEAR(std::hypot(p[0] - 1, p[1]), 1.0, 1e-15);
    }
    lowest = std::min(lowest, p[1]);
  }
  EXPECT_NEAR(lowest, -1.0, 1e-3);
  expect_point(point_at(view, domain.upper), {0, 0});  // closed: back to the first vertex
  // The old POLYLINE with VERTEX entities, the same half circle, and a 3D one.
  const auto old = read_dxf(dxf("0\nPOLYLINE\n66\n1\n10\n0\n20\n0\n30\n0\n0\nVERTEX\n10\n0\n20\n0\n42\n1\n"
                                  "0\nVERTEX\n10\n2\n20\n0\n0\nSEQEND\n"
                                  "0\nPOLYLINE\n66\n1\n70\n8\n0\nVERTEX\n10\n0\n20\n0\n30\n1\n70\n32\n"
                                  "0\nVERTEX\n10\n1\n20\n1\n30\n2\n70\n32\n0\nSEQEND\n"));
  ASSERT_EQ(old.curves.size(), 2u);
  EXPECT_EQ(dimension_of(old.curves[1].curve), 3);
  expect_point(point_at(curve_view(old.curves[1].curve), 1.0), {1, 1, 2});
}

TEST(DxfRead, SplinesWithControlPointsKnotsAndWeights) {
  const BSplineCurve circle = make_circle(0.0, 0.0, 2.0).value();
  std::string entity = "0\nSPLINE\n70\n12\n71\n2\n72\n12\n73\n9\n";
  for (double k : circle.knots()) entity += fmt::format("40\n{}\n", k);
  for (double w : circle.weights()) entity += fmt::format("41\n{}\n", w);
  for (std::size_t i = 0; i < circle.control_points().size(); ++i)
    entity += fmt::format("10\n{}\n20\n{}\n30\n0\n", circle.control_points()[i][0], circle.control_points()[i][1]);
  const auto drawing = read_dxf(dxf(entity));
  EXPECT_EQ(std::get<BSplineCurve>(drawing.curves.at(0).curve), circle);  // exactly the curve written
}

TEST(DxfRead, SplinesWithFitPointsOnlyPassThroughThem) {
  const auto drawing = read_dxf(dxf("0\nSPLINE\n71\n3\n74\n5\n11\n0\n21\n0\n11\n1\n21\n2\n11\n3\n21\n3\n"
                                      "11\n5\n21\n1\n11\n6\n21\n-1\n"));
  const auto& spline = std::get<BSplineCurve>(drawing.curves.at(0).curve);
  expect_point(point_at(spline, spline.knots().front()), {0, 0});
  expect_point(point_at(spline, spline.knots().back()), {6, -1}, 1e-13);
}

// A fit-point spline in space with both end tangents (groups 11/21/31,
// 12/22/32, 13/23/33): the cubic through the fit points at their chord-length
// parameters (worked here from the points), leaving along the start tangent
// and arriving along the end tangent, each scaled to the total chord length.
TEST(DxfRead, SplinesWithFitPointsAndEndTangentsInSpace) {
  const std::vector<std::array<double, 3>> fit = {{0, 0, 0}, {1, 2, 1}, {3, 3, 0}, {5, 1, 2}, {6, -1, 1}};
  std::string entity = "0\nSPLINE\n71\n3\n74\n5\n12\n0\n22\n3\n32\n4\n13\n2\n23\n0\n33\n0\n";
  for (const auto& q : fit) entity += fmt::format("11\n{}\n21\n{}\n31\n{}\n", q[0], q[1], q[2]);
  const auto drawing = read_dxf(dxf(entity));
  const auto& spline = std::get<BSplineCurve>(drawing.curves.at(0).curve);
  std::vector<double> chords{0.0};
  for (std::size_t i = 1; i < fit.size(); ++i)
    chords.push_back(chords.back() + std::hypot(fit[i][0] - fit[i - 1][0], fit[i][1] - fit[i - 1][1],
                                                fit[i][2] - fit[i - 1][2]));
  const double total = chords.back();
  for (std::size_t i = 0; i < fit.size(); ++i)
    expect_point(point_at(spline, chords[i] / total), {fit[i][0], fit[i][1], fit[i][2]}, 1e-13);
  // (0, 3, 4) has length 5, (2, 0, 0) length 2: unit directions times the chord length.
  expect_point(derivative_at(spline, 0.0, 1), {0, 0.6 * total, 0.8 * total}, 1e-12);
  expect_point(derivative_at(spline, 1.0, 1), {total, 0, 0}, 1e-12);
}

// Every number every entity reads is checked: a value that is not a number
// in any of its groups makes that entity a problem naming the entity, the
// line and the group, and the drawing keeps its other entities.
TEST(DxfRead, EveryNumberOfEveryEntityIsCheckedAndNamed) {
  const std::vector<std::string> entities = {
      "0\nLINE\n10\n0\n20\n0\n30\n0\n11\n1\n21\n1\n31\n0\n",
      "0\nCIRCLE\n10\n1\n20\n2\n30\n0\n40\n3\n",
      "0\nARC\n10\n1\n20\n2\n30\n0\n40\n3\n50\n10\n51\n80\n",
      "0\nELLIPSE\n10\n0\n20\n0\n30\n0\n11\n4\n21\n0\n31\n0\n210\n0\n220\n0\n230\n1\n40\n0.5\n41\n0\n42\n1\n",
      "0\nLWPOLYLINE\n38\n0\n70\n1\n10\n0\n20\n0\n42\n0.5\n10\n4\n20\n0\n10\n4\n20\n3\n",
      "0\nPOLYLINE\n66\n1\n70\n0\n10\n0\n20\n0\n30\n0\n0\nVERTEX\n70\n0\n10\n1\n20\n1\n42\n0.25\n"
      "0\nVERTEX\n70\n0\n10\n3\n20\n2\n0\nSEQEND\n",
      "0\nSPLINE\n70\n8\n71\n1\n40\n0\n40\n0\n40\n1\n40\n1\n41\n1\n41\n2\n10\n0\n20\n0\n30\n0\n10\n1\n20\n1\n30\n0\n",
      "0\nSPLINE\n71\n3\n11\n0\n21\n0\n31\n0\n11\n1\n21\n2\n31\n0\n11\n3\n21\n3\n31\n1\n"
      "12\n1\n22\n0\n32\n0\n13\n1\n23\n0\n33\n0\n"};
  const std::string other = "0\nLINE\n10\n7\n20\n7\n11\n8\n21\n8\n";
  int checked = 0;
  for (const std::string& entity : entities) {
    ASSERT_EQ(read_dxf(dxf(entity)).curves.size(), 1u) << entity;  // as written, it reads
    // Each value line of a numeric group, in turn, replaced by "x".
    std::vector<std::string> lines;
    for (std::size_t start = 0; start < entity.size();) {
      const std::size_t end = entity.find('\n', start);
      lines.push_back(entity.substr(start, end - start));
      start = end + 1;
    }
    for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
      const int code = std::stoi(lines[i]);
      if (code == 0 || code == 66) continue;  // 66 ("vertices follow") is not read: the VERTEX entities say it
      std::string broken;
      for (std::size_t k = 0; k < lines.size(); ++k) broken += (k == i + 1 ? std::string("x") : lines[k]) + "\n";
      auto drawing = parse_dxf_drawing(dxf(broken + other), "t.dxf");
      ASSERT_TRUE(drawing.has_value()) << drawing.error().message;
      EXPECT_EQ(drawing->problems.size(), 1u) << broken;
      if (drawing->problems.size() != 1u) continue;
      const std::string& message = drawing->problems[0].message;
      const std::string name = lines[1];
      EXPECT_EQ(message.rfind("t.dxf, line 11, " + name, 0), 0u) << message;
      const bool named = message.find(fmt::format("group {}: 'x' is not a number", code)) != std::string::npos ||
                         message.find("the extrusion direction (210, 220, 230)") != std::string::npos;
      EXPECT_TRUE(named) << "group " << code << ": " << message;
      ASSERT_EQ(drawing->curves.size(), 1u) << message;  // the other line is kept
      EXPECT_EQ(drawing->curves[0].entity, "LINE");
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);
}

// Issue 42 (the dxf fuzzer, UBSan): an LWPOLYLINE whose flags (70) were
// 3.3e65 was cast to int, which is undefined. Flags, unit codes and the
// spline degree are whole numbers within int's range, or the entity (the
// file, for $INSUNITS) is refused, naming the group.
TEST(DxfRead, WholeNumberGroupsRefuseFractionsAndHugeValues) {
  auto drawing = parse_dxf_drawing(
      dxf("0\nLWPOLYLINE\n70\n3.3e65\n10\n0\n20\n0\n10\n1\n20\n0\n"
          "0\nPOLYLINE\n70\n1.5\n0\nVERTEX\n10\n0\n20\n0\n0\nSEQEND\n"
          "0\nSPLINE\n71\n3e65\n40\n0\n40\n0\n40\n1\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n"
          "0\nLWPOLYLINE\n70\n-1\n10\n0\n20\n0\n10\n1\n20\n0\n"),
      "t.dxf");
  ASSERT_TRUE(drawing.has_value()) << drawing.error().message;
  ASSERT_EQ(drawing->problems.size(), 3u);
  EXPECT_EQ(drawing->problems[0].message,
            "t.dxf, line 11, LWPOLYLINE: line 14, group 70: 3.3e65 is not a whole number within +-2147483647");
  EXPECT_EQ(drawing->problems[1].message,
            "t.dxf, line 23, POLYLINE: line 26, group 70: 1.5 is not a whole number within +-2147483647");
  EXPECT_EQ(drawing->problems[2].message.rfind("t.dxf, line 35, SPLINE: the degree (71) must be a whole number in 1..", 0),
            0u)
      << drawing->problems[2].message;
  EXPECT_EQ(drawing->curves.size(), 1u);  // -1 has every bit set: a closed polyline
  auto units = parse_dxf_drawing(dxf("", "9\n$INSUNITS\n70\n1e20\n"), "t.dxf");
  ASSERT_FALSE(units.has_value());
  EXPECT_EQ(units.error().message, "t.dxf: line 8, group 70: 1e20 is not a whole number within +-2147483647");
}

TEST(DxfRead, HeaderUnitsAndSkippedEntities) {
  const auto drawing = read_dxf(dxf("0\nTEXT\n1\nhello\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n0\n",
                                      "9\n$ACADVER\n1\nAC1015\n9\n$INSUNITS\n70\n4\n"));
  EXPECT_EQ(drawing.insunits, 4);
  ASSERT_EQ(drawing.skipped.size(), 1u);
  EXPECT_EQ(drawing.skipped[0], "line 19: TEXT");
}

TEST(DxfRead, TheUnitAFileStatesIsKeptWithItsModels) {
  // read_file_models (io/model_file.hpp): a DXF's own $INSUNITS, 4 when
  // read in millimetres (then scaled), 0 for files that state no unit.
  const test::TemporaryFolder folder;
  const std::string line = "0\nLINE\n10\n0\n20\n0\n11\n3\n21\n4\n";
  test::write_text(folder / "inches.dxf", dxf(line, "9\n$INSUNITS\n70\n1\n"));
  test::write_text(folder / "plain.dxf", dxf(line));
  test::write_text(folder / "page.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='10mm' height='10mm'><path d='M0 0H1'/></svg>");
  test::write_text(folder / "model.json", "{\"type\": \"bezier\", \"control_points\": [[0, 0], [1, 1]]}");
  EXPECT_EQ(read_file_models(folder / "inches.dxf").value().insunits, 1);
  const FileModels millimetres = read_file_models(folder / "inches.dxf", DrawingUnits::millimetres).value();
  EXPECT_EQ(millimetres.insunits, 4);
  EXPECT_EQ(std::get<BezierCurve>(millimetres.models.at(0)).control_points()[1][1], 4 * 25.4);
  EXPECT_EQ(read_file_models(folder / "plain.dxf").value().insunits, 0);
  EXPECT_EQ(read_file_models(folder / "page.svg").value().insunits, 0);
  EXPECT_EQ(read_file_models(folder / "page.svg", DrawingUnits::millimetres).value().insunits, 4);
  EXPECT_EQ(read_file_models(folder / "model.json").value().insunits, 0);
  EXPECT_EQ(dxf_unit_millimetres(2), 304.8);
  EXPECT_EQ(dxf_unit_name(6), "metres");
  EXPECT_EQ(dxf_unit_millimetres(15), 1e4);
  EXPECT_EQ(dxf_unit_millimetres(21), 0.0);  // no unit code of DXF
  EXPECT_EQ(dxf_unit_name(21), "unit code 21");
}

// Every $INSUNITS code (Autodesk's DXF reference, HEADER section) against the
// unit's definition, not against the table: an inch is 25.4 mm, a foot 12
// inches, a yard 3 feet, a mile 5280 feet, a mil and a microinch 10^-3 and
// 10^-6 inch; the metric units are powers of ten of the metre; the astronomical
// unit is 149 597 870 700 m (IAU 2012), the light year c times 365.25 days of
// 86 400 s (c = 299 792 458 m/s), the parsec 648 000 / pi au (IAU 2015).
TEST(DxfRead, EveryUnitCodeHasTheScaleOfItsDefinition) {
  const double inch = 25.4, foot = 12 * inch;
  const struct {
    int code;
    double millimetres;
    const char* name;
  } units[] = {{1, inch, "inches"}, {2, foot, "feet"}, {3, 5280 * foot, "miles"}, {4, 1.0, "millimetres"},
               {5, 10.0, "centimetres"}, {6, 1e3, "metres"}, {7, 1e6, "kilometres"}, {8, inch * 1e-6, "microinches"},
               {9, inch * 1e-3, "mils"}, {10, 3 * foot, "yards"}, {11, 1e-7, "angstroms"}, {12, 1e-6, "nanometres"},
               {13, 1e-3, "microns"}, {14, 100.0, "decimetres"}, {15, 1e4, "decametres"}, {16, 1e5, "hectometres"},
               {17, 1e12, "gigametres"}, {18, 149597870700.0 * 1e3, "astronomical units"},
               {19, 299792458.0 * 365.25 * 86400 * 1e3, "light years"},
               {20, 648000 / std::numbers::pi * 149597870700.0 * 1e3, "parsecs"}};
  for (const auto& unit : units) {
    EXPECT_NEAR(dxf_unit_millimetres(unit.code), unit.millimetres, 1e-15 * unit.millimetres) << unit.name;
    EXPECT_EQ(dxf_unit_name(unit.code), unit.name);
  }
  EXPECT_EQ(dxf_unit_millimetres(0), 0.0);  // unitless: no scale
  EXPECT_EQ(dxf_unit_name(0), "no unit");
  EXPECT_EQ(dxf_unit_millimetres(-1), 0.0);
  EXPECT_EQ(dxf_unit_name(-1), "unit code -1");
}

TEST(DxfRead, FileErrorsNameTheirLine) {
  const auto message = [](const std::string& text) {
    auto drawing = parse_dxf_drawing(text, "t.dxf");
    return drawing ? std::string("(read)") : drawing.error().message;
  };
  EXPECT_EQ(message("0\nSECTION\nSECTION\n"), "t.dxf, line 3: 'SECTION' is not a group code (a whole number); a "
                                              "DXF file alternates code and value lines");
  EXPECT_EQ(message("0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n"),
            "t.dxf, line 7: the file ends after group code 10, before its value");
  EXPECT_EQ(message("0\nSECTION\n2\nENTITIES\n0\nLINE\n"),
            "t.dxf, line 1: the ENTITIES section has no ENDSEC (the file is cut short)");
  EXPECT_EQ(message("0\nSECTION\n2\nENTITIES\n0\nENDSEC\n"), "t.dxf: the file ends without EOF (it is cut short, or not DXF)");
  EXPECT_EQ(message(std::string("AutoCAD Binary DXF\r\n\x1a\0", 23)),
            "t.dxf: a binary DXF, casteljau reads ASCII DXF (save as ASCII)");
  auto bad = parse_dxf_drawing(dxf("0\nLINE\n5\nA1\n10\nnan\n0\nCIRCLE\n10\n0\n20\n0\n40\n-1\n"), "t.dxf");
  ASSERT_TRUE(bad);
  ASSERT_EQ(bad->problems.size(), 2u);
  EXPECT_EQ(bad->problems[0].message, "t.dxf, line 11, LINE (handle A1): line 16, group 10: 'nan' is NaN, numbers must be finite");
  EXPECT_EQ(bad->problems[1].message, "t.dxf, line 17, CIRCLE: the radius must be > 0, got -1");
}

TEST(DxfWrite, RoundTripsTheSameDoubles) {
  std::vector<Model> models{make_circle(1.0, -2.0, 0.3).value(),
                            BezierCurve::make(PointArray::make(3, {0.1, 0.2, 0.3, 1, 2, 3, -4, 5, 0.7}).value(),
                                              {1.0, 2.5, 0.5})
                                .value(),
                            BezierCurve::make(PointArray::make(2, {0, 0, 1, 1, 2, 0, 3, 1}).value()).value()};
  const std::string text = write_dxf_drawing(models, 4).value();
  EXPECT_NE(text.find("AC1015"), std::string::npos);
  const auto back = read_dxf(text);
  EXPECT_EQ(back.insunits, 4);
  ASSERT_EQ(back.curves.size(), 3u);
  // The drawing holds a 3D curve, so all read back in R^3; the plane ones with z = 0.
  EXPECT_EQ(to_json(back.curves[1].curve), to_json(to_bspline(models[1]).value()));
  const auto& circle = std::get<BSplineCurve>(back.curves[0].curve);
  EXPECT_EQ(circle.knots().size(), std::get<BSplineCurve>(models[0]).knots().size());
  for (std::size_t i = 0; i < circle.control_points().size(); ++i) {
    EXPECT_EQ(circle.control_points()[i][0], std::get<BSplineCurve>(models[0]).control_points()[i][0]);
    EXPECT_EQ(circle.control_points()[i][2], 0.0);
  }
  const std::vector<Model> plane{models[0], models[2]};
  const auto flat = read_dxf(write_dxf_drawing(plane).value());
  EXPECT_EQ(to_json(flat.curves[0].curve), to_json(models[0]));
  EXPECT_EQ(to_json(flat.curves[1].curve), to_json(to_bspline(models[2]).value()));
}

TEST(DxfWrite, RefusesWhatDxfCannotHold) {
  const std::vector<Model> line4{BezierCurve::make(PointArray::make(4, {0, 0, 0, 0, 1, 1, 1, 1}).value()).value()};
  EXPECT_EQ(write_dxf_drawing(line4).error().message, "curve 0 lives in R^4, DXF holds plane and space curves");
}

// Any bytes, and any prefix of a valid file, read without a crash.
RC_GTEST_PROP(DxfRead, AnyBytesOrPrefixReadWithoutACrash, ()) {
  const std::string valid =
      dxf("0\nLWPOLYLINE\n90\n3\n70\n1\n10\n0\n20\n0\n42\n0.5\n10\n2\n20\n0\n10\n1\n20\n1\n42\n-2\n"
          "0\nSPLINE\n71\n2\n40\n0\n40\n0\n40\n0\n40\n1\n40\n1\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n10\n2\n20\n0\n"
          "0\nELLIPSE\n10\n0\n20\n0\n11\n1\n21\n0\n40\n0.5\n");
  const auto cut = *rc::gen::inRange<std::size_t>(0, valid.size() + 1);
  auto drawing = parse_dxf_drawing(valid.substr(0, cut), "t.dxf");
  if (cut == valid.size()) {
    RC_ASSERT(drawing.has_value());
    RC_ASSERT(drawing->problems.empty());
    RC_ASSERT(drawing->curves.size() == 3u);
  }
  const auto bytes = *rc::gen::container<std::string>(
      rc::gen::element<char>('0', '1', '2', '4', '\n', ' ', 'S', 'E', 'C', 'T', 'I', 'O', 'N', 'L', '-', '.'));
  (void)parse_dxf_drawing("0\nSECTION\n2\nENTITIES\n" + bytes, "t.dxf");
}

}  // namespace
}  // namespace casteljau

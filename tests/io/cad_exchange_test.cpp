// IGES and STEP files (io/cad_exchange.hpp): the record structure each
// specification requires (IGES 5.3 section 2: 80 columns, section letters and
// sequence numbers, Directory Entry pointers, the Terminate counts; ISO
// 10303-21: header, numbered instances, every reference defined), the
// parameters of one small curve worked by hand from IGES 5.3 4.23 and ISO
// 10303-42, the number and string forms, and the errors. Whether readers
// accept the files: tests/exchange/occt_exchange_test.cpp (OpenCASCADE).
#include "casteljau/io/cad_exchange.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "io_test_support.hpp"

namespace casteljau {
namespace {

ExchangeHeader fixed_header() {
  ExchangeHeader header;
  header.file_name = "part.igs";
  header.timestamp = "2026-12-04T09:05:03";
  header.author = "A. Student";
  return header;
}

using test::lines_of;

/// Columns 1-72 of the records of one section without their trailing blanks, joined.
std::string section_data(const std::vector<std::string>& lines, char section) {
  std::string out;
  for (const std::string& line : lines)
    if (line[72] == section) {
      const std::string data = line.substr(0, 72);
      out += data.substr(0, data.find_last_not_of(' ') + 1);
    }
  return out;
}

Model parabola() {
  // The quadratic Bézier (0,0) (1,2) (2,0): on clamped knots 0 0 0 1 1 1.
  return Model{BezierCurve::make(PointArray::make(2, {0, 0, 1, 2, 2, 0}).value()).value()};
}

TEST(Iges, EveryRecordHasEightyColumnsItsSectionAndItsSequenceNumber) {
  const std::vector<Model> models = {parabola(), Model{make_circle(0, 0, 2).value()},
                                     Model{make_sphere({0, 0, 0}, 1.0).value()}};
  const auto text = write_iges(models, fixed_header());
  ASSERT_TRUE(text.has_value()) << text.error().message;
  const auto lines = lines_of(*text);
  std::string order;
  int counts[5] = {0, 0, 0, 0, 0};
  const std::string letters = "SGDPT";
  for (const std::string& line : lines) {
    ASSERT_EQ(line.size(), 80u) << line;
    const auto section = letters.find(line[72]);
    ASSERT_NE(section, std::string::npos) << line;
    EXPECT_EQ(std::stoi(line.substr(73)), ++counts[section]) << line;
    if (order.empty() || order.back() != line[72]) order += line[72];
  }
  EXPECT_EQ(order, "SGDPT");  // each section once, in this order
  EXPECT_EQ(counts[2], 6);     // two Directory Entry records per entity
  EXPECT_EQ(lines.back().substr(0, 32),
            fmt::format("S{:>7}G{:>7}D{:>7}P{:>7}", counts[0], counts[1], counts[2], counts[3]));
}

TEST(Iges, DirectoryEntriesPointAtTheirParametersAndBack) {
  const std::vector<Model> models = {parabola(), Model{make_sphere({0, 0, 0}, 1.0).value()}};
  const auto lines = lines_of(write_iges(models, fixed_header()).value());
  std::vector<std::string> directory, parameters;
  for (const std::string& line : lines) {
    if (line[72] == 'D') directory.push_back(line);
    if (line[72] == 'P') parameters.push_back(line);
  }
  ASSERT_EQ(directory.size(), 4u);
  for (std::size_t e = 0; e < 2; ++e) {
    const std::string& first = directory[2 * e];
    const std::string& second = directory[2 * e + 1];
    const int type = std::stoi(first.substr(0, 8));
    EXPECT_EQ(type, e == 0 ? 126 : 128);
    EXPECT_EQ(std::stoi(second.substr(0, 8)), type);
    EXPECT_EQ(first.substr(64, 8), "00000000");  // status: independent geometry
    const int start = std::stoi(first.substr(8, 8));
    const int count = std::stoi(second.substr(24, 8));
    EXPECT_EQ(second.substr(56, 8), e == 0 ? "   CURVE" : " SURFACE");
    // Its Parameter Data records point back at the first Directory record (2e + 1).
    for (int k = start; k < start + count; ++k)
      EXPECT_EQ(std::stoi(parameters[static_cast<std::size_t>(k - 1)].substr(65, 7)), static_cast<int>(2 * e + 1));
    // They begin with the type and end with the record delimiter.
    EXPECT_EQ(parameters[static_cast<std::size_t>(start - 1)].substr(0, 4), std::to_string(type) + ",");
    const std::string last = parameters[static_cast<std::size_t>(start + count - 2)].substr(0, 64);
    EXPECT_EQ(last.substr(last.find_last_not_of(' '), 1), ";");
  }
}

TEST(Iges, TheCurvesParametersWorkedByHand) {
  // Entity 126 (IGES 5.3, 4.23): K = 2 (three points), M = 2, planar, open,
  // polynomial, not periodic; knots T(-2)..T(3); weights; points; V(0), V(1);
  // the plane's normal (0, 0, 1).
  const auto lines = lines_of(write_iges(std::vector<Model>{parabola()}, fixed_header()).value());
  std::string data;
  for (const std::string& line : lines)
    if (line[72] == 'P') data += line.substr(0, 64);
  data.erase(std::remove(data.begin(), data.end(), ' '), data.end());
  EXPECT_EQ(data, "126,2,2,1,0,1,0,0.,0.,0.,1.,1.,1.,1.,1.,1.,0.,0.,0.,1.,2.,0.,2.,0.,0.,0.,1.,0.,0.,1.;");
}

TEST(Iges, TheGlobalSectionStatesUnitsDateAndVersion) {
  auto header = fixed_header();
  const auto mm = section_data(lines_of(write_iges(std::vector<Model>{parabola()}, header).value()), 'G');
  EXPECT_NE(mm.find("1H,,1H;,8Hpart.igs,8Hpart.igs,"), std::string::npos) << mm;
  EXPECT_NE(mm.find(",1.,2,2HMM,1,"), std::string::npos) << mm;
  EXPECT_NE(mm.find("15H20261204.090503"), std::string::npos) << mm;
  EXPECT_NE(mm.find("10HA. Student,0H,11,0,15H20261204.090503;"), std::string::npos) << mm;
  header.unit = ExchangeUnit::inch;
  const auto inch = section_data(lines_of(write_iges(std::vector<Model>{parabola()}, header).value()), 'G');
  EXPECT_NE(inch.find(",1.,1,4HINCH,1,"), std::string::npos) << inch;
}

TEST(Step, TheFileIsAnExchangeStructureWithEveryReferenceDefined) {
  const std::vector<Model> models = {parabola(), Model{make_circle(0, 0, 2).value()},
                                     Model{make_sphere({0, 0, 0}, 1.0).value()}};
  const auto text = write_step(models, fixed_header());
  ASSERT_TRUE(text.has_value()) << text.error().message;
  EXPECT_EQ(text->substr(0, 21), "ISO-10303-21;\nHEADER;");
  EXPECT_NE(text->find("FILE_NAME('part.igs','2026-12-04T09:05:03',('A. Student'),(''),"), std::string::npos);
  EXPECT_NE(text->find("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));"), std::string::npos);
  EXPECT_EQ(text->substr(text->size() - 26), "ENDSEC;\nEND-ISO-10303-21;\n");
  // Instances #1..#n in order, each referring only to defined ones.
  const std::regex instance(R"(^#(\d+)=(.*);$)"), reference(R"(#(\d+))");
  std::set<int> defined;
  std::vector<int> referenced;
  int expected = 1;
  for (const std::string& line : lines_of(*text)) {
    std::smatch m;
    if (!std::regex_match(line, m, instance)) continue;
    EXPECT_EQ(std::stoi(m[1]), expected++);
    defined.insert(std::stoi(m[1]));
    const std::string body = m[2];
    for (auto it = std::sregex_iterator(body.begin(), body.end(), reference); it != std::sregex_iterator(); ++it)
      referenced.push_back(std::stoi((*it)[1]));
  }
  for (int r : referenced) EXPECT_TRUE(defined.count(r)) << "#" << r << " is referred to but not defined";
  // One polynomial curve, one rational curve, one rational surface, in a surface representation.
  EXPECT_NE(text->find("=B_SPLINE_CURVE_WITH_KNOTS('model 0',2,("), std::string::npos);
  EXPECT_NE(text->find("RATIONAL_B_SPLINE_CURVE("), std::string::npos);
  EXPECT_NE(text->find("RATIONAL_B_SPLINE_SURFACE("), std::string::npos);
  EXPECT_NE(text->find("=GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION("), std::string::npos);
  EXPECT_NE(text->find("SI_UNIT(.MILLI.,.METRE.)"), std::string::npos);
}

TEST(Step, TheCurveWorkedByHand) {
  // ISO 10303-42 b_spline_curve_with_knots: degree 2, three points, open,
  // knots 0 and 1 of multiplicity 3; a curve set in a wireframe representation.
  const auto text = write_step(std::vector<Model>{parabola()}, fixed_header()).value();
  EXPECT_NE(text.find("CARTESIAN_POINT('',(0.,0.,0.));\n"), std::string::npos);
  EXPECT_NE(text.find("CARTESIAN_POINT('',(1.,2.,0.));\n"), std::string::npos);
  EXPECT_NE(text.find("B_SPLINE_CURVE_WITH_KNOTS('model 0',2,(#"), std::string::npos);
  EXPECT_NE(text.find("),.UNSPECIFIED.,.F.,.U.,(3,3),(0.,1.),.UNSPECIFIED.);"), std::string::npos);
  EXPECT_NE(text.find("=GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('part.igs',(#"), std::string::npos);
  EXPECT_NE(text.find("=GEOMETRIC_CURVE_SET('',(#"), std::string::npos);
}

TEST(Step, StringsAreEscapedAndNonAsciiEncoded) {
  auto header = fixed_header();
  header.file_name = "tête d'Hélène\\π😀.stp";
  const auto text = write_step(std::vector<Model>{parabola()}, header).value();
  EXPECT_NE(text.find("FILE_NAME('t\\X2\\00EA\\X0\\te d''H\\X2\\00E9\\X0\\l\\X2\\00E8\\X0\\ne\\\\\\X2\\03C0\\X0\\"
                      "\\X4\\0001F600\\X0\\.stp',"),
            std::string::npos)
      << text.substr(0, 400);
}

TEST(Exchange, NumbersHaveADecimalPointAndReadBackAsTheSameDouble) {
  // Through the files: a control point of each kind of number.
  const auto curve = BezierCurve::make(PointArray::make(2, {-0.0, 1e-5, 1.0 / 3.0, 2.5e99, 7, -1e-300}).value());
  const auto text = write_step(std::vector<Model>{Model{*curve}}, fixed_header()).value();
  EXPECT_NE(text.find("CARTESIAN_POINT('',(0.,1.E-05,0.));"), std::string::npos);
  EXPECT_NE(text.find("CARTESIAN_POINT('',(0.3333333333333333,2.5E+99,0.));"), std::string::npos);
  EXPECT_NE(text.find("CARTESIAN_POINT('',(7.,-1.E-300,0.));"), std::string::npos);
}

TEST(Exchange, Errors) {
  const ExchangeHeader header = fixed_header();
  EXPECT_EQ(write_iges(std::vector<Model>{}, header).error().message, "no models to write: IGES needs at least one curve or surface");
  const Model space4{BezierCurve::make(PointArray::make(4, {0, 0, 0, 0, 1, 1, 1, 1}).value()).value()};
  EXPECT_EQ(write_step(std::vector<Model>{parabola(), space4}, header).error().message,
            "model 1 (bezier) lives in R^4, STEP holds plane and space geometry");
  const Model point{BezierCurve::make(PointArray::make(2, {1, 2}).value()).value()};
  EXPECT_EQ(write_iges(std::vector<Model>{point}, header).error().message,
            "model 0 (bezier) has degree 0 (steps, not a curve); IGES B-splines have degree >= 1");
  ExchangeHeader undated = header;
  undated.timestamp = "4 Dec 2026";
  EXPECT_EQ(write_iges(std::vector<Model>{parabola()}, undated).error().message,
            "the timestamp '4 Dec 2026' is not of the form YYYY-MM-DDTHH:MM:SS");
  EXPECT_EQ(write_step(std::vector<Model>{parabola()}, undated).error().message,
            "the timestamp '4 Dec 2026' is not of the form YYYY-MM-DDTHH:MM:SS");
}

}  // namespace
}  // namespace casteljau

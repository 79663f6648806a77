// IGES and STEP as OpenCASCADE reads them (io/cad_exchange.hpp). Each file
// casteljau writes is read by OpenCASCADE's own readers (IGESControl_Reader,
// STEPControl_Reader, Debian's libocct-data-exchange), which must report no
// message at all (load and transfer checks, warnings included) and give one
// shape per model whose edges and faces pass BRepCheck_Analyzer. Each curve
// and surface found is compared with the model it came from: degree, knots,
// control points and weights equal to the bit (the numbers are written in
// shortest round-trip form), and OpenCASCADE's evaluation at 64 (curves) or
// 8 x 8 (surfaces) parameters within 1e-12 of the model's size from ours.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/cad_exchange.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/io/svg_drawing.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/surfaces/coons.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "support/examples_dir.hpp"
#include "casteljau/surfaces/refinement.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "support/bspline_generators.hpp"
#include "support/surface_generators.hpp"

namespace casteljau {
namespace {

enum class Format { iges, step };
const char* name_of(Format format) { return format == Format::iges ? "IGES" : "STEP"; }

/// What OpenCASCADE made of a file: its messages, the B-spline curves of its
/// edges and the surfaces of its faces in file order, and the shape check.
struct OcctReading {
  std::string messages;  ///< every load and transfer fail and warning but the notes; empty when clean
  int notes = 0;         ///< is_note() messages
  std::vector<Handle(Geom_BSplineCurve)> curves;
  std::vector<Handle(Geom_BSplineSurface)> surfaces;
  std::vector<std::string> other;  ///< edges or faces whose geometry is not a B-spline
  bool valid = false;              ///< BRepCheck_Analyzer of every shape
  int shapes = 0;
};

/// OpenCASCADE's IGES notes on what it made of valid geometry, not on a
/// defect of the file (XSMessage/XSTEP.us, IGES_1221 and IGES_1255): it
/// makes a surface flagged closed periodic, and says so; it tells when the
/// result is only C0 (the NURBS sphere's and torus's double knots are, by
/// construction). Every other message, fails and warnings alike, is reported.
bool is_note(std::string_view message) {
  return message == "Surface is made periodic." || message == "Resulting Geom_Surface is C0-continuous.";
}

/// Adds the fails and warnings of the checks to the reading.
void collect(const Interface_CheckIterator& checks, OcctReading& reading) {
  for (checks.Start(); checks.More(); checks.Next()) {
    const Handle(Interface_Check)& check = checks.Value();
    for (int i = 1; i <= check->NbFails(); ++i) reading.messages += std::string("fail: ") + check->CFail(i) + "\n";
    for (int i = 1; i <= check->NbWarnings(); ++i) {
      const std::string warning = check->CWarning(i);
      if (is_note(warning))
        ++reading.notes;
      else
        reading.messages += "warning: " + warning + "\n";
    }
  }
}

OcctReading read_with_occt(const std::filesystem::path& path, Format format) {
  OcctReading reading;
  std::unique_ptr<XSControl_Reader> reader;
  if (format == Format::iges)
    reader = std::make_unique<IGESControl_Reader>();
  else
    reader = std::make_unique<STEPControl_Reader>();
  // Keep every B-spline as written: IGES's default splits C0 curves into C1
  // pieces (the setting exists once the reader has started its controller).
  if (!Interface_Static::SetIVal("read.iges.bspline.continuity", 0)) {
    reading.messages = "no setting read.iges.bspline.continuity";
    return reading;
  }
  if (reader->ReadFile(path.c_str()) != IFSelect_RetDone) {
    reading.messages = "ReadFile failed";
    return reading;
  }
  collect(reader->WS()->ModelCheckList(), reading);
  reader->TransferRoots();
  collect(reader->WS()->TransferReader()->TransientProcess()->CheckList(Standard_False), reading);
  reading.valid = reader->NbShapes() > 0;
  for (int s = 1; s <= reader->NbShapes(); ++s) {
    const TopoDS_Shape shape = reader->Shape(s);
    reading.valid = reading.valid && BRepCheck_Analyzer(shape).IsValid();
    for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next()) {
      ++reading.shapes;
      Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(face.Current()));
      if (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = trimmed->BasisSurface();
      if (auto spline = Handle(Geom_BSplineSurface)::DownCast(surface))
        reading.surfaces.push_back(spline);
      else
        reading.other.push_back(surface->DynamicType()->Name());
    }
    // Edges not on a face: the curves.
    for (TopExp_Explorer edge(shape, TopAbs_EDGE, TopAbs_FACE); edge.More(); edge.Next()) {
      ++reading.shapes;
      double first = 0, last = 0;
      Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(edge.Current()), first, last);
      if (curve.IsNull()) {
        reading.other.push_back("an edge without a 3D curve");
        continue;
      }
      if (auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(curve)) curve = trimmed->BasisCurve();
      if (auto spline = Handle(Geom_BSplineCurve)::DownCast(curve))
        reading.curves.push_back(spline);
      else
        reading.other.push_back(curve->DynamicType()->Name());
    }
  }
  return reading;
}

std::vector<double> flat_knots(const TColStd_Array1OfReal& knots, const TColStd_Array1OfInteger& multiplicities) {
  std::vector<double> out;
  for (int i = knots.Lower(); i <= knots.Upper(); ++i)
    out.insert(out.end(), static_cast<std::size_t>(multiplicities(i)), knots(i));
  return out;
}

std::vector<double> as_vector(std::span<const double> values) { return {values.begin(), values.end()}; }

/// x y z of a point with z = 0 for a plane one.
std::vector<double> in_space(std::span<const double> p) { return {p[0], p[1], p.size() > 2 ? p[2] : 0.0}; }

double diagonal(const PointArray& points) {
  double size = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < points.size(); j += std::max<std::size_t>(1, points.size() / 16)) {
      double d = 0.0;
      for (int k = 0; k < points.dimension(); ++k) d += (points[i][k] - points[j][k]) * (points[i][k] - points[j][k]);
      size = std::max(size, std::sqrt(d));
    }
  return std::max(size, 1e-300);
}

/// How many curves and surfaces OpenCASCADE kept as written (same knots,
/// poles and weights, to the bit), and how many it rewrote as the same shape
/// in a form of its own (closed ones made periodic), for which only the
/// points are compared.
int kept = 0, rewritten = 0;

/// The curve OpenCASCADE read is the model: the representation written
/// (`ours`, the model's clamped B-spline form) to the bit when the reader
/// kept it, and the points of the model itself (`model`).
void expect_same_curve(const Handle(Geom_BSplineCurve)& occt, const BSplineCurve& ours, const BSplineCurve& model,
                       double* largest) {
  ASSERT_EQ(occt->Degree(), ours.degree());
  EXPECT_EQ(occt->IsRational() == Standard_True, ours.is_rational());
  const bool same_form = occt->NbPoles() == static_cast<int>(ours.control_points().size()) &&
                         flat_knots(occt->Knots(), occt->Multiplicities()) == as_vector(ours.knots());
  ++(same_form ? kept : rewritten);
  if (same_form) {
    for (int i = 0; i < occt->NbPoles(); ++i) {
      const gp_Pnt pole = occt->Pole(i + 1);
      EXPECT_EQ((std::vector<double>{pole.X(), pole.Y(), pole.Z()}), in_space(ours.control_points()[i])) << "pole " << i;
      EXPECT_EQ(occt->Weight(i + 1), ours.is_rational() ? ours.weights()[i] : 1.0) << "weight " << i;
    }
  } else {
    EXPECT_TRUE(occt->IsPeriodic()) << "OpenCASCADE changed an open curve";  // its form for a closed one
  }
  const double size = diagonal(ours.control_points());
  const Interval domain = ours.domain();
  EXPECT_EQ(occt->FirstParameter(), domain.lower);
  EXPECT_EQ(occt->LastParameter(), domain.upper);
  for (int s = 0; s <= 64; ++s) {
    const double u = domain.lerp(s / 64.0);
    const gp_Pnt p = occt->Value(u);
    const auto q = in_space(point_at(model, u));
    const double distance = std::hypot(p.X() - q[0], p.Y() - q[1], p.Z() - q[2]) / size;
    *largest = std::max(*largest, distance);
    EXPECT_LE(distance, 1e-12) << "at u = " << u;
  }
}

void expect_same_surface(const Handle(Geom_BSplineSurface)& occt, const BSplineSurface& ours,
                         const BSplineSurface& model, double* largest) {
  ASSERT_EQ(occt->UDegree(), ours.degree_u());
  ASSERT_EQ(occt->VDegree(), ours.degree_v());
  const ControlNet& net = ours.control_net();
  const bool same_form = occt->NbUPoles() == static_cast<int>(net.rows()) &&
                         occt->NbVPoles() == static_cast<int>(net.columns()) &&
                         flat_knots(occt->UKnots(), occt->UMultiplicities()) == as_vector(ours.knots_u()) &&
                         flat_knots(occt->VKnots(), occt->VMultiplicities()) == as_vector(ours.knots_v());
  ++(same_form ? kept : rewritten);
  if (same_form) {
    for (std::size_t i = 0; i < net.rows(); ++i)
      for (std::size_t j = 0; j < net.columns(); ++j) {
        const gp_Pnt pole = occt->Pole(static_cast<int>(i) + 1, static_cast<int>(j) + 1);
        EXPECT_EQ((std::vector<double>{pole.X(), pole.Y(), pole.Z()}), in_space(net(i, j))) << "pole " << i << "," << j;
        EXPECT_EQ(occt->Weight(static_cast<int>(i) + 1, static_cast<int>(j) + 1),
                  ours.is_rational() ? ours.weights()[i * net.columns() + j] : 1.0);
      }
  } else {
    EXPECT_TRUE(occt->IsUPeriodic() || occt->IsVPeriodic()) << "OpenCASCADE changed an open surface";
  }
  const double size = diagonal(net.points());
  const Interval du = ours.domain_u(), dv = ours.domain_v();
  for (int a = 0; a <= 8; ++a)
    for (int b = 0; b <= 8; ++b) {
      const double u = du.lerp(a / 8.0), v = dv.lerp(b / 8.0);
      const gp_Pnt p = occt->Value(u, v);
      const auto q = in_space(point_at(model, u, v));
      const double distance = std::hypot(p.X() - q[0], p.Y() - q[1], p.Z() - q[2]) / size;
      *largest = std::max(*largest, distance);
      EXPECT_LE(distance, 1e-12) << "at (u, v) = (" << u << ", " << v << ")";
    }
}

/// Largest relative gap seen by each format, reported at the end.
double largest_gap[2] = {0.0, 0.0};

/// Writes the models in the format and has OpenCASCADE read the file.
OcctReading written_and_read(const std::vector<Model>& models, Format format, const ExchangeHeader& header) {
  auto text = format == Format::iges ? write_iges(models, header) : write_step(models, header);
  if (!text) {
    ADD_FAILURE() << text.error().message;
    return {};
  }
  const auto path = std::filesystem::temp_directory_path() /
                    (std::string("casteljau_exchange_") + std::to_string(::getpid()) +
                     (format == Format::iges ? ".igs" : ".stp"));
  if (auto written = write_file_atomically(path, *text); !written) {
    ADD_FAILURE() << written.error().message;
    return {};
  }
  OcctReading reading = read_with_occt(path, format);
  std::filesystem::remove(path);
  return reading;
}

/// Writes the models in the format, reads them back with OpenCASCADE, compares.
void expect_read_alike(const std::vector<Model>& models, Format format) {
  SCOPED_TRACE(name_of(format));
  ExchangeHeader header;
  header.file_name = "exchange_test";
  header.timestamp = "2026-12-04T12:00:00";
  const OcctReading reading = written_and_read(models, format, header);
  EXPECT_EQ(reading.messages, "");
  EXPECT_TRUE(reading.valid);
  EXPECT_TRUE(reading.other.empty()) << reading.other.front();
  std::size_t curve = 0, surface = 0;
  for (const Model& model : models) {
    const Model spline = to_bspline(model).value();
    double* largest = &largest_gap[format == Format::iges ? 0 : 1];
    if (const auto* c = std::get_if<BSplineCurve>(&spline)) {
      ASSERT_LT(curve, reading.curves.size()) << "OpenCASCADE found " << reading.curves.size() << " curves";
      expect_same_curve(reading.curves[curve++], clamped(*c), *c, largest);
    } else {
      ASSERT_LT(surface, reading.surfaces.size()) << "OpenCASCADE found " << reading.surfaces.size() << " surfaces";
      const auto& s = std::get<BSplineSurface>(spline);
      expect_same_surface(reading.surfaces[surface++], clamped(clamped(s, Direction::u), Direction::v), s, largest);
    }
  }
  EXPECT_EQ(curve, reading.curves.size());
  EXPECT_EQ(surface, reading.surfaces.size());
}

void expect_read_alike(const std::vector<Model>& models) {
  expect_read_alike(models, Format::iges);
  expect_read_alike(models, Format::step);
}

Model semicircle() {
  return read_models_json(test::examples_dir() / "semicircle.json").value().front();
}

TEST(OcctExchange, TheSeedsSemicircleAndTheNurbsCircle) {
  expect_read_alike({semicircle()});
  expect_read_alike({Model{make_circle(1.5, -2.0, 3.0).value()}});
}

TEST(OcctExchange, BezierAndPiecewiseCurvesInThePlaneAndInSpace) {
  const auto bezier = BezierCurve::make(PointArray::make(3, {0, 0, 0, 1, 2, 0.5, 3, 3, 1, 4, 0, 2, 6, 1, -1}).value());
  const auto rational = BezierCurve::make(PointArray::make(2, {0, 0, 1, 2, 3, 0}).value(), {1.0, 0.25, 2.0});
  const auto first = BezierCurve::make(PointArray::make(2, {0, 0, 1, 1, 2, 0}).value());
  const auto second = BezierCurve::make(PointArray::make(2, {2, 0, 3, -1, 4, 0, 5, 2}).value());
  const auto pieces = PiecewiseBezierCurve::make({*first, *second});
  expect_read_alike({Model{*bezier}, Model{*rational}, Model{*pieces}});
}

TEST(OcctExchange, ASegmentOfDegreeOne) {
  expect_read_alike({Model{BezierCurve::make(PointArray::make(3, {1, 2, 3, 4, 5, 6}).value()).value()}});
}

TEST(OcctExchange, SurfacesSphereTorusBezierAndCoons) {
  const auto sphere = make_sphere({0, 0, 0}, 2.0);
  const auto torus = make_torus({1, 2, 3}, {0, 0, 1}, 3.0, 1.0);
  const auto net = ControlNet::make(3, 4, PointArray::make(3, {0, 0, 0, 1, 0, 1, 2, 0, 0, 3, 0, 1,  //
                                                               0, 1, 1, 1, 1, 2, 2, 1, 1, 3, 1, 0,  //
                                                               0, 2, 0, 1, 2, 1, 2, 2, 0, 3, 2, 2})
                                              .value());
  const auto patch = BezierSurface::make(*net);
  // A Coons patch of four cubic boundaries (written as its tensor-product form).
  const auto cubic = [](std::vector<double> xyz) {
    return BSplineCurve::make(3, {0, 0, 0, 0, 1, 1, 1, 1}, PointArray::make(3, std::move(xyz)).value()).value();
  };
  const auto coons = CoonsPatch::make(cubic({0, 0, 0, 0, 1, 1, 0, 2, -1, 0, 3, 0}),  // u0 = P(0, v)
                                      cubic({3, 0, 0, 3, 1, 0.5, 3, 2, 0.5, 3, 3, 0}),  // u1 = P(1, v)
                                      cubic({0, 0, 0, 1, 0, 1, 2, 0, 1, 3, 0, 0}),  // v0 = P(u, 0)
                                      cubic({0, 3, 0, 1, 3, -1, 2, 3, 0, 3, 3, 0}),  // v1 = P(u, 1)
                                      CoonsBlending::cubic);
  ASSERT_TRUE(coons.has_value()) << coons.error().message;
  expect_read_alike({Model{*sphere}, Model{*torus}, Model{*patch}, Model{*coons}});
}

TEST(OcctExchange, InchesAreConvertedToMillimetresByTheReader) {
  // OpenCASCADE works in millimetres: a file in inches comes back x 25.4.
  const BSplineCurve circle = make_circle(1.0, 2.0, 0.5).value();
  ExchangeHeader header;
  header.unit = ExchangeUnit::inch;
  for (Format format : {Format::iges, Format::step}) {
    SCOPED_TRACE(name_of(format));
    const OcctReading reading = written_and_read({Model{circle}}, format, header);
    EXPECT_EQ(reading.messages, "");
    ASSERT_EQ(reading.curves.size(), 1u);
    for (int i = 0; i < reading.curves[0]->NbPoles(); ++i) {
      const gp_Pnt pole = reading.curves[0]->Pole(i + 1);
      EXPECT_NEAR(pole.X(), 25.4 * circle.control_points()[i][0], 1e-12 * 25.4 * 2);
      EXPECT_NEAR(pole.Y(), 25.4 * circle.control_points()[i][1], 1e-12 * 25.4 * 2);
    }
  }
}

TEST(OcctExchange, AnSvgLetterStaysUprightInStepAndIges) {
  // Issue 39: SVG is y down, STEP and IGES y up; an SVG converted to them
  // came out mirrored. An "F" on a 10 x 10 page: OpenCASCADE must find its
  // corners with the bar at the top (y = 10, out to x = 6), the middle arm
  // reaching x = 5 at y = 4..6, the stem's foot at y = 0 (x = 0..2), and no
  // corner of the mirrored F (6, 0).
  const auto drawing = parse_svg_drawing(
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 10 10'><path d='M0 0H6V2H2V4H5V6H2V10H0Z'/></svg>", "f.svg");
  ASSERT_TRUE(drawing.has_value());
  ASSERT_EQ(drawing->curves.size(), 1u);
  for (const Format format : {Format::iges, Format::step}) {
    SCOPED_TRACE(name_of(format));
    const OcctReading reading = written_and_read({Model{drawing->curves[0].curve}}, format, ExchangeHeader{});
    ASSERT_EQ(reading.curves.size(), 1u);
    std::vector<std::pair<double, double>> corners;
    const TColgp_Array1OfPnt& poles = reading.curves[0]->Poles();
    for (int i = poles.Lower(); i <= poles.Upper(); ++i) corners.emplace_back(poles(i).X(), poles(i).Y());
    const auto has = [&](double x, double y) {
      return std::any_of(corners.begin(), corners.end(), [&](const auto& p) {
        return std::abs(p.first - x) <= 1e-12 && std::abs(p.second - y) <= 1e-12;
      });
    };
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0, 10}, {6, 10}, {6, 8}, {5, 6}, {5, 4}, {0, 0}, {2, 0}})
      EXPECT_TRUE(has(x, y)) << "(" << x << ", " << y << ")";
    EXPECT_FALSE(has(6, 0));
  }
}

TEST(OcctExchange, CurvesAndSurfacesInOneFile) {
  expect_read_alike({semicircle(), Model{make_sphere({0, 0, 0}, 1.0).value()}, Model{make_circle(0, 0, 2).value()}});
}

RC_GTEST_PROP(OcctExchange, RandomBSplineAndNurbsCurvesReadBackExactly, ()) {
  const auto curve = *test::bspline_curve({.max_degree = 9});
  expect_read_alike({Model{curve}});
}

RC_GTEST_PROP(OcctExchange, RandomBSplineAndNurbsSurfacesReadBackExactly, ()) {
  const auto surface = *test::bspline_surface({.max_degree = 5});
  // A surface collapsed to one point is no face (BRepCheck says so, rightly).
  const auto points = surface.control_net().points().coordinates();
  bool one_point = true;
  for (std::size_t i = 3; i < points.size(); ++i) one_point = one_point && points[i] == points[i % 3];
  RC_PRE(!one_point);
  expect_read_alike({Model{surface}});
}

/// At the end of the run (every test, or the one ctest runs): the largest
/// relative distance seen per format and what the reader kept.
class Summary : public ::testing::Environment {
 public:
  void TearDown() override {
    std::printf("largest gap between OpenCASCADE's points and casteljau's: IGES %.3g, STEP %.3g of the size; "
                "%d curves and surfaces kept to the bit, %d made periodic by the reader\n",
                largest_gap[0], largest_gap[1], kept, rewritten);
  }
};
const auto* const summary = ::testing::AddGlobalTestEnvironment(new Summary);

}  // namespace
}  // namespace casteljau

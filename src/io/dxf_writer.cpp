// Curves to a DXF R2000 document of SPLINE entities, arc splines to one of
// LWPOLYLINE entities with bulges (io/dxf.hpp says what).
// The structure follows the DXF reference for AC1015: every table and block
// record a reader looks up (the layer 0, the Continuous line type, the model
// and paper space blocks), owner handles (330) and subclass markers (100), and
// the root dictionary of OBJECTS. Handles are hexadecimal and unique;
// $HANDSEED is the next free one.
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/io/dxf.hpp"
#include "casteljau/io/model.hpp"

namespace casteljau {
namespace {

class Writer {
 public:
  void group(int code, std::string_view value) { fmt::format_to(std::back_inserter(out_), "{:>3}\n{}\n", code, value); }
  void group(int code, int value) { group(code, std::to_string(value)); }
  /// A real in shortest round-trip form (-0 written as 0).
  void real(int code, double value) { group(code, fmt::format("{}", value == 0.0 ? 0.0 : value)); }
  std::string handle() { return fmt::format("{:X}", next_++); }
  unsigned next() const { return next_; }
  std::string& text() { return out_; }

 private:
  std::string out_;
  unsigned next_ = 0x20;  // below: the fixed handles of the tables and dictionaries
};

// Fixed handles of the structure (AutoCAD's own numbering for R2000 files).
constexpr const char* kRootDictionary = "C";
constexpr const char* kGroupDictionary = "D";
constexpr const char* kVportTable = "8";
constexpr const char* kLtypeTable = "5";
constexpr const char* kLayerTable = "2";
constexpr const char* kStyleTable = "3";
constexpr const char* kViewTable = "6";
constexpr const char* kUcsTable = "7";
constexpr const char* kAppidTable = "9";
constexpr const char* kDimstyleTable = "A";
constexpr const char* kBlockRecordTable = "1";
constexpr const char* kModelSpace = "1F";
constexpr const char* kPaperSpace = "1B";

void table_start(Writer& w, const char* name, const char* handle, int entries) {
  w.group(0, "TABLE");
  w.group(2, name);
  w.group(5, handle);
  w.group(330, "0");
  w.group(100, "AcDbSymbolTable");
  w.group(70, entries);
}

void record_start(Writer& w, const char* type, const char* table, const char* subclass, const std::string& handle) {
  w.group(0, type);
  w.group(5, handle);
  w.group(330, table);
  w.group(100, "AcDbSymbolTableRecord");
  w.group(100, subclass);
}

void tables(Writer& w) {
  w.group(0, "SECTION");
  w.group(2, "TABLES");
  table_start(w, "VPORT", kVportTable, 1);
  record_start(w, "VPORT", kVportTable, "AcDbViewportTableRecord", w.handle());
  w.group(2, "*ACTIVE");
  w.group(70, 0);
  for (auto [code, value] : {std::pair{10, 0.0}, {20, 0.0}, {11, 1.0}, {21, 1.0}, {12, 0.0}, {22, 0.0}, {13, 0.0},
                             {23, 0.0}, {14, 1.0}, {24, 1.0}, {15, 1.0}, {25, 1.0}, {16, 0.0}, {26, 0.0}, {36, 1.0},
                             {17, 0.0}, {27, 0.0}, {37, 0.0}, {40, 1.0}, {41, 1.0}, {42, 50.0}, {43, 0.0}, {44, 0.0},
                             {50, 0.0}, {51, 0.0}})
    w.real(code, value);
  w.group(0, "ENDTAB");

  table_start(w, "LTYPE", kLtypeTable, 3);
  for (const char* name : {"ByBlock", "ByLayer", "Continuous"}) {
    record_start(w, "LTYPE", kLtypeTable, "AcDbLinetypeTableRecord", w.handle());
    w.group(2, name);
    w.group(70, 0);
    w.group(3, std::string_view(name) == "Continuous" ? "Solid line" : "");
    w.group(72, 65);
    w.group(73, 0);
    w.real(40, 0.0);
  }
  w.group(0, "ENDTAB");

  table_start(w, "LAYER", kLayerTable, 1);
  record_start(w, "LAYER", kLayerTable, "AcDbLayerTableRecord", w.handle());
  w.group(2, "0");
  w.group(70, 0);
  w.group(62, 7);
  w.group(6, "Continuous");
  w.group(0, "ENDTAB");

  table_start(w, "STYLE", kStyleTable, 1);
  record_start(w, "STYLE", kStyleTable, "AcDbTextStyleTableRecord", w.handle());
  w.group(2, "Standard");
  w.group(70, 0);
  w.real(40, 0.0);
  w.real(41, 1.0);
  w.real(50, 0.0);
  w.group(71, 0);
  w.real(42, 2.5);
  w.group(3, "txt");
  w.group(4, "");
  w.group(0, "ENDTAB");

  table_start(w, "VIEW", kViewTable, 0);
  w.group(0, "ENDTAB");
  table_start(w, "UCS", kUcsTable, 0);
  w.group(0, "ENDTAB");

  table_start(w, "APPID", kAppidTable, 1);
  record_start(w, "APPID", kAppidTable, "AcDbRegAppTableRecord", w.handle());
  w.group(2, "ACAD");
  w.group(70, 0);
  w.group(0, "ENDTAB");

  table_start(w, "DIMSTYLE", kDimstyleTable, 1);
  w.group(100, "AcDbDimStyleTable");
  w.group(0, "DIMSTYLE");
  w.group(105, w.handle());
  w.group(330, kDimstyleTable);
  w.group(100, "AcDbSymbolTableRecord");
  w.group(100, "AcDbDimStyleTableRecord");
  w.group(2, "Standard");
  w.group(70, 0);
  w.group(0, "ENDTAB");

  table_start(w, "BLOCK_RECORD", kBlockRecordTable, 2);
  for (auto [name, handle] : {std::pair{"*Model_Space", kModelSpace}, std::pair{"*Paper_Space", kPaperSpace}}) {
    record_start(w, "BLOCK_RECORD", kBlockRecordTable, "AcDbBlockTableRecord", handle);
    w.group(2, name);
  }
  w.group(0, "ENDTAB");
  w.group(0, "ENDSEC");
}

/// An entity's common groups: its type, a new handle, its owner, the
/// AcDbEntity subclass (in paper space: 67 1) on layer 0.
void entity_start(Writer& w, const char* type, const char* owner, bool paper) {
  w.group(0, type);
  w.group(5, w.handle());
  w.group(330, owner);
  w.group(100, "AcDbEntity");
  if (paper) w.group(67, 1);
  w.group(8, "0");
}

void blocks(Writer& w) {
  w.group(0, "SECTION");
  w.group(2, "BLOCKS");
  for (auto [name, record, paper] : {std::tuple{"*Model_Space", kModelSpace, false},
                                     std::tuple{"*Paper_Space", kPaperSpace, true}}) {
    entity_start(w, "BLOCK", record, paper);
    w.group(100, "AcDbBlockBegin");
    w.group(2, name);
    w.group(70, 0);
    w.real(10, 0.0);
    w.real(20, 0.0);
    w.real(30, 0.0);
    w.group(3, name);
    w.group(1, "");
    entity_start(w, "ENDBLK", record, paper);
    w.group(100, "AcDbBlockEnd");
  }
  w.group(0, "ENDSEC");
}

void spline(Writer& w, const BSplineCurve& curve) {
  const int d = curve.dimension();
  entity_start(w, "SPLINE", kModelSpace, false);
  w.group(100, "AcDbSpline");
  if (d == 2) {  // the plane z = 0, its normal the extrusion direction
    w.real(210, 0.0);
    w.real(220, 0.0);
    w.real(230, 1.0);
  }
  w.group(70, (d == 2 ? 8 : 0) | (curve.is_rational() ? 4 : 0));
  w.group(71, curve.degree());
  w.group(72, static_cast<int>(curve.knots().size()));
  w.group(73, static_cast<int>(curve.control_points().size()));
  w.group(74, 0);
  w.real(42, 1e-10);
  w.real(43, 1e-10);
  for (double knot : curve.knots()) w.real(40, knot);
  if (curve.is_rational())
    for (double weight : curve.weights()) w.real(41, weight);
  const PointArray& p = curve.control_points();
  for (std::size_t i = 0; i < p.size(); ++i) {
    w.real(10, p[i][0]);
    w.real(20, p[i][1]);
    w.real(30, d == 3 ? p[i][2] : 0.0);
  }
}

/// An arc spline as one LWPOLYLINE: a vertex at each segment's start, its
/// bulge on the vertex it leaves; the last end as a vertex too unless the
/// spline closes (flag 1: the closing segment's bulge on the last vertex).
void polyline(Writer& w, const ArcSpline& spline) {
  const std::vector<ArcSegment>& segments = spline.segments;
  const bool closed = segments.front().start == segments.back().end;
  entity_start(w, "LWPOLYLINE", kModelSpace, false);
  w.group(100, "AcDbPolyline");
  w.group(90, static_cast<int>(segments.size() + (closed ? 0 : 1)));
  w.group(70, closed ? 1 : 0);
  w.real(43, 0.0);
  for (const ArcSegment& segment : segments) {
    w.real(10, segment.start[0]);
    w.real(20, segment.start[1]);
    if (segment.bulge != 0.0) w.real(42, segment.bulge);
  }
  if (!closed) {
    w.real(10, segments.back().end[0]);
    w.real(20, segments.back().end[1]);
  }
}

/// The whole document around the entities `write_entities` writes.
std::string document(int insunits, const std::function<void(Writer&)>& write_entities) {
  Writer body;
  tables(body);
  blocks(body);
  body.group(0, "SECTION");
  body.group(2, "ENTITIES");
  write_entities(body);
  body.group(0, "ENDSEC");
  body.group(0, "SECTION");
  body.group(2, "OBJECTS");
  body.group(0, "DICTIONARY");
  body.group(5, kRootDictionary);
  body.group(330, "0");
  body.group(100, "AcDbDictionary");
  body.group(281, 1);
  body.group(3, "ACAD_GROUP");
  body.group(350, kGroupDictionary);
  body.group(0, "DICTIONARY");
  body.group(5, kGroupDictionary);
  body.group(330, kRootDictionary);
  body.group(100, "AcDbDictionary");
  body.group(281, 1);
  body.group(0, "ENDSEC");
  body.group(0, "EOF");

  Writer head;
  head.group(999, "casteljau");
  head.group(0, "SECTION");
  head.group(2, "HEADER");
  head.group(9, "$ACADVER");
  head.group(1, "AC1015");
  head.group(9, "$HANDSEED");
  head.group(5, fmt::format("{:X}", body.next()));
  head.group(9, "$INSUNITS");
  head.group(70, insunits);
  head.group(0, "ENDSEC");
  head.group(0, "SECTION");
  head.group(2, "CLASSES");
  head.group(0, "ENDSEC");
  return head.text() + body.text();
}

}  // namespace

Expected<std::string> write_dxf_drawing(std::span<const Model> curves, int insunits) {
  std::vector<BSplineCurve> splines;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    if (is_surface(curves[i]))
      return Error{fmt::format("curve {} is a surface ({}); DXF SPLINE entities hold curves", i, type_name(curves[i]))};
    const int d = dimension_of(curves[i]);
    if (d != 2 && d != 3)
      return Error{fmt::format("curve {} lives in R^{}, DXF holds plane and space curves", i, d)};
    auto spline = to_bspline(curves[i]);
    if (!spline) return with_context(spline.error(), fmt::format("curve {}", i));
    splines.push_back(std::get<BSplineCurve>(std::move(*spline)));
  }
  return document(insunits, [&](Writer& w) {
    for (const BSplineCurve& s : splines) spline(w, s);
  });
}

Expected<std::string> write_dxf_arc_polylines(std::span<const ArcSpline> splines, int insunits) {
  for (std::size_t i = 0; i < splines.size(); ++i) {
    if (splines[i].segments.empty()) return Error{fmt::format("arc spline {} has no segment", i)};
    for (const ArcSegment& segment : splines[i].segments)
      for (const double x : {segment.start[0], segment.start[1], segment.end[0], segment.end[1], segment.bulge})
        if (!std::isfinite(x)) return Error{fmt::format("arc spline {} has a number that is not finite: {}", i, x)};
  }
  return document(insunits, [&](Writer& w) {
    for (const ArcSpline& s : splines) polyline(w, s);
  });
}

}  // namespace casteljau

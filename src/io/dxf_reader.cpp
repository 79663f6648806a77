// DXF drawings to curves (io/dxf.hpp says what). The file is read as group
// pairs (a code line, a value line); each entity of the ENTITIES section is
// gathered with its pairs and built by its reader; curves are built in R^3
// and brought to the plane at the end when every z is 0.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/dxf.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/nurbs/conics.hpp"

namespace casteljau {
namespace {

using Vec3d = std::array<double, 3>;

Vec3d operator+(Vec3d a, Vec3d b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3d operator*(double s, Vec3d a) { return {s * a[0], s * a[1], s * a[2]}; }
Vec3d cross(Vec3d a, Vec3d b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(Vec3d a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/// One group: its code, its value, the line of its code (0-based; the value
/// is on the next line, which errors about the value name).
struct Group {
  int code = 0;
  std::string_view value;
  std::size_t line = 0;
};

/// The axes of an object coordinate system (DXF's arbitrary axis algorithm):
/// Ax, Ay, Az for the extrusion direction N.
struct Ocs {
  Vec3d x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  Vec3d to_world(Vec3d p) const { return p[0] * x + p[1] * y + p[2] * z; }
};

std::optional<Ocs> ocs_of(Vec3d normal) {
  const double length = norm(normal);
  if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
  Ocs ocs;
  ocs.z = (1.0 / length) * normal;
  if (ocs.z[0] == 0.0 && ocs.z[1] == 0.0 && ocs.z[2] > 0.0) return Ocs{};  // the world's own axes, exactly
  const bool near_z = std::abs(ocs.z[0]) < 1.0 / 64.0 && std::abs(ocs.z[1]) < 1.0 / 64.0;
  Vec3d x = near_z ? cross(Vec3d{0, 1, 0}, ocs.z) : cross(Vec3d{0, 0, 1}, ocs.z);
  ocs.x = (1.0 / norm(x)) * x;
  ocs.y = cross(ocs.z, ocs.x);
  return ocs;
}

/// The groups of one entity and typed access to them; errors name the line.
class Entity {
 public:
  Entity(std::string name, std::vector<Group> groups, std::size_t line)
      : name_(std::move(name)), groups_(std::move(groups)), line_(line) {}
  const std::string& name() const { return name_; }
  std::size_t line() const { return line_; }
  const std::vector<Group>& groups() const { return groups_; }
  std::string text(int code) const {
    for (const Group& g : groups_)
      if (g.code == code) return std::string(g.value);
    return "";
  }
  /// The first value of `code` as a number (`fallback` when absent).
  Expected<double> number(int code, double fallback) const {
    for (const Group& g : groups_)
      if (g.code == code) return parse(g);
    return fallback;
  }
  /// A group that holds a whole number (flags, a unit code): refused unless
  /// it is an integer within int's range (a cast of 3e65 to int is undefined
  /// behaviour: the dxf fuzzer's LWPOLYLINE flags).
  Expected<int> whole(int code, int fallback) const {
    for (const Group& g : groups_)
      if (g.code == code) return whole_of(g);
    return fallback;
  }
  static Expected<int> whole_of(const Group& g) {
    auto value = parse(g);
    if (!value) return value.error();
    if (*value != std::trunc(*value) || std::abs(*value) > static_cast<double>(std::numeric_limits<int>::max()))
      return Error{fmt::format("line {}, group {}: {} is not a whole number within +-{}", g.line + 2, g.code, g.value,
                               std::numeric_limits<int>::max()),
                   ErrorKind::parse};
    return static_cast<int>(*value);
  }
  static Expected<double> parse(const Group& g) {
    auto value = parse_number(g.value);
    if (!value)
      return Error{fmt::format("line {}, group {}: {}", g.line + 2, g.code, value.error().message), ErrorKind::parse};
    if (std::abs(*value) > tolerances::kMaxCoordinate)
      return Error{fmt::format("line {}, group {}: {} is beyond {:g}, the largest coordinate casteljau takes",
                               g.line + 2, g.code, g.value, tolerances::kMaxCoordinate),
                   ErrorKind::limit};
    return *value;
  }
  /// The point of codes (x, x + 10, x + 20), z 0 when absent.
  Expected<Vec3d> point(int x_code, Vec3d fallback = {0, 0, 0}) const {
    Vec3d p = fallback;
    for (int k = 0; k < 3; ++k) {
      auto c = number(x_code + 10 * k, fallback[k]);
      if (!c) return c.error();
      p[k] = *c;
    }
    return p;
  }
  std::optional<Ocs> ocs() const {
    auto normal = point(210, {0, 0, 1});
    if (!normal) return std::nullopt;
    return ocs_of(*normal);
  }

 private:
  std::string name_;
  std::vector<Group> groups_;
  std::size_t line_;
};

/// C + x U + y V for the control points of a plane curve (z of the plane 0):
/// the affine image, exact for rational curves with the weights kept.
BSplineCurve mapped(const BSplineCurve& plane, Vec3d c, Vec3d u, Vec3d v) {
  const PointArray& p = plane.control_points();
  std::vector<double> out;
  out.reserve(p.size() * 3);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3d q = c + p[i][0] * u + p[i][1] * v;
    out.insert(out.end(), q.begin(), q.end());
  }
  return BSplineCurve::make(plane.degree(), std::vector<double>(plane.knots().begin(), plane.knots().end()),
                            PointArray::from_trusted(3, std::move(out)),
                            std::vector<double>(plane.weights().begin(), plane.weights().end()))
      .value();
}

/// The start of a counter-clockwise arc from angle `from` to angle `to` (in
/// units of which `turn` makes a whole turn) within one turn, and its sweep in
/// (0, turn]: equal angles sweep a whole turn. Each angle is reduced on its own
/// first (std::fmod is exact): the difference of 4e21 and 210 degrees keeps
/// nothing of the 210, and the fuzzer's ARC of 4e21 degrees became four pieces
/// running out and back along one chord.
std::pair<double, double> start_and_sweep(double from, double to, double turn) {
  const double start = std::fmod(from, turn);
  double sweep = std::fmod(std::fmod(to, turn) - start, turn);
  if (sweep <= 0.0) sweep += turn;
  return {start, sweep};
}

/// The arc of the circle (centre, radius) in the plane of `ocs` from angle a
/// over `sweep` (radians, counter-clockwise about the extrusion).
Expected<BSplineCurve> ocs_arc(const Ocs& ocs, Vec3d centre, double radius, double a, double sweep) {
  if (!(radius > 0.0)) return Error{fmt::format("the radius must be > 0, got {}", radius)};
  auto unit = std::abs(sweep) >= 2.0 * std::numbers::pi ? make_circle(0.0, 0.0, 1.0) : make_arc(0.0, 0.0, 1.0, a, sweep);
  if (!unit) return unit.error();
  return mapped(*unit, ocs.to_world(centre), radius * ocs.x, radius * ocs.y);
}

/// Bézier pieces of one polyline segment from p to q with `bulge` (tan of a
/// quarter of the included angle, positive counter-clockwise in the OCS).
Status add_segment(std::vector<BezierCurve>& pieces, const Ocs& ocs, Vec3d p, Vec3d q, double bulge) {
  if (bulge == 0.0 || (p[0] == q[0] && p[1] == q[1])) {
    const Vec3d a = ocs.to_world(p), b = ocs.to_world(q);
    pieces.push_back(BezierCurve::make(PointArray::from_trusted(3, {a[0], a[1], a[2], b[0], b[1], b[2]})).value());
    return {};
  }
  const double theta = 4.0 * std::atan(bulge);  // the included angle, signed
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  const double chord = std::hypot(dx, dy);
  const double radius = chord / (2.0 * std::abs(std::sin(theta / 2.0)));
  // The centre lies on the chord's perpendicular bisector, at distance
  // (chord / 2) / tan(θ / 2) to the left of p -> q for θ > 0.
  const double offset = (chord / 2.0) / std::tan(theta / 2.0);
  const Vec3d centre{(p[0] + q[0]) / 2.0 - offset * dy / chord, (p[1] + q[1]) / 2.0 + offset * dx / chord, p[2]};
  const double start = std::atan2(p[1] - centre[1], p[0] - centre[0]);
  auto arc = ocs_arc(ocs, centre, radius, start, theta);
  if (!arc) return arc.error();
  std::vector<BezierCurve> arc_pieces = to_bezier_pieces(*arc).pieces;
  const Vec3d first = ocs.to_world(p), last = ocs.to_world(q);
  for (std::size_t k = 0; k < arc_pieces.size(); ++k) {
    // The ends are the vertices themselves, not their image to rounding.
    const BezierCurve& piece = arc_pieces[k];
    std::vector<double> c(piece.control_points().coordinates().begin(), piece.control_points().coordinates().end());
    if (k == 0) std::copy(first.begin(), first.end(), c.begin());
    if (k + 1 == arc_pieces.size()) std::copy(last.begin(), last.end(), c.end() - 3);
    pieces.push_back(BezierCurve::make(PointArray::from_trusted(3, std::move(c)),
                                       std::vector<double>(piece.weights().begin(), piece.weights().end()))
                         .value());
  }
  return {};
}

Model as_model(BSplineCurve curve) { return Model{std::move(curve)}; }

/// The curve of a piecewise polyline; the joints of consecutive pieces are made
/// exactly equal (each arc's ends are the vertices up to rounding).
Expected<Model> polyline_model(std::vector<BezierCurve> pieces) {
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    const auto end = pieces[i - 1].control_points()[pieces[i - 1].control_points().size() - 1];
    std::vector<double> c(pieces[i].control_points().coordinates().begin(),
                          pieces[i].control_points().coordinates().end());
    std::copy(end.begin(), end.end(), c.begin());
    pieces[i] = BezierCurve::make(PointArray::from_trusted(3, std::move(c)),
                                  std::vector<double>(pieces[i].weights().begin(), pieces[i].weights().end()))
                    .value();
  }
  auto curve = PiecewiseBezierCurve::make(std::move(pieces));
  if (!curve) return curve.error();
  return Model{std::move(*curve)};
}

/// The curve of a polyline's vertices (in `ocs`) and the bulge of the segment
/// after each: a line or an exact arc per segment, the closing one when `closed`.
Expected<Model> polyline_curve(const std::vector<Vec3d>& vertices, const std::vector<double>& bulges, const Ocs& ocs,
                               bool closed) {
  if (vertices.size() < 2) return Error{fmt::format("a polyline needs 2 vertices, it has {}", vertices.size())};
  std::vector<BezierCurve> pieces;
  const std::size_t segments = closed ? vertices.size() : vertices.size() - 1;
  for (std::size_t i = 0; i < segments; ++i)
    if (Status ok = add_segment(pieces, ocs, vertices[i], vertices[(i + 1) % vertices.size()], bulges[i]); !ok)
      return ok.error();
  return polyline_model(std::move(pieces));
}

// --- one reader per entity ---------------------------------------------------

Expected<Model> read_line(const Entity& e) {
  auto a = e.point(10), b = e.point(11);
  if (!a) return a.error();
  if (!b) return b.error();
  return Model{BezierCurve::make(PointArray::from_trusted(3, {(*a)[0], (*a)[1], (*a)[2], (*b)[0], (*b)[1], (*b)[2]}))
                   .value()};
}

Expected<Model> read_arc(const Entity& e, bool full_circle) {
  const auto ocs = e.ocs();
  if (!ocs) return Error{"the extrusion direction (210, 220, 230) is zero or not finite"};
  auto centre = e.point(10);
  if (!centre) return centre.error();
  auto radius = e.number(40, 0.0);
  if (!radius) return radius.error();
  double start = 0.0, sweep = 2.0 * std::numbers::pi;
  if (!full_circle) {
    auto a = e.number(50, 0.0), b = e.number(51, 360.0);
    if (!a) return a.error();
    if (!b) return b.error();
    const auto [from, degrees] = start_and_sweep(*a, *b, 360.0);  // ARC runs counter-clockwise from 50 to 51
    start = from * std::numbers::pi / 180.0;
    sweep = degrees * std::numbers::pi / 180.0;
  }
  auto arc = ocs_arc(*ocs, *centre, *radius, start, sweep);
  if (!arc) return arc.error();
  return as_model(std::move(*arc));
}

Expected<Model> read_ellipse(const Entity& e) {
  auto centre = e.point(10), major = e.point(11), normal = e.point(210, {0, 0, 1});
  if (!centre) return centre.error();
  if (!major) return major.error();
  if (!normal) return normal.error();
  auto ratio = e.number(40, 1.0), start = e.number(41, 0.0), end = e.number(42, 2.0 * std::numbers::pi);
  if (!ratio) return ratio.error();
  if (!start) return start.error();
  if (!end) return end.error();
  const double major_length = norm(*major), normal_length = norm(*normal);
  if (!(major_length > 0.0)) return Error{"the major axis (11, 21, 31) is zero"};
  if (!(normal_length > 0.0)) return Error{"the extrusion direction (210, 220, 230) is zero"};
  if (!(*ratio > 0.0 && *ratio <= 1.0)) return Error{fmt::format("the axis ratio (40) must be in (0, 1], got {}", *ratio)};
  // Minor axis: ratio |major| along N x major (DXF's ELLIPSE, counter-clockwise about N).
  const Vec3d n = (1.0 / normal_length) * *normal;
  const Vec3d minor = *ratio * cross(n, *major);
  const auto [from, sweep] = start_and_sweep(*start, *end, 2.0 * std::numbers::pi);
  auto unit = sweep >= 2.0 * std::numbers::pi ? make_circle(0.0, 0.0, 1.0) : make_arc(0.0, 0.0, 1.0, from, sweep);
  if (!unit) return unit.error();
  return as_model(mapped(*unit, *centre, *major, minor));
}

Expected<Model> read_lwpolyline(const Entity& e) {
  const auto ocs = e.ocs();
  if (!ocs) return Error{"the extrusion direction (210, 220, 230) is zero or not finite"};
  auto elevation = e.number(38, 0.0);
  auto flags = e.whole(70, 0);
  if (!elevation) return elevation.error();
  if (!flags) return flags.error();
  std::vector<Vec3d> vertices;
  std::vector<double> bulges;
  for (const Group& g : e.groups()) {
    if (g.code == 10) {
      auto x = Entity::parse(g);
      if (!x) return x.error();
      vertices.push_back({*x, 0.0, *elevation});
      bulges.push_back(0.0);
    } else if ((g.code == 20 || g.code == 42) && !vertices.empty()) {
      auto v = Entity::parse(g);
      if (!v) return v.error();
      (g.code == 20 ? vertices.back()[1] : bulges.back()) = *v;
    }
  }
  const bool closed = (*flags & 1) != 0;
  return polyline_curve(vertices, bulges, *ocs, closed);
}

/// POLYLINE with its VERTEX entities (SEQEND ends them).
Expected<Model> read_polyline(const Entity& e, const std::vector<Entity>& vertices) {
  auto flags = e.whole(70, 0);
  if (!flags) return flags.error();
  const int f = *flags;
  if (f & (16 | 64)) return Error{"polygon and polyface meshes are surfaces, not curves"};
  const bool space = (f & 8) != 0, closed = (f & 1) != 0;
  const auto ocs = space ? std::optional<Ocs>(Ocs{}) : e.ocs();
  if (!ocs) return Error{"the extrusion direction (210, 220, 230) is zero or not finite"};
  auto elevation = e.point(10);
  if (!elevation) return elevation.error();
  std::vector<Vec3d> points;
  std::vector<double> bulges;
  for (const Entity& v : vertices) {
    auto vertex_flags = v.whole(70, 0);
    if (!vertex_flags) return vertex_flags.error();
    if (*vertex_flags & 16) continue;  // a spline frame control point, not on the curve
    auto p = v.point(10);
    auto bulge = v.number(42, 0.0);
    if (!p) return p.error();
    if (!bulge) return bulge.error();
    if (!space) (*p)[2] = (*elevation)[2];
    points.push_back(*p);
    bulges.push_back(space ? 0.0 : *bulge);
  }
  return polyline_curve(points, bulges, *ocs, closed);
}

Expected<Model> read_spline(const Entity& e) {
  auto flags = e.number(70, 0.0), degree = e.number(71, 3.0);
  if (!flags) return flags.error();
  if (!degree) return degree.error();
  std::vector<double> knots, weights, control, fit;
  std::optional<Vec3d> start_tangent, end_tangent;
  for (const Group& g : e.groups()) {
    const int code = g.code;
    const bool wanted = code == 40 || code == 41 || (code >= 10 && code <= 13) || (code >= 20 && code <= 23) ||
                        (code >= 30 && code <= 33);
    if (!wanted) continue;
    auto v = Entity::parse(g);
    if (!v) return v.error();
    if (code == 40) knots.push_back(*v);
    else if (code == 41) weights.push_back(*v);
    else if (code == 10) control.insert(control.end(), {*v, 0.0, 0.0});
    else if (code == 20 && !control.empty()) control[control.size() - 2] = *v;
    else if (code == 30 && !control.empty()) control.back() = *v;
    else if (code == 11) fit.insert(fit.end(), {*v, 0.0, 0.0});
    else if (code == 21 && !fit.empty()) fit[fit.size() - 2] = *v;
    else if (code == 31 && !fit.empty()) fit.back() = *v;
    else if (code == 12) start_tangent = Vec3d{*v, 0, 0};
    else if (code == 22 && start_tangent) (*start_tangent)[1] = *v;
    else if (code == 32 && start_tangent) (*start_tangent)[2] = *v;
    else if (code == 13) end_tangent = Vec3d{*v, 0, 0};
    else if (code == 23 && end_tangent) (*end_tangent)[1] = *v;
    else if (code == 33 && end_tangent) (*end_tangent)[2] = *v;
  }
  // The range first: the cast of a degree beyond int's is undefined.
  if (!(*degree >= 1 && *degree <= tolerances::kMaxBSplineDegree) || *degree != std::trunc(*degree))
    return Error{fmt::format("the degree (71) must be a whole number in 1..{}, got {}", tolerances::kMaxBSplineDegree,
                             *degree)};
  const int p = static_cast<int>(*degree);
  if (!control.empty()) {
    const std::size_t n = control.size() / 3;
    if (!weights.empty() && weights.size() != n)
      return Error{fmt::format("{} weights (41) for {} control points (10)", weights.size(), n)};
    // Weights all 1 are a polynomial curve (AutoCAD writes them for every spline).
    if (std::all_of(weights.begin(), weights.end(), [](double w) { return w == 1.0; })) weights.clear();
    auto curve = BSplineCurve::make(p, knots, PointArray::from_trusted(3, std::move(control)), weights);
    if (!curve) return curve.error();
    return as_model(std::move(*curve));
  }
  if (fit.size() < 6) return Error{"a spline needs control points (10) or at least 2 fit points (11)"};
  // Fit points only: the cubic through them, chord-length parameters on [0, 1];
  // given end tangents (unit directions) scaled by the total chord length.
  auto points = PointArray::make(3, std::move(fit));
  if (!points) return points.error();
  auto parameters = parameter_values(*points, Parameterization::chord_length);
  if (!parameters) return parameters.error();
  double chord = 0.0;
  for (std::size_t i = 1; i < points->size(); ++i) {
    double s = 0.0;
    for (int k = 0; k < 3; ++k) s += ((*points)[i][k] - (*points)[i - 1][k]) * ((*points)[i][k] - (*points)[i - 1][k]);
    chord += std::sqrt(s);
  }
  CubicEnds ends;
  if (start_tangent && end_tangent && norm(*start_tangent) > 0.0 && norm(*end_tangent) > 0.0) {
    ends.condition = EndCondition::clamped;
    const Vec3d a = (chord / norm(*start_tangent)) * *start_tangent, b = (chord / norm(*end_tangent)) * *end_tangent;
    ends.start_tangent = Point(a.begin(), a.end());
    ends.end_tangent = Point(b.begin(), b.end());
  } else if (points->size() < 4) {
    ends.condition = EndCondition::natural;
  }
  auto curve = interpolate_cubic(*points, *parameters, ends);
  if (!curve) return curve.error();
  return as_model(std::move(*curve));
}

// --- the file -------------------------------------------------------------------

/// The model with its third coordinate dropped (every z is 0).
Model in_the_plane(const Model& model) {
  const auto flat = [](const PointArray& p) {
    std::vector<double> out;
    out.reserve(p.size() * 2);
    for (std::size_t i = 0; i < p.size(); ++i) out.insert(out.end(), {p[i][0], p[i][1]});
    return PointArray::from_trusted(2, std::move(out));
  };
  const auto flat_bezier = [&](const BezierCurve& c) {
    return BezierCurve::make(flat(c.control_points()), std::vector<double>(c.weights().begin(), c.weights().end()))
        .value();
  };
  if (const auto* b = std::get_if<BezierCurve>(&model)) return Model{flat_bezier(*b)};
  if (const auto* pieces = std::get_if<PiecewiseBezierCurve>(&model)) {
    std::vector<BezierCurve> out;
    for (const BezierCurve& piece : pieces->pieces()) out.push_back(flat_bezier(piece));
    return Model{PiecewiseBezierCurve::make(std::move(out)).value()};
  }
  const auto& s = std::get<BSplineCurve>(model);
  return Model{BSplineCurve::make(s.degree(), std::vector<double>(s.knots().begin(), s.knots().end()),
                                  flat(s.control_points()), std::vector<double>(s.weights().begin(), s.weights().end()))
                   .value()};
}

bool is_flat(const Model& model) {
  bool flat = true;
  const auto check = [&](const PointArray& p) {
    for (std::size_t i = 0; i < p.size(); ++i) flat = flat && p[i][2] == 0.0;
  };
  if (const auto* b = std::get_if<BezierCurve>(&model)) check(b->control_points());
  else if (const auto* pieces = std::get_if<PiecewiseBezierCurve>(&model))
    for (const BezierCurve& piece : pieces->pieces()) check(piece.control_points());
  else check(std::get<BSplineCurve>(model).control_points());
  return flat;
}

}  // namespace

Expected<DxfDrawing> parse_dxf_drawing(std::string_view text, const std::string& source) {
  if (text.starts_with("AutoCAD Binary DXF"))
    return Error{fmt::format("{}: a binary DXF, casteljau reads ASCII DXF (save as ASCII)", source), ErrorKind::parse};
  // The groups: a code line then a value line, each without its line end.
  std::vector<Group> groups;
  std::size_t at = 0, line = 0;
  const auto next_line = [&](std::string_view& out) {
    if (at >= text.size()) return false;
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    out = text.substr(at, end - at);
    if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
    at = end + 1;
    ++line;
    return true;
  };
  std::string_view code_text, value;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") at = 3;
  while (next_line(code_text)) {
    const std::size_t code_line = line - 1;
    std::string_view trimmed = code_text;
    while (!trimmed.empty() && (trimmed.front() == ' ' || trimmed.front() == '\t')) trimmed.remove_prefix(1);
    while (!trimmed.empty() && (trimmed.back() == ' ' || trimmed.back() == '\t')) trimmed.remove_suffix(1);
    if (trimmed.empty() && at >= text.size()) break;  // a last empty line
    int code = 0;
    const auto [end, ec] = std::from_chars(trimmed.data(), trimmed.data() + trimmed.size(), code);
    if (ec != std::errc() || end != trimmed.data() + trimmed.size() || trimmed.empty())
      return Error{fmt::format("{}, line {}: '{}' is not a group code (a whole number); a DXF file alternates "
                               "code and value lines",
                               source, code_line + 1, std::string(trimmed.substr(0, 40))),
                   ErrorKind::parse};
    if (!next_line(value))
      return Error{fmt::format("{}, line {}: the file ends after group code {}, before its value", source,
                               code_line + 1, code),
                   ErrorKind::parse};
    if (code != 1 && code != 3) {  // text values keep their blanks; the others do not
      while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
      while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
    }
    groups.push_back({code, value, code_line});
  }

  DxfDrawing drawing;
  // Sections: find HEADER's $INSUNITS and the ENTITIES section.
  std::size_t i = 0;
  bool saw_eof = false;
  std::vector<Entity> entities;
  while (i < groups.size()) {
    const Group& g = groups[i];
    if (g.code == 0 && g.value == "EOF") {
      saw_eof = true;
      break;
    }
    if (!(g.code == 0 && g.value == "SECTION")) {
      ++i;
      continue;
    }
    if (i + 1 >= groups.size() || groups[i + 1].code != 2)
      return Error{fmt::format("{}, line {}: a SECTION without its name (group 2)", source, g.line + 1),
                   ErrorKind::parse};
    const std::string_view section = groups[i + 1].value;
    const std::size_t section_line = g.line;
    i += 2;
    std::size_t end = i;
    while (end < groups.size() && !(groups[end].code == 0 && groups[end].value == "ENDSEC")) ++end;
    if (end == groups.size())
      return Error{fmt::format("{}, line {}: the {} section has no ENDSEC (the file is cut short)", source,
                               section_line + 1, std::string(section)),
                   ErrorKind::parse};
    if (section == "HEADER") {
      for (std::size_t k = i; k + 1 < end; ++k)
        if (groups[k].code == 9 && groups[k].value == "$INSUNITS" && groups[k + 1].code == 70) {
          auto units = Entity::whole_of(groups[k + 1]);
          if (!units) return with_context(units.error(), source);
          drawing.insunits = *units;
        }
    } else if (section == "ENTITIES") {
      for (std::size_t k = i; k < end;) {
        if (groups[k].code != 0) {
          ++k;
          continue;
        }
        std::size_t next = k + 1;
        while (next < end && groups[next].code != 0) ++next;
        entities.emplace_back(std::string(groups[k].value),
                              std::vector<Group>(groups.begin() + static_cast<std::ptrdiff_t>(k) + 1,
                                                 groups.begin() + static_cast<std::ptrdiff_t>(next)),
                              groups[k].line + 1);
        k = next;
      }
    }
    i = end + 1;
  }
  if (!saw_eof)
    return Error{fmt::format("{}: the file ends without EOF (it is cut short, or not DXF)", source), ErrorKind::parse};

  std::size_t total_points = 0;
  for (std::size_t k = 0; k < entities.size(); ++k) {
    const Entity& e = entities[k];
    const std::string& name = e.name();
    Expected<Model> model = Error{""};
    if (name == "LINE") model = read_line(e);
    else if (name == "ARC") model = read_arc(e, false);
    else if (name == "CIRCLE") model = read_arc(e, true);
    else if (name == "ELLIPSE") model = read_ellipse(e);
    else if (name == "LWPOLYLINE") model = read_lwpolyline(e);
    else if (name == "SPLINE") model = read_spline(e);
    else if (name == "POLYLINE") {
      std::vector<Entity> vertices;
      while (k + 1 < entities.size() && entities[k + 1].name() == "VERTEX") vertices.push_back(entities[++k]);
      if (k + 1 < entities.size() && entities[k + 1].name() == "SEQEND") ++k;
      model = read_polyline(e, vertices);
    } else {
      if (name != "VERTEX" && name != "SEQEND" && name != "POINT" && name != "VIEWPORT")
        drawing.skipped.push_back(fmt::format("line {}: {}", e.line(), name.substr(0, 40)));
      continue;
    }
    const std::string handle = e.text(5);
    if (!model) {
      drawing.problems.push_back(Error{fmt::format("{}, line {}, {}{}: {}", source, e.line(), name,
                                                   handle.empty() ? "" : " (handle " + handle + ")",
                                                   model.error().message),
                                       model.error().kind});
      continue;
    }
    total_points += control_point_count(*model);
    if (total_points > tolerances::kMaxControlPoints)
      return Error{fmt::format("{}: the drawing needs more than {} control points", source,
                               tolerances::kMaxControlPoints),
                   ErrorKind::limit};
    drawing.curves.push_back(DxfCurve{std::move(*model), name, handle, e.text(8), e.line()});
  }
  const bool flat = std::all_of(drawing.curves.begin(), drawing.curves.end(),
                                [](const DxfCurve& c) { return is_flat(c.curve); });
  if (flat)
    for (DxfCurve& c : drawing.curves) c.curve = in_the_plane(c.curve);
  return drawing;
}

double dxf_unit_millimetres(int insunits) {
  switch (insunits) {
    case 1: return 25.4;        // inches
    case 2: return 304.8;       // feet
    case 3: return 1609344.0;   // miles
    case 4: return 1.0;         // millimetres
    case 5: return 10.0;        // centimetres
    case 6: return 1000.0;      // metres
    case 7: return 1e6;         // kilometres
    case 8: return 25.4e-6;     // microinches
    case 9: return 0.0254;      // mils
    case 10: return 914.4;      // yards
    case 11: return 1e-7;       // angstroms
    case 12: return 1e-6;       // nanometres
    case 13: return 1e-3;       // microns
    case 14: return 100.0;      // decimetres
    case 15: return 1e4;        // decametres
    case 16: return 1e5;        // hectometres
    case 17: return 1e12;       // gigametres
    case 18: return 1.495978707e14;         // astronomical units (IAU 2012)
    case 19: return 9.4607304725808e18;     // light years (Julian)
    case 20: return 3.0856775814913673e19;  // parsecs (IAU 2015)
    default: return 0.0;        // unitless, or no unit code of DXF
  }
}

std::string dxf_unit_name(int insunits) {
  switch (insunits) {
    case 0: return "no unit";
    case 1: return "inches";
    case 2: return "feet";
    case 3: return "miles";
    case 4: return "millimetres";
    case 5: return "centimetres";
    case 6: return "metres";
    case 7: return "kilometres";
    case 8: return "microinches";
    case 9: return "mils";
    case 10: return "yards";
    case 11: return "angstroms";
    case 12: return "nanometres";
    case 13: return "microns";
    case 14: return "decimetres";
    case 15: return "decametres";
    case 16: return "hectometres";
    case 17: return "gigametres";
    case 18: return "astronomical units";
    case 19: return "light years";
    case 20: return "parsecs";
    default: return fmt::format("unit code {}", insunits);
  }
}

Expected<DxfDrawing> read_dxf_drawing(const std::filesystem::path& path) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  return parse_dxf_drawing(*text, display_name(path));
}

}  // namespace casteljau

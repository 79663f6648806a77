// The playground's questions asked of any curve (the curve concept through
// CurveView): points to draw, points at parameters, the nearest point,
// intersections, equal arc-length spacing and arc splines. JavaScript names
// in camelCase; see playground/js/library.js for how the page calls them.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "casteljau/ops/arc_spline.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/ops/intersection.hpp"
#include "curve_values.hpp"
#include "js_values.hpp"

namespace casteljau::wasm {
namespace {

using emscripten::val;

/// {points, parameters}: the certified polyline within `tolerance` (flatten).
val polyline(const val& description, double tolerance) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  return value_or_error(flatten(view_of(*curve), Tolerance{tolerance}), [](const Polyline& line) {
    val out = val::object();
    out.set("points", float64_array(line.points.coordinates()));
    out.set("parameters", float64_array(line.parameters));
    return out;
  });
}

/// The points at the given parameters, flat (the curve extrapolates outside its domain).
val points_at_parameters(const val& description, const val& parameters) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  const CurveView view = view_of(*curve);
  const std::vector<double> us = numbers_of(parameters);
  std::vector<double> out(us.size() * static_cast<std::size_t>(view.dimension()));
  points_at(view, us, out);
  return float64_array(out);
}

/// [lower, upper] of the curve's parameter.
val domain_of(const val& description) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  const Interval domain = view_of(*curve).domain();
  const double bounds[] = {domain.lower, domain.upper};
  return float64_array(bounds);
}

/// {parameter, distance, point}: the nearest point of the curve to (x, y).
val nearest_point(const val& description, double x, double y) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  return value_or_error(closest_point(view_of(*curve), {x, y}), [](const NearestPoint& nearest) {
    val out = val::object();
    out.set("parameter", nearest.parameter);
    out.set("distance", nearest.distance);
    out.set("point", float64_array(nearest.point));
    return out;
  });
}

/// [{kind, a: [a0, a1], b: [b0, b1], point}]: every intersection of two curves
/// (self-intersections when `other` is null), at the library's default tolerance.
val curve_intersections(const val& first, const val& other) {
  const auto a = curve_of(first);
  if (!a) return error_value(a.error());
  const bool self = other.isNull() || other.isUndefined();
  const auto b = self ? a : curve_of(other);
  if (!b) return error_value(b.error());
  const CurveView view_a = view_of(*a), view_b = view_of(*b);
  const Tolerance tolerance = default_intersection_tolerance(view_a, view_b);
  const auto found = self ? self_intersections(view_a, tolerance) : intersections(view_a, view_b, tolerance);
  return value_or_error(found, [](const std::vector<CurveIntersection>& list) {
    val out = val::array();
    for (const CurveIntersection& meeting : list) {
      val entry = val::object();
      entry.set("kind", std::string(kind_name(meeting.kind)));
      const double a_range[] = {meeting.a.lower, meeting.a.upper}, b_range[] = {meeting.b.lower, meeting.b.upper};
      entry.set("a", float64_array(a_range));
      entry.set("b", float64_array(b_range));
      entry.set("point", float64_array(meeting.point));
      out.call<void>("push", entry);
    }
    return out;
  });
}

/// `count` parameters equally spaced along the curve (default arc-length tolerance).
val equal_length_parameters(const val& description, int count) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  if (count < 2) return error_value(Error{"equal arc-length spacing needs at least 2 points"});
  const CurveView view = view_of(*curve);
  return value_or_error(equal_arc_length_parameters(view, static_cast<std::size_t>(count),
                                                    default_arc_length_tolerance(view)),
                        [](const std::vector<double>& us) { return float64_array(us); });
}

/// The curve's length at the default arc-length tolerance.
val length_of(const val& description) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  const CurveView view = view_of(*curve);
  return value_or_error(arc_length(view, default_arc_length_tolerance(view)),
                        [](double length) { return val(length); });
}

// The most points the page may ask for along each arc when drawing an arc spline.
constexpr int kMaxPointsPerArc = 256;

/// {segments: Float64Array of (x0, y0, x1, y1, bulge) rows, points: each
/// element drawn as points_per_arc + 1 points along it (point_along, end to
/// end), parameters, deviationBound}.
val arc_spline(const val& description, double tolerance, int points_per_arc) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  if (points_per_arc < 1 || points_per_arc > kMaxPointsPerArc) {
    return error_value(Error{"points per arc must be in 1.." + std::to_string(kMaxPointsPerArc)});
  }
  return value_or_error(fit_arcs(view_of(*curve), Tolerance{tolerance}), [&](const ArcSpline& arcs) {
    std::vector<double> rows, points;
    rows.reserve(arcs.segments.size() * 5);
    for (const ArcSegment& arc : arcs.segments) {
      rows.insert(rows.end(), {arc.start[0], arc.start[1], arc.end[0], arc.end[1], arc.bulge});
      for (int k = 0; k <= points_per_arc; ++k) {
        const Vec2 p = point_along(arc, static_cast<double>(k) / points_per_arc);
        points.insert(points.end(), {p[0], p[1]});
      }
    }
    val out = val::object();
    out.set("segments", float64_array(rows));
    out.set("points", float64_array(points));
    out.set("parameters", float64_array(arcs.parameters));
    out.set("deviationBound", arcs.deviation_bound);
    return out;
  });
}

/// The curve read and written back: checks a description, and gives its canonical form.
val checked_curve(const val& description) {
  const auto curve = curve_of(description);
  if (!curve) return error_value(curve.error());
  return description_of(*curve);
}

}  // namespace
}  // namespace casteljau::wasm

EMSCRIPTEN_BINDINGS(casteljau_curves) {
  using namespace casteljau::wasm;
  emscripten::function("polyline", &polyline);
  emscripten::function("pointsAt", &points_at_parameters);
  emscripten::function("domain", &domain_of);
  emscripten::function("closestPoint", &nearest_point);
  emscripten::function("intersections", &curve_intersections);
  emscripten::function("equalArcLengthParameters", &equal_length_parameters);
  emscripten::function("arcLength", &length_of);
  emscripten::function("fitArcs", &arc_spline);
  emscripten::function("checkCurve", &checked_curve);
}

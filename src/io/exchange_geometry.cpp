// Models in the one form IGES and STEP share (src/io/exchange_geometry.hpp).
#include "exchange_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/surfaces/refinement.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "text.hpp"

namespace casteljau::detail {
namespace {

/// Appends the point as x y z (0 for the coordinates a plane point lacks).
void append_point(std::vector<double>& out, std::span<const double> p) {
  for (int k = 0; k < 3; ++k) out.push_back(k < static_cast<int>(p.size()) ? p[k] : 0.0);
}

std::vector<double> weights_or_ones(std::span<const double> weights, std::size_t count) {
  if (weights.empty()) return std::vector<double>(count, 1.0);
  return {weights.begin(), weights.end()};
}

/// The axis along which every point (x y z triples) has the same coordinate,
/// z first; -1 when there is none.
int plane_axis(const std::vector<double>& points) {
  for (int k : {2, 0, 1}) {
    bool equal = true;
    for (std::size_t i = 3 + k; i < points.size() && equal; i += 3) equal = points[i] == points[k];
    if (equal) return k;
  }
  return -1;
}

ExchangeCurve exchange_curve(const BSplineCurve& curve) {
  ExchangeCurve out;
  out.degree = curve.degree();
  out.knots.assign(curve.knots().begin(), curve.knots().end());
  const PointArray& points = curve.control_points();
  out.points.reserve(3 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i) append_point(out.points, points[i]);
  out.weights = weights_or_ones(curve.weights(), points.size());
  out.rational = curve.is_rational();
  out.domain = curve.domain();
  out.closed = point_at(curve, out.domain.lower) == point_at(curve, out.domain.upper);
  out.plane_axis = curve.dimension() == 2 ? 2 : plane_axis(out.points);
  return out;
}

ExchangeSurface exchange_surface(const BSplineSurface& surface) {
  ExchangeSurface out;
  out.degree_u = surface.degree_u();
  out.degree_v = surface.degree_v();
  out.knots_u.assign(surface.knots_u().begin(), surface.knots_u().end());
  out.knots_v.assign(surface.knots_v().begin(), surface.knots_v().end());
  const ControlNet& net = surface.control_net();
  out.rows = net.rows();
  out.columns = net.columns();
  out.points.reserve(3 * out.rows * out.columns);
  for (std::size_t i = 0; i < out.rows; ++i)
    for (std::size_t j = 0; j < out.columns; ++j) append_point(out.points, net(i, j));
  out.weights = weights_or_ones(surface.weights(), out.rows * out.columns);
  out.rational = surface.is_rational();
  out.domain_u = surface.domain_u();
  out.domain_v = surface.domain_v();
  // Closed in u: S(u0, v) = S(u1, v) for every v, which for clamped knots
  // (the writers clamp first) is the first row of weighted control points
  // equal to the last.
  const auto same = [&](std::size_t a, std::size_t b) {
    return out.weights[a] == out.weights[b] && std::equal(out.points.begin() + 3 * a, out.points.begin() + 3 * a + 3,
                                                          out.points.begin() + 3 * b);
  };
  out.closed_u = out.closed_v = true;
  for (std::size_t j = 0; j < out.columns; ++j) out.closed_u = out.closed_u && same(j, (out.rows - 1) * out.columns + j);
  for (std::size_t i = 0; i < out.rows; ++i)
    out.closed_v = out.closed_v && same(i * out.columns, i * out.columns + out.columns - 1);
  return out;
}

/// The lowest degree of a B-spline curve or surface (in either direction).
struct Lowest {
  int operator()(const BSplineCurve& curve) const { return curve.degree(); }
  int operator()(const BSplineSurface& surface) const { return std::min(surface.degree_u(), surface.degree_v()); }
  int operator()(const auto&) const { return 1; }  // to_bspline gives only the two above
};

void include_in_box(ExchangeGeometry& geometry, const std::vector<double>& points, double lower[3], double upper[3],
                    bool& first) {
  for (std::size_t i = 0; i < points.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      const double x = points[i + k];
      geometry.largest_coordinate = std::max(geometry.largest_coordinate, std::abs(x));
      lower[k] = first ? x : std::min(lower[k], x);
      upper[k] = first ? x : std::max(upper[k], x);
      if (k == 2) first = false;
    }
}

}  // namespace

Expected<ExchangeGeometry> exchange_geometry(std::span<const Model> models, const char* format) {
  if (models.empty()) return Error{fmt::format("no models to write: {} needs at least one curve or surface", format)};
  ExchangeGeometry geometry;
  double lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};
  bool first = true;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const int d = dimension_of(models[i]);
    if (d != 2 && d != 3)
      return Error{fmt::format("model {} ({}) lives in R^{}, {} holds plane and space geometry", i,
                               type_name(models[i]), d, format)};
    auto spline = to_bspline(models[i]);
    if (!spline) return with_context(spline.error(), fmt::format("model {} ({})", i, type_name(models[i])));
    const int lowest = std::visit(Lowest{}, *spline);
    if (lowest < 1)
      return Error{fmt::format("model {} ({}) has degree 0 (steps, not a curve); {} B-splines have degree >= 1", i,
                               type_name(models[i]), format)};
    // Clamped knots: CAD readers expect them (OpenCASCADE evaluates an
    // unclamped surface as NaN), and clamping keeps the curve.
    if (const auto* curve = std::get_if<BSplineCurve>(&*spline)) {
      const ExchangeCurve& item = std::get<ExchangeCurve>(geometry.items.emplace_back(exchange_curve(clamped(*curve))));
      include_in_box(geometry, item.points, lower, upper, first);
    } else {
      const BSplineSurface& surface = std::get<BSplineSurface>(*spline);
      const ExchangeSurface& item = std::get<ExchangeSurface>(
          geometry.items.emplace_back(exchange_surface(clamped(clamped(surface, Direction::u), Direction::v))));
      include_in_box(geometry, item.points, lower, upper, first);
      geometry.has_surfaces = true;
    }
  }
  geometry.size = std::hypot(upper[0] - lower[0], upper[1] - lower[1], upper[2] - lower[2]);
  return geometry;
}

DistinctKnots distinct_knots(std::span<const double> knots) {
  DistinctKnots out;
  for (double knot : knots) {
    if (!out.values.empty() && out.values.back() == knot) {
      ++out.multiplicities.back();
    } else {
      out.values.push_back(knot);
      out.multiplicities.push_back(1);
    }
  }
  return out;
}

Expected<std::string> timestamp_digits(std::string_view timestamp) {
  constexpr std::string_view shape = "dddd-dd-ddTdd:dd:dd";
  std::string digits;
  bool valid = timestamp.size() == shape.size();
  for (std::size_t i = 0; valid && i < shape.size(); ++i) {
    valid = shape[i] == 'd' ? timestamp[i] >= '0' && timestamp[i] <= '9' : timestamp[i] == shape[i];
    if (shape[i] == 'd') digits += timestamp[i];
  }
  if (!valid)
    return Error{fmt::format("the timestamp {} is not of the form YYYY-MM-DDTHH:MM:SS", io_detail::in_quotes(timestamp, 40))};
  return digits;
}

std::string exchange_real(double value) {
  if (value == 0.0) return "0.";
  // fmt's {} is the shortest round-trip form: "1", "0.5", "1e-05", "1.5e+20".
  std::string text = fmt::format("{}", value);
  const auto exponent = text.find('e');
  std::string mantissa = text.substr(0, exponent);
  if (mantissa.find('.') == std::string::npos) mantissa += '.';
  if (exponent == std::string::npos) return mantissa;
  return mantissa + 'E' + text.substr(exponent + 1);
}

}  // namespace casteljau::detail

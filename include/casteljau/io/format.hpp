#pragma once
// The text form of points and curves, for logs, tests and debugging:
// fmt::formatter specialisations and operator<< for Vec<D>, PointArray and
// the three curve kinds. A format spec applies to every number, as it would
// to one double: fmt::format("{:.3f}", point) gives "(1.000, 2.500)"; the
// default "{}" is the shortest text that reads back to the same double.
//
//   Vec<2>            (1, 2.5)
//   PointArray        [(0, 0), (1, 2), (2, 0)]
//   BezierCurve       bezier degree 2 in R^2 [(0, 0), (1, 2), (2, 0)] weights [1, 0.5, 1]
//   PiecewiseBezier   piecewise_bezier of 2 pieces in R^2 [degree 1 [(0, 0), (1, 1)], degree 1 [...]]
//   BSplineCurve      bspline degree 2 in R^2 knots [0, 0, 0, 1, 1, 1] [(0, 0), (1, 2), (2, 0)]
//
// The kinds are named as in model JSON; weights appear only for a rational
// curve. Not a file format (model JSON is: io/model_json.hpp).

#include <cstddef>
#include <ostream>
#include <span>

#include <fmt/format.h>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau::detail {

/// A formatter whose spec is a double's, applied to each number it writes.
struct NumbersFormatter : fmt::formatter<double> {
  /// "(x, y, ...)".
  fmt::format_context::iterator point(std::span<const double> coordinates, fmt::format_context& context) const {
    return sequence(coordinates, '(', ')', context);
  }
  /// "[a, b, ...]".
  fmt::format_context::iterator numbers(std::span<const double> values, fmt::format_context& context) const {
    return sequence(values, '[', ']', context);
  }
  /// "[(..), (..)]".
  fmt::format_context::iterator points(const PointArray& points, fmt::format_context& context) const {
    auto out = context.out();
    *out++ = '[';
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i > 0) out = fmt::format_to(out, ", ");
      context.advance_to(out);
      out = point(points[i], context);
    }
    *out++ = ']';
    return out;
  }
  /// " weights [..]" for a rational curve, nothing otherwise.
  fmt::format_context::iterator weights(std::span<const double> weights, fmt::format_context& context) const {
    auto out = context.out();
    if (weights.empty()) return out;
    out = fmt::format_to(out, " weights ");
    context.advance_to(out);
    return numbers(weights, context);
  }

 private:
  fmt::format_context::iterator sequence(std::span<const double> values, char open, char close,
                                         fmt::format_context& context) const {
    auto out = context.out();
    *out++ = open;
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (i > 0) out = fmt::format_to(out, ", ");
      context.advance_to(out);
      out = fmt::formatter<double>::format(values[i], context);
    }
    *out++ = close;
    return out;
  }
};

}  // namespace casteljau::detail

/// (x, y, ...).
template <int D>
struct fmt::formatter<casteljau::Vec<D>> : casteljau::detail::NumbersFormatter {
  auto format(const casteljau::Vec<D>& v, fmt::format_context& context) const {
    return point(std::span<const double>(v.coordinates), context);
  }
};

/// [(x, y), ...].
template <>
struct fmt::formatter<casteljau::PointArray> : casteljau::detail::NumbersFormatter {
  auto format(const casteljau::PointArray& array, fmt::format_context& context) const {
    return points(array, context);
  }
};

/// bezier degree n in R^d [control points] (weights [..]).
template <>
struct fmt::formatter<casteljau::BezierCurve> : casteljau::detail::NumbersFormatter {
  auto format(const casteljau::BezierCurve& curve, fmt::format_context& context) const {
    context.advance_to(fmt::format_to(context.out(), "bezier degree {} in R^{} ", curve.degree(), curve.dimension()));
    context.advance_to(points(curve.control_points(), context));
    return weights(curve.weights(), context);
  }
};

/// piecewise_bezier of m pieces in R^d [degree n [..] (weights [..]), ...].
template <>
struct fmt::formatter<casteljau::PiecewiseBezierCurve> : casteljau::detail::NumbersFormatter {
  auto format(const casteljau::PiecewiseBezierCurve& curve, fmt::format_context& context) const {
    const auto& pieces = curve.pieces();
    context.advance_to(fmt::format_to(context.out(), "piecewise_bezier of {} pieces in R^{} [", pieces.size(),
                                      curve.dimension()));
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      context.advance_to(fmt::format_to(context.out(), "{}degree {} ", i > 0 ? ", " : "", pieces[i].degree()));
      context.advance_to(points(pieces[i].control_points(), context));
      context.advance_to(weights(pieces[i].weights(), context));
    }
    auto out = context.out();
    *out++ = ']';
    return out;
  }
};

/// bspline degree p in R^d knots [..] [control points] (weights [..]).
template <>
struct fmt::formatter<casteljau::BSplineCurve> : casteljau::detail::NumbersFormatter {
  auto format(const casteljau::BSplineCurve& curve, fmt::format_context& context) const {
    context.advance_to(
        fmt::format_to(context.out(), "bspline degree {} in R^{} knots ", curve.degree(), curve.dimension()));
    context.advance_to(numbers(curve.knots(), context));
    context.advance_to(fmt::format_to(context.out(), " "));
    context.advance_to(points(curve.control_points(), context));
    return weights(curve.weights(), context);
  }
};

namespace casteljau {

/// The text form above, with the default "{}" format.
template <int D>
std::ostream& operator<<(std::ostream& out, const Vec<D>& v) { return out << fmt::format("{}", v); }
inline std::ostream& operator<<(std::ostream& out, const PointArray& points) {
  return out << fmt::format("{}", points);
}
inline std::ostream& operator<<(std::ostream& out, const BezierCurve& curve) {
  return out << fmt::format("{}", curve);
}
inline std::ostream& operator<<(std::ostream& out, const PiecewiseBezierCurve& curve) {
  return out << fmt::format("{}", curve);
}
inline std::ostream& operator<<(std::ostream& out, const BSplineCurve& curve) {
  return out << fmt::format("{}", curve);
}

}  // namespace casteljau

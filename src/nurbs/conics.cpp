// Exact conics as rational quadratic B-splines (The NURBS Book §7.5, A7.1).
#include "casteljau/nurbs/conics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/nurbs/tolerance.hpp"
#include "../core/number_text.hpp"

namespace casteljau {
namespace {

using detail::number_text;

constexpr double kPi = std::numbers::pi;
constexpr double kEighthTurn = kPi / 4;  // exact: pi scaled by 2^-2
constexpr double kSqrtHalf = std::numbers::sqrt2 / 2;  // cos 45° rounded once (0.7071067811865476)

/// cos θ and sin θ, exact (0, ±1, ±√½ rounded once) when θ is, in double, a
/// multiple k π/4 of an eighth turn: std::cos(std::numbers::pi / 2) is 6e-17,
/// not 0, and that would put a quarter circle's control points off the axes.
std::pair<double, double> cos_sin(double angle) {
  const double eighths = angle / kEighthTurn;
  const double k = std::nearbyint(eighths);
  if (eighths == k && std::abs(k) <= 64 && k * kEighthTurn == angle) {
    static constexpr double kCos[8] = {1, kSqrtHalf, 0, -kSqrtHalf, -1, -kSqrtHalf, 0, kSqrtHalf};
    static constexpr double kSin[8] = {0, kSqrtHalf, 1, kSqrtHalf, 0, -kSqrtHalf, -1, -kSqrtHalf};
    const int index = ((static_cast<int>(k) % 8) + 8) % 8;
    return {kCos[index], kSin[index]};
  }
  return {std::cos(angle), std::sin(angle)};
}

/// A radius or semi-axis: finite, > 0 and a valid coordinate (at most
/// tolerances::kMaxCoordinate).
Status check_positive(double value, const char* what) {
  if (auto ok = check_finite(value, what); !ok) return Error{ok.error().message + ", it must be finite and > 0", ok.error().kind};
  if (!(value > 0.0)) {
    return Error{std::string(what) + " is " + number_text(value) + ", it must be finite and > 0"};
  }
  if (!is_valid_coordinate(value)) {
    return Error{std::string(what) + " is " + number_text(value) + ", outside (0, " +
                 number_text(tolerances::kMaxCoordinate) + "], the range of coordinates"};
  }
  return {};
}

double dot(const Point& a, const Point& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

/// Checks the frame and returns it with its axes re-orthonormalized
/// (Gram–Schmidt): exact unit axes such as (1, 0, 0) come back unchanged.
Expected<ConicFrame> checked_frame(const ConicFrame& frame) {
  const std::size_t d = frame.center.size();
  if (d < 2) return Error{"the centre has " + std::to_string(d) + " coordinates, a conic needs a plane (d >= 2)"};
  if (frame.x_axis.size() != d || frame.y_axis.size() != d) {
    return Error{"the axes have " + std::to_string(frame.x_axis.size()) + " and " +
                 std::to_string(frame.y_axis.size()) + " coordinates, the centre has " + std::to_string(d)};
  }
  // The centre is a point of the curve's space (a valid coordinate each); the
  // axes need only be finite, the orthonormality check bounds them.
  const std::pair<const Point*, const char*> parts[] = {
      {&frame.center, "centre"}, {&frame.x_axis, "x axis"}, {&frame.y_axis, "y axis"}};
  for (const auto& [point, name] : parts) {
    for (std::size_t i = 0; i < d; ++i) {
      const std::string what = "coordinate " + std::to_string(i) + " of the " + name;
      if (auto ok = point == &frame.center ? check_coordinate((*point)[i], what) : check_finite((*point)[i], what);
          !ok) {
        return ok.error();
      }
    }
  }
  const double x_norm = std::sqrt(dot(frame.x_axis, frame.x_axis));
  const double y_norm = std::sqrt(dot(frame.y_axis, frame.y_axis));
  const double cosine = dot(frame.x_axis, frame.y_axis);
  const double tol = tolerances::kOrthonormalAxes;
  if (std::abs(x_norm - 1.0) > tol || std::abs(y_norm - 1.0) > tol || std::abs(cosine) > tol) {
    return Error{"the axes are not orthonormal (|x axis| = " + number_text(x_norm) + ", |y axis| = " +
                 number_text(y_norm) + ", x axis . y axis = " + number_text(cosine) + "; each must be within " +
                 number_text(tol) + " of 1, 1, 0)"};
  }
  ConicFrame out = frame;
  for (double& c : out.x_axis) c /= x_norm;
  const double projection = dot(out.y_axis, out.x_axis);
  for (std::size_t i = 0; i < d; ++i) out.y_axis[i] -= projection * out.x_axis[i];
  const double norm = std::sqrt(dot(out.y_axis, out.y_axis));
  for (double& c : out.y_axis) c /= norm;
  return out;
}

/// Appends O + a X + b Y (a, b already scaled by the radius).
void push_point(std::vector<double>& coordinates, const ConicFrame& frame, double a, double b) {
  for (std::size_t i = 0; i < frame.center.size(); ++i) {
    coordinates.push_back(frame.center[i] + a * frame.x_axis[i] + b * frame.y_axis[i]);
  }
}

/// The control net of an elliptic arc O + a cos θ X + b sin θ Y, θ from
/// `start` over `sweep` (A7.1 with the circle's net scaled by (a, b) in the
/// frame). Inputs already checked.
Expected<BSplineCurve> elliptic_arc(const ConicFrame& frame, double a, double b, double start, double sweep) {
  // A7.1: one piece per started quarter turn, so that no piece spans more
  // than 90° (cos(dθ/2) >= √½ keeps the middle control point near the arc).
  const double turn = std::abs(sweep);
  const int pieces = turn <= kPi / 2 ? 1 : turn <= kPi ? 2 : turn <= 1.5 * kPi ? 3 : 4;
  const double step = sweep / pieces;
  const double weight = cos_sin(std::abs(step) / 2).first;
  std::vector<double> coordinates;
  std::vector<double> weights;
  std::vector<double> knots{0.0, 0.0, 0.0};
  coordinates.reserve(static_cast<std::size_t>(2 * pieces + 1) * frame.center.size());
  const auto [c0, s0] = cos_sin(start);
  push_point(coordinates, frame, a * c0, b * s0);
  weights.push_back(1.0);
  for (int i = 1; i <= pieces; ++i) {
    // Middle control point: where the end tangents meet, at angle
    // θ_{i-1} + dθ/2 and distance r / cos(dθ/2) (for the circle; the
    // ellipse is its image under the axis scaling).
    const double end_angle = i == pieces ? start + sweep : start + i * step;
    const double middle_angle = start + (2 * i - 1) * (step / 2);
    const auto [cm, sm] = cos_sin(middle_angle);
    push_point(coordinates, frame, a * (cm / weight), b * (sm / weight));
    weights.push_back(weight);
    // A full turn closes exactly: its last point is its first, bit for bit.
    const auto [c1, s1] = i == pieces && turn == 2 * kPi ? std::pair{c0, s0} : cos_sin(end_angle);
    push_point(coordinates, frame, a * c1, b * s1);
    weights.push_back(1.0);
    if (i < pieces) {
      const double knot = static_cast<double>(i) / pieces;
      knots.push_back(knot);
      knots.push_back(knot);
    }
  }
  knots.insert(knots.end(), {1.0, 1.0, 1.0});
  // The centre and the radius are each within the range of coordinates, and
  // so every control point within a few times it (finite): the middle ones
  // lie at distance r / cos(dθ/2) <= r √2 from the centre, and can leave it.
  PointArray points = PointArray::from_trusted(static_cast<int>(frame.center.size()), std::move(coordinates));
  if (auto ok = check_coordinates(points, "control point"); !ok) {
    return with_context(ok.error(), "the conic reaches outside the range of coordinates");
  }
  return BSplineCurve::make(2, std::move(knots), std::move(points), std::move(weights));
}

Expected<BSplineCurve> checked_arc(const ConicFrame& frame, double a, double b, double start, double sweep) {
  auto checked = checked_frame(frame);
  if (!checked) return checked.error();
  if (auto ok = check_finite(start, "the start angle"); !ok) return ok.error();
  if (auto ok = check_finite(sweep, "the sweep"); !ok) return ok.error();
  if (sweep == 0.0) return Error{"the sweep is 0, an arc needs a sweep in [-2π, 0) or (0, 2π]"};
  if (std::abs(sweep) > 2 * kPi) {
    return Error{"the sweep is " + number_text(sweep) + ", more than a full turn (|sweep| <= 2π = " +
                 number_text(2 * kPi) + ")"};
  }
  return elliptic_arc(*checked, a, b, start, sweep);
}

}  // namespace

ConicFrame plane_frame(double center_x, double center_y) {
  return ConicFrame{{center_x, center_y}, {1.0, 0.0}, {0.0, 1.0}};
}

Expected<BSplineCurve> make_arc(const ConicFrame& frame, double radius, double start_angle, double sweep) {
  if (auto ok = check_positive(radius, "the radius"); !ok) return ok.error();
  return checked_arc(frame, radius, radius, start_angle, sweep);
}

Expected<BSplineCurve> make_arc(double center_x, double center_y, double radius, double start_angle,
                                double sweep) {
  return make_arc(plane_frame(center_x, center_y), radius, start_angle, sweep);
}

Expected<BSplineCurve> make_circle(const ConicFrame& frame, double radius) {
  if (auto ok = check_positive(radius, "the radius"); !ok) return ok.error();
  // Four quarter arcs from angle 0: cos_sin makes every control point the
  // exact corner or edge midpoint of the square around the circle.
  return checked_arc(frame, radius, radius, 0.0, 2 * kPi);
}

Expected<BSplineCurve> make_circle(double center_x, double center_y, double radius) {
  return make_circle(plane_frame(center_x, center_y), radius);
}

Expected<BSplineCurve> make_ellipse(const ConicFrame& frame, double semi_axis_x, double semi_axis_y) {
  if (auto ok = check_positive(semi_axis_x, "the semi-axis along x"); !ok) return ok.error();
  if (auto ok = check_positive(semi_axis_y, "the semi-axis along y"); !ok) return ok.error();
  return checked_arc(frame, semi_axis_x, semi_axis_y, 0.0, 2 * kPi);
}

Expected<BSplineCurve> make_ellipse(double center_x, double center_y, double semi_axis_x, double semi_axis_y) {
  return make_ellipse(plane_frame(center_x, center_y), semi_axis_x, semi_axis_y);
}

BSplineCurve seed_semicircle() { return make_arc(0.0, 0.0, 3.0, kPi, -kPi).value(); }

BezierCurve seed_semicircle_cubic() {
  return BezierCurve::from_trusted(PointArray::from_trusted(2, {-3.0, 0.0, -3.0, 4.0, 3.0, 4.0, 3.0, 0.0}));
}

}  // namespace casteljau

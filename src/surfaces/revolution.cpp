// Surfaces of revolution (The NURBS Book A8.1), the sphere and the torus.
#include "casteljau/surfaces/revolution.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/core/vec.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "../core/number_text.hpp"

namespace casteljau {
namespace {

using detail::number_text;

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;  // exact: pi scaled by 2
constexpr double kEighthTurn = kPi / 4.0;          // exact: pi scaled by 2^-2
constexpr double kSqrtHalf = std::numbers::sqrt2 / 2.0;

/// cos and sin of an angle; exact (0, ±1, ±√½ rounded once) when the angle
/// is, in double, a multiple of π/4: the arcs of a full turn start at 0,
/// π/2, π, 3π/2, whose library cosines are 6e-17 and the like, which would
/// put the control points of an axis-aligned circle off its axes.
std::pair<double, double> cos_sin(double angle) {
  const double eighths = std::nearbyint(angle / kEighthTurn);
  if (std::abs(eighths) <= 64 && eighths * kEighthTurn == angle) {
    static constexpr double kCos[8] = {1, kSqrtHalf, 0, -kSqrtHalf, -1, -kSqrtHalf, 0, kSqrtHalf};
    static constexpr double kSin[8] = {0, kSqrtHalf, 1, kSqrtHalf, 0, -kSqrtHalf, -1, -kSqrtHalf};
    const int index = ((static_cast<int>(eighths) % 8) + 8) % 8;
    return {kCos[index], kSin[index]};
  }
  return {std::cos(angle), std::sin(angle)};
}

/// Three finite coordinates, named in the error.
Expected<Vec3> checked_point(std::span<const double> point, const char* what) {
  if (point.size() != 3) {
    return Error{std::string("the ") + what + " has " + std::to_string(point.size()) + " coordinates, it needs 3"};
  }
  for (std::size_t c = 0; c < 3; ++c) {
    if (auto ok = check_finite(point[c], "coordinate " + std::to_string(c) + " of the " + what); !ok) return ok.error();
  }
  return Vec3{{point[0], point[1], point[2]}};
}

/// The unit axis direction, or an error for a zero one.
Expected<Vec3> checked_direction(std::span<const double> direction, const char* what) {
  auto d = checked_point(direction, what);
  if (!d) return d.error();
  const double length = norm(*d);
  if (!(length > 0.0) || !std::isfinite(length)) {
    return Error{std::string("the ") + what + " is the zero vector (or too large to normalize), it must give a direction"};
  }
  return Vec3{{(*d)[0] / length, (*d)[1] / length, (*d)[2] / length}};
}

Status check_radius(double radius, const char* what) {
  if (auto ok = check_finite(radius, what); !ok) return Error{ok.error().message + ", it must be finite and > 0", ok.error().kind};
  if (!(radius > 0.0)) return Error{std::string(what) + " is " + number_text(radius) + ", it must be finite and > 0"};
  return {};
}

/// A unit vector orthogonal to the unit vector t: t crossed with the
/// coordinate axis it is least aligned with, normalized.
Vec3 orthogonal_unit(const Vec3& t) {
  std::size_t k = 0;
  for (std::size_t c = 1; c < 3; ++c)
    if (std::abs(t[c]) < std::abs(t[k])) k = c;
  Vec3 e{};
  e[k] = 1.0;
  const Vec3 x = cross(t, e);
  const double length = norm(x);
  return Vec3{{x[0] / length, x[1] / length, x[2] / length}};
}

}  // namespace

Expected<BSplineSurface> revolve(const BSplineCurve& profile, std::span<const double> axis_point,
                                 std::span<const double> axis_direction, double angle) {
  if (profile.dimension() != 3) {
    return Error{"the profile has " + std::to_string(profile.dimension()) +
                 " coordinates, a surface of revolution needs a 3D profile"};
  }
  auto origin = checked_point(axis_point, "axis point");
  if (!origin) return origin.error();
  auto axis = checked_direction(axis_direction, "axis direction");
  if (!axis) return axis.error();
  if (auto ok = check_finite(angle, "the angle"); !ok) return ok.error();
  if (!(angle > 0.0) || angle > kTwoPi) {
    return Error{"the angle is " + number_text(angle) + ", it must be > 0 and at most 2π (" + number_text(kTwoPi) + ")"};
  }
  const bool full_turn = angle == kTwoPi;
  const int arcs = angle <= kPi / 2 ? 1 : angle <= kPi ? 2 : angle <= 3 * kPi / 2 ? 3 : 4;
  const double sweep = angle / arcs;
  const double mid_weight = cos_sin(sweep / 2).first;
  const Vec3& s = *origin;
  const Vec3& t = *axis;

  const std::size_t rows = static_cast<std::size_t>(2 * arcs + 1);
  const std::size_t columns = profile.control_points().size();
  std::vector<double> coordinates(rows * columns * 3);
  std::vector<double> weights(rows * columns);
  auto put = [&](std::size_t i, std::size_t j, const Vec3& point, double weight) {
    for (std::size_t c = 0; c < 3; ++c) coordinates[(i * columns + j) * 3 + c] = point[c];
    weights[i * columns + j] = weight;
  };
  for (std::size_t j = 0; j < columns; ++j) {
    const auto p = profile.control_points()[j];
    const Vec3 point{{p[0], p[1], p[2]}};
    const double w = profile.is_rational() ? profile.weights()[j] : 1.0;
    // O: the foot of P on the axis; X, Y: the plane of P's circle.
    const Vec3 offset = point - s;
    const double along = dot(offset, t);
    const Vec3 foot{{s[0] + along * t[0], s[1] + along * t[1], s[2] + along * t[2]}};
    Vec3 x = point - foot;
    const double r = norm(x);
    put(0, j, point, w);
    if (r == 0.0) {  // on the axis: the point does not move
      for (std::size_t i = 1; i < rows; ++i) put(i, j, point, (i % 2 == 1) ? w * mid_weight : w);
      continue;
    }
    x = Vec3{{x[0] / r, x[1] / r, x[2] / r}};
    const Vec3 y = cross(t, x);
    auto on_circle = [&](double theta, double radius) {
      const auto [c, sn] = cos_sin(theta);
      return Vec3{{foot[0] + radius * (c * x[0] + sn * y[0]), foot[1] + radius * (c * x[1] + sn * y[1]),
                     foot[2] + radius * (c * x[2] + sn * y[2])}};
    };
    for (int a = 0; a < arcs; ++a) {
      const double start = a * sweep;
      // Where the end tangents of the arc meet: at r / cos(dθ/2) on the bisector.
      put(static_cast<std::size_t>(2 * a + 1), j, on_circle(start + sweep / 2, r / mid_weight), w * mid_weight);
      const std::size_t end_row = static_cast<std::size_t>(2 * a + 2);
      if (end_row == rows - 1 && full_turn) {
        put(end_row, j, point, w);  // the seam: a copy of row 0
      } else {
        put(end_row, j, on_circle(a + 1 == arcs ? angle : (a + 1) * sweep, r), w);
      }
    }
  }
  std::vector<double> knots_u(3, 0.0);
  for (int a = 1; a < arcs; ++a) knots_u.insert(knots_u.end(), 2, static_cast<double>(a) / arcs);
  knots_u.insert(knots_u.end(), 3, 1.0);
  const auto knots_v = profile.knots();
  return BSplineSurface::from_trusted(2, profile.degree(), std::move(knots_u),
                                      std::vector<double>(knots_v.begin(), knots_v.end()),
                                      ControlNet::from_trusted(rows, columns, PointArray::from_trusted(3, std::move(coordinates))),
                                      std::move(weights));
}

Expected<BSplineSurface> make_sphere(std::span<const double> center, double radius) {
  auto c = checked_point(center, "centre");
  if (!c) return c.error();
  if (auto ok = check_radius(radius, "the radius"); !ok) return ok.error();
  const ConicFrame frame{{(*c)[0], (*c)[1], (*c)[2]}, {1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
  auto semicircle = make_arc(frame, radius, -kPi / 2, kPi);
  if (!semicircle) return semicircle.error();
  const double z[3] = {0.0, 0.0, 1.0};
  return revolve(*semicircle, center, z, kTwoPi);
}

Expected<BSplineSurface> make_torus(std::span<const double> center, std::span<const double> axis, double major_radius,
                                    double minor_radius) {
  auto c = checked_point(center, "centre");
  if (!c) return c.error();
  auto t = checked_direction(axis, "axis");
  if (!t) return t.error();
  if (auto ok = check_radius(major_radius, "the major radius"); !ok) return ok.error();
  if (auto ok = check_radius(minor_radius, "the minor radius"); !ok) return ok.error();
  if (!(minor_radius < major_radius)) {
    return Error{"the minor radius " + number_text(minor_radius) + " is not smaller than the major radius " +
                 number_text(major_radius) + ": that torus touches or crosses itself on its axis (only ring tori are made)"};
  }
  const Vec3 e = orthogonal_unit(*t);
  const ConicFrame frame{{(*c)[0] + major_radius * e[0], (*c)[1] + major_radius * e[1], (*c)[2] + major_radius * e[2]},
                         {e[0], e[1], e[2]},
                         {(*t)[0], (*t)[1], (*t)[2]}};
  auto circle = make_circle(frame, minor_radius);
  if (!circle) return circle.error();
  return revolve(*circle, center, t->coordinates, kTwoPi);
}

}  // namespace casteljau

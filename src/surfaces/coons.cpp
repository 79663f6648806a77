// Coons patches (Coons 1967; seed 001 §2 with f0 = 2t^3 - 3t^2 + 1; Farin
// ch. 22; The NURBS Book §10.5 for the B-spline form).
#include "casteljau/surfaces/coons.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"
#include "casteljau/core/precondition.hpp"
#include "../core/number_text.hpp"
#include "construction_support.hpp"
#include "surface_rows.hpp"

namespace casteljau {
namespace {

using detail::point_text;

/// The patch's formula, grouped so that the u-boundaries come out exactly:
///   P = f0(u) U0(v) + f1(u) U1(v)
///     + f0(v) (V0(u) - (f0(u) P00 + f1(u) P10)) + f1(v) (V1(u) - (f0(u) P01 + f1(u) P11)),
/// which expands to the header's formula. Every term is a product of a
/// function of u and a function of v, so the (k, l)-th partial derivative is
/// the same expression with the k-th u-derivatives (blending fu, curves V)
/// and the l-th v-derivatives (blending fv, curves U); the corner terms keep
/// the corners themselves. At u = 0 (f0 = 1, f1 = 0 exactly) with corners
/// that match bit for bit, the bracketed differences vanish exactly and
/// P(0, v) = U0(v) bit for bit.
struct Corners {
  Point p00, p01, p10, p11;
};

Corners corners_of(const CoonsPatch& patch) {
  return {point_at(patch.u0(), 0.0), point_at(patch.u0(), 1.0), point_at(patch.u1(), 0.0), point_at(patch.u1(), 1.0)};
}

/// Writes the combination into out (d values): fu, fv are the blending
/// functions (or their derivatives) at u and v, u0, u1 the u-boundaries
/// (or derivatives) at v, v0, v1 the v-boundaries at u.
void combine(std::array<double, 2> fu, std::array<double, 2> fv, std::span<const double> u0, std::span<const double> u1,
             std::span<const double> v0, std::span<const double> v1, const Corners& c, std::span<double> out) {
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double bottom = v0[i] - (fu[0] * c.p00[i] + fu[1] * c.p10[i]);
    const double top = v1[i] - (fu[0] * c.p01[i] + fu[1] * c.p11[i]);
    out[i] = fu[0] * u0[i] + fu[1] * u1[i] + fv[0] * bottom + fv[1] * top;
  }
}

Point curve_derivative(const BSplineCurve& curve, double t, int order) {
  return order == 0 ? point_at(curve, t) : derivative_at(curve, t, order);
}

double patch_scale(const CoonsPatch& patch) {
  double scale = tolerances::kScaleFloor;
  for (const BSplineCurve* c : {&patch.u0(), &patch.u1(), &patch.v0(), &patch.v1()}) {
    scale = std::max(scale, scale_of(c->control_points()));
  }
  return scale;
}

/// The Bézier knots 0^(b+1) 1^(b+1) of the blending direction.
std::vector<double> bezier_knots(int degree) {
  std::vector<double> knots(static_cast<std::size_t>(degree + 1), 0.0);
  knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), 1.0);
  return knots;
}

}  // namespace

Expected<CoonsPatch> CoonsPatch::make(BSplineCurve u0, BSplineCurve u1, BSplineCurve v0, BSplineCurve v1,
                                      CoonsBlending blending) {
  const BSplineCurve* curves[4] = {&u0, &u1, &v0, &v1};
  const char* names[4] = {"u0", "u1", "v0", "v1"};
  for (int k = 1; k < 4; ++k) {
    if (curves[k]->dimension() != u0.dimension()) {
      return Error{std::string("the boundaries have different dimensions: u0 has ") + std::to_string(u0.dimension()) +
                   " coordinates, " + names[k] + " has " + std::to_string(curves[k]->dimension())};
    }
  }
  const Interval unit{0.0, 1.0};
  double scale = tolerances::kScaleFloor;
  for (BSplineCurve* curve : {&u0, &u1, &v0, &v1}) {
    if (curve->domain() != unit) *curve = *reparameterized(*curve, unit);  // a valid domain maps without error
    scale = std::max(scale, scale_of(curve->control_points()));
  }
  // P(0,0), P(0,1), P(1,0), P(1,1): which ends of which boundaries meet there.
  struct Meeting {
    const char* corner;
    int a;
    double a_end;
    int b;
    double b_end;
  };
  const Meeting meetings[4] = {{"P(0,0)", 0, 0.0, 2, 0.0},
                               {"P(0,1)", 0, 1.0, 3, 0.0},
                               {"P(1,0)", 1, 0.0, 2, 1.0},
                               {"P(1,1)", 1, 1.0, 3, 1.0}};
  for (const Meeting& m : meetings) {
    const Point a = point_at(*curves[m.a], m.a_end);
    const Point b = point_at(*curves[m.b], m.b_end);
    const double gap = distance(a, b);
    if (!(gap <= tolerances::kJointRelativeGap * scale)) {
      auto verb = [](double end) { return end == 0.0 ? " starts at " : " ends at "; };
      return Error{std::string("the boundaries ") + names[m.a] + " and " + names[m.b] + " do not meet at the corner " +
                   m.corner + ": " + names[m.a] + verb(m.a_end) + point_text(a) + ", " + names[m.b] + verb(m.b_end) +
                   point_text(b) + ", " + detail::number_text(gap) + " apart"};
    }
  }
  return CoonsPatch(std::move(u0), std::move(u1), std::move(v0), std::move(v1), blending);
}

const char* blending_name(CoonsBlending blending) { return blending == CoonsBlending::cubic ? "cubic" : "linear"; }

std::array<double, 2> blending_functions(CoonsBlending blending, double t, int order) {
  detail::require(order >= 0, "blending_functions", "order must be >= 0");
  if (blending == CoonsBlending::linear) {
    switch (order) {
      case 0: return {1.0 - t, t};
      case 1: return {-1.0, 1.0};
      default: return {0.0, 0.0};
    }
  }
  switch (order) {
    case 0: {
      const double s = 1.0 - t;
      return {s * s * (1.0 + 2.0 * t), t * t * (3.0 - 2.0 * t)};
    }
    case 1: {
      const double d = 6.0 * t * (t - 1.0);  // f0' = 6t^2 - 6t
      return {d, -d};
    }
    case 2: {
      const double d = 12.0 * t - 6.0;
      return {d, -d};
    }
    case 3: return {12.0, -12.0};
    default: return {0.0, 0.0};
  }
}

Point point_at(const CoonsPatch& patch, double u, double v) {
  return partial_derivative_at(patch, u, v, 0, 0);
}

Point partial_derivative_at(const CoonsPatch& patch, double u, double v, int order_u, int order_v) {
  detail::require(order_u >= 0 && order_v >= 0, "partial_derivative_at", "the derivative orders must be >= 0");
  const Corners c = corners_of(patch);
  const Point u0 = curve_derivative(patch.u0(), v, order_v);
  const Point u1 = curve_derivative(patch.u1(), v, order_v);
  const Point v0 = curve_derivative(patch.v0(), u, order_u);
  const Point v1 = curve_derivative(patch.v1(), u, order_u);
  Point out(static_cast<std::size_t>(patch.dimension()));
  combine(blending_functions(patch.blending(), u, order_u), blending_functions(patch.blending(), v, order_v), u0, u1,
          v0, v1, c, out);
  return out;
}

Point normal_at(const CoonsPatch& patch, double u, double v) {
  detail::require(patch.dimension() == 3, "normal_at", "the patch must lie in 3D (dimension() == 3)");
  const Vec3 su = Vec3::from(partial_derivative_at(patch, u, v, 1, 0));
  const Vec3 sv = Vec3::from(partial_derivative_at(patch, u, v, 0, 1));
  Vec3 n = cross(su, sv);
  // A derivative below this is a collapsed edge (a boundary that is one
  // point); compare with the patch's scale, never an absolute epsilon.
  const double vanishing = tolerances::kVanishingDerivative * patch_scale(patch);
  if (norm(n) <= vanishing * vanishing) {
    // Near an edge where S_v = 0 (u = 0 or 1 collapsed), S_v ~ (u - u_edge) S_uv,
    // so the normal from inside is along +-(S_u x S_uv); likewise for S_u.
    const Vec3 suv = Vec3::from(partial_derivative_at(patch, u, v, 1, 1));
    if (norm(sv) <= vanishing && norm(su) > vanishing) {
      n = cross(su, suv);
      if (u > 0.5) n = -n;
    } else if (norm(su) <= vanishing && norm(sv) > vanishing) {
      n = cross(suv, sv);
      if (v > 0.5) n = -n;
    }
  }
  const double length = norm(n);
  if (!(length > 0.0)) return {0.0, 0.0, 0.0};
  return {n[0] / length, n[1] / length, n[2] / length};
}

void points_at(const CoonsPatch& patch, std::span<const double> us, std::span<const double> vs, std::span<double> out) {
  detail::require(us.size() == vs.size(), "points_at", "us and vs must have one size");
  const std::size_t d = static_cast<std::size_t>(patch.dimension());
  detail::require(out.size() == us.size() * d, "points_at", "out must hold us.size() * dimension() values");
  const Corners c = corners_of(patch);
  Point u0(d), u1(d), v0(d), v1(d);
  for (std::size_t k = 0; k < us.size(); ++k) {
    const double u = us[k];
    const double v = vs[k];
    points_at(patch.u0(), std::span<const double>(&vs[k], 1), u0);
    points_at(patch.u1(), std::span<const double>(&vs[k], 1), u1);
    points_at(patch.v0(), std::span<const double>(&us[k], 1), v0);
    points_at(patch.v1(), std::span<const double>(&us[k], 1), v1);
    combine(blending_functions(patch.blending(), u), blending_functions(patch.blending(), v), u0, u1, v0, v1, c,
            out.subspan(k * d, d));
  }
}

void grid_points_at(const CoonsPatch& patch, std::span<const double> us, std::span<const double> vs,
                    std::span<double> out) {
  const std::size_t d = static_cast<std::size_t>(patch.dimension());
  detail::require(out.size() == us.size() * vs.size() * d, "grid_points_at",
                  "out must hold us.size() * vs.size() * dimension() values");
  // The four boundaries are evaluated once per grid line, not per point.
  std::vector<double> u0(vs.size() * d), u1(vs.size() * d), v0(us.size() * d), v1(us.size() * d);
  points_at(patch.u0(), vs, u0);
  points_at(patch.u1(), vs, u1);
  points_at(patch.v0(), us, v0);
  points_at(patch.v1(), us, v1);
  std::vector<std::array<double, 2>> fv(vs.size());
  for (std::size_t b = 0; b < vs.size(); ++b) fv[b] = blending_functions(patch.blending(), vs[b]);
  const Corners c = corners_of(patch);
  for (std::size_t a = 0; a < us.size(); ++a) {
    const auto fu = blending_functions(patch.blending(), us[a]);
    const std::span<const double> v0a(v0.data() + a * d, d);
    const std::span<const double> v1a(v1.data() + a * d, d);
    for (std::size_t b = 0; b < vs.size(); ++b) {
      combine(fu, fv[b], std::span<const double>(u0.data() + b * d, d), std::span<const double>(u1.data() + b * d, d),
              v0a, v1a, c, out.subspan((a * vs.size() + b) * d, d));
    }
  }
}

Expected<BSplineSurface> to_bspline_surface(const CoonsPatch& patch) {
  const BSplineCurve* curves[4] = {&patch.u0(), &patch.u1(), &patch.v0(), &patch.v1()};
  const char* names[4] = {"u0", "u1", "v0", "v1"};
  for (int k = 0; k < 4; ++k) {
    if (curves[k]->is_rational()) {
      return Error{std::string("a Coons patch with rational boundaries has no B-spline form of the same degree; "
                               "boundary ") +
                   names[k] + " is rational"};
    }
  }
  const int b = patch.blending() == CoonsBlending::cubic ? 3 : 1;
  const int d = patch.dimension();
  const std::size_t blend_points = static_cast<std::size_t>(b + 1);
  // Which boundary (0 or 1) each control point of the blending direction
  // repeats: the linear blend is (1-t, t) on one segment; the cubic Hermite
  // blend f0 = B0 + B1, f1 = B2 + B3 in the Bernstein basis of degree 3.
  auto side = [b](std::size_t i) { return static_cast<int>(i) * 2 > b ? 1 : 0; };

  auto u_pair = detail::unify_curves({clamped(patch.u0()), clamped(patch.u1())});
  if (!u_pair) return u_pair.error();
  auto v_pair = detail::unify_curves({clamped(patch.v0()), clamped(patch.v1())});
  if (!v_pair) return v_pair.error();

  // R1(u,v) = f0(u) U0(v) + f1(u) U1(v): rows along u are copies of U0, U1.
  const BSplineCurve& U0 = (*u_pair)[0];
  const std::size_t u_count = U0.control_points().size();
  std::vector<double> r1;
  for (std::size_t i = 0; i < blend_points; ++i) {
    const auto& points = (*u_pair)[static_cast<std::size_t>(side(i))].control_points().coordinates();
    r1.insert(r1.end(), points.begin(), points.end());
  }
  BSplineSurface ruled_u = BSplineSurface::from_trusted(
      b, U0.degree(), bezier_knots(b), std::vector<double>(U0.knots().begin(), U0.knots().end()),
      ControlNet::from_trusted(blend_points, u_count, PointArray::from_trusted(d, std::move(r1))));

  // R2(u,v) = f0(v) V0(u) + f1(v) V1(u): columns along v are copies of V0, V1.
  const BSplineCurve& V0 = (*v_pair)[0];
  const std::size_t v_count = V0.control_points().size();
  std::vector<double> r2;
  for (std::size_t i = 0; i < v_count; ++i) {
    for (std::size_t j = 0; j < blend_points; ++j) {
      const auto point = (*v_pair)[static_cast<std::size_t>(side(j))].control_points()[i];
      r2.insert(r2.end(), point.begin(), point.end());
    }
  }
  BSplineSurface ruled_v = BSplineSurface::from_trusted(
      V0.degree(), b, std::vector<double>(V0.knots().begin(), V0.knots().end()), bezier_knots(b),
      ControlNet::from_trusted(v_count, blend_points, PointArray::from_trusted(d, std::move(r2))));

  // B(u,v) = sum f_a(u) f_c(v) P_ac, the corners of U0 and U1 as point_at uses.
  const Corners c = corners_of(patch);
  const Point* corner[2][2] = {{&c.p00, &c.p01}, {&c.p10, &c.p11}};
  std::vector<double> bc;
  for (std::size_t i = 0; i < blend_points; ++i) {
    for (std::size_t j = 0; j < blend_points; ++j) {
      const Point& point = *corner[side(i)][side(j)];
      bc.insert(bc.end(), point.begin(), point.end());
    }
  }
  BSplineSurface bilinear = BSplineSurface::from_trusted(
      b, b, bezier_knots(b), bezier_knots(b),
      ControlNet::from_trusted(blend_points, blend_points, PointArray::from_trusted(d, std::move(bc))));

  // One degree and one knot vector per direction for the three surfaces:
  // the curve algorithms on the wide rows (surface_rows.hpp).
  BSplineSurface* parts[3] = {&ruled_u, &ruled_v, &bilinear};
  for (Direction direction : {Direction::u, Direction::v}) {
    std::vector<BSplineCurve> wides;
    for (const BSplineSurface* part : parts) wides.push_back(detail::wide_curve(*part, direction));
    auto unified = detail::unify_curves(std::move(wides));
    if (!unified) return unified.error();
    for (std::size_t k = 0; k < 3; ++k) *parts[k] = detail::surface_from_wide((*unified)[k], direction, *parts[k]);
  }
  std::vector<double> sum(ruled_u.control_net().points().coordinates().begin(),
                          ruled_u.control_net().points().coordinates().end());
  const auto second = ruled_v.control_net().points().coordinates();
  const auto corners = bilinear.control_net().points().coordinates();
  assert(second.size() == sum.size() && corners.size() == sum.size());
  for (std::size_t k = 0; k < sum.size(); ++k) sum[k] = sum[k] + second[k] - corners[k];
  const auto knots_u = ruled_u.knots_u();
  const auto knots_v = ruled_u.knots_v();
  return BSplineSurface::from_trusted(
      ruled_u.degree_u(), ruled_u.degree_v(), std::vector<double>(knots_u.begin(), knots_u.end()),
      std::vector<double>(knots_v.begin(), knots_v.end()),
      ControlNet::from_trusted(ruled_u.control_net().rows(), ruled_u.control_net().columns(),
                               PointArray::from_trusted(d, std::move(sum))));
}

}  // namespace casteljau

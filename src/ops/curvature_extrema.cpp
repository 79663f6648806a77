// Curvature extrema and cusps (curvature_extrema.hpp): the polynomials
// P, F or H, G and N of each Bézier piece in Bernstein form, their roots, and
// the junction rules between pieces.
#include "casteljau/ops/curvature_extrema.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/tolerance.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/differential_geometry.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "bernstein_columns.hpp"

namespace casteljau {
namespace {

using detail::column;
using detail::derivative;
using detail::difference;
using detail::sum;
using Polynomial = std::vector<double>;

Polynomial product(const Polynomial& a, const Polynomial& b) { return bernstein_product(a, b); }

Polynomial scaled(Polynomial a, double factor) {
  for (double& c : a) c *= factor;
  return a;
}

double largest_magnitude(const Polynomial& a) {
  double m = 0.0;
  for (const double c : a) m = std::max(m, std::abs(c));
  return m;
}

/// The velocity polynomials of one piece: P (one per coordinate), P', and
/// the weight W (the constant 1 for a polynomial piece).
struct Velocity {
  std::vector<Polynomial> p, dp;
  Polynomial w{1.0};
};

Velocity velocity_of(const BezierCurve& piece) {
  Velocity v;
  v.p = detail::velocity_numerators(piece);
  if (piece.is_rational()) v.w = column(homogeneous_points(piece), piece.dimension());
  for (const Polynomial& p : v.p) v.dp.push_back(derivative(p));
  return v;
}

/// sum_i a_i b_i.
Polynomial dot(const std::vector<Polynomial>& a, const std::vector<Polynomial>& b) {
  Polynomial s = product(a[0], b[0]);
  for (std::size_t i = 1; i < a.size(); ++i) s = sum(s, product(a[i], b[i]));
  return s;
}

/// The largest |P_i| coefficient: the scale a vanishing velocity is measured against.
double velocity_scale(const Velocity& v) {
  double m = 0.0;
  for (const Polynomial& p : v.p) m = std::max(m, largest_magnitude(p));
  return m;
}

/// |P(t)|^2.
double speed_squared(const Velocity& v, double t) {
  double s = 0.0;
  for (const Polynomial& p : v.p) {
    const double c = bernstein_value(p, t);
    s += c * c;
  }
  return s;
}

/// N of the piece (curvature_extrema.hpp), empty when the piece has constant
/// curvature (N vanishes within tolerances::kConstantCurvature of its terms).
Polynomial numerator(const Velocity& v) {
  const Polynomial g = dot(v.p, v.p);
  const Polynomial along = dot(v.p, v.dp);
  Polynomial first, second;
  if (v.p.size() == 2) {
    Polynomial f = difference(product(v.p[0], v.dp[1]), product(v.p[1], v.dp[0]));
    if (v.w.size() > 1) f = product(product(v.w, v.w), f);
    first = product(derivative(f), g);
    second = scaled(product(f, along), 3.0);
  } else {
    Polynomial h = difference(product(g, dot(v.dp, v.dp)), product(along, along));
    if (v.w.size() > 1) {
      const Polynomial w2 = product(v.w, v.w);
      h = product(product(w2, w2), h);
    }
    first = product(derivative(h), g);
    second = scaled(product(h, along), 6.0);
  }
  const Polynomial n = difference(first, second);
  const double scale = std::max(largest_magnitude(first), largest_magnitude(second));
  if (!(largest_magnitude(n) > tolerances::kConstantCurvature * scale)) return {};
  return n;
}

int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

bool at_start(double t) { return t <= tolerances::kCurvatureRootResolution; }
bool at_end(double t) { return t >= 1.0 - tolerances::kCurvatureRootResolution; }

/// The roots of a piece's N that lie inside it (those at its ends are the
/// junction's), and the sign of N on each interval between them.
struct CriticalPoints {
  std::vector<double> roots;
  std::vector<int> signs;  // roots.size() + 1 entries; empty for constant curvature
};

CriticalPoints critical_points(const Polynomial& n) {
  CriticalPoints c;
  if (n.empty()) return c;
  for (const BernsteinRoot& root : bernstein_roots(n, tolerances::kCurvatureRootResolution))
    if (!at_start(root.t) && !at_end(root.t)) c.roots.push_back(root.t);
  double previous = 0.0;
  for (std::size_t j = 0; j <= c.roots.size(); ++j) {
    const double next = j < c.roots.size() ? c.roots[j] : 1.0;
    c.signs.push_back(sign_of(bernstein_value(n, 0.5 * (previous + next))));
    previous = next;
  }
  return c;
}

Error needs_a_plane_or_space(int d) {
  return Error{"curvature extrema need a curve in R^2 or more, this one lives in R^" + std::to_string(d)};
}

/// The curvature of the curve at u, signed in the plane.
double curvature_of(CurveView curve, double u) {
  return curve.dimension() == 2 ? signed_curvature_at(curve, u) : curvature_at(curve, u);
}

/// True when the rise-then-fall (or fall-then-rise) of the signed quantity
/// whose derivative has signs `before`, `after` is a maximum of |kappa|.
bool is_maximum_of_magnitude(int before, int after, double kappa, int dimension) {
  const bool rises_then_falls = before > 0 && after < 0;
  if (dimension != 2) return rises_then_falls;  // N has the sign of d(kappa^2)/dt
  return kappa != 0.0 && (rises_then_falls == (kappa > 0.0));
}

}  // namespace

Expected<std::vector<CurvatureExtremum>> curvature_extrema(CurveView curve) {
  const int d = curve.dimension();
  if (d < 2) return needs_a_plane_or_space(d);
  const BezierPieces pieces = to_bezier_pieces(curve);
  const std::size_t count = pieces.pieces.size();
  std::vector<CriticalPoints> critical(count);
  std::vector<CurvatureExtremum> result;
  for (std::size_t k = 0; k < count; ++k) {
    const BezierCurve& piece = pieces.pieces[k];
    if (piece.degree() < 2) continue;  // a segment: no curvature
    const Velocity v = velocity_of(piece);
    critical[k] = critical_points(numerator(v));
    const CriticalPoints& c = critical[k];
    const double vanishing = tolerances::kVanishingDerivative * velocity_scale(v);
    const Interval span{pieces.breakpoints[k], pieces.breakpoints[k + 1]};
    // The junction with the previous piece, where the curvature is continuous.
    if (k > 0 && !critical[k - 1].signs.empty() && !c.signs.empty()) {
      const int before = critical[k - 1].signs.back(), after = c.signs.front();
      const double left = curvature_of(pieces.pieces[k - 1], 1.0), right = curvature_of(piece, 0.0);
      const bool continuous = std::isfinite(left) && std::isfinite(right) &&
                              std::abs(left - right) <= tolerances::kCurvatureContinuity *
                                                            std::max(std::abs(left), std::abs(right));
      if (continuous && before * after < 0)
        result.push_back({span.lower, right, is_maximum_of_magnitude(before, after, right, d)});
    }
    for (std::size_t j = 0; j < c.roots.size(); ++j) {
      const int before = c.signs[j], after = c.signs[j + 1];
      if (before * after >= 0) continue;  // not a sign change: an inflection of kappa
      const double t = c.roots[j];
      if (speed_squared(v, t) <= vanishing * vanishing) continue;  // a cusp: kappa is infinite there
      const double u = span.lerp(t);
      const double kappa = curvature_of(curve, u);
      result.push_back({u, kappa, is_maximum_of_magnitude(before, after, kappa, d)});
    }
  }
  return result;
}

Expected<std::vector<double>> cusp_parameters(CurveView curve) {
  const int d = curve.dimension();
  if (d < 2) return needs_a_plane_or_space(d);
  const BezierPieces pieces = to_bezier_pieces(curve);
  std::vector<double> result;
  for (std::size_t k = 0; k < pieces.pieces.size(); ++k) {
    const BezierCurve& piece = pieces.pieces[k];
    const Interval span{pieces.breakpoints[k], pieces.breakpoints[k + 1]};
    if (k > 0) {
      // The tangent arriving at the junction and the one leaving it.
      const Point arriving = unit_tangent_at(pieces.pieces[k - 1], 1.0);
      const Point leaving = unit_tangent_at(piece, 0.0);
      double together = 0.0, apart = 0.0;
      for (int i = 0; i < d; ++i) {
        together += (arriving[i] + leaving[i]) * (arriving[i] + leaving[i]);
        apart += (arriving[i] - leaving[i]) * (arriving[i] - leaving[i]);
      }
      // The angle between the arriving tangent and the reversed leaving one.
      if (apart > 0.0 && 2.0 * std::atan2(std::sqrt(together), std::sqrt(apart)) <= tolerances::kTangentAngle)
        result.push_back(span.lower);
    }
    if (piece.degree() < 2) continue;  // a segment moves at constant velocity
    const Velocity v = velocity_of(piece);
    const double vanishing = tolerances::kVanishingDerivative * velocity_scale(v);
    double last = -1.0;  // the last cusp of this piece: a higher-order one may show as a cluster of roots
    for (const BernsteinRoot& root : bernstein_roots(dot(v.p, v.dp), tolerances::kCurvatureRootResolution)) {
      const double t = root.t;
      if (at_start(t) || at_end(t) || speed_squared(v, t) > vanishing * vanishing) continue;
      if (last >= 0.0 && t - last <= tolerances::kCuspSide) continue;
      // The velocities just before and just after: opposite at a cusp.
      const double before = std::max(0.0, t - tolerances::kCuspSide), after = std::min(1.0, t + tolerances::kCuspSide);
      double turn = 0.0;
      for (const Polynomial& p : v.p) turn += bernstein_value(p, before) * bernstein_value(p, after);
      if (turn < 0.0) {
        result.push_back(span.lerp(t));
        last = t;
      }
    }
  }
  return result;
}

}  // namespace casteljau

// Arc splines (arc_spline.hpp): biarcs fitted to the spiral stretches of a
// plane curve, each certified by the bound of docs/cnc.md ("The
// certificate"): the stretch lies in the arc's wedge (between the normals at
// its ends) and its distance to the arc's circle, bounded through the
// polynomial h = (C - A) . N - (k/2) |C - A|^2, is within the budget.
#include "casteljau/ops/arc_spline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/curvature_extrema.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "certified_budget.hpp"

namespace casteljau {

double sweep_of(const ArcSegment& arc) { return 4.0 * std::atan(arc.bulge); }

namespace {

Vec2 rotated(Vec2 v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {{c * v[0] - s * v[1], s * v[0] + c * v[1]}};
}
Vec2 left_normal(Vec2 t) { return {{-t[1], t[0]}}; }

}  // namespace

double curvature_of(const ArcSegment& arc) {
  const double chord = norm(arc.end - arc.start);
  return chord > 0.0 ? 2.0 * std::sin(0.5 * sweep_of(arc)) / chord : 0.0;
}

double radius_of(const ArcSegment& arc) {
  return norm(arc.end - arc.start) * (1.0 + arc.bulge * arc.bulge) / (4.0 * std::abs(arc.bulge));
}

Vec2 center_of(const ArcSegment& arc) {
  // From the chord's middle along its left normal by (1 - b^2) / (4 b) of the
  // chord (the sagitta relation; negative b puts the centre on the right).
  const Vec2 chord = arc.end - arc.start;
  return 0.5 * (arc.start + arc.end) + ((1.0 - arc.bulge * arc.bulge) / (4.0 * arc.bulge)) * left_normal(chord);
}

double length_of(const ArcSegment& arc) {
  if (arc.bulge == 0.0) return norm(arc.end - arc.start);
  return radius_of(arc) * std::abs(sweep_of(arc));
}

Vec2 tangent_along(const ArcSegment& arc, double fraction) {
  const Vec2 chord = arc.end - arc.start;
  const double length = norm(chord);
  const Vec2 u = length > 0.0 ? (1.0 / length) * chord : Vec2{{1.0, 0.0}};
  // The chord seen from the start makes half the sweep with the tangent.
  return rotated(u, (fraction - 0.5) * sweep_of(arc));
}

Vec2 point_along(const ArcSegment& arc, double fraction) {
  if (fraction <= 0.0) return arc.start;
  if (fraction >= 1.0) return arc.end;
  if (arc.bulge == 0.0) return arc.start + fraction * (arc.end - arc.start);
  const Vec2 c = center_of(arc);
  return c + rotated(arc.start - c, fraction * sweep_of(arc));
}

namespace {

using tolerances::kArcFitReachSteps;
using tolerances::kArcSameCircle;
using tolerances::kArcStraightSagitta;

/// A stretch of curve as homogeneous Bernstein coefficients (w x, w y, w).
struct Stretch {
  BezierCurve curve;
  PointArray h;
};

Stretch stretch_of(const BezierCurve& piece, double t0, double t1) {
  BezierCurve part = extended_segment(piece, t0, t1);
  PointArray h = homogeneous_points(part);
  return {std::move(part), std::move(h)};
}

Vec2 cartesian(const PointArray& h, std::size_t i) { return {{h[i][0] / h[i][2], h[i][1] / h[i][2]}}; }

/// The one-sided unit tangents at a stretch's ends: towards the first control
/// point that differs from the start (from the last that differs from the
/// end), the tangent of a Bézier curve, rational or not, even where its
/// velocity vanishes (a cusp). False for a stretch that is a single point.
bool end_tangents(const PointArray& h, double scale, Vec2& start, Vec2& end) {
  const std::size_t n = h.size() - 1;
  const double tiny = tolerances::kVanishingDerivative * scale;
  const Vec2 first = cartesian(h, 0), last = cartesian(h, n);
  bool found = false;
  for (std::size_t i = 1; i <= n && !found; ++i)
    if (const Vec2 d = cartesian(h, i) - first; norm(d) > tiny) start = (1.0 / norm(d)) * d, found = true;
  if (!found) return false;
  for (std::size_t i = n; i-- > 0;)
    if (const Vec2 d = last - cartesian(h, i); norm(d) > tiny) {
      end = (1.0 / norm(d)) * d;
      return true;
    }
  return false;
}

/// Coefficients (X_i - P W_i) . direction: the signed distance of the
/// stretch from the line through P normal to `direction`, times W.
std::vector<double> side_coefficients(const PointArray& h, Vec2 p, Vec2 direction) {
  std::vector<double> c(h.size());
  for (std::size_t i = 0; i < h.size(); ++i)
    c[i] = (h[i][0] - p[0] * h[i][2]) * direction[0] + (h[i][1] - p[1] * h[i][2]) * direction[1];
  return c;
}

/// The one parameter in (0, 1) where the stretch crosses the line through P
/// normal to `direction` (from behind to ahead), or a negative value when it
/// does not cross it exactly once.
double crossing(const PointArray& h, Vec2 p, Vec2 direction) {
  const std::vector<double> c = side_coefficients(h, p, direction);
  if (!(c.front() < 0.0 && c.back() > 0.0)) {
    // The ends on the line (rounding): the sign of the neighbours decides.
    if (!(c.front() <= 0.0 && c.back() >= 0.0)) return -1.0;
  }
  double found = -1.0;
  int count = 0;
  for (const BernsteinRoot& root : bernstein_roots(c)) {
    if (root.t <= 0.0 || root.t >= 1.0) continue;
    if (root.multiplicity != 1) return -1.0;
    found = root.t;
    ++count;
  }
  return count == 1 ? found : -1.0;
}

/// The largest |H(t)| on [0, 1] for H in Bernstein form: at the ends and at
/// the roots of H' (the exact maximum up to rounding).
double largest_magnitude(const std::vector<double>& b) {
  double largest = std::max(std::abs(b.front()), std::abs(b.back()));
  std::vector<double> d(b.size() - 1);
  const double n = static_cast<double>(b.size() - 1);
  for (std::size_t i = 0; i + 1 < b.size(); ++i) d[i] = n * (b[i + 1] - b[i]);
  for (const BernsteinRoot& root : bernstein_roots(d)) largest = std::max(largest, std::abs(bernstein_value(b, root.t)));
  return largest;
}

/// Whether the stretch is within `budget` of the arc, by the certificate of
/// docs/cnc.md; the bound in `bound`. Arcs of more than a quarter turn are
/// checked as two halves, the stretch cut where it crosses the normal at the
/// arc's middle.
bool certify(const ArcSegment& arc, const Stretch& stretch, double budget, double slack, double& bound, int depth = 0) {
  const double chord = norm(arc.end - arc.start);
  if (!(chord > 0.0)) return false;
  const double sweep = sweep_of(arc);
  if (std::abs(sweep) > 0.5 * std::numbers::pi) {
    if (depth > 4) return false;
    const Vec2 middle = point_along(arc, 0.5);
    const double t = crossing(stretch.h, middle, tangent_along(arc, 0.5));
    if (t < 0.0) return false;
    const double half = std::tan(sweep / 8.0);
    double first = 0.0, second = 0.0;
    const bool ok = certify({arc.start, middle, half}, stretch_of(stretch.curve, 0.0, t), budget, slack, first, depth + 1) &&
                    certify({middle, arc.end, half}, stretch_of(stretch.curve, t, 1.0), budget, slack, second, depth + 1);
    bound = std::max(first, second);
    return ok;
  }
  const PointArray& h = stretch.h;
  // In the wedge: ahead of the normal at the start, behind the normal at the end.
  const Vec2 ts = tangent_along(arc, 0.0), te = tangent_along(arc, 1.0);
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double ahead = (h[i][0] - arc.start[0] * h[i][2]) * ts[0] + (h[i][1] - arc.start[1] * h[i][2]) * ts[1];
    const double behind = (h[i][0] - arc.end[0] * h[i][2]) * te[0] + (h[i][1] - arc.end[1] * h[i][2]) * te[1];
    if (ahead < -slack * h[i][2] || behind > slack * h[i][2]) return false;
  }
  // h W^2 = W ((X - A W) . N) - (k/2) |X - A W|^2, degree 2n.
  const double k = curvature_of(arc);
  const Vec2 normal = left_normal(ts);
  const std::size_t count = h.size();
  std::vector<double> dx(count), dy(count), w(count), along(count);
  double lightest = h[0][2];
  for (std::size_t i = 0; i < count; ++i) {
    dx[i] = h[i][0] - arc.start[0] * h[i][2];
    dy[i] = h[i][1] - arc.start[1] * h[i][2];
    w[i] = h[i][2];
    along[i] = dx[i] * normal[0] + dy[i] * normal[1];
    lightest = std::min(lightest, w[i]);
  }
  std::vector<double> H = bernstein_product(w, along);
  const std::vector<double> xx = bernstein_product(dx, dx), yy = bernstein_product(dy, dy);
  for (std::size_t i = 0; i < H.size(); ++i) H[i] -= 0.5 * k * (xx[i] + yy[i]);
  // The convex hull's bound first (cheap); the exact maximum where it is not enough.
  const auto within = [&](double magnitude) {
    const double g = magnitude / (lightest * lightest);
    const double root = 1.0 - 2.0 * g * std::abs(k);
    if (!(root > 0.0)) return false;
    bound = 2.0 * g / (1.0 + std::sqrt(root));
    return bound <= budget;
  };
  double hull = 0.0;
  for (const double c : H) hull = std::max(hull, std::abs(c));
  return within(hull) || within(largest_magnitude(H));
}

/// Where a stretch of the curve is, on its Bézier pieces: local parameter t
/// on piece `piece`.
struct Place {
  std::size_t piece;
  double t;
};

/// The curve's Bézier pieces, the budget and slack of their certificates,
/// and the run of pieces a stretch covers.
struct Pieces {
  const BezierPieces& bezier;
  double budget, slack, scale;

  /// The place of global parameter u as the start (end) of a stretch: on the
  /// piece it begins (ends) in.
  Place start_of(double u) const {
    const auto& b = bezier.breakpoints;
    std::size_t p = static_cast<std::size_t>(std::upper_bound(b.begin(), b.end(), u) - b.begin());
    p = std::clamp<std::size_t>(p, 1, b.size() - 1) - 1;
    return {p, std::clamp((u - b[p]) / (b[p + 1] - b[p]), 0.0, 1.0)};
  }
  Place end_of(double u) const {
    const auto& b = bezier.breakpoints;
    std::size_t p = static_cast<std::size_t>(std::lower_bound(b.begin(), b.end(), u) - b.begin());
    p = std::clamp<std::size_t>(p, 1, b.size() - 1) - 1;
    return {p, std::clamp((u - b[p]) / (b[p + 1] - b[p]), 0.0, 1.0)};
  }
  double global(Place place) const {
    const auto& b = bezier.breakpoints;
    return place.t >= 1.0 ? b[place.piece + 1] : b[place.piece] + place.t * (b[place.piece + 1] - b[place.piece]);
  }
  /// The stretches of the pieces from `from` to `to`, in order.
  std::vector<Stretch> stretches(Place from, Place to) const {
    std::vector<Stretch> result;
    for (std::size_t p = from.piece; p <= to.piece; ++p)
      result.push_back(stretch_of(bezier.pieces[p], p == from.piece ? from.t : 0.0, p == to.piece ? to.t : 1.0));
    return result;
  }
};

/// Where the run of stretches crosses the line through P normal to
/// `direction` (once, from behind to ahead): index of the stretch and local
/// parameter on it; false when it does not cross exactly once.
bool crossing_over(const std::vector<Stretch>& run, Vec2 p, Vec2 direction, std::size_t& index, double& t) {
  int found = 0;
  for (std::size_t i = 0; i < run.size(); ++i) {
    const std::vector<double> c = side_coefficients(run[i].h, p, direction);
    const bool behind_start = c.front() < 0.0, ahead_end = c.back() > 0.0;
    if (!behind_start && !ahead_end) {
      // Ahead at both ends: no crossing inside unless it comes back, which a certificate refuses anyway.
      continue;
    }
    if (behind_start && !ahead_end) continue;  // behind throughout (checked by the sides later)
    if (!behind_start && ahead_end) return false;
    const double root = crossing(run[i].h, p, direction);
    if (root < 0.0) return false;
    index = i, t = root;
    ++found;
  }
  return found == 1;
}

/// Whether the run of stretches is within the budget of the arc: the arc cut
/// at the angle (for a segment: the foot) of each joint between stretches,
/// each part certified against its stretch.
bool certify_run(const ArcSegment& arc, const std::vector<Stretch>& run, double budget, double slack, double& bound) {
  if (run.size() == 1) return certify(arc, run[0], budget, slack, bound);
  bound = 0.0;
  const double sweep = sweep_of(arc);
  Vec2 from = arc.start;
  double swept = 0.0;
  for (std::size_t i = 0; i < run.size(); ++i) {
    Vec2 to = arc.end;
    double part = sweep - swept;
    if (i + 1 < run.size()) {
      const Vec2 q = cartesian(run[i].h, run[i].h.size() - 1);
      if (arc.bulge == 0.0) {
        const Vec2 u = arc.end - arc.start;
        to = arc.start + (dot(q - arc.start, u) / dot(u, u)) * u;
        part = 0.0;
      } else {
        const Vec2 c = center_of(arc);
        to = c + (radius_of(arc) / norm(q - c)) * (q - c);
        double angle = std::atan2(cross(arc.start - c, to - c), dot(arc.start - c, to - c));
        if (angle * sweep < 0.0) angle += (sweep > 0.0 ? 2.0 : -2.0) * std::numbers::pi;
        part = angle - swept;
      }
    }
    double b = 0.0;
    // A stretch that is one point (a piece of zero length) lies on the arc's cut.
    if (norm(to - from) > 0.0 && !certify({from, to, std::tan(part / 4.0)}, run[i], budget, slack, b)) return false;
    bound = std::max(bound, b);
    from = to;
    swept += part;
  }
  return true;
}

/// The biarc from `start` (the chain's point, on the stretch's start within
/// rounding) to the end of the curve's stretch [u0, u1] matching its end
/// tangents, with equal tangent lengths (Bolton 1975): the joint
/// J = (P0 + P1 + a (T0 - T1)) / 2 where a solves
/// 2 (1 - T0.T1) a^2 + 2 (T0 + T1).d a - |d|^2 = 0, taken in the form that has
/// no cancellation (and holds for parallel tangents). Certified arc by arc,
/// the stretch cut where it crosses the normal at J (at um).
bool certified_biarc(const Pieces& pieces, double u0, double u1, Vec2 start, std::array<ArcSegment, 2>& arcs,
                     double& um, double& bound) {
  const Place from = pieces.start_of(u0), to = pieces.end_of(u1);
  const std::vector<Stretch> run = pieces.stretches(from, to);
  Vec2 t0, t1, unused;
  std::size_t first = 0, last = run.size() - 1;
  while (first < run.size() && !end_tangents(run[first].h, pieces.scale, t0, unused)) ++first;
  while (last > first && !end_tangents(run[last].h, pieces.scale, unused, t1)) --last;
  if (first == run.size() || !end_tangents(run[last].h, pieces.scale, unused, t1)) return false;
  const Vec2 end = cartesian(run.back().h, run.back().h.size() - 1);
  const Vec2 d = end - start;
  const double dd = dot(d, d);
  if (!(dd > 0.0)) return false;
  const Vec2 v = t0 + t1;
  const double vd = dot(v, d), turn = 1.0 - dot(t0, t1);
  const double denominator = vd + std::sqrt(vd * vd + 2.0 * turn * dd);
  if (!(denominator > 0.0)) return false;
  const double a = dd / denominator;
  const Vec2 j = 0.5 * (start + end + a * (t0 - t1));
  const Vec2 d1 = j - start, d2 = end - j;
  if (!(norm(d1) > 0.0 && norm(d2) > 0.0)) return false;
  const double sweep1 = 2.0 * std::atan2(cross(t0, d1), dot(t0, d1));
  const double sweep2 = 2.0 * std::atan2(cross(d2, t1), dot(d2, t1));
  arcs = {ArcSegment{start, j, std::tan(sweep1 / 4.0)}, ArcSegment{j, end, std::tan(sweep2 / 4.0)}};
  std::size_t index = 0;
  double t = 0.0;
  if (!crossing_over(run, j, tangent_along(arcs[0], 1.0), index, t)) return false;
  const std::size_t joint_piece = from.piece + index;
  const double local = (joint_piece == from.piece ? from.t : 0.0) +
                       t * ((joint_piece == to.piece ? to.t : 1.0) - (joint_piece == from.piece ? from.t : 0.0));
  const Place middle{joint_piece, local};
  um = pieces.global(middle);
  if (!(um > u0 && um < u1)) return false;
  double b1 = 0.0, b2 = 0.0;
  if (!certify_run(arcs[0], pieces.stretches(from, middle), pieces.budget, pieces.slack, b1)) return false;
  if (!certify_run(arcs[1], pieces.stretches(middle, to), pieces.budget, pieces.slack, b2)) return false;
  bound = std::max(b1, b2) + pieces.slack;
  return true;
}

/// A segment of the chain and the stretch [u0, u1] of curve it stands for.
struct Fitted {
  ArcSegment arc;
  double u0, u1;
  double bound;
};

/// Whether two consecutive elements lie on one circle (or one line) and
/// share their tangent at the joint.
bool same_circle(const ArcSegment& a, const ArcSegment& b, double scale) {
  const double ka = curvature_of(a), kb = curvature_of(b);
  if (std::abs(ka - kb) > kArcSameCircle * std::max({std::abs(ka), std::abs(kb), 1.0 / scale})) return false;
  const Vec2 ta = tangent_along(a, 1.0), tb = tangent_along(b, 0.0);
  return std::abs(cross(ta, tb)) <= kArcSameCircle && dot(ta, tb) > 0.0;
}

/// The element joining a and b (consecutive, on one circle), certified
/// again over both stretches; false when it would turn (nearly) a whole
/// circle or is not within the budget.
bool certified_join(const Fitted& a, const Fitted& b, const Pieces& pieces, Fitted& joined) {
  const double sweep = sweep_of(a.arc) + sweep_of(b.arc);
  if (std::abs(sweep) >= tolerances::kArcLargestSweep) return false;
  joined = {{a.arc.start, b.arc.end, std::tan(sweep / 4.0)}, a.u0, b.u1, 0.0};
  const auto run = pieces.stretches(pieces.start_of(a.u0), pieces.end_of(b.u1));
  if (!certify_run(joined.arc, run, pieces.budget, pieces.slack, joined.bound)) return false;
  joined.bound += pieces.slack;
  return true;
}

/// The parameters where the chain must break: the domain's ends, cusps,
/// corners (joints of pieces whose tangents differ) and pieces of zero
/// length; an error where pieces do not meet.
Expected<std::vector<double>> hard_cuts(CurveView curve, const BezierPieces& pieces, double scale, double tolerance) {
  std::vector<double> cuts{pieces.breakpoints.front()};
  for (const double u : cusp_parameters(curve).value()) cuts.push_back(u);
  for (std::size_t p = 0; p + 1 < pieces.pieces.size(); ++p) {
    const PointArray a = homogeneous_points(pieces.pieces[p]), b = homogeneous_points(pieces.pieces[p + 1]);
    if (norm(cartesian(a, a.size() - 1) - cartesian(b, 0)) > tolerance)
      return Error{"arc fitting needs a curve without jumps, this one jumps at u = " +
                   std::to_string(pieces.breakpoints[p + 1])};
    Vec2 s0, e0, s1, e1;
    const bool a_line = end_tangents(a, scale, s0, e0), b_line = end_tangents(b, scale, s1, e1);
    if (!a_line || !b_line || std::abs(cross(e0, s1)) > kArcSameCircle || dot(e0, s1) <= 0.0)
      cuts.push_back(pieces.breakpoints[p + 1]);
  }
  cuts.push_back(pieces.breakpoints.back());
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

}  // namespace

Expected<ArcSpline> fit_arcs(CurveView curve, Tolerance tolerance) {
  if (curve.dimension() != 2)
    return Error{"arc fitting needs a plane curve, this one lives in R^" + std::to_string(curve.dimension())};
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the arc fitting tolerance must be a finite distance > 0, got " + std::to_string(tolerance.distance)};
  const BezierPieces bezier = to_bezier_pieces(curve);
  const double scale = std::max(size_of(curve), tolerances::kScaleFloor);
  double budget = tolerance.distance;
  for (std::size_t p = 0; p < bezier.pieces.size(); ++p) {
    auto piece_budget = ops_detail::certified_budget(bezier.pieces[p], tolerance, "arc fitting");
    if (!piece_budget) return with_context(piece_budget.error(), "piece " + std::to_string(p));
    budget = std::min(budget, *piece_budget);
  }
  const Pieces pieces{bezier, budget, tolerance.distance - budget, scale};
  auto cuts = hard_cuts(curve, bezier, scale, tolerance.distance);
  if (!cuts) return cuts.error();

  std::vector<Fitted> chain;
  Vec2 at = cartesian(homogeneous_points(bezier.pieces.front()), 0);
  for (std::size_t c = 0; c + 1 < cuts->size(); ++c) {
    double from = (*cuts)[c];
    const double to = (*cuts)[c + 1];
    const Place probe_start = pieces.start_of(from), probe_end = pieces.end_of(to);
    bool empty = true;
    for (const Stretch& s : pieces.stretches(probe_start, probe_end)) {
      Vec2 a, b;
      empty &= !end_tangents(s.h, scale, a, b);
    }
    if (empty) continue;  // a stretch of zero length
    while (from < to) {
      // The longest certified biarc from `from`: the whole stretch, else
      // bisection on its end (a certificate holds on shorter stretches).
      std::array<ArcSegment, 2> arcs, best_arcs;
      double um = 0.0, bound = 0.0, best_um = 0.0, best_bound = 0.0, reach = from;
      if (certified_biarc(pieces, from, to, at, arcs, um, bound)) {
        reach = to, best_arcs = arcs, best_um = um, best_bound = bound;
      } else {
        double lo = from, hi = to;
        for (int step = 0; step < kArcFitReachSteps || reach == from; ++step) {
          if (step > kArcFitReachSteps + 60) break;
          const double mid = 0.5 * (lo + hi);
          if (!(mid > lo && mid < hi)) break;
          if (certified_biarc(pieces, from, mid, at, arcs, um, bound)) {
            lo = mid, reach = mid, best_arcs = arcs, best_um = um, best_bound = bound;
          } else {
            hi = mid;
          }
        }
      }
      if (reach == from)
        return Error{"no biarc within the arc fitting tolerance " + std::to_string(tolerance.distance) +
                     " near u = " + std::to_string(from)};
      chain.push_back({best_arcs[0], from, best_um, best_bound});
      chain.push_back({best_arcs[1], best_um, reach, best_bound});
      at = best_arcs[1].end;
      from = reach;
      if (chain.size() > static_cast<std::size_t>(tolerances::kMaxFlattenSegments))
        return Error{"arc fitting would need more than " + std::to_string(tolerances::kMaxFlattenSegments) +
                     " segments at the tolerance " + std::to_string(tolerance.distance)};
    }
  }
  if (chain.empty()) return Error{"arc fitting needs a curve of nonzero length, this one is a single point"};

  // Join consecutive elements of one circle (one line), certified again.
  std::vector<Fitted> joined;
  for (const Fitted& f : chain) {
    Fitted both;
    if (!joined.empty() && same_circle(joined.back().arc, f.arc, scale) && certified_join(joined.back(), f, pieces, both)) {
      joined.back() = both;
      continue;
    }
    joined.push_back(f);
  }
  ArcSpline result;
  result.segments.reserve(joined.size());
  result.parameters.reserve(joined.size() + 1);
  for (const Fitted& f : joined) {
    ArcSegment segment = f.arc;
    double bound = f.bound;
    // An arc straight within rounding is its chord (the sagitta is |bulge| chord / 2).
    const double sagitta = std::abs(segment.bulge) * norm(segment.end - segment.start) / 2.0;
    if (segment.bulge != 0.0 && sagitta <= kArcStraightSagitta * scale && bound + sagitta <= tolerance.distance) {
      segment.bulge = 0.0;
      bound += sagitta;
    }
    result.segments.push_back(segment);
    result.parameters.push_back(f.u0);
    result.deviation_bound = std::max(result.deviation_bound, bound);
  }
  result.parameters.push_back(bezier.breakpoints.back());
  // The last end exactly the curve's end.
  const PointArray last = homogeneous_points(bezier.pieces.back());
  result.segments.back().end = cartesian(last, last.size() - 1);
  return result;
}

}  // namespace casteljau

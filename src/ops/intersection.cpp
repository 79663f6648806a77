// Intersections of curves (intersection.hpp): in the plane: per pair of Bézier
// pieces, the lower-degree piece implicitized (Bézout matrix), the other
// substituted, the roots of the resulting polynomial inverted and refined.
// In space: subdivision and Gauss-Newton on the nearest pair of points.
#include "casteljau/ops/intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <tuple>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "../core/number_text.hpp"
#include "bernstein_columns.hpp"
#include "line_passes.hpp"
#include "segment_distance.hpp"

namespace casteljau {
namespace {

using detail::column;
using detail::derivative;
using tolerances::kIntersectionContactCurvature;
using tolerances::kIntersectionContactRate;
using tolerances::kIntersectionContactZone;
using tolerances::kIntersectionConverged;
using tolerances::kIntersectionJointSlack;
using tolerances::kIntersectionLooseRoot;
using tolerances::kIntersectionSameCrossing;
using tolerances::kIntersectionSameTangency;
using tolerances::kIntersectionSubdivisionWidth;
using tolerances::kIntersectionTangentSine;
using tolerances::kIntersectionZoneReach;

/// A polynomial in Bernstein form and a bound of the terms that were summed
/// to make it (the scale its rounding is relative to), coefficient by coefficient.
struct Bounded {
  std::vector<double> value;
  std::vector<double> magnitude;
};

Bounded product(const Bounded& p, const Bounded& q) {
  return {bernstein_product(p.value, q.value), bernstein_product(p.magnitude, q.magnitude)};
}
Bounded combination(const Bounded& p, double sign, const Bounded& q) {
  Bounded r = p;
  for (std::size_t i = 0; i < r.value.size(); ++i) {
    r.value[i] += sign * q.value[i];
    r.magnitude[i] += q.magnitude[i];
  }
  return r;
}

/// Power-basis coefficients a_k = C(n,k) sum_{i<=k} (-1)^(k-i) C(k,i) b_i of
/// a polynomial in Bernstein form (Farin §5.5): well conditioned on [0, 1]
/// for the degrees (<= 3) the implicitization takes.
std::vector<double> power_coefficients(const std::vector<double>& b) {
  const int n = static_cast<int>(b.size()) - 1;
  std::vector<double> a(b.size(), 0.0);
  for (int k = 0; k <= n; ++k) {
    double sum = 0.0;
    for (int i = 0; i <= k; ++i) sum += ((k - i) % 2 == 0 ? 1.0 : -1.0) * binomial(k, i) * b[i];
    a[k] = binomial(n, k) * sum;
  }
  return a;
}

/// The implicit form of a plane piece of degree n: the n x n Bézout matrix of
/// X w(t) - x(t) and Y w(t) - y(t), entry (i, j) = sum over k <= min(i,
/// n-1-j) of the bracket [j+k+1, i-k], where [u, v] = p_u q_v - p_v q_u is the
/// line a X + b Y + c with a = w_v y_u - w_u y_v, b = x_v w_u - x_u w_v,
/// c = x_u y_v - x_v y_u (power coefficients x_u, y_u, w_u).
/// Its determinant vanishes exactly on the piece's algebraic curve.
using Line = std::array<double, 3>;
std::vector<Line> bezout_matrix(const BezierCurve& piece) {
  const PointArray h = homogeneous_points(piece);
  const std::vector<double> x = power_coefficients(column(h, 0)), y = power_coefficients(column(h, 1)),
                            w = power_coefficients(column(h, 2));
  const int n = piece.degree();
  std::vector<Line> matrix(static_cast<std::size_t>(n * n), Line{0, 0, 0});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k <= std::min(i, n - 1 - j); ++k) {
        const int u = j + k + 1, v = i - k;
        Line& line = matrix[static_cast<std::size_t>(i * n + j)];
        line[0] += w[v] * y[u] - w[u] * y[v];
        line[1] += x[v] * w[u] - x[u] * w[v];
        line[2] += x[u] * y[v] - x[v] * y[u];
      }
  return matrix;
}

/// p(t) = det(Bézout matrix of `implicit` at other(t)) times w(t)^n, in
/// Bernstein form of degree n m, with the magnitude of its terms: the
/// determinant expanded along its rows with every minor computed once
/// (minors of the last rows indexed by their set of columns, 2^n of them),
/// each product exact up to rounding (Farin §5.8).
Bounded substituted(const BezierCurve& implicit, const BezierCurve& other) {
  const int n = implicit.degree();
  const std::vector<Line> matrix = bezout_matrix(implicit);
  const PointArray h = homogeneous_points(other);
  std::vector<Bounded> entries(matrix.size());
  for (std::size_t e = 0; e < matrix.size(); ++e) {
    const Line& line = matrix[e];
    for (std::size_t l = 0; l < h.size(); ++l) {
      entries[e].value.push_back(line[0] * h[l][0] + line[1] * h[l][1] + line[2] * h[l][2]);
      entries[e].magnitude.push_back(std::abs(line[0] * h[l][0]) + std::abs(line[1] * h[l][1]) +
                                     std::abs(line[2] * h[l][2]));
    }
  }
  // minors[S]: the determinant of the last |S| rows on the columns of S.
  const std::size_t subsets = std::size_t{1} << n;
  std::vector<Bounded> minors(subsets);
  minors[0] = {{1.0}, {1.0}};
  for (std::size_t set = 1; set < subsets; ++set) {
    const int size = __builtin_popcountll(set);
    const int row = n - size;
    Bounded sum;
    int position = 0;
    for (int j = 0; j < n; ++j) {
      if (!(set & (std::size_t{1} << j))) continue;
      const Bounded term = product(entries[static_cast<std::size_t>(row * n + j)], minors[set & ~(std::size_t{1} << j)]);
      sum = sum.value.empty() ? Bounded{std::vector<double>(term.value.size(), 0.0), std::vector<double>(term.value.size(), 0.0)} : sum;
      sum = combination(sum, position % 2 == 0 ? 1.0 : -1.0, term);
      ++position;
    }
    minors[set] = std::move(sum);
  }
  return minors[subsets - 1];
}

struct Hit {
  double s, t;  // local parameters on the two pieces
  IntersectionKind kind;
  int multiplicity;
  double s_end = 0.0, t_end = 0.0;  // an overlap's other end
};

double distance(const Point& p, const Point& q) {
  if (p.size() == 2) return std::hypot(p[0] - q[0], p[1] - q[1]);
  double squared = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) squared += (p[i] - q[i]) * (p[i] - q[i]);
  return std::sqrt(squared);
}

double dot(const Point& p, const Point& q) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) sum += p[i] * q[i];
  return sum;
}

/// |sin| of the angle between two tangents (0 when either vanishes).
double tangent_sine(const Point& ta, const Point& tb) {
  if (ta.size() == 2)
    return std::abs(ta[0] * tb[1] - ta[1] * tb[0]) /
           std::max(std::hypot(ta[0], ta[1]) * std::hypot(tb[0], tb[1]), tolerances::kScaleFloor);
  // Lagrange's identity: |a x b|^2 = |a|^2 |b|^2 - (a . b)^2, in any dimension.
  const double aa = dot(ta, ta), bb = dot(tb, tb), ab = dot(ta, tb);
  return std::sqrt(std::max(0.0, aa * bb - ab * ab)) / std::max(std::sqrt(aa * bb), tolerances::kScaleFloor);
}

/// The step (ds, dt) from (s, t): in the plane Newton's on A(s) - B(t) = 0;
/// in space Gauss-Newton's on |A(s) - B(t)|^2 (the normal equations of
/// [A' -B'] (ds, dt) = B - A), towards the nearest pair of points. False
/// where the Jacobian is singular.
bool newton_step(const BezierCurve& a, const BezierCurve& b, double s, double t, double& ds, double& dt) {
  const std::vector<Point> da = derivatives_up_to(a, s, 1), db = derivatives_up_to(b, t, 1);
  if (a.dimension() == 2) {
    // [A' -B'] (ds, dt) = B - A.
    const double f0 = db[0][0] - da[0][0], f1 = db[0][1] - da[0][1];
    const double det = -da[1][0] * db[1][1] + db[1][0] * da[1][1];
    if (det == 0.0) return false;
    ds = (-f0 * db[1][1] + db[1][0] * f1) / det;
    dt = (da[1][0] * f1 - da[1][1] * f0) / det;
    return true;
  }
  Point r(da[0].size());
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = db[0][i] - da[0][i];
  const double aa = dot(da[1], da[1]), ab = -dot(da[1], db[1]), bb = dot(db[1], db[1]);
  const double ra = dot(da[1], r), rb = -dot(db[1], r);
  const double det = aa * bb - ab * ab;
  if (!(det > 0.0)) return false;
  ds = (ra * bb - ab * rb) / det;
  dt = (aa * rb - ab * ra) / det;
  return true;
}

/// Whether (s, t) is where Newton (Gauss-Newton in space) has converged: its
/// next step is below kIntersectionSameCrossing. In space, the nearest pair
/// of two branches passing each other; a point of a contact zone, or near a
/// cusp, is not one.
bool converged_pair(const BezierCurve& a, const BezierCurve& b, double s, double t) {
  double ds = 0.0, dt = 0.0;
  if (!newton_step(a, b, s, t, ds, dt)) return false;
  // At an end of a piece the nearest pair may lie beyond it: no step out.
  if ((s == 0.0 && ds < 0.0) || (s == 1.0 && ds > 0.0)) ds = 0.0;
  if ((t == 0.0 && dt < 0.0) || (t == 1.0 && dt > 0.0)) dt = 0.0;
  return std::abs(ds) <= kIntersectionSameCrossing && std::abs(dt) <= kIntersectionSameCrossing;
}

/// From (s, t) near an intersection, kept inside [0, 1]^2, newton_step
/// halved until the points come nearer (at most 16 steps): where the
/// curves cross, or in space pass each other closest. It stops early where
/// Newton creeps: after a step that had to be halved 10 times, or after three
/// steps in a row that each took less than a quarter off the gap (Newton
/// converges quadratically at a crossing and takes 2/3 or more off per step
/// at contacts of order 2 to 4; near-parallel branches a few tolerances
/// apart, issue 42's fuzzer, took all 16 steps of 10 halvings at each of
/// 40,000 pairs of sub-curves).
void refine(const BezierCurve& a, const BezierCurve& b, double& s, double& t) {
  double gap = distance(point_at(a, s), point_at(b, t));
  int slow = 0;
  for (int iteration = 0; iteration < 16 && gap > 0.0; ++iteration) {
    double ds = 0.0, dt = 0.0;
    if (!newton_step(a, b, s, t, ds, dt)) break;
    // The step, halved until it brings the points nearer (near a tangency
    // the Jacobian is nearly singular and the full step overshoots).
    double factor = 1.0, s1 = s, t1 = t, gap1 = gap;
    int halvings = 0;
    for (; halvings < 30; ++halvings, factor *= 0.5) {
      s1 = std::clamp(s + factor * ds, 0.0, 1.0), t1 = std::clamp(t + factor * dt, 0.0, 1.0);
      gap1 = distance(point_at(a, s1), point_at(b, t1));
      if (gap1 < gap) break;
    }
    if (!(gap1 < gap)) break;
    slow = gap1 > 0.75 * gap ? slow + 1 : 0;
    s = s1, t = t1, gap = gap1;
    if (halvings >= 10 || slow >= 3) break;
  }
}

/// The multiplicity of a root of p inside a zone where |p| is rounding noise:
/// the order k (of the parity the sign changes gave) whose Taylor term
/// |p^(k)(t)| (w/2)^k / k! over the zone's half width w/2 is what reaches the
/// noise; lower orders' terms are far below it at the zone's middle.
int zone_multiplicity(const std::vector<double>& p, double t, double noise, int parity_hint) {
  // The zone's half width: how far |p| stays within the noise around t.
  double half = 1e-15;
  while (half < 0.25 && std::abs(bernstein_value(p, std::clamp(t - half, 0.0, 1.0))) <= noise &&
         std::abs(bernstein_value(p, std::clamp(t + half, 0.0, 1.0))) <= noise)
    half *= 2.0;
  std::vector<double> d = p;
  double factorial = 1.0;
  const int degree = static_cast<int>(p.size()) - 1;
  for (int k = 1; k <= degree; ++k) {
    d = derivative(d);
    factorial *= k;
    if (k < 2 || (k % 2) != (parity_hint % 2)) continue;
    if (std::abs(bernstein_value(d, t)) * std::pow(half, k) / factorial >= 0.1 * noise) return k;
  }
  return parity_hint;
}

/// Whether a piece stays within `tolerance` of its first point (its control
/// points do, and the piece lies in their hull): where a curve rests.
bool stays_at_one_point(const BezierCurve& piece, double tolerance) {
  const PointArray& control = piece.control_points();
  const Point first(control[0].begin(), control[0].end());
  for (std::size_t j = 1; j < control.size(); ++j)
    if (distance(Point(control[j].begin(), control[j].end()), first) > tolerance) return false;
  return true;
}

bool boxes_meet(const BezierCurve& a, const BezierCurve& b, double tolerance) {
  for (int j = 0; j < a.dimension(); ++j) {
    double a_low = INFINITY, a_high = -INFINITY, b_low = INFINITY, b_high = -INFINITY;
    for (std::size_t i = 0; i < a.control_points().size(); ++i)
      a_low = std::min(a_low, a.control_points()[i][j]), a_high = std::max(a_high, a.control_points()[i][j]);
    for (std::size_t i = 0; i < b.control_points().size(); ++i)
      b_low = std::min(b_low, b.control_points()[i][j]), b_high = std::max(b_high, b.control_points()[i][j]);
    if (a_low > b_high + tolerance || b_low > a_high + tolerance) return false;
  }
  return true;
}

/// Whether two sub-curves lie farther apart than the tolerance, by their
/// chords: each lies within its flatness (the largest distance of a control
/// point from its chord segment) of the chord, so chords farther apart than
/// the tolerance and both flatnesses part them (with kRoundingSlack of the
/// largest coordinate for the rounding of the distances). The axis-aligned
/// boxes of two sub-curves running side by side along a diagonal meet however
/// far apart the curves are (issue 42's fuzzer: a curve of degree 10 running
/// out along y = x and back, 20 to 3,000 tolerances off its way out, had every
/// pair of its sub-curves there halved to the narrowest and Newton at each).
bool chords_apart(const BezierCurve& a, const BezierCurve& b, double tolerance) {
  const PointArray& p = a.control_points();
  const PointArray& q = b.control_points();
  double flat = 0.0, largest = 0.0;
  for (const PointArray* points : {&p, &q}) {
    const std::span<const double> first = (*points)[0], last = (*points)[points->size() - 1];
    for (std::size_t i = 0; i < points->size(); ++i)
      for (const double x : (*points)[i]) largest = std::max(largest, std::abs(x));
    double deviation = 0.0;
    for (std::size_t i = 1; i + 1 < points->size(); ++i)
      deviation = std::max(deviation, detail::distance_to_segment((*points)[i], first, last));
    flat += deviation;
  }
  const double gap = detail::distance_between_segments(p[0], p[p.size() - 1], q[0], q[q.size() - 1]);
  return gap > tolerance + flat + tolerances::kRoundingSlack * largest;
}

/// A hit of two pieces on their spans of the curves' domains, into the
/// points or the overlaps.
void record(const Hit& hit, const BezierCurve& piece_a, Interval span_a, Interval span_b,
            std::vector<CurveIntersection>& points, std::vector<CurveIntersection>& overlaps) {
  CurveIntersection found;
  found.kind = hit.kind;
  found.multiplicity = hit.multiplicity;
  found.point = point_at(piece_a, hit.s);
  const bool overlap = hit.kind == IntersectionKind::overlap;
  found.a = {span_a.lerp(hit.s), span_a.lerp(overlap ? hit.s_end : hit.s)};
  found.b = {span_b.lerp(hit.t), span_b.lerp(overlap ? hit.t_end : hit.t)};
  (overlap ? overlaps : points).push_back(found);
}

/// The coefficients of a piece's hodograph (detail::velocity_numerators),
/// the zero ones left out.
std::vector<Point> hodograph_directions(const BezierCurve& piece) {
  const int d = piece.dimension();
  const std::vector<std::vector<double>> coordinates = detail::velocity_numerators(piece);
  std::vector<Point> directions;
  for (std::size_t i = 0; i < coordinates[0].size(); ++i) {
    Point v(d);
    for (int j = 0; j < d; ++j) v[j] = coordinates[j][i];
    if (dot(v, v) > 0.0) directions.push_back(std::move(v));
  }
  return directions;
}

/// Whether the hodograph's coefficients lie in an open half plane (half
/// space): then C' . m > 0 inside for some direction m, and the piece is
/// injective. In the plane exactly (the largest angular gap between them
/// exceeds pi); in space by a sufficient test: every coefficient has a
/// positive component along the sum of their unit vectors.
bool turns_less_than_half(const BezierCurve& piece) {
  const std::vector<Point> directions = hodograph_directions(piece);
  if (directions.empty()) return true;  // a point: nothing to cross
  if (piece.dimension() == 2) {
    std::vector<double> angles;
    for (const Point& v : directions) angles.push_back(std::atan2(v[1], v[0]));
    std::sort(angles.begin(), angles.end());
    double gap = angles.front() + 2 * M_PI - angles.back();
    for (std::size_t i = 0; i + 1 < angles.size(); ++i) gap = std::max(gap, angles[i + 1] - angles[i]);
    return gap > M_PI;
  }
  Point mean(static_cast<std::size_t>(piece.dimension()), 0.0);
  for (const Point& v : directions) {
    const double length = std::sqrt(dot(v, v));
    for (std::size_t j = 0; j < v.size(); ++j) mean[j] += v[j] / length;
  }
  return std::all_of(directions.begin(), directions.end(), [&](const Point& v) { return dot(v, mean) > 0.0; });
}

/// A part of one piece: its local interval and the part itself.
struct Part {
  Interval span;
  BezierCurve curve;
};

/// The piece cut into parts that turn by less than half a turn (halving, at
/// most kMaxDepth times: parts at a cusp stay small and non-injective).
void injective_parts(const BezierCurve& curve, Interval span, int depth, std::vector<Part>& parts) {
  constexpr int kMaxDepth = 16;
  if (depth >= kMaxDepth || turns_less_than_half(curve)) {
    parts.push_back({span, curve});
    return;
  }
  const auto halves = split_at(curve, 0.5).value();
  const double middle = 0.5 * (span.lower + span.upper);
  injective_parts(halves.first, {span.lower, middle}, depth + 1, parts);
  injective_parts(halves.second, {middle, span.upper}, depth + 1, parts);
}

/// The hits of every piece pair as the result: overlaps of consecutive
/// pieces joined, each point once (a hit at a knot is seen from both
/// pieces), none inside an overlap nor at its ends, sorted by the parameter
/// on a. Where a shared stretch ends the curves continue one another, so
/// the point search finds that end as a meeting known only to about the
/// square root of the rounding (kIntersectionSameTangency): the sailboat's
/// mast and hull gave it 1.6e-9 and 4.5e-8 off in the parameters, 1.3e-7
/// in the plane, reported beside the overlap.
std::vector<CurveIntersection> merged(std::vector<CurveIntersection> points, std::vector<CurveIntersection> overlaps,
                                      double width_a, double width_b) {
  // Overlaps of consecutive pieces that continue one another become one:
  // end to end in both parameters, b running the same way in both (a curve
  // folding back on itself has overlaps that meet end to end with b turning
  // back: those stay apart).
  std::sort(overlaps.begin(), overlaps.end(),
            [](const CurveIntersection& x, const CurveIntersection& y) { return x.a.lower < y.a.lower; });
  std::vector<CurveIntersection> joined;
  for (const CurveIntersection& o : overlaps) {
    if (!joined.empty()) {
      CurveIntersection& last = joined.back();
      const bool same_way = (o.b.upper >= o.b.lower) == (last.b.upper >= last.b.lower);
      if (same_way && std::abs(o.a.lower - last.a.upper) <= kIntersectionJointSlack * width_a &&
          std::abs(o.b.lower - last.b.upper) <= kIntersectionJointSlack * width_b) {
        last.a.upper = o.a.upper;
        last.b.upper = o.b.upper;
        continue;
      }
    }
    joined.push_back(o);
  }
  // Points: once each (a hit at a knot is seen from both pieces), none inside an overlap.
  const auto inside = [&](const CurveIntersection& p, const CurveIntersection& o) {
    // On the overlap's own diagonal: b where the overlap puts a's point (the
    // parameterizations of one curve by polynomial pieces of one degree are
    // affine in each other); a crossing at a double point lies off it.
    const double slack_a = kIntersectionJointSlack * width_a, slack_b = kIntersectionLooseRoot * width_b;
    if (p.a.lower < o.a.lower - slack_a || p.a.lower > o.a.upper + slack_a) return false;
    const double f = o.a.length() > 0.0 ? (p.a.lower - o.a.lower) / o.a.length() : 0.0;
    return std::abs(p.b.lower - (o.b.lower + f * (o.b.upper - o.b.lower))) <= slack_b;
  };
  const auto at_an_end = [&](const CurveIntersection& p) {
    const double slack_a = kIntersectionSameTangency * width_a, slack_b = kIntersectionSameTangency * width_b;
    return std::any_of(joined.begin(), joined.end(), [&](const CurveIntersection& o) {
      return (std::abs(p.a.lower - o.a.lower) <= slack_a && std::abs(p.b.lower - o.b.lower) <= slack_b) ||
             (std::abs(p.a.lower - o.a.upper) <= slack_a && std::abs(p.b.lower - o.b.upper) <= slack_b);
    });
  };
  std::sort(points.begin(), points.end(),
            [](const CurveIntersection& x, const CurveIntersection& y) { return x.a.lower < y.a.lower; });
  std::vector<CurveIntersection> result;
  for (const CurveIntersection& p : points) {
    if (std::any_of(joined.begin(), joined.end(), [&](const CurveIntersection& o) { return inside(p, o); })) continue;
    if (at_an_end(p)) continue;
    const double same = p.kind == IntersectionKind::transversal ? kIntersectionSameCrossing : kIntersectionSameTangency;
    const double same_a = same * width_a, same_b = same * width_b;
    const auto duplicate = std::find_if(result.begin(), result.end(), [&](const CurveIntersection& q) {
      const double joint = q.kind != IntersectionKind::transversal ? kIntersectionJointSlack : 0.0;
      return std::abs(q.a.lower - p.a.lower) <= std::max(same_a, joint * width_a) &&
             std::abs(q.b.lower - p.b.lower) <= std::max(same_b, joint * width_b);
    });
    if (duplicate != result.end()) {
      if (duplicate->kind == IntersectionKind::tangent && duplicate->multiplicity == 0) *duplicate = p;
      continue;
    }
    result.push_back(p);
  }
  result.insert(result.end(), joined.begin(), joined.end());
  std::sort(result.begin(), result.end(),
            [](const CurveIntersection& x, const CurveIntersection& y) { return x.a.lower < y.a.lower; });
  return result;
}

/// Whether the segment from (s0, t0) to (s1, t1) passes within `margin` of
/// the rectangle si x ti of parameters (Liang–Barsky clipping): the pairs of
/// sub-curves along an overlap's diagonal, where every pair meets.
bool along_segment(Interval si, Interval ti, double s0, double t0, double s1, double t1, double margin) {
  double low = 0.0, high = 1.0;
  const double ds = s1 - s0, dt = t1 - t0;
  const auto clip = [&](double p, double q) {
    if (p == 0.0) return q >= 0.0;
    const double r = q / p;
    if (p < 0.0) low = std::max(low, r);
    else high = std::min(high, r);
    return low <= high;
  };
  return clip(-ds, s0 - (si.lower - margin)) && clip(ds, (si.upper + margin) - s0) && clip(-dt, t0 - (ti.lower - margin)) &&
         clip(dt, (ti.upper + margin) - t0);
}

/// The order of contact of two branches meeting with one tangent line at
/// a(s) = b(t): 2 where their signed curvatures (b's taken along a's
/// direction) differ, 3 where the curvatures agree but not their rates of
/// change along the arc, 4 beyond (the corpus' highest contacts).
int contact_order(const BezierCurve& a, double s, const BezierCurve& b, double t) {
  const auto curvature = [](const BezierCurve& c, double u, double& speed) {
    const std::vector<Point> d = derivatives_up_to(c, std::clamp(u, 0.0, 1.0), 2);
    speed = std::hypot(d[1][0], d[1][1]);
    return (d[1][0] * d[2][1] - d[1][1] * d[2][0]) / std::max(speed * speed * speed, tolerances::kScaleFloor);
  };
  double speed_a = 0.0, speed_b = 0.0;
  const double ka = curvature(a, s, speed_a);
  const double kb0 = curvature(b, t, speed_b);
  const Point ta = derivative_at(a, s, 1), tb = derivative_at(b, t, 1);
  const double orientation = ta[0] * tb[0] + ta[1] * tb[1] >= 0.0 ? 1.0 : -1.0;
  const double kb = orientation * kb0;
  const double size = std::max(size_of(a), size_of(b));
  const double scale = std::max({std::abs(ka), std::abs(kb), 1.0 / std::max(size, tolerances::kScaleFloor)});
  if (std::abs(ka - kb) > kIntersectionContactCurvature * scale) return 2;
  // Rates of change along the arc, by central differences over 1e-4 of each piece.
  const double h = 1e-4;
  double unused = 0.0;
  const double rate_a = (curvature(a, s + h, unused) - curvature(a, s - h, unused)) / (2 * h * std::max(speed_a, 1e-300));
  const double rate_b = orientation * orientation *
                        (curvature(b, t + orientation * h, unused) - curvature(b, t - orientation * h, unused)) /
                        (2 * h * std::max(speed_b, 1e-300)) * orientation;
  const double rate_scale = std::max({std::abs(rate_a), std::abs(rate_b), scale / std::max(size, tolerances::kScaleFloor)});
  return std::abs(rate_a - rate_b) > kIntersectionContactRate * rate_scale ? 3 : 4;
}

/// Whether c is at or next to a cusp at u (in space): its velocity vanishes
/// within kIntersectionContactZone of u, |C'(u)| <= kIntersectionContactZone
/// |C''(u)| (near a cusp C' ~ C'' (u - u0); the curves stay within the
/// tolerance over such a zone around it, and the nearest pairs found there
/// are not crossings).
bool at_cusp(const BezierCurve& c, double u) {
  const std::vector<Point> d = derivatives_up_to(c, u, 2);
  return std::sqrt(dot(d[1], d[1])) <= kIntersectionContactZone * std::sqrt(dot(d[2], d[2]));
}

/// The order of contact of two branches in space meeting with one tangent
/// line at a(s) ~ b(t): 2 where their curvature vectors (C'' - (C'' . T) T)
/// / |C'|^2 differ (relative to the larger, or to 1 / size), 3 where they
/// agree (a contact of order 3 or more: osculating branches).
int space_contact_order(const BezierCurve& a, double s, const BezierCurve& b, double t) {
  // At a cusp (a singular point of multiplicity 2): 2 across its tangent
  // (the direction of C'' there, known to about the contact zone's width,
  // where the cusp is found), 3 along it.
  for (const auto& [cusp, u, other, v] : {std::tuple{&a, s, &b, t}, std::tuple{&b, t, &a, s}})
    if (at_cusp(*cusp, u))
      return tangent_sine(derivative_at(*cusp, u, 2), derivative_at(*other, v, 1)) > kIntersectionContactZone ? 2 : 3;
  const auto curvature_vector = [](const BezierCurve& c, double u) {
    const std::vector<Point> d = derivatives_up_to(c, std::clamp(u, 0.0, 1.0), 2);
    const double speed2 = std::max(dot(d[1], d[1]), tolerances::kScaleFloor);
    const double along = dot(d[2], d[1]) / speed2;
    Point k(d[1].size());
    for (std::size_t i = 0; i < k.size(); ++i) k[i] = (d[2][i] - along * d[1][i]) / speed2;
    return k;
  };
  const Point ka = curvature_vector(a, s), kb = curvature_vector(b, t);
  const double size = std::max(size_of(a), size_of(b));
  const double scale = std::max({std::sqrt(dot(ka, ka)), std::sqrt(dot(kb, kb)), 1.0 / std::max(size, tolerances::kScaleFloor)});
  return distance(ka, kb) > kIntersectionContactCurvature * scale ? 2 : 3;
}

/// Where a subdivision search stopped short, its pair budget spent: the
/// spans (on the two pieces) of a pair of sub-curves it had still to settle.
struct Unsettled {
  Interval s, t;
};

/// Where two pieces meet that their implicit equations cannot tell apart
/// (parts of one piece, or two pieces of one algebraic curve crossing at its
/// double point): pairs of sub-curves whose boxes and chords come within the
/// tolerance, halved down to 1e-6 of a piece, then Newton on a(s) - b(t) = 0
/// from their middles. After kIntersectionPairBudget pairs the search goes on
/// outside the contact zones found (a pair within kIntersectionContactZone of
/// a zone's extent in both parameters adds only that zone's solutions) for as
/// many again; where pairs still meet after that, or after the first budget
/// with no zone to leave out, it stops and says where (Unsettled): its answer
/// would depend on the order of the search. A solution is kept as a crossing
/// when it converges to a few ulps of the scale with distinct tangents, as a tangency (one per cluster,
/// multiplicity contact_order) when the points come within the tolerance
/// with one tangent line. `skip(s, t)` drops the pairs already known (an
/// overlap's diagonal, the parts' joint); for parts of one piece
/// (`same_curve`) a solution needs s < t and a loop between them that
/// reaches beyond the tolerance (near a cusp C(s) and C(t) come within
/// rounding on loops of the size (t - s)^2).
template <class Skip>
[[nodiscard]] std::optional<Unsettled> subdivided_hits(const BezierCurve& a, Interval span_a, const BezierCurve& part_a,
                                                       const BezierCurve& b, Interval span_b, const BezierCurve& part_b,
                                                       bool same_curve, double tolerance, Skip&& skip,
                                                       std::vector<Hit>& found) {
  struct Pair {
    Interval s, t;
    BezierCurve a, b;
  };
  std::vector<Pair> stack{{span_a, span_b, part_a, part_b}};
  const double scale = std::max(size_of(a), size_of(b));
  const double converged = kIntersectionConverged * std::max(scale, tolerances::kScaleFloor);
  const bool plane = a.dimension() == 2;
  const std::size_t first_new = found.size();
  struct Zone {
    std::vector<std::pair<double, double>> solutions;
    Interval s, t;  // their extent
  };
  std::vector<Zone> zones;  // of each new hit
  const auto add_solution = [](Zone& zone, double s, double t) {
    zone.solutions.push_back({s, t});
    zone.s = {std::min(zone.s.lower, s), std::max(zone.s.upper, s)};
    zone.t = {std::min(zone.t.lower, t), std::max(zone.t.upper, t)};
  };
  const auto in_a_zone = [&](const Pair& pair) {
    for (std::size_t k = first_new; k < found.size(); ++k) {
      if (found[k].kind != IntersectionKind::tangent) continue;
      const Zone& zone = zones[k - first_new];
      const double m = kIntersectionContactZone;
      if (pair.s.lower >= zone.s.lower - m && pair.s.upper <= zone.s.upper + m && pair.t.lower >= zone.t.lower - m &&
          pair.t.upper <= zone.t.upper + m)
        return true;
    }
    return false;
  };
  const auto any_tangent = [&] {
    return std::any_of(found.begin() + static_cast<std::ptrdiff_t>(first_new), found.end(),
                       [](const Hit& f) { return f.kind == IntersectionKind::tangent; });
  };
  std::size_t visited = 0;
  bool beyond_budget = false;  // visiting pairs outside the zones found
  // Whether a pair may still hold a hit the search has not settled.
  const auto unsettled = [&](const Pair& pair) {
    return boxes_meet(pair.a, pair.b, tolerance) && !chords_apart(pair.a, pair.b, tolerance) &&
           !skip(pair.s, pair.t) && !(beyond_budget && in_a_zone(pair));
  };
  while (!stack.empty()) {
    if (++visited > tolerances::kIntersectionPairBudget) {
      if (beyond_budget || !any_tangent()) {
        // The latest pair still to settle: the narrowest, where the search was.
        const auto latest = std::find_if(stack.rbegin(), stack.rend(), unsettled);
        if (latest != stack.rend()) return Unsettled{latest->s, latest->t};
        break;
      }
      beyond_budget = true;
      visited = 0;
    }
    Pair pair = std::move(stack.back());
    stack.pop_back();
    if (!unsettled(pair)) continue;
    // Halved until narrow, or until both sub-curves rest within the
    // tolerance of a point (a stall: repeated control points, a cusp), where
    // every finer pair would be one more solution of the same zone (a
    // degree-15 curve resting at both ends took 140 s; issue 42's fuzzer).
    const bool open_a = pair.s.length() > kIntersectionSubdivisionWidth && !stays_at_one_point(pair.a, tolerance);
    const bool open_b = pair.t.length() > kIntersectionSubdivisionWidth && !stays_at_one_point(pair.b, tolerance);
    if (open_a || open_b) {
      const bool split_a = open_a && (!open_b || pair.s.length() >= pair.t.length());
      const auto halves = split_at(split_a ? pair.a : pair.b, 0.5).value();
      const Interval& span = split_a ? pair.s : pair.t;
      const double middle = 0.5 * (span.lower + span.upper);
      if (split_a) {
        stack.push_back({{middle, span.upper}, pair.t, halves.second, pair.b});
        stack.push_back({{span.lower, middle}, pair.t, halves.first, pair.b});
      } else {
        stack.push_back({pair.s, {middle, span.upper}, pair.a, halves.second});
        stack.push_back({pair.s, {span.lower, middle}, pair.a, halves.first});
      }
      continue;
    }
    double s = 0.5 * (pair.s.lower + pair.s.upper), t = 0.5 * (pair.t.lower + pair.t.upper);
    refine(a, b, s, t);
    const double gap = distance(point_at(a, s), point_at(b, t));
    if (gap > tolerance) continue;
    if (same_curve) {
      if (std::abs(s - t) <= kIntersectionJointSlack) continue;
      if (!(distance(point_at(a, s), point_at(a, 0.5 * (s + t))) > tolerance)) continue;
      if (s > t) std::swap(s, t);
    }
    bool crossing = tangent_sine(derivative_at(a, s, 1), derivative_at(b, t, 1)) > kIntersectionTangentSine;
    // In the plane two branches with distinct tangents cross: Newton must
    // have converged to rounding. In space they may pass within the
    // tolerance without meeting; Gauss-Newton gave their nearest pair.
    if (crossing && plane && gap > converged) continue;
    // In space, a pair within the tolerance that is not the nearest pair of
    // two branches passing each other belongs to a contact zone, and so does
    // a cusp of either (its tangent is the limit of C'' there, not C').
    if (crossing && !plane && (!converged_pair(a, b, s, t) || at_cusp(a, s) || at_cusp(b, t))) crossing = false;
    // Crossings seen twice land within rounding; tangent solutions spread
    // over the contact zone, where the curves stay within the tolerance: one
    // tangency per zone.
    const auto seen = std::find_if(found.begin() + static_cast<std::ptrdiff_t>(first_new), found.end(), [&](const Hit& f) {
      if (crossing) {
        if (f.kind != IntersectionKind::transversal) return false;
        const bool same_s = std::abs(f.s - s) <= kIntersectionSameCrossing;
        const bool same_t = std::abs(f.t - t) <= kIntersectionSameCrossing;
        // One branch crossing a stretch where the other rests: one crossing
        // (that other branch stays at the point between the two solutions).
        if (same_s && !same_t) return stays_at_one_point(extended_segment(b, std::min(f.t, t), std::max(f.t, t)), tolerance);
        if (same_t && !same_s) return stays_at_one_point(extended_segment(a, std::min(f.s, s), std::max(f.s, s)), tolerance);
        return same_s && same_t;
      }
      if (f.kind != IntersectionKind::tangent || std::abs(f.s - s) > kIntersectionZoneReach ||
          std::abs(f.t - t) > kIntersectionZoneReach)
        return false;
      return distance(point_at(a, 0.5 * (f.s + s)), point_at(b, 0.5 * (f.t + t))) <= tolerance;
    });
    if (seen != found.end()) {
      if (!crossing) add_solution(zones[static_cast<std::size_t>(seen - found.begin()) - first_new], s, t);
      continue;
    }
    found.push_back({s, t, crossing ? IntersectionKind::transversal : IntersectionKind::tangent, crossing ? 1 : 2});
    zones.push_back({{{s, t}}, {s, s}, {t, t}});
  }
  // A zone's tangency: the median of its solutions where the curves come
  // nearest (within rounding of the least gap): the contact, where the gap
  // grows away from it; the middle of the zone, where rounding hides it.
  for (std::size_t k = first_new; k < found.size(); ++k) {
    if (found[k].kind != IntersectionKind::tangent) continue;
    const std::vector<std::pair<double, double>>& zone = zones[k - first_new].solutions;
    std::vector<double> gaps;
    for (const auto& [s, t] : zone) gaps.push_back(distance(point_at(a, s), point_at(b, t)));
    const double least = *std::min_element(gaps.begin(), gaps.end());
    std::vector<std::pair<double, double>> nearest;
    for (std::size_t i = 0; i < zone.size(); ++i)
      if (gaps[i] <= least + converged) nearest.push_back(zone[i]);
    std::sort(nearest.begin(), nearest.end());
    found[k].s = nearest[nearest.size() / 2].first;
    found[k].t = nearest[nearest.size() / 2].second;
  }
  for (std::size_t k = first_new; k < found.size(); ++k)
    if (found[k].kind == IntersectionKind::tangent)
      found[k].multiplicity = plane ? contact_order(a, found[k].s, b, found[k].t)
                                    : space_contact_order(a, found[k].s, b, found[k].t);
  return std::nullopt;
}

/// Tangencies of one contact zone found from several pairs of parts: one,
/// the median of the zone's (a pair that meets, inside the zone). A
/// tangency joins a zone when it lies within 1e-3 of one of the zone's in
/// both parameters (contact zones are about sqrt(tolerance / curvature)
/// wide), or the curves stay within the tolerance at the pair of their middles.
void merge_tangent_zones(const BezierCurve& a, const BezierCurve& b, double tolerance, std::vector<Hit>& hits) {
  std::vector<Hit> result;
  std::vector<std::vector<Hit>> zones;
  for (const Hit& hit : hits) {
    if (hit.kind != IntersectionKind::tangent) {
      result.push_back(hit);
      continue;
    }
    bool joined = false;
    for (auto& zone : zones) {
      const bool near = std::any_of(zone.begin(), zone.end(), [&](const Hit& f) {
        if (std::abs(f.s - hit.s) > kIntersectionZoneReach || std::abs(f.t - hit.t) > kIntersectionZoneReach) return false;
        if (std::abs(f.s - hit.s) <= kIntersectionContactZone && std::abs(f.t - hit.t) <= kIntersectionContactZone)
          return true;
        return distance(point_at(a, 0.5 * (f.s + hit.s)), point_at(b, 0.5 * (f.t + hit.t))) <= tolerance;
      });
      if (near) {
        zone.push_back(hit);
        joined = true;
        break;
      }
    }
    if (!joined) zones.push_back({hit});
  }
  for (auto& zone : zones) {
    std::sort(zone.begin(), zone.end(), [](const Hit& x, const Hit& y) { return x.s < y.s; });
    result.push_back(zone[zone.size() / 2]);
  }
  hits = std::move(result);
}

/// A point of two pieces on one curve: a(s) = b(t).
struct SharedPoint {
  double s, t;
};

/// The end points of either piece that lie on the other (within the
/// tolerance), by s.
std::vector<SharedPoint> ends_on_each_other(const BezierCurve& a, const BezierCurve& b, double tolerance) {
  std::vector<SharedPoint> pairs;
  for (const double t : {0.0, 1.0}) {
    const NearestPoint on = closest_point(a, point_at(b, t)).value();
    if (on.distance <= tolerance) pairs.push_back({on.parameter, t});
  }
  for (const double s : {0.0, 1.0}) {
    const NearestPoint on = closest_point(b, point_at(a, s)).value();
    if (on.distance <= tolerance) pairs.push_back({s, on.parameter});
  }
  std::sort(pairs.begin(), pairs.end(), [](const SharedPoint& x, const SharedPoint& y) { return x.s < y.s; });
  return pairs;
}

/// Whether the pair of sub-curves si x ti lies along the stretch the shared
/// points span (every such pair meets: they are dropped once small, not at
/// the start).
bool on_shared_stretch(const std::vector<SharedPoint>& pairs, Interval si, Interval ti) {
  if (pairs.empty() || std::max(si.length(), ti.length()) > kIntersectionContactZone) return false;
  return along_segment(si, ti, pairs.front().s, pairs.front().t, pairs.back().s, pairs.back().t,
                       kIntersectionSubdivisionWidth);
}

/// Whether the pair of sub-curves si x ti lies along the stretch that a and b
/// share between the first and last shared points, followed exactly: b's
/// parameter of the point of a at the middle of si falls within ti. Two
/// pieces of one curve need not be parameterized alike (two arcs of one
/// circle with other weights are related by a Möbius map, not an affine
/// one), so the straight diagonal of on_shared_stretch can miss the stretch
/// and leave every pair along it to be found as a tangency (a DXF polyline
/// of two arcs of one circle: 200 of them in 2 s; issue 42's dxf fuzzer).
bool along_shared_stretch(const BezierCurve& a, const BezierCurve& b, const std::vector<SharedPoint>& pairs,
                          Interval si, Interval ti) {
  if (pairs.size() < 2 || std::max(si.length(), ti.length()) > kIntersectionContactZone) return false;
  const double s = 0.5 * (si.lower + si.upper);
  if (s < pairs.front().s - kIntersectionSubdivisionWidth || s > pairs.back().s + kIntersectionSubdivisionWidth)
    return false;
  const double t = closest_point(b, point_at(a, s)).value().parameter;
  return t >= ti.lower - kIntersectionSubdivisionWidth && t <= ti.upper + kIntersectionSubdivisionWidth;
}

/// What the shared points of two pieces of one curve make: the overlap from
/// the first to the last, or, where they span no stretch, a tangency of order
/// 0 (two arcs continuing one another at a point).
Hit shared_hit(const std::vector<SharedPoint>& pairs) {
  const SharedPoint first = pairs.front(), last = pairs.back();
  if (!(last.s - first.s > kIntersectionJointSlack)) return {first.s, first.t, IntersectionKind::tangent, 0};
  Hit overlap{first.s, first.t, IntersectionKind::overlap, 0};
  overlap.s_end = last.s;
  overlap.t_end = last.t;
  return overlap;
}

/// The hit with its two pieces exchanged when `swap` (an overlap still from
/// its lower parameter on the first).
Hit oriented(Hit hit, bool swap) {
  if (!swap) return hit;
  std::swap(hit.s, hit.t);
  std::swap(hit.s_end, hit.t_end);
  if (hit.kind == IntersectionKind::overlap && hit.s_end < hit.s) {
    std::swap(hit.s, hit.s_end);
    std::swap(hit.t, hit.t_end);
  }
  return hit;
}

/// Whether b traces a between two shared points: n m + 1 points of a
/// between them lie within the tolerance of b (two distinct algebraic curves
/// of degrees n and m share at most n m points, Bézout's theorem; within a
/// tolerance this is the test's premise, not a proof).
bool trace_one_another(const BezierCurve& a, const BezierCurve& b, SharedPoint first, SharedPoint last,
                       double tolerance) {
  const int samples = std::max(a.degree(), 1) * std::max(b.degree(), 1) + 1;
  for (int k = 1; k <= samples; ++k) {
    const double s = first.s + (last.s - first.s) * k / (samples + 1);
    if (closest_point(b, point_at(a, s)).value().distance > tolerance) return false;
  }
  return true;
}

/// Whether a's weights stay positive over its extension to [t0, t1]: the
/// weights' own polynomial extended (the same arithmetic as the homogeneous
/// rows' last coordinate), all its coefficients > 0. Beyond [0, 1] a rational
/// piece's weight polynomial may reach zero, where the curve has a pole
/// (extended_segment's contract leaves the check to its caller).
bool extends_with_positive_weights(const BezierCurve& a, double t0, double t1) {
  if (!a.is_rational()) return true;
  const std::span<const double> w = a.weights();
  const BezierCurve weights = BezierCurve::from_trusted(PointArray::from_trusted(1, {w.begin(), w.end()}));
  const PointArray extended = extended_segment(weights, t0, t1).control_points();
  return std::all_of(extended.coordinates().begin(), extended.coordinates().end(), [](double x) { return x > 0.0; });
}

/// Whether b continues a at a shared end point (two pieces of one curve
/// meeting there): b's points kIntersectionZoneReach either side of it lie
/// within the tolerance of a's polynomial extended beyond the piece (pieces
/// that only join with high continuity part by far more there). A rational
/// a is extended by half its domain, or less where its weights would reach
/// zero (a DXF spline with a weight of 17 beside weights of 1 and 0.7 has
/// poles just beyond its pieces' ends: the extension asserted; issue 42's dxf
/// fuzzer); not at all when even 2^-10 would.
bool continue_one_another(const BezierCurve& a, const BezierCurve& b, SharedPoint shared, double tolerance) {
  double reach = 0.5;
  while (!extends_with_positive_weights(a, shared.s - reach, shared.s + reach)) {
    reach *= 0.5;
    if (reach < 0x1p-10) return false;
  }
  const BezierCurve extended = extended_segment(a, shared.s - reach, shared.s + reach);
  int checked = 0;
  for (const double side : {-kIntersectionZoneReach, kIntersectionZoneReach}) {
    const double t = shared.t + side;
    if (t < 0.0 || t > 1.0) continue;
    if (closest_point(extended, point_at(b, t)).value().distance > tolerance) return false;
    ++checked;
  }
  return checked > 0;
}

/// A pass contact (line_passes.hpp) as a hit: an overlap, or a point where
/// two pieces on one line touch (a tangency of order 0, as shared_hit makes).
Hit hit_of(const detail::PassContact& contact) {
  if (!contact.overlap) return {contact.s, contact.t, IntersectionKind::tangent, 0};
  Hit overlap{contact.s, contact.t, IntersectionKind::overlap, 0};
  overlap.s_end = contact.s_end;
  overlap.t_end = contact.t_end;
  return overlap;
}

/// The contacts of two pieces that lie within the tolerance of one line, as
/// their monotone passes meet (line_passes.hpp); no value when they do not.
/// Where two passes run over one stretch every pair of their points is a
/// "tangency" to the searches of the general case, thousands of them, slowly
/// (a DXF arc whose pieces each run out and back along one chord: 84 hits in
/// 4.2 s; issue 42's dxf fuzzer). In the plane it is asked only of two pieces
/// of one algebraic curve (lines whose slopes differ by 2^-40 still cross
/// once); in space the overlap test is the tolerance's already.
std::optional<std::vector<Hit>> hits_on_one_line(const BezierCurve& a, const BezierCurve& b, double tolerance) {
  auto line_a = detail::line_passes(a, tolerance);
  if (!line_a) return std::nullopt;
  auto line_b = detail::line_passes(b, tolerance, &*line_a);
  if (!line_b) return std::nullopt;
  std::vector<Hit> hits;
  for (const detail::PassContact& contact : detail::pass_contacts(*line_a, *line_b, tolerance))
    hits.push_back(hit_of(contact));
  return hits;
}

/// The intersections of two pieces in R^d, d >= 3: the overlap where each
/// traces the other between shared points, a tangency of order 0 where one
/// continues the other, and the points where they come within the tolerance
/// (subdivision of their boxes and Gauss-Newton on the nearest pair),
/// classified by their tangents.
std::vector<Hit> space_piece_hits(const BezierCurve& a, const BezierCurve& b, double tolerance,
                                  std::optional<Unsettled>& unsettled) {
  if (auto on_line = hits_on_one_line(a, b, tolerance)) return *on_line;
  std::vector<Hit> hits;
  std::vector<SharedPoint> pairs = ends_on_each_other(a, b, tolerance);
  const bool overlap = pairs.size() >= 2 && pairs.back().s - pairs.front().s > kIntersectionJointSlack &&
                       trace_one_another(a, b, pairs.front(), pairs.back(), tolerance);
  std::vector<SharedPoint> continued;
  if (!overlap)
    for (const SharedPoint& p : pairs)
      if (continue_one_another(a, b, p, tolerance)) continued.push_back(p);
  const auto shared = [&](Interval si, Interval ti) {
    if (overlap) return on_shared_stretch(pairs, si, ti) || along_shared_stretch(a, b, pairs, si, ti);
    return std::any_of(continued.begin(), continued.end(),
                       [&](const SharedPoint& p) { return on_shared_stretch({p}, si, ti); });
  };
  unsettled = subdivided_hits(a, {0.0, 1.0}, a, b, {0.0, 1.0}, b, false, tolerance, shared, hits);
  // Around a cusp the nearest pairs spread along a zone the midpoint test of
  // subdivided_hits does not join (the parameter is quadratic there).
  merge_tangent_zones(a, b, tolerance, hits);
  if (overlap) hits.push_back(shared_hit(pairs));
  for (const SharedPoint& p : continued) hits.push_back(shared_hit({p}));
  return hits;
}

/// The intersections of piece a with piece b (local parameters), or where
/// their subdivision search stopped short (`unsettled`, set).
std::vector<Hit> piece_hits(const BezierCurve& a, const BezierCurve& b, double tolerance,
                            std::optional<Unsettled>& unsettled) {
  std::vector<Hit> hits;
  if (a.degree() == 0 || b.degree() == 0) {
    // A point piece meets the other where it lies on it.
    const bool a_point = a.degree() == 0;
    const BezierCurve& point = a_point ? a : b;
    const BezierCurve& curve = a_point ? b : a;
    const Point p = point_at(point, 0.0);
    const NearestPoint nearest = closest_point(curve, p).value();
    if (nearest.distance <= tolerance)
      hits.push_back({a_point ? 0.0 : nearest.parameter, a_point ? nearest.parameter : 0.0,
                      IntersectionKind::transversal, 1});
    return hits;
  }
  if (a.dimension() != 2) return space_piece_hits(a, b, tolerance, unsettled);
  // Implicitize the piece of lower degree (the Bézout matrix is n x n).
  const bool swap = a.degree() > b.degree();
  const BezierCurve& implicit = swap ? b : a;
  const BezierCurve& other = swap ? a : b;
  const auto emit = [&](double s_implicit, double t_other, IntersectionKind kind, int multiplicity) {
    hits.push_back(swap ? Hit{t_other, s_implicit, kind, multiplicity} : Hit{s_implicit, t_other, kind, multiplicity});
  };
  const Bounded p = substituted(implicit, other);
  double largest_magnitude = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < p.value.size(); ++i) {
    largest_magnitude = std::max(largest_magnitude, p.magnitude[i]);
    largest = std::max(largest, std::abs(p.value[i]));
  }
  const double noise = tolerances::kRoundingSlack * static_cast<double>(p.value.size()) * 4.0 * largest_magnitude;
  if (largest <= noise) {
    if (auto on_line = hits_on_one_line(a, b, tolerance)) return *on_line;
    // One algebraic curve: the end points of each piece that lie on the other.
    const std::vector<SharedPoint> pairs = ends_on_each_other(implicit, other, tolerance);
    // Crossings where the algebraic curve passes twice through a point (a
    // double point), away from the shared stretch or point.
    std::vector<Hit> crossings;
    const auto shared = [&](Interval si, Interval ti) {
      return on_shared_stretch(pairs, si, ti) || along_shared_stretch(implicit, other, pairs, si, ti);
    };
    const std::optional<Unsettled> stopped =
        subdivided_hits(implicit, {0.0, 1.0}, implicit, other, {0.0, 1.0}, other, false, tolerance, shared, crossings);
    if (stopped) unsettled = swap ? Unsettled{stopped->t, stopped->s} : *stopped;
    for (const Hit& crossing : crossings) emit(crossing.s, crossing.t, crossing.kind, crossing.multiplicity);
    if (!pairs.empty()) hits.push_back(oriented(shared_hit(pairs), swap));
    return hits;
  }
  const double scale = std::max(size_of(implicit), size_of(other));
  // A zone of p may hide crossings closer than rounding lets p tell apart
  // (two crossings 1e-6 apart, the curves 1e-9 apart between them): Newton
  // on the pair from either side of the zone finds them when they are there
  // (emitted, true); a true tangency gives it nothing that converges.
  const double converged = kIntersectionConverged * std::max(scale, tolerances::kScaleFloor);
  const auto split_zone = [&](double s, double t, int multiplicity) {
    if (multiplicity != 2) return false;
    std::vector<std::pair<double, double>> crossings;
    for (const double offset : {-1e-5, -1e-6, -1e-7, 1e-7, 1e-6, 1e-5}) {
      double tc = std::clamp(t + offset, 0.0, 1.0);
      double sc = closest_point(implicit, point_at(other, tc)).value().parameter;
      refine(implicit, other, sc, tc);
      if (distance(point_at(implicit, sc), point_at(other, tc)) > converged) continue;
      if (std::abs(tc - t) > 1e-4 || std::abs(sc - s) > 1e-4) continue;  // another intersection's
      const bool seen = std::any_of(crossings.begin(), crossings.end(), [&](const std::pair<double, double>& c) {
        // Newton lands within about 1e-11 of a crossing this close to a tangency.
        return std::abs(c.first - sc) <= kIntersectionJointSlack && std::abs(c.second - tc) <= kIntersectionJointSlack;
      });
      if (!seen) crossings.emplace_back(sc, tc);
    }
    if (crossings.size() != 2) return false;
    // Two crossings part the curves between them; near a true tangency
    // Newton also comes within rounding on both sides, where the curves
    // never part: between such points they stay within rounding.
    const double middle_s = 0.5 * (crossings[0].first + crossings[1].first);
    if (!(closest_point(other, point_at(implicit, middle_s)).value().distance > 16 * converged)) return false;
    for (const auto& [sc, tc] : crossings) emit(sc, tc, IntersectionKind::transversal, 1);
    return true;
  };
  for (const BernsteinRoot& root : bernstein_roots(p.value)) {
    const Point on_other = point_at(other, root.t);
    const std::vector<NearestPoint> feet = local_closest_points(implicit, on_other).value();
    // A simple root of a high-degree p may be off by more than the tolerance
    // allows (its rounding grows with the degree): its feet within a looser
    // bound are refined by Newton on the pair first, then held to the tolerance.
    // A multiple root is known to about the square root of the rounding: its
    // point may miss the piece by more than the tolerance where the contact
    // is at the piece's end (the zone's middle slid past it). Such a foot is
    // brought to the nearest pair of points by alternate projections.
    const double loose = std::max(tolerance, kIntersectionLooseRoot * scale);
    std::vector<double> branches;
    for (const NearestPoint& foot : feet) {
      if (foot.distance <= tolerance) {
        branches.push_back(foot.parameter);
      } else if (foot.distance <= loose && root.multiplicity == 1) {
        double s = foot.parameter, t = root.t;
        refine(implicit, other, s, t);
        if (distance(point_at(implicit, s), point_at(other, t)) <= tolerance) emit(s, t, IntersectionKind::transversal, 1);
      } else if (foot.distance <= loose) {
        double s = foot.parameter, t = root.t;
        if (split_zone(s, t, root.multiplicity)) continue;
        for (int step = 0; step < 4; ++step) {
          t = closest_point(other, point_at(implicit, s)).value().parameter;
          s = closest_point(implicit, point_at(other, t)).value().parameter;
        }
        if (distance(point_at(implicit, s), point_at(other, t)) <= tolerance)
          emit(s, t, IntersectionKind::tangent, zone_multiplicity(p.value, root.t, noise, root.multiplicity));
      }
    }
    std::sort(branches.begin(), branches.end());
    int multiplicity = root.multiplicity;
    if (multiplicity >= 2 && branches.size() == 1) multiplicity = zone_multiplicity(p.value, root.t, noise, multiplicity);
    for (const double s0 : branches) {
      double s = s0, t = root.t;
      if (multiplicity == 1 || branches.size() > 1) {
        // A simple root, or one branch of the implicit curve's double point:
        // transversal where the tangents differ.
        const double sine = tangent_sine(derivative_at(implicit, s, 1), derivative_at(other, t, 1));
        if (multiplicity == 1 || sine > kIntersectionTangentSine) {
          refine(implicit, other, s, t);
          emit(s, t, IntersectionKind::transversal, 1);
          continue;
        }
        emit(s, t, IntersectionKind::tangent, std::max(2, multiplicity - static_cast<int>(branches.size()) + 1));
        continue;
      }
      if (split_zone(s, t, multiplicity)) continue;
      emit(s, t, IntersectionKind::tangent, multiplicity);
    }
  }
  return hits;
}

/// The refusal of a search that stopped short: where, in the curves'
/// parameters (the middle of the unsettled pair's spans on the pieces
/// spanning span_a and span_b), `which` naming the curves.
Error unsettled_search(const Unsettled& where, Interval span_a, Interval span_b, const std::string& which) {
  const auto curve_parameter = [](Interval piece, Interval local) {
    return piece.lower + 0.5 * (local.lower + local.upper) * (piece.upper - piece.lower);
  };
  return Error{"the intersection search gave up near parameters " +
                   detail::number_text(curve_parameter(span_a, where.s)) + " and " +
                   detail::number_text(curve_parameter(span_b, where.t)) + " " + which +
                   ", where they come within the tolerance of one another in more pairs of sub-curves than it visits (" +
                   std::to_string(tolerances::kIntersectionPairBudget) +
                   ", as many again outside contact zones): they run along one another about the tolerance apart, "
                   "neither crossing nor one overlap; try a smaller or a larger tolerance",
               ErrorKind::limit};
}

}  // namespace

const char* kind_name(IntersectionKind kind) {
  switch (kind) {
    case IntersectionKind::transversal: return "transversal";
    case IntersectionKind::tangent: return "tangent";
    case IntersectionKind::overlap: return "overlap";
  }
  return "transversal";
}

Tolerance default_intersection_tolerance(CurveView a, CurveView b) {
  const double size = std::max(size_of(a), size_of(b));
  return Tolerance{size > 0.0 ? tolerances::kDefaultIntersectionRelativeTolerance * size : 1e-300};
}

Expected<std::vector<CurveIntersection>> intersections(CurveView a, CurveView b, Tolerance tolerance) {
  for (const auto& [curve, which] : {std::pair{a, "first"}, std::pair{b, "second"}})
    if (curve.dimension() < 2)
      return Error{std::string("intersections need curves in R^2 or more, the ") + which + " lives in R^" +
                   std::to_string(curve.dimension())};
  if (a.dimension() != b.dimension())
    return Error{"intersections need curves in one space, the first lives in R^" + std::to_string(a.dimension()) +
                 ", the second in R^" + std::to_string(b.dimension())};
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the intersection tolerance is " + std::to_string(tolerance.distance) + ", it must be finite and > 0"};
  const BezierPieces pa = to_bezier_pieces(a), pb = to_bezier_pieces(b);
  std::vector<CurveIntersection> points, overlaps;
  for (std::size_t i = 0; i < pa.pieces.size(); ++i) {
    const Interval span_a{pa.breakpoints[i], pa.breakpoints[i + 1]};
    for (std::size_t k = 0; k < pb.pieces.size(); ++k) {
      if (!boxes_meet(pa.pieces[i], pb.pieces[k], tolerance.distance)) continue;
      const Interval span_b{pb.breakpoints[k], pb.breakpoints[k + 1]};
      std::optional<Unsettled> unsettled;
      const std::vector<Hit> hits = piece_hits(pa.pieces[i], pb.pieces[k], tolerance.distance, unsettled);
      if (unsettled) return unsettled_search(*unsettled, span_a, span_b, "of the first curve and the second");
      for (const Hit& hit : hits) record(hit, pa.pieces[i], span_a, span_b, points, overlaps);
    }
  }
  // On a closed curve the two ends of the domain are one point: a hit there
  // is reported once, at the start.
  for (const auto& [curve, pieces, on_a] : {std::tuple{a, &pa, true}, std::tuple{b, &pb, false}}) {
    const Interval domain = curve.domain();
    if (distance(point_at(pieces->pieces.front(), 0.0), point_at(pieces->pieces.back(), 1.0)) > tolerance.distance) continue;
    for (CurveIntersection& p : points) {
      Interval& u = on_a ? p.a : p.b;
      if (u.lower == domain.upper) u = {domain.lower, domain.lower};
    }
  }
  return merged(std::move(points), std::move(overlaps), a.domain().length(), b.domain().length());
}

/// The direction in which a piece leaves its start (`at_end` false) or
/// arrives at its end: along the first leg of its control polygon that is
/// not a point (for positive weights, the tangent's direction there; Farin §5.3).
Point end_direction(const BezierCurve& piece, bool at_end) {
  const PointArray& points = piece.control_points();
  const std::size_t n = points.size() - 1;
  const std::size_t end = at_end ? n : 0;
  Point direction(piece.dimension(), 0.0);
  for (std::size_t step = 1; step <= n; ++step) {
    const std::size_t other = at_end ? n - step : step;
    for (int j = 0; j < piece.dimension(); ++j)
      direction[j] = at_end ? points[end][j] - points[other][j] : points[other][j] - points[end][j];
    if (dot(direction, direction) > 0.0) break;
  }
  return direction;
}

/// Whether a point hit (s on `arriving` near its end, t on `leaving` near its
/// start) is the joint where `arriving` ends and `leaving` starts, found off by
/// rounding: within the tolerance of the joint on both, or within
/// kIntersectionJointWindow of it in both parameters where the curve does not
/// turn back (ops/tolerance.hpp says why nothing else meets there).
bool is_joint(const BezierCurve& arriving, double s, const BezierCurve& leaving, double t, double tolerance) {
  const Point joint = point_at(leaving, 0.0);
  if (distance(point_at(arriving, s), joint) <= tolerance && distance(point_at(leaving, t), joint) <= tolerance)
    return true;
  if (1.0 - s > tolerances::kIntersectionJointWindow || t > tolerances::kIntersectionJointWindow) return false;
  const Point in = end_direction(arriving, true), out = end_direction(leaving, false);
  const double lengths = std::sqrt(dot(in, in) * dot(out, out));
  return lengths > 0.0 && dot(in, out) > tolerances::kJointReversalCosine * lengths;
}

Expected<std::vector<CurveIntersection>> self_intersections(CurveView curve, Tolerance tolerance) {
  if (curve.dimension() < 2)
    return Error{"self-intersections need a curve in R^2 or more, this one lives in R^" +
                 std::to_string(curve.dimension())};
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the intersection tolerance is " + std::to_string(tolerance.distance) + ", it must be finite and > 0"};
  // Pieces that stay within the tolerance of one point (a closing segment of
  // length zero, a repeated knot's sliver) add no point of their own: they are
  // left out, so that their neighbours meet as consecutive pieces.
  const BezierPieces all = to_bezier_pieces(curve);
  std::vector<BezierCurve> pieces;
  std::vector<Interval> spans;
  for (std::size_t i = 0; i < all.pieces.size(); ++i) {
    if (stays_at_one_point(all.pieces[i], tolerance.distance)) continue;
    pieces.push_back(all.pieces[i]);
    spans.push_back({all.breakpoints[i], all.breakpoints[i + 1]});
  }
  const std::size_t count = pieces.size();
  const double width = curve.domain().length();
  std::vector<CurveIntersection> points, overlaps;
  if (count == 0) return points;  // the curve is a point
  const bool closed = distance(point_at(pieces.front(), 0.0), point_at(pieces.back(), 1.0)) <= tolerance.distance;
  for (std::size_t i = 0; i < count; ++i) {
    const BezierCurve& piece = pieces[i];
    // Inside piece i: a line folding back on itself overlaps itself; any
    // other piece has its injective parts tried against each other.
    std::vector<Hit> inside;
    if (auto line = detail::line_passes(piece, tolerance.distance)) {
      for (const detail::PassContact& fold : detail::self_overlaps(*line, tolerance.distance))
        inside.push_back(hit_of(fold));
    } else {
      std::vector<Part> parts;
      injective_parts(piece, {0.0, 1.0}, 0, parts);
      const auto nothing = [](Interval, Interval) { return false; };
      for (std::size_t p = 0; p < parts.size(); ++p)
        for (std::size_t q = p + 1; q < parts.size(); ++q)
          if (const auto unsettled = subdivided_hits(piece, parts[p].span, parts[p].curve, piece, parts[q].span,
                                                     parts[q].curve, true, tolerance.distance, nothing, inside))
            return unsettled_search(*unsettled, spans[i], spans[i], "of the curve");
      merge_tangent_zones(piece, piece, tolerance.distance, inside);
    }
    for (const Hit& hit : inside) {
      const bool seam = closed && count == 1 && hit.kind != IntersectionKind::overlap &&
                        is_joint(piece, std::max(hit.s, hit.t), piece, std::min(hit.s, hit.t), tolerance.distance);
      if (!seam) record(hit, piece, spans[i], spans[i], points, overlaps);
    }
    // Piece i against the later pieces.
    for (std::size_t k = i + 1; k < count; ++k) {
      if (!boxes_meet(piece, pieces[k], tolerance.distance)) continue;
      std::optional<Unsettled> unsettled;
      const std::vector<Hit> hits = piece_hits(piece, pieces[k], tolerance.distance, unsettled);
      if (unsettled) return unsettled_search(*unsettled, spans[i], spans[k], "of the curve");
      for (const Hit& hit : hits) {
        if (hit.kind != IntersectionKind::overlap) {
          const bool joint = k == i + 1 && is_joint(piece, hit.s, pieces[k], hit.t, tolerance.distance);
          const bool seam =
              closed && i == 0 && k + 1 == count && is_joint(pieces[k], hit.t, piece, hit.s, tolerance.distance);
          if (joint || seam) continue;
        }
        record(hit, piece, spans[i], spans[k], points, overlaps);
      }
    }
  }
  return merged(std::move(points), std::move(overlaps), width, width);
}

}  // namespace casteljau

// Intersections of plane curves (intersection.hpp): per pair of Bézier
// pieces, the lower-degree piece implicitized (Bézout matrix), the other
// substituted, the roots of the resulting polynomial inverted and refined.
#include "casteljau/ops/intersection.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "bernstein_columns.hpp"

namespace casteljau {
namespace {

using detail::column;
using detail::derivative;

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
/// Bernstein form of degree n m, with the magnitude of its terms. Exact
/// products for n <= 3; beyond, the determinant at n m + 1 points and the
/// Bernstein-Vandermonde system (fine for the moderate degrees it meets).
Bounded substituted(const BezierCurve& implicit, const BezierCurve& other) {
  const int n = implicit.degree(), m = other.degree();
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
  const auto at = [&](int i, int j) -> const Bounded& { return entries[static_cast<std::size_t>(i * n + j)]; };
  if (n == 1) return at(0, 0);
  if (n == 2) return combination(product(at(0, 0), at(1, 1)), -1.0, product(at(0, 1), at(1, 0)));
  if (n == 3) {
    Bounded det = product(at(0, 0), combination(product(at(1, 1), at(2, 2)), -1.0, product(at(1, 2), at(2, 1))));
    det = combination(det, -1.0, product(at(0, 1), combination(product(at(1, 0), at(2, 2)), -1.0, product(at(1, 2), at(2, 0)))));
    det = combination(det, 1.0, product(at(0, 2), combination(product(at(1, 0), at(2, 1)), -1.0, product(at(1, 1), at(2, 0)))));
    return det;
  }
  const int count = n * m + 1;
  Eigen::MatrixXd vandermonde(count, count);
  Eigen::VectorXd values(count);
  double largest = 0.0;
  for (int k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) / (count - 1);
    Eigen::MatrixXd at_t(n, n), magnitude_at_t(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        at_t(i, j) = bernstein_value(at(i, j).value, t);
        magnitude_at_t(i, j) = bernstein_value(at(i, j).magnitude, t);
      }
    values(k) = at_t.fullPivLu().determinant();
    largest = std::max(largest, std::abs(magnitude_at_t.fullPivLu().determinant()));
    for (int i = 0; i < count; ++i) vandermonde(k, i) = binomial(count - 1, i) * std::pow(t, i) * std::pow(1 - t, count - 1 - i);
  }
  const Eigen::VectorXd coefficients = vandermonde.fullPivLu().solve(values);
  Bounded result{std::vector<double>(coefficients.data(), coefficients.data() + count),
                 std::vector<double>(static_cast<std::size_t>(count), largest * count)};
  return result;
}

struct Hit {
  double s, t;  // local parameters on the two pieces
  IntersectionKind kind;
  int multiplicity;
  double s_end = 0.0, t_end = 0.0;  // an overlap's other end
};

double distance(const Point& p, const Point& q) { return std::hypot(p[0] - q[0], p[1] - q[1]); }

/// Newton on A(s) - B(t) = 0 from a simple root, kept inside [0, 1]^2, each
/// step kept only when the points come nearer.
void refine(const BezierCurve& a, const BezierCurve& b, double& s, double& t) {
  double gap = distance(point_at(a, s), point_at(b, t));
  for (int iteration = 0; iteration < 8 && gap > 0.0; ++iteration) {
    const std::vector<Point> da = derivatives_up_to(a, s, 1), db = derivatives_up_to(b, t, 1);
    // [A' -B'] (ds, dt) = B - A.
    const double f0 = db[0][0] - da[0][0], f1 = db[0][1] - da[0][1];
    const double det = -da[1][0] * db[1][1] + db[1][0] * da[1][1];
    if (det == 0.0) break;
    const double ds = (-f0 * db[1][1] + db[1][0] * f1) / det;
    const double dt = (da[1][0] * f1 - da[1][1] * f0) / det;
    const double s1 = std::clamp(s + ds, 0.0, 1.0), t1 = std::clamp(t + dt, 0.0, 1.0);
    const double gap1 = distance(point_at(a, s1), point_at(b, t1));
    if (!(gap1 < gap)) break;
    s = s1, t = t1, gap = gap1;
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

/// The intersections of piece a with piece b (local parameters).
std::vector<Hit> piece_hits(const BezierCurve& a, const BezierCurve& b, double tolerance) {
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
    // One algebraic curve: the end points of each piece that lie on the other.
    struct Pair {
      double s, t;
    };
    std::vector<Pair> pairs;
    for (const double t : {0.0, 1.0}) {
      const NearestPoint on = closest_point(implicit, point_at(other, t)).value();
      if (on.distance <= tolerance) pairs.push_back({on.parameter, t});
    }
    for (const double s : {0.0, 1.0}) {
      const NearestPoint on = closest_point(other, point_at(implicit, s)).value();
      if (on.distance <= tolerance) pairs.push_back({s, on.parameter});
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.s < y.s; });
    if (pairs.empty()) return hits;
    const Pair first = pairs.front(), last = pairs.back();
    if (last.s - first.s > 1e-9) {
      Hit overlap = swap ? Hit{first.t, first.s, IntersectionKind::overlap, 0}
                         : Hit{first.s, first.t, IntersectionKind::overlap, 0};
      overlap.s_end = swap ? last.t : last.s;
      overlap.t_end = swap ? last.s : last.t;
      if (overlap.s_end < overlap.s) {
        std::swap(overlap.s, overlap.s_end);
        std::swap(overlap.t, overlap.t_end);
      }
      hits.push_back(overlap);
    } else {
      emit(first.s, first.t, IntersectionKind::tangent, 0);
    }
    return hits;
  }
  for (const BernsteinRoot& root : bernstein_roots(p.value)) {
    const Point on_other = point_at(other, root.t);
    const std::vector<NearestPoint> feet = local_closest_points(implicit, on_other).value();
    std::vector<double> branches;
    for (const NearestPoint& foot : feet)
      if (foot.distance <= tolerance) branches.push_back(foot.parameter);
    std::sort(branches.begin(), branches.end());
    int multiplicity = root.multiplicity;
    if (multiplicity >= 2 && branches.size() == 1) multiplicity = zone_multiplicity(p.value, root.t, noise, multiplicity);
    for (const double s0 : branches) {
      double s = s0, t = root.t;
      if (multiplicity == 1 || branches.size() > 1) {
        // A simple root, or one branch of the implicit curve's double point:
        // transversal where the tangents differ.
        const Point ta = derivative_at(implicit, s, 1), tb = derivative_at(other, t, 1);
        const double sine = std::abs(ta[0] * tb[1] - ta[1] * tb[0]) /
                            std::max(std::hypot(ta[0], ta[1]) * std::hypot(tb[0], tb[1]), tolerances::kScaleFloor);
        if (multiplicity == 1 || sine > 1e-6) {
          refine(implicit, other, s, t);
          emit(s, t, IntersectionKind::transversal, 1);
          continue;
        }
        emit(s, t, IntersectionKind::tangent, std::max(2, multiplicity - static_cast<int>(branches.size()) + 1));
        continue;
      }
      emit(s, t, IntersectionKind::tangent, multiplicity);
    }
  }
  return hits;
}

bool boxes_meet(const BezierCurve& a, const BezierCurve& b, double tolerance) {
  for (int j = 0; j < 2; ++j) {
    double a_low = INFINITY, a_high = -INFINITY, b_low = INFINITY, b_high = -INFINITY;
    for (std::size_t i = 0; i < a.control_points().size(); ++i)
      a_low = std::min(a_low, a.control_points()[i][j]), a_high = std::max(a_high, a.control_points()[i][j]);
    for (std::size_t i = 0; i < b.control_points().size(); ++i)
      b_low = std::min(b_low, b.control_points()[i][j]), b_high = std::max(b_high, b.control_points()[i][j]);
    if (a_low > b_high + tolerance || b_low > a_high + tolerance) return false;
  }
  return true;
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

/// Whether the hodograph's coefficients of a plane piece lie in an open half
/// plane (the largest angular gap between them exceeds pi): then C' . d > 0
/// inside for some direction d, and the piece is injective. For a rational
/// piece, the coefficients of the numerator A' w - A w' of C' w^2.
bool turns_less_than_half(const BezierCurve& piece) {
  std::vector<double> dx, dy;
  if (!piece.is_rational()) {
    dx = derivative(column(piece.control_points(), 0));
    dy = derivative(column(piece.control_points(), 1));
  } else {
    const PointArray h = homogeneous_points(piece);
    const std::vector<double> x = column(h, 0), y = column(h, 1), w = column(h, 2), w1 = derivative(w);
    const auto numerator = [&](const std::vector<double>& c) {
      std::vector<double> left = bernstein_product(derivative(c), w), right = bernstein_product(c, w1);
      for (std::size_t i = 0; i < left.size(); ++i) left[i] -= right[i];
      return left;
    };
    dx = numerator(x), dy = numerator(y);
  }
  std::vector<double> angles;
  for (std::size_t i = 0; i < dx.size(); ++i)
    if (dx[i] != 0.0 || dy[i] != 0.0) angles.push_back(std::atan2(dy[i], dx[i]));
  if (angles.empty()) return true;  // a point: nothing to cross
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * M_PI - angles.back();
  for (std::size_t i = 0; i + 1 < angles.size(); ++i) gap = std::max(gap, angles[i + 1] - angles[i]);
  return gap > M_PI;
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

/// Crossings of two parts of one piece (one algebraic curve, so not by
/// implicitization): pairs of sub-parts whose boxes meet, halved down to
/// 1e-6 of the piece, then Newton on P(s) - Q(t) = 0; kept when it
/// converges to a few ulps of the scale with the two parameters apart and
/// the loop between them reaching beyond the tolerance.
void part_crossings(const BezierCurve& piece, const Part& p, const Part& q, double scale, double tolerance,
                    std::vector<std::pair<double, double>>& found) {
  struct Pair {
    Interval s, t;
    BezierCurve a, b;
  };
  std::vector<Pair> stack{{p.span, q.span, p.curve, q.curve}};
  const double converged = 64 * 2.220446049250313e-16 * std::max(scale, tolerances::kScaleFloor);
  while (!stack.empty()) {
    Pair pair = std::move(stack.back());
    stack.pop_back();
    if (!boxes_meet(pair.a, pair.b, converged)) continue;
    const double width = std::max(pair.s.length(), pair.t.length());
    if (width > 1e-6) {
      const bool split_a = pair.s.length() >= pair.t.length();
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
    // Newton on the whole piece from the middles, parameters local to the piece.
    double s = 0.5 * (pair.s.lower + pair.s.upper), t = 0.5 * (pair.t.lower + pair.t.upper);
    refine(piece, piece, s, t);
    if (distance(point_at(piece, s), point_at(piece, t)) > converged) continue;
    if (std::abs(s - t) <= 1e-9) continue;  // the same point (the parts' joint)
    // The loop between s and t must reach beyond the tolerance: near a cusp
    // C(s) and C(t) come within rounding of each other for s != t, on a
    // "loop" far smaller than any tolerance (of the size delta^2 for
    // parameters delta from the cusp).
    if (!(distance(point_at(piece, s), point_at(piece, 0.5 * (s + t))) > tolerance)) continue;
    if (s > t) std::swap(s, t);
    const bool seen = std::any_of(found.begin(), found.end(), [&](const std::pair<double, double>& f) {
      return std::abs(f.first - s) <= 1e-12 && std::abs(f.second - t) <= 1e-12;
    });
    if (!seen) found.emplace_back(s, t);
  }
}

/// The hits of every piece pair as the result: overlaps of consecutive
/// pieces joined, each point once (a hit at a knot is seen from both
/// pieces), none inside an overlap, sorted by the parameter on a.
std::vector<CurveIntersection> merged(std::vector<CurveIntersection> points, std::vector<CurveIntersection> overlaps,
                                      double width_a, double width_b) {
  // Overlaps of consecutive pieces that continue one another become one.
  std::sort(overlaps.begin(), overlaps.end(),
            [](const CurveIntersection& x, const CurveIntersection& y) { return x.a.lower < y.a.lower; });
  std::vector<CurveIntersection> joined;
  for (const CurveIntersection& o : overlaps) {
    if (!joined.empty()) {
      CurveIntersection& last = joined.back();
      if (std::abs(o.a.lower - last.a.upper) <= 1e-9 * width_a && std::abs(o.b.lower - last.b.upper) <= 1e-9 * width_b) {
        last.a.upper = o.a.upper;
        last.b.upper = o.b.upper;
        continue;
      }
    }
    joined.push_back(o);
  }
  // Points: once each (a hit at a knot is seen from both pieces), none inside an overlap.
  const auto inside = [&](const CurveIntersection& p, const CurveIntersection& o) {
    const double slack_a = 1e-9 * width_a, slack_b = 1e-9 * width_b;
    const double b_low = std::min(o.b.lower, o.b.upper), b_high = std::max(o.b.lower, o.b.upper);
    return p.a.lower >= o.a.lower - slack_a && p.a.lower <= o.a.upper + slack_a && p.b.lower >= b_low - slack_b &&
           p.b.lower <= b_high + slack_b;
  };
  std::sort(points.begin(), points.end(),
            [](const CurveIntersection& x, const CurveIntersection& y) { return x.a.lower < y.a.lower; });
  std::vector<CurveIntersection> result;
  for (const CurveIntersection& p : points) {
    if (std::any_of(joined.begin(), joined.end(), [&](const CurveIntersection& o) { return inside(p, o); })) continue;
    const double same_a = (p.kind == IntersectionKind::transversal ? 1e-12 : 1e-7) * width_a;
    const double same_b = (p.kind == IntersectionKind::transversal ? 1e-12 : 1e-7) * width_b;
    const auto duplicate = std::find_if(result.begin(), result.end(), [&](const CurveIntersection& q) {
      return std::abs(q.a.lower - p.a.lower) <= std::max(same_a, 1e-9 * width_a * (q.kind != IntersectionKind::transversal)) &&
             std::abs(q.b.lower - p.b.lower) <= std::max(same_b, 1e-9 * width_b * (q.kind != IntersectionKind::transversal));
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
    if (curve.dimension() != 2)
      return Error{std::string("intersections need plane curves, the ") + which + " lives in R^" +
                   std::to_string(curve.dimension())};
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the intersection tolerance is " + std::to_string(tolerance.distance) + ", it must be finite and > 0"};
  const BezierPieces pa = to_bezier_pieces(a), pb = to_bezier_pieces(b);
  std::vector<CurveIntersection> points, overlaps;
  for (std::size_t i = 0; i < pa.pieces.size(); ++i) {
    const Interval span_a{pa.breakpoints[i], pa.breakpoints[i + 1]};
    for (std::size_t k = 0; k < pb.pieces.size(); ++k) {
      if (!boxes_meet(pa.pieces[i], pb.pieces[k], tolerance.distance)) continue;
      const Interval span_b{pb.breakpoints[k], pb.breakpoints[k + 1]};
      for (const Hit& hit : piece_hits(pa.pieces[i], pb.pieces[k], tolerance.distance))
        record(hit, pa.pieces[i], span_a, span_b, points, overlaps);
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

Expected<std::vector<CurveIntersection>> self_intersections(CurveView curve, Tolerance tolerance) {
  if (curve.dimension() != 2)
    return Error{"self-intersections need a plane curve, this one lives in R^" + std::to_string(curve.dimension())};
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the intersection tolerance is " + std::to_string(tolerance.distance) + ", it must be finite and > 0"};
  const BezierPieces pieces = to_bezier_pieces(curve);
  const std::size_t count = pieces.pieces.size();
  const Interval domain = curve.domain();
  const double width = domain.length();
  const bool closed = distance(point_at(pieces.pieces.front(), 0.0), point_at(pieces.pieces.back(), 1.0)) <= tolerance.distance;
  std::vector<CurveIntersection> points, overlaps;
  for (std::size_t i = 0; i < count; ++i) {
    const Interval span_i{pieces.breakpoints[i], pieces.breakpoints[i + 1]};
    // Inside piece i: its injective parts against each other.
    std::vector<Part> parts;
    injective_parts(pieces.pieces[i], {0.0, 1.0}, 0, parts);
    std::vector<std::pair<double, double>> crossings;
    for (std::size_t p = 0; p < parts.size(); ++p)
      for (std::size_t q = p + 1; q < parts.size(); ++q)
        part_crossings(pieces.pieces[i], parts[p], parts[q], size_of(pieces.pieces[i]), tolerance.distance, crossings);
    for (const auto& [s, t] : crossings)
      record(Hit{s, t, IntersectionKind::transversal, 1}, pieces.pieces[i], span_i, span_i, points, overlaps);
    // Piece i against the later pieces.
    for (std::size_t k = i + 1; k < count; ++k) {
      if (!boxes_meet(pieces.pieces[i], pieces.pieces[k], tolerance.distance)) continue;
      const Interval span_k{pieces.breakpoints[k], pieces.breakpoints[k + 1]};
      for (const Hit& hit : piece_hits(pieces.pieces[i], pieces.pieces[k], tolerance.distance)) {
        const bool joint = k == i + 1 && hit.kind != IntersectionKind::overlap && hit.s == 1.0 && hit.t == 0.0;
        const bool seam = closed && i == 0 && k + 1 == count && hit.kind != IntersectionKind::overlap &&
                          hit.s == 0.0 && hit.t == 1.0;
        if (joint || seam) continue;
        record(hit, pieces.pieces[i], span_i, span_k, points, overlaps);
      }
    }
  }
  return merged(std::move(points), std::move(overlaps), width, width);
}

}  // namespace casteljau

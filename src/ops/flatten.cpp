#include "casteljau/ops/flatten.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/core/vec.hpp"
#include "../bezier/de_casteljau.hpp"

// Method and proof of the guarantee: docs/flattening.md. In short: greedy
// furthest reach (each segment as long as a certified deviation bound allows),
// the reach found by a secant search on sqrt(deviation), which is about
// linear in the step for a smooth curve (deviation ~ kappa h^2 / 8).

namespace casteljau {
namespace {

// --- search parameters (ratios of the budget, not tolerances) ---------------
// The search aims a little below the budget so that its prediction usually
// passes, keeps a certified step once its deviation reaches kGoodEnough of the
// budget (the step is then within ~2% of the furthest reach, as deviation
// grows like h^2), and stops when the largest certified step is within
// kBracket of the smallest refused one.
constexpr double kAim = 0.985;
constexpr double kGoodEnough = 0.96;
constexpr double kBracket = 0.985;
// After this many trials the largest certified step is kept as it is.
constexpr int kMaxTrials = 6;

/// Distance from point p to the segment [a, b] (any dimension; a == b allowed).
double distance_to_segment(std::span<const double> p, std::span<const double> a, std::span<const double> b) {
  double ab2 = 0.0, apab = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    ab2 += (b[j] - a[j]) * (b[j] - a[j]);
    apab += (p[j] - a[j]) * (b[j] - a[j]);
  }
  const double u = ab2 > 0.0 ? std::clamp(apab / ab2, 0.0, 1.0) : 0.0;
  double sum = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const double e = p[j] - (a[j] + u * (b[j] - a[j]));
    sum += e * e;
  }
  return std::sqrt(sum);
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  return distance_to_segment(std::span<const double>(p.coordinates), std::span<const double>(a.coordinates),
                             std::span<const double>(b.coordinates));
}

/// s clamped to [0, 1], NaN to 0 (comparisons with NaN are false).
inline double unit_clamp(double s) { return s > 0.0 ? (s < 1.0 ? s : 1.0) : 0.0; }

/// Largest |p(s)| over s in [0, 1] of the cubic p(s) = s (c1 + s (c2 + s c3)),
/// p(0) = 0: at s = 1 or at a root of p'(s) = c1 + 2 c2 s + 3 c3 s^2. Stable
/// quadratic formula (Numerical Recipes, 3rd ed., §5.6): q = -(b + sign(b)
/// sqrt(disc)) / 2, roots q / a and c / q. Roots outside [0, 1], infinite or
/// NaN (a or q zero) are clamped to an end, where p is also a
/// candidate, so no branch is needed. A discriminant rounded below zero is
/// taken as zero: its double root is still examined.
double cubic_peak(double c1, double c2, double c3) {
  const double a = 3.0 * c3, b = 2.0 * c2;
  const double discriminant = std::max(b * b - 4.0 * a * c1, 0.0);
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  const double s1 = unit_clamp(q / a), s2 = unit_clamp(c1 / q);
  const double p1 = s1 * (c1 + s1 * (c2 + s1 * c3)), p2 = s2 * (c1 + s2 * (c2 + s2 * c3));
  return std::max(std::abs(c1 + c2 + c3), std::max(std::abs(p1), std::abs(p2)));
}

/// Lowest and highest value over [0, 1] of p(s) = s (c1 + s (c2 + s c3)),
/// same critical points as cubic_peak.
std::pair<double, double> cubic_range(double c1, double c2, double c3) {
  const double a = 3.0 * c3, b = 2.0 * c2;
  const double discriminant = std::max(b * b - 4.0 * a * c1, 0.0);
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  const double s1 = unit_clamp(q / a), s2 = unit_clamp(c1 / q);
  const double p1 = s1 * (c1 + s1 * (c2 + s1 * c3)), p2 = s2 * (c1 + s2 * (c2 + s2 * c3));
  const double p3 = c1 + c2 + c3;
  return {std::min({0.0, p1, p2, p3}), std::max({0.0, p1, p2, p3})};
}

/// A plane polynomial curve of degree <= 3 in power form, c0 + c1 t + c2 t^2
/// + c3 t^3, with its Taylor expansion at a start parameter a:
/// C(a + h s) - C(a) = q1 s + q2 s^2 + q3 s^3, q1 = h C'(a), q2 = h^2 C''(a)/2,
/// q3 = h^3 c3. The deviation of a piece is computed from the q's, with no
/// cancellation against C(a).
class PlaneCubic {
 public:
  explicit PlaneCubic(const PointArray& points) : degree_(static_cast<int>(points.size()) - 1) {
    Vec2 p[4];
    for (int i = 0; i <= degree_; ++i) {
      p[i] = points.vec<2>(static_cast<std::size_t>(i));
      rows_[2 * i] = p[i][0];
      rows_[2 * i + 1] = p[i][1];
    }
    // Bernstein to power basis (expand the Bernstein polynomials; Farin §3.6).
    switch (degree_) {
      case 1: c1_ = p[1] - p[0]; break;
      case 2: c1_ = 2.0 * (p[1] - p[0]); c2_ = p[2] - 2.0 * p[1] + p[0]; break;
      case 3:
        c1_ = 3.0 * (p[1] - p[0]);
        c2_ = 3.0 * (p[2] - 2.0 * p[1] + p[0]);
        c3_ = (p[3] - p[0]) + 3.0 * (p[1] - p[2]);
        break;
      default: break;  // degree 0: a point, every coefficient zero
    }
  }

  /// C(t) with the arithmetic of point_at: the same de Casteljau steps
  /// (detail::lerp_step on the same operands), so the same bits.
  Vec2 point(double t) const {
    if (degree_ == 3) {
      const double s = 1.0 - t;
      Vec2 out;
      for (int j = 0; j < 2; ++j) {
        const double p01 = detail::lerp_step(rows_[j], rows_[2 + j], s, t);
        const double p12 = detail::lerp_step(rows_[2 + j], rows_[4 + j], s, t);
        const double p23 = detail::lerp_step(rows_[4 + j], rows_[6 + j], s, t);
        const double p012 = detail::lerp_step(p01, p12, s, t), p123 = detail::lerp_step(p12, p23, s, t);
        out[j] = detail::lerp_step(p012, p123, s, t);
      }
      return out;
    }
    double rows[8];
    std::copy(rows_, rows_ + 8, rows);
    detail::de_casteljau_in_place(rows, degree_, 2, t);
    return {{rows[0], rows[1]}};
  }

  /// Taylor coefficients at a: C'(a) and C''(a)/2.
  void start(double a) {
    first_ = c1_ + a * (2.0 * c2_ + (3.0 * a) * c3_);
    half_second_ = c2_ + (3.0 * a) * c3_;
  }

  /// A step estimate from the parabola r(s) ~ q1 s + q2 s^2, whose distance to
  /// its chord peaks at h^2 |C' x C''/2| / (4 |C' + h C''/2|) ~ h^2 k: returns
  /// 1 / sqrt(k) (the step for a unit budget), +inf where the curve is locally straight.
  double parabola_step_scale() const {
    const double turn = std::fabs(cross(first_, half_second_));
    return std::sqrt(4.0 * std::sqrt(dot(first_, first_)) / turn);
  }

  /// Upper bound on the distance from C on [a, a+h] (a from start()) to its
  /// chord. Chords shorter than hull_below use the convex hull bound instead
  /// of the line's direction.
  double deviation(double h, double hull_below) const {
    const double h2 = h * h;
    const Vec2 q1 = h * first_, q2 = h2 * half_second_, q3 = (h2 * h) * c3_;
    const Vec2 chord = q1 + q2 + q3;
    const double length2 = dot(chord, chord), length = std::sqrt(length2);
    if (!(length >= hull_below && length >= std::numeric_limits<double>::min())) return hull(q1, q2, chord);
    // length x signed distance to the chord's line: F(s) = chord x r(s), a
    // cubic with F(0) = 0 and F(1) = 0 up to rounding.
    const double across = cubic_peak(cross(chord, q1), cross(chord, q2), cross(chord, q3));
    // length x position along the chord: G(s) = chord . r(s), G(0) = 0,
    // G(1) = length^2. Bernstein coefficients 0, G1/3, (2 G1 + G2)/3,
    // length^2 inside [0, length^2] prove that the curve never runs past the
    // chord's ends: the distance to the segment is the distance to the line.
    const double g1 = dot(chord, q1), g2 = dot(chord, q2);
    if (g1 >= 0.0 && g1 <= 3.0 * length2 && 2.0 * g1 + g2 >= 0.0 && 2.0 * g1 + g2 <= 3.0 * length2)
      return across / length;
    const auto [lowest, highest] = cubic_range(g1, g2, dot(chord, q3));
    const double overshoot = std::fmax(-lowest, highest - length2);
    return std::sqrt(across * across + overshoot * overshoot) / length;
  }

 private:
  /// r(s) lies in the convex hull of its Bernstein coefficients 0, q1/3,
  /// (2 q1 + q2)/3, chord: the largest distance from them to [0, chord].
  static double hull(const Vec2& q1, const Vec2& q2, const Vec2& chord) {
    const Vec2 origin{};
    return std::max(distance_to_segment((1.0 / 3.0) * q1, origin, chord),
                    distance_to_segment((1.0 / 3.0) * (2.0 * q1 + q2), origin, chord));
  }

  int degree_;
  double rows_[8] = {};
  Vec2 c1_{}, c2_{}, c3_{};
  Vec2 first_{}, half_second_{};
};

/// The convex hull bound for any curve: C on [t0, t1] split at its middle;
/// the largest distance from the halves' control points to [v0, v1].
double hull_deviation(const BezierCurve& curve, double t0, double t1, std::span<const double> v0,
                      std::span<const double> v1) {
  const auto [left, right] = split_at(segment(curve, t0, t1), 0.5);
  double bound = 0.0;
  for (const auto* half : {&left, &right}) {
    const auto& p = half->control_points();
    for (std::size_t i = 0; i < p.size(); ++i) bound = std::max(bound, distance_to_segment(p[i], v0, v1));
  }
  return bound;
}

/// Greedy furthest reach from a: a step h (a + h <= 1) whose deviation(b),
/// b = a + h, is <= limit, as long as the search can make it in a few trials.
/// aim = sqrt(kAim x limit), hoisted out by the caller.
/// 0 when no step can be certified (only below the rounding floor).
template <class Deviation>
double furthest_step(const Deviation& deviation, double a, double guess, double limit, double aim) {
  const double rest = 1.0 - a;
  const double infinity = std::numeric_limits<double>::infinity();
  double h = std::min(guess, rest);
  double certified = 0.0, refused = infinity, previous_h = 0.0, previous_root = 0.0;
  for (int trial = 0;; ++trial) {
    const double b = h >= rest ? 1.0 : a + h;
    if (!(b > a)) return 0.0;
    h = b - a;
    const double bound = deviation(b, h);
    if (bound <= limit) {
      certified = h;
      if (b == 1.0 || bound >= kGoodEnough * limit) return h;
    } else {
      refused = h;
    }
    if (certified >= kBracket * refused || (trial >= kMaxTrials && certified > 0.0)) return certified;
    // Next trial: sqrt(deviation) is about linear in h; secant through the
    // last two trials, or through the origin after the first.
    const double root = std::sqrt(bound);
    double next = previous_h > 0.0 && root != previous_root
                      ? h + (aim - root) * (h - previous_h) / (root - previous_root)
                      : (root > 0.0 ? h * (aim / root) : 4.0 * h);
    if (refused == infinity) {
      next = std::min(std::max(next, 1.02 * h), 4.0 * h);
    } else if (!(next > certified && next < refused)) {
      next = 0.5 * (certified + refused);
    } else if (certified > 0.0) {
      // Stay clear of the bracket's ends so that it shrinks every trial.
      const double width = refused - certified;
      next = std::clamp(next, certified + 0.02 * width, refused - 0.02 * width);
    }
    previous_h = h;
    previous_root = root;
    h = next;
  }
}

Error too_many_segments(long max_segments) {
  return Error{"flattening needs more than " + std::to_string(max_segments) +
               " segments at this tolerance (tolerance too small for the curve's size)"};
}

Error cannot_certify(double t) {
  return Error{"flattening cannot certify a segment from t = " + std::to_string(t) +
               " in double precision (tolerance too small for the curve's coordinates)"};
}

/// Vertices (t, point) pushed into a sink: either stored, or only counted.
struct PolylineSink {
  std::vector<double> coordinates;
  std::vector<double> parameters;
  void add(double t, std::span<const double> point) {
    parameters.push_back(t);
    for (double c : point) coordinates.push_back(c);
  }
  void add(double t, const Vec2& point) {
    parameters.push_back(t);
    coordinates.push_back(point[0]);
    coordinates.push_back(point[1]);
  }
};

struct CountingSink {
  long vertices = 0;
  void add(double, std::span<const double>) { ++vertices; }
  void add(double, const Vec2&) { ++vertices; }
};

/// The budget each segment is certified against: tolerance minus the rounding
/// allowance; an error for a tolerance that is not finite and > 0, or below
/// what double precision can certify.
Expected<double> segment_budget(const BezierCurve& curve, Tolerance tolerance) {
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the flattening tolerance must be a finite distance > 0, got " + std::to_string(tolerance.distance)};
  double weight_ratio = 1.0;
  if (curve.is_rational()) {
    const auto [lightest, heaviest] = std::minmax_element(curve.weights().begin(), curve.weights().end());
    weight_ratio = *heaviest / *lightest;
  }
  const double allowance = tolerances::kFlattenRoundingAllowance * scale_of(curve.control_points()) *
                           std::max(1.0, curve.degree() / 4.0) * weight_ratio;
  if (tolerance.distance < tolerances::kFlattenSmallestToleranceFactor * allowance)
    return Error{"the flattening tolerance " + std::to_string(tolerance.distance) +
                 " is below what double precision can certify for this curve (" +
                 std::to_string(tolerances::kFlattenSmallestToleranceFactor * allowance) + ")"};
  return tolerance.distance - allowance;
}

template <class Sink>
Status flatten_plane_cubic(const BezierCurve& curve, double limit, long max_segments, Sink& sink) {
  const auto& p = curve.control_points();
  PlaneCubic cubic(p);
  const double aim = std::sqrt(kAim * limit);
  sink.add(0.0, p[0]);
  double a = 0.0, guess = 1.0, previous_scale = 0.0;
  long segments = 0;
  while (a < 1.0) {
    cubic.start(a);
    // Scale the last step by the change of the parabola estimate (the step
    // ~ 1/sqrt(curvature x speed^2)); the search corrects what it misses.
    const double scale = cubic.parabola_step_scale();
    if (previous_scale > 0.0 && std::isfinite(previous_scale) && std::isfinite(scale))
      guess *= std::clamp(scale / previous_scale, 0.5, 2.0);
    previous_scale = scale;
    const double h =
        furthest_step([&](double, double step) { return cubic.deviation(step, limit); }, a, guess, limit, aim);
    if (h <= 0.0) return cannot_certify(a);
    if (++segments > max_segments) return too_many_segments(max_segments);
    const double b = h >= 1.0 - a ? 1.0 : a + h;
    if (b == 1.0) {
      sink.add(1.0, p[p.size() - 1]);
    } else {
      sink.add(b, cubic.point(b));
    }
    a = b;
    guess = h;
  }
  return {};
}

template <class Sink>
Status flatten_general(const BezierCurve& curve, double limit, long max_segments, Sink& sink) {
  const auto& p = curve.control_points();
  sink.add(0.0, p[0]);
  Point start(p[0].begin(), p[0].end());
  const double aim = std::sqrt(kAim * limit);
  double a = 0.0, guess = 1.0;
  long segments = 0;
  while (a < 1.0) {
    auto deviation = [&](double b, double) {
      const Point end = b == 1.0 ? Point(p[p.size() - 1].begin(), p[p.size() - 1].end()) : point_at(curve, b);
      return hull_deviation(curve, a, b, start, end);
    };
    const double h = furthest_step(deviation, a, guess, limit, aim);
    if (h <= 0.0) return cannot_certify(a);
    if (++segments > max_segments) return too_many_segments(max_segments);
    const double b = h >= 1.0 - a ? 1.0 : a + h;
    start = b == 1.0 ? Point(p[p.size() - 1].begin(), p[p.size() - 1].end()) : point_at(curve, b);
    sink.add(b, start);
    a = b;
    guess = h;
  }
  return {};
}

bool is_plane_cubic(const BezierCurve& curve) {
  return !curve.is_rational() && curve.dimension() == 2 && curve.degree() <= 3;
}

template <class Sink>
Status flatten_into(const BezierCurve& curve, Tolerance tolerance, long max_segments, Sink& sink) {
  auto limit = segment_budget(curve, tolerance);
  if (!limit) return limit.error();
  return is_plane_cubic(curve) ? flatten_plane_cubic(curve, *limit, max_segments, sink)
                               : flatten_general(curve, *limit, max_segments, sink);
}

}  // namespace

double control_polygon_flatness(const BezierCurve& curve) {
  const auto& p = curve.control_points();
  const auto a = p[0], b = p[p.size() - 1];
  double flatness = 0.0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) flatness = std::max(flatness, distance_to_segment(p[i], a, b));
  return flatness;
}

double chord_deviation_bound(const BezierCurve& curve, double t0, double t1) {
  if (is_plane_cubic(curve)) {
    PlaneCubic cubic(curve.control_points());
    cubic.start(t0);
    return cubic.deviation(t1 - t0, 0.0);
  }
  return hull_deviation(curve, t0, t1, point_at(curve, t0), point_at(curve, t1));
}

Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance) {
  return flatten(curve, tolerance, tolerances::kMaxFlattenSegments);
}

Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance, long max_segments) {
  PolylineSink sink;
  sink.coordinates.reserve(static_cast<std::size_t>(128 * curve.dimension()));
  sink.parameters.reserve(128);
  if (auto ok = flatten_into(curve, tolerance, max_segments, sink); !ok) return ok.error();
  return Polyline{PointArray::from_trusted(curve.dimension(), std::move(sink.coordinates)),
                  std::move(sink.parameters)};
}

Expected<long> flatten_segment_count(const BezierCurve& curve, Tolerance tolerance) {
  CountingSink sink;
  if (auto ok = flatten_into(curve, tolerance, tolerances::kMaxFlattenSegments, sink); !ok) return ok.error();
  return sink.vertices - 1;
}

}  // namespace casteljau

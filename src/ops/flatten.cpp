#include "casteljau/ops/flatten.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/vec.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "../bezier/de_casteljau.hpp"
#include "certified_budget.hpp"
#include "segment_distance.hpp"

#if defined(__AVX__) || defined(__AVX512F__)
#include <immintrin.h>
#endif

// Method and proof of the guarantee: docs/flattening.md. In short: every
// segment is certified by an upper bound on its chord deviation. Plane
// polynomial cubics (the fast path): breakpoints proposed all at once so that
// the deviations come out equal (about the greedy optimum's count), certified
// in SIMD batches, greedy steps only where a proposal fails or falls short.
// Every other curve: greedy furthest reach, each reach found by a secant
// search on sqrt(deviation), about linear in the step for a smooth curve
// (deviation ~ kappa h^2 / 8).

namespace casteljau {
namespace {

using detail::distance_to_segment;
using ops_detail::certified_budget;

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

// --- the plane cubics' fast path (plane_cubic_parameters) -------------------
// Grid cells on which the parabola estimate's density is integrated for the
// first proposal.
constexpr int kDensityCells = 32;
// Measure per piece the redistribution aims at (a piece of measure 1 deviates
// by the budget): the margin absorbs the error of the interpolated measure.
constexpr double kEquidistributionAim = 0.99;
// A certified piece whose ratio (bound / limit)^2 is at least kNearlyFull x
// (planned measure)^4 is kept by the sweep: its step is then within about
// 1 - kNearlyFull^(1/4) ~ 3% of the step planned for it.
constexpr double kNearlyFull = 0.88;
// Sweep events (a piece replaced by a greedy step and the rest redistributed)
// before greedy furthest reach finishes the curve.
constexpr int kMaxEvents = 8;
// Proposals of at most this many pieces go to greedy furthest reach instead.
constexpr double kGreedyBelow = 8.0;

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

// ---- the fast path for plane cubics: equidistributed proposals, certified in batches ----

/// One lane of SIMD arithmetic (double), or kLanes of them (Pack, a GCC/clang
/// vector extension as in src/bezier/points_at.cpp): the kernels below are
/// written once for both. Targets without AVX (em++ included) use the scalar
/// lane only.
#if defined(__AVX512F__)
constexpr int kLanes = 8;
#elif defined(__AVX__)
constexpr int kLanes = 4;
#endif

inline double splat(double x, double) { return x; }
inline double root(double x) { return std::sqrt(x); }
inline double absolute(double x) { return std::fabs(x); }
inline double larger(double x, double y) { return x > y ? x : y; }
inline double smaller(double x, double y) { return x < y ? x : y; }
inline double with_sign_of(double x, double s) { return std::copysign(x, s); }
inline double quarter_root(double x) { return std::sqrt(std::sqrt(x)); }
inline double unit_clamp_lane(double s) { return unit_clamp(s); }
inline bool every(bool lane) { return lane; }

#if defined(__AVX__) || defined(__AVX512F__)
typedef double Pack __attribute__((vector_size(kLanes * sizeof(double))));
inline Pack splat(double x, Pack) {
  Pack v;
  for (int l = 0; l < kLanes; ++l) v[l] = x;
  return v;
}
#if defined(__AVX512F__)
// The masked form (all lanes on): g++ 12's plain _mm512_sqrt_pd starts from an
// undefined vector and trips -Wmaybe-uninitialized.
inline Pack root(Pack x) { return _mm512_mask_sqrt_pd(x, 0xFF, x); }
#else
inline Pack root(Pack x) { return _mm256_sqrt_pd(x); }
#endif
inline Pack absolute(Pack x) { return x < 0.0 ? -x : x; }
inline Pack larger(Pack x, Pack y) { return x > y ? x : y; }
inline Pack smaller(Pack x, Pack y) { return x < y ? x : y; }
// Differs from copysign only for s = -0, where either sign gives the same
// pair of quadratic roots.
inline Pack with_sign_of(Pack x, Pack s) { return s < 0.0 ? -x : x; }
// NaN compares false: clamped to 0, as unit_clamp.
inline Pack unit_clamp_lane(Pack s) { return s > 0.0 ? (s < 1.0 ? s : splat(1.0, s)) : splat(0.0, s); }
/// x^(1/4) in every lane, to about 2e-9 relative (measures and densities
/// steer proposals, never certify): z ~ x^(-1/4) from the exponent bits
/// (the bits of x, read as an integer, are about 2^52 (log2 x + 1023)), three
/// Newton steps z <- z (5 - x z^4) / 4, then x z^3. Four multiplies a step
/// instead of two square roots, the slowest vector instructions. 0 below
/// 1e-280, x itself above 1e280, inf and NaN (where z^4 would leave the range).
inline Pack quarter_root(Pack x) {
  typedef long long Bits __attribute__((vector_size(kLanes * sizeof(long long))));
  Bits bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = 0x4feb0a3d70a3d70bLL - (bits >> 2);  // the offset centres the first guess's error (~10%)
  Pack z;
  std::memcpy(&z, &bits, sizeof z);
  for (int step = 0; step < 3; ++step) {
    const Pack z2 = z * z;
    z = z * (1.25 - (0.25 * x) * (z2 * z2));
  }
  const Pack root4 = x * (z * z * z);
  return x <= 1e280 ? (x >= 1e-280 ? root4 : splat(0.0, x)) : x;
}

/// Whether a comparison holds in every lane.
template <class Mask>
inline bool every(Mask lanes) {
  bool all = true;
  for (int l = 0; l < kLanes; ++l) all &= lanes[l] != 0;
  return all;
}
#endif

/// Critical points of p(s) = s (c1 + s (c2 + s c3)) in [0, 1] (stable
/// quadratic formula, as cubic_peak), returned as the values p(s1), p(s2).
template <class R>
inline void critical_values(R c1, R c2, R c3, R& p1, R& p2) {
  const R a = 3.0 * c3, b = 2.0 * c2;
  const R discriminant = larger(b * b - 4.0 * a * c1, splat(0.0, a));
  const R q = -0.5 * (b + with_sign_of(root(discriminant), b));
  const R s1 = unit_clamp_lane(q / a), s2 = unit_clamp_lane(c1 / q);
  p1 = s1 * (c1 + s1 * (c2 + s1 * c3));
  p2 = s2 * (c1 + s2 * (c2 + s2 * c3));
}

/// Power-form coefficients of a plane cubic, laid out for the batch kernel.
struct PowerForm {
  double c1x, c1y, c2x, c2y, c3x, c3y;
};

/// (bound / limit)^2 for the pieces [a, a + h] of lanes: the same exact bound
/// as PlaneCubic::deviation (largest |F| from the critical points; the
/// overshoot O from the exact range of G, zero when the curve stays over the
/// chord; bound = sqrt(F^2 + O^2) / |d|). Lanes whose chord is shorter than the
/// limit get -1: the caller certifies them with the hull bound instead.
template <class R>
inline R squared_ratio(const PowerForm& k, R a, R h, double limit2) {
  const R three_a = 3.0 * a;
  const R hx = k.c2x + three_a * k.c3x, hy = k.c2y + three_a * k.c3y;  // C''(a)/2
  const R fx = k.c1x + a * (k.c2x + hx), fy = k.c1y + a * (k.c2y + hy);  // C'(a)
  const R h2 = h * h, h3 = h2 * h;
  const R q1x = h * fx, q1y = h * fy, q2x = h2 * hx, q2y = h2 * hy, q3x = h3 * k.c3x, q3y = h3 * k.c3y;
  const R dx = q1x + q2x + q3x, dy = q1y + q2y + q3y;
  const R length2 = dx * dx + dy * dy;
  const R f1 = dx * q1y - dy * q1x, f2 = dx * q2y - dy * q2x, f3 = dx * q3y - dy * q3x;
  const R g1 = dx * q1x + dy * q1y, g2 = dx * q2x + dy * q2y, g3 = dx * q3x + dy * q3y;
  R p1, p2;
  critical_values(f1, f2, f3, p1, p2);
  const R across = larger(absolute(f1 + f2 + f3), larger(absolute(p1), absolute(p2)));
  // G's Bernstein coefficients 0, G1/3, (2 G1 + G2)/3, |d|^2 inside
  // [0, |d|^2] in every lane prove that no lane overshoots (as in
  // PlaneCubic::deviation): the range of G is then not needed.
  const R three_length2 = 3.0 * length2, g12 = 2.0 * g1 + g2;
  R overshoot = splat(0.0, a);
  if (!every(g1 >= 0.0 && g1 <= three_length2 && g12 >= 0.0 && g12 <= three_length2)) {
    R r1, r2;
    critical_values(g1, g2, g3, r1, r2);
    const R g_end = g1 + g2 + g3;
    const R lowest = smaller(smaller(r1, r2), g_end), highest = larger(larger(r1, r2), g_end);
    overshoot = larger(larger(-lowest, highest - length2), overshoot);
  }
  const R ratio = (across * across + overshoot * overshoot) / (length2 * limit2);
  // !(x >= y) also sends NaN to the hull bound.
  return length2 >= limit2 && length2 >= std::numeric_limits<double>::min() ? ratio : splat(-1.0, a);
}

/// The parabola estimate of the segments needed per unit of t: a piece
/// [t, t + h] deviates about h^2 k, k = |C' x C''/2| / (4 |C'|) (the distance
/// of a parabola's chord), so a piece of deviation `limit` spans
/// h = sqrt(limit / k) and the density is sqrt(k / limit) = (k^2 /
/// limit^2)^(1/4); 0 where it is undefined (C' = 0, a point).
template <class R>
inline R density_at(const PowerForm& k, R t, double inverse_limit2) {
  const R three_t = 3.0 * t;
  const R hx = k.c2x + three_t * k.c3x, hy = k.c2y + three_t * k.c3y;
  const R fx = k.c1x + t * (k.c2x + hx), fy = k.c1y + t * (k.c2y + hy);
  const R turn = fx * hy - fy * hx;
  const R k2 = (turn * turn) * inverse_limit2 / (16.0 * (fx * fx + fy * fy));
  const R rho = quarter_root(k2);
  return rho <= std::numeric_limits<double>::max() ? rho : splat(0.0, t);  // NaN and inf to 0
}

/// density_at for count parameters, kLanes at a time.
void densities(const PowerForm& form, const double* t, int count, double inverse_limit2, double* out) {
  int i = 0;
#if defined(__AVX__) || defined(__AVX512F__)
  for (; i + kLanes <= count; i += kLanes) {
    Pack x;
    std::memcpy(&x, t + i, sizeof x);
    const Pack rho = density_at(form, x, inverse_limit2);
    std::memcpy(out + i, &rho, sizeof rho);
  }
#endif
  for (; i < count; ++i) out[i] = density_at(form, t[i], inverse_limit2);
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

  /// The power-form coefficients c1, c2, c3.
  PowerForm power_form() const { return {c1_[0], c1_[1], c2_[0], c2_[1], c3_[0], c3_[1]}; }

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
  Vec2 c1_{}, c2_{}, c3_{};
  Vec2 first_{}, half_second_{};
};

/// Degree up to which the hull bound splits the piece at its middle and takes
/// the halves' control points: for a short piece of degree n the control
/// points stray from the chord about n / (n - 1) times as far as the curve
/// (the quadratic term), 1.5 x for a cubic but 1.07 x at n = 16, so beyond
/// that the halving (a third de Casteljau triangle per trial) buys nothing.
constexpr int kHalvedHullDegree = 16;

/// The convex hull bound for any curve, given the piece C|[t0, t1] as its own
/// Bézier curve: the largest distance from its control points (or, up to
/// degree kHalvedHullDegree, those of its two halves) to [v0, v1].
double hull_deviation(const BezierCurve& piece, std::span<const double> v0, std::span<const double> v1) {
  double bound = 0.0;
  auto hull = [&](const BezierCurve& part) {
    const auto& p = part.control_points();
    for (std::size_t i = 0; i < p.size(); ++i) bound = std::max(bound, distance_to_segment(p[i], v0, v1));
  };
  if (piece.degree() > kHalvedHullDegree) {
    hull(piece);
  } else {
    const auto [left, right] = split_at(piece, 0.5).value();
    hull(left);
    hull(right);
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
               " segments at this tolerance (tolerance too small for the curve's size)", ErrorKind::limit};
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

/// Greedy furthest reach on a plane cubic (the fallback of the fast path):
/// appends t_1 .. t_m = 1 to `parameters` (t_0 = 0 already there).
Status greedy_plane_cubic(const PlaneCubic& curve_form, double limit, long max_segments,
                          std::vector<double>& parameters) {
  PlaneCubic cubic = curve_form;
  const double aim = std::sqrt(kAim * limit);
  double a = parameters.back(), guess = 1.0 - a, previous_scale = 0.0;
  long segments = static_cast<long>(parameters.size()) - 1;
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
    parameters.push_back(b);
    a = b;
    guess = h;
  }
  return {};
}

/// ratio[i] = (bound of [t[i], t[i+1]] / limit)^2 for i < count, kLanes
/// pieces per kernel call; chords shorter than the limit by the hull bound.
void certify_pieces(const PlaneCubic& cubic, const PowerForm& form, const double* t, long count, double limit,
                    double* ratio) {
  const double limit2 = limit * limit;
  long i = 0;
#if defined(__AVX__) || defined(__AVX512F__)
  for (; i + kLanes <= count; i += kLanes) {
    Pack a, b;
    std::memcpy(&a, t + i, sizeof a);
    std::memcpy(&b, t + i + 1, sizeof b);
    const Pack r = squared_ratio(form, a, b - a, limit2);
    std::memcpy(ratio + i, &r, sizeof r);
  }
#endif
  for (; i < count; ++i) ratio[i] = squared_ratio(form, t[i], t[i + 1] - t[i], limit2);
  for (i = 0; i < count; ++i) {
    if (ratio[i] >= 0.0) continue;
    PlaneCubic piece = cubic;
    piece.start(t[i]);
    const double bound = piece.deviation(t[i + 1] - t[i], limit) / limit;
    ratio[i] = bound * bound;
  }
}

/// measure[i] = ratio[i]^(1/4) (quarter_root): the piece's length in units of a segment
/// whose deviation is the limit (deviation ~ h^2 locally). Returns the sum.
double piece_measures(const double* ratio, long count, double* measure) {
  long i = 0;
  double total = 0.0;
#if defined(__AVX__) || defined(__AVX512F__)
  // Lane-wise partial sums: one serial chain of additions would cost more
  // than the roots.
  Pack sum = splat(0.0, Pack{});
  for (; i + kLanes <= count; i += kLanes) {
    Pack r;
    std::memcpy(&r, ratio + i, sizeof r);
    r = quarter_root(r);
    std::memcpy(measure + i, &r, sizeof r);
    sum += r;
  }
  for (int l = 0; l < kLanes; ++l) total += sum[l];
#endif
  for (; i < count; ++i) {
    measure[i] = quarter_root(ratio[i]);
    total += measure[i];
  }
  return total;
}

/// Breakpoints out[0..count], from t[0] to t[n], splitting the cumulative
/// measure (piecewise linear through the t[i], the piece [t[i], t[i+1]]
/// holding measure[i], i < n, `total` in all) into `count` equal parts.
/// False when rounding would make them not strictly increasing.
bool equidistribute(const double* t, const double* measure, long n, double total, long count, double* out) {
  out[0] = t[0];
  const double step = total / static_cast<double>(count);
  long k = 1;
  double below = 0.0;  // measure of [t[0], t[i]]
  for (long i = 0; i < n && k < count; ++i) {
    const double above = below + measure[i];
    // Targets k step inside this piece; one division per piece.
    const double slope = (t[i + 1] - t[i]) / measure[i];
    for (double target = static_cast<double>(k) * step; target < above && k < count;
         target = static_cast<double>(++k) * step)
      out[k] = t[i] + (target - below) * slope;
    below = above;
  }
  for (; k < count; ++k) out[k] = t[n];  // a total rounded above the sum: caught below
  out[count] = t[n];
  for (k = 1; k <= count; ++k)
    if (!(out[k] > out[k - 1])) return false;
  return true;
}

/// How many pieces of a proposal, from its start, the sweep keeps: certified
/// (ratio <= 1) and near the measure planned for them, ratio >= kNearlyFull x
/// planned^4 (about 3% of the step at most); the last piece only certified.
long accepted_prefix(const double* ratio, long count, double planned) {
  const double planned2 = planned * planned, nearly_full = kNearlyFull * planned2 * planned2;
  long k = 0;
  while (k < count && ratio[k] <= 1.0 && ratio[k] >= nearly_full) ++k;
  if (k + 1 == count && ratio[k] <= 1.0) ++k;
  return k;
}

/// Working memory of the fast path: two proposals (breakpoints), the ratios
/// and the measures of the current one's pieces. On the stack up to
/// kStackPieces pieces, one allocation above.
class Scratch {
 public:
  explicit Scratch(long pieces) : capacity_(pieces) {
    double* base = local_;
    if (pieces > kStackPieces) {
      heap_.resize(4 * static_cast<std::size_t>(pieces + 1));
      base = heap_.data();
    }
    const std::size_t stride = static_cast<std::size_t>(pieces) + 1;
    t_ = base, next_ = base + stride, ratio = base + 2 * stride, measure = base + 3 * stride;
  }
  Scratch(const Scratch&) = delete;  // the pointers may point into local_
  Scratch& operator=(const Scratch&) = delete;
  long capacity() const { return capacity_; }
  double* t() { return t_; }
  double* next() { return next_; }
  void swap() { std::swap(t_, next_); }
  double* ratio;
  double* measure;

 private:
  static constexpr long kStackPieces = 255;
  long capacity_;
  double* t_;
  double* next_;
  double local_[4 * (kStackPieces + 1)];
  std::vector<double> heap_;
};

/// The parameters t_0 = 0 < ... < t_m = 1 of a plane cubic's flattening.
/// Greedy furthest reach is serial: each segment waits for the previous
/// one's end. Here the breakpoints are proposed all at once and certified in
/// batches instead (docs/flattening.md):
///  1. the parabola estimate's density sqrt(k / limit), integrated on a grid,
///     gives a first proposal; every piece is certified by the exact bound;
///     its measure (bound / limit)^(1/2), about linear in the step and so
///     about additive, tells the count the curve needs; when that differs
///     from the proposal's, the breakpoints are redistributed to equal
///     measure with that count (which equalises the deviations) and certified;
///  2. a sweep keeps the pieces in order while they are certified and near
///     the measure planned for them (ratio >= kNearlyFull x planned^4); at the
///     first that is not (an inflection or a cusp, where the measure is not
///     additive), one greedy furthest-reach step replaces it and the rest of
///     the curve is redistributed by this pass's measures and certified;
///  3. after kMaxEvents such events, greedy furthest reach finishes the curve.
/// Only certified pieces are ever returned.
Status plane_cubic_parameters(const PlaneCubic& cubic, double limit, long max_segments,
                              std::vector<double>& parameters) {
  const PowerForm form = cubic.power_form();
  // The proposal from the parabola estimate (trapezoid rule on the grid).
  double grid[kDensityCells + 1], density[kDensityCells + 1], grid_measure[kDensityCells];
  for (int j = 0; j <= kDensityCells; ++j) grid[j] = static_cast<double>(j) / kDensityCells;
  densities(form, grid, kDensityCells + 1, 1.0 / (limit * limit), density);
  double total = 0.0;
  for (int j = 0; j < kDensityCells; ++j) {
    grid_measure[j] = (0.5 / kDensityCells) * (density[j] + density[j + 1]);
    total += grid_measure[j];
  }
  const auto pieces_for = [](double measure) { return std::max(1.0, std::ceil(measure / kEquidistributionAim)); };
  parameters.assign(1, 0.0);
  // A few segments: greedy is as fast, and the measure is the least additive
  // there (its ceil loses the most). Far beyond the cap (or not finite):
  // greedy reports the cap exactly, without the working memory for that many.
  const double cap = static_cast<double>(max_segments);
  if (!(pieces_for(total) > kGreedyBelow && pieces_for(total) <= cap + cap / 8.0 + 64.0))
    return greedy_plane_cubic(cubic, limit, max_segments, parameters);
  long count = static_cast<long>(pieces_for(total));
  // Room for a redistribution to a quarter more pieces; one that asks for
  // more leaves the rest to greedy.
  Scratch scratch(count + count / 4 + 16);
  parameters.reserve(static_cast<std::size_t>(count) + 8);
  bool proposed = equidistribute(grid, grid_measure, kDensityCells, total, count, scratch.t());
  double planned = 1.0;
  long prefix = 0;  // pieces of the current proposal the sweep keeps
  if (proposed) {
    certify_pieces(cubic, form, scratch.t(), count, limit, scratch.ratio);
    total = piece_measures(scratch.ratio, count, scratch.measure);
    const double wanted = pieces_for(total);
    planned = total / wanted;
    prefix = accepted_prefix(scratch.ratio, count, planned);
    if (wanted != static_cast<double>(count) || prefix != count) {
      // Redistribute by the measured measures, once.
      proposed = wanted <= static_cast<double>(scratch.capacity()) &&
                 equidistribute(scratch.t(), scratch.measure, count, total, static_cast<long>(wanted), scratch.next());
      if (proposed) {
        scratch.swap();
        count = static_cast<long>(wanted);
        certify_pieces(cubic, form, scratch.t(), count, limit, scratch.ratio);
        piece_measures(scratch.ratio, count, scratch.measure);
        prefix = accepted_prefix(scratch.ratio, count, planned);
      }
    }
  }
  for (int event = 0; proposed && event < kMaxEvents; ++event) {
    double* t = scratch.t();
    const long k = prefix;
    parameters.insert(parameters.end(), t + 1, t + k + 1);
    if (k == count) break;
    if (static_cast<long>(parameters.size()) - 1 >= max_segments) return too_many_segments(max_segments);
    // One greedy step from the piece that failed or fell short, guessed from
    // its ratio (deviation ~ h^2, ratio ~ h^4).
    PlaneCubic piece = cubic;
    const double a = t[k], width = t[k + 1] - a;
    piece.start(a);
    const double guess = width * std::sqrt(std::sqrt(kAim * kAim / scratch.ratio[k]));
    const double aim = std::sqrt(kAim * limit);
    const double h = furthest_step([&](double, double step) { return piece.deviation(step, limit); }, a,
                                   std::isfinite(guess) && guess > 0.0 ? guess : width, limit, aim);
    if (h <= 0.0) return cannot_certify(a);
    const double b = h >= 1.0 - a ? 1.0 : a + h;
    parameters.push_back(b);
    if (b == 1.0) break;
    // The rest [b, 1] with this pass's measures, the piece holding b in part.
    long i = k;
    while (i + 1 < count && t[i + 1] <= b) ++i;
    scratch.measure[i] *= (t[i + 1] - b) / (t[i + 1] - t[i]);
    t[i] = b;
    double rest = 0.0;
    for (long j = i; j < count; ++j) rest += scratch.measure[j];
    const double wanted = pieces_for(rest);
    proposed = std::isfinite(rest) && wanted <= static_cast<double>(scratch.capacity()) &&
               equidistribute(t + i, scratch.measure + i, count - i, rest, static_cast<long>(wanted), scratch.next());
    if (proposed) {
      scratch.swap();
      count = static_cast<long>(wanted);
      planned = rest / wanted;
      certify_pieces(cubic, form, scratch.t(), count, limit, scratch.ratio);
      piece_measures(scratch.ratio, count, scratch.measure);
      prefix = accepted_prefix(scratch.ratio, count, planned);
    }
  }
  if (parameters.back() < 1.0) {
    // Too many events, or a proposal rounding could not order: greedy ends it.
    if (auto ok = greedy_plane_cubic(cubic, limit, max_segments, parameters); !ok) return ok;
  }
  if (static_cast<long>(parameters.size()) - 1 > max_segments) return too_many_segments(max_segments);
  return {};
}

template <class Sink>
Status flatten_general(const BezierCurve& curve, double limit, long max_segments, Sink& sink) {
  const auto& p = curve.control_points();
  sink.add(0.0, p[0]);
  const Point last(p[p.size() - 1].begin(), p[p.size() - 1].end());
  Point start(p[0].begin(), p[0].end());
  const double aim = std::sqrt(kAim * limit);
  double a = 0.0, guess = 1.0;
  long segments = 0;
  // The end point of the furthest certified trial, kept for the next vertex.
  double certified_b = -1.0;
  Point certified_end;
  while (a < 1.0) {
    // One trial costs two de Casteljau triangles, O(n^2 d): C split at b gives
    // C on [0, b], whose last point is point_at(C, b) bit for bit (split_at's
    // shared point), and that piece split at a / b gives C on [a, b].
    auto deviation = [&](double b, double) {
      if (b == 1.0) {
        const BezierCurve piece = a == 0.0 ? curve : split_at(curve, a).value().second;
        return hull_deviation(piece, start, last);
      }
      const BezierCurve before = split_at(curve, b).value().first;
      const auto& q = before.control_points();
      Point end(q[q.size() - 1].begin(), q[q.size() - 1].end());
      const double bound = hull_deviation(a == 0.0 ? before : split_at(before, a / b).value().second, start, end);
      if (bound <= limit && b > certified_b) certified_b = b, certified_end = std::move(end);
      return bound;
    };
    const double h = furthest_step(deviation, a, guess, limit, aim);
    if (h <= 0.0) return cannot_certify(a);
    if (++segments > max_segments) return too_many_segments(max_segments);
    const double b = h >= 1.0 - a ? 1.0 : a + h;
    start = b == 1.0 ? last : (b == certified_b ? certified_end : point_at(curve, b));
    sink.add(b, start);
    a = b;
    guess = h;
  }
  return {};
}

bool is_plane_cubic(const BezierCurve& curve) {
  return !curve.is_rational() && curve.dimension() == 2 && curve.degree() <= 3;
}

/// The budget, then the parameters of a plane cubic's flattening (fast path).
Status plane_cubic_flattening(const BezierCurve& curve, Tolerance tolerance, long max_segments,
                              std::vector<double>& parameters) {
  auto limit = certified_budget(curve, tolerance, "flattening");
  if (!limit) return limit.error();
  return plane_cubic_parameters(PlaneCubic(curve.control_points()), *limit, max_segments, parameters);
}

template <class Sink>
Status flatten_general_into(const BezierCurve& curve, Tolerance tolerance, long max_segments, Sink& sink) {
  auto limit = certified_budget(curve, tolerance, "flattening");
  if (!limit) return limit.error();
  return flatten_general(curve, *limit, max_segments, sink);
}

/// Power of two 2^k that brings the curve's coordinates near 1, or k = 0 when
/// they already are. The bounds square coordinate differences and cross
/// products (up to the fourth power of the scale), which would overflow
/// beyond about 1e77 and lose precision in subnormals below 1e-77.
int rescaling_exponent(const BezierCurve& curve) {
  const double scale = scale_of(curve.control_points());
  if (scale == 0.0 || (scale < 0x1p100 && scale > 0x1p-100)) return 0;
  int exponent = 0;
  std::frexp(scale, &exponent);
  return -exponent;
}

/// 2^k C: exact (a power-of-two factor only changes exponents), and every
/// operation on it is exactly 2^k times the same operation on C, so its
/// flattening has the same parameters and 2^k times the vertices.
BezierCurve scaled_by_power_of_two(const BezierCurve& curve, int k) {
  std::vector<double> coordinates(curve.control_points().coordinates().begin(),
                                  curve.control_points().coordinates().end());
  for (double& c : coordinates) c = std::ldexp(c, k);
  return BezierCurve::from_trusted(PointArray::from_trusted(curve.dimension(), std::move(coordinates)),
                                   {curve.weights().begin(), curve.weights().end()});
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
  return hull_deviation(extended_segment(curve, t0, t1), point_at(curve, t0), point_at(curve, t1));
}

Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance) {
  return flatten(curve, tolerance, tolerances::kMaxFlattenSegments);
}

Expected<Polyline> flatten(const BezierCurve& curve, Tolerance tolerance, long max_segments) {
  if (const int k = rescaling_exponent(curve); k != 0) {
    auto line = flatten(scaled_by_power_of_two(curve, k), Tolerance{std::ldexp(tolerance.distance, k)}, max_segments);
    if (line)
      for (double& c : line->points.coordinates()) c = std::ldexp(c, -k);
    return line;
  }
  if (is_plane_cubic(curve)) {
    std::vector<double> parameters;
    if (auto ok = plane_cubic_flattening(curve, tolerance, max_segments, parameters); !ok) return ok.error();
    // Vertices by the batch evaluator, bit for bit point_at (the same de
    // Casteljau steps); the ends are the end control points exactly.
    const std::size_t count = parameters.size();
    const auto& p = curve.control_points();
    std::vector<double> coordinates(2 * count);
    points_at(curve, std::span<const double>(parameters).subspan(1, count - 2),
              std::span<double>(coordinates).subspan(2, 2 * (count - 2)));
    std::copy(p[0].begin(), p[0].end(), coordinates.begin());
    std::copy(p[p.size() - 1].begin(), p[p.size() - 1].end(), coordinates.end() - 2);
    return Polyline{PointArray::from_trusted(2, std::move(coordinates)), std::move(parameters)};
  }
  PolylineSink sink;
  sink.coordinates.reserve(static_cast<std::size_t>(128 * curve.dimension()));
  sink.parameters.reserve(128);
  if (auto ok = flatten_general_into(curve, tolerance, max_segments, sink); !ok) return ok.error();
  return Polyline{PointArray::from_trusted(curve.dimension(), std::move(sink.coordinates)),
                  std::move(sink.parameters)};
}

Expected<long> flatten_segment_count(const BezierCurve& curve, Tolerance tolerance) {
  if (const int k = rescaling_exponent(curve); k != 0)
    return flatten_segment_count(scaled_by_power_of_two(curve, k), Tolerance{std::ldexp(tolerance.distance, k)});
  if (is_plane_cubic(curve)) {
    std::vector<double> parameters;
    if (auto ok = plane_cubic_flattening(curve, tolerance, tolerances::kMaxFlattenSegments, parameters); !ok)
      return ok.error();
    return static_cast<long>(parameters.size()) - 1;
  }
  CountingSink sink;
  if (auto ok = flatten_general_into(curve, tolerance, tolerances::kMaxFlattenSegments, sink); !ok)
    return ok.error();
  return sink.vertices - 1;
}

Expected<Polyline> flatten(CurveView curve, Tolerance tolerance) {
  const BezierPieces pieces = to_bezier_pieces(curve);
  Polyline line{PointArray::zeros(curve.dimension(), 0), {}};
  long budget = tolerances::kMaxFlattenSegments;
  for (std::size_t i = 0; i < pieces.pieces.size(); ++i) {
    if (budget < 1) return too_many_segments(tolerances::kMaxFlattenSegments);
    auto part = flatten(pieces.pieces[i], tolerance, budget);
    if (!part) return with_context(part.error(), "piece " + std::to_string(i));
    const Interval span{pieces.breakpoints[i], pieces.breakpoints[i + 1]};
    budget -= static_cast<long>(part->parameters.size()) - 1;
    for (std::size_t j = 0; j < part->parameters.size(); ++j) {
      const bool joint = j == 0 && !line.parameters.empty();
      if (joint && std::equal(part->points[0].begin(), part->points[0].end(), line.points[line.points.size() - 1].begin()))
        continue;
      line.points.push_back(part->points[j]);
      line.parameters.push_back(span.lerp(part->parameters[j]));
    }
  }
  return line;
}

}  // namespace casteljau

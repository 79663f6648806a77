// Arc length by adaptive Gauss–Kronrod quadrature on the Bézier pieces
// (arc_length.hpp says why the request is met).
#include "casteljau/ops/arc_length.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <cassert>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "../core/number_text.hpp"

namespace casteljau {
namespace {

using detail::number_text;

// The 15-point Kronrod rule on [-1, 1] and the 7-point Gauss rule on its odd
// nodes (QUADPACK's qk15, Piessens et al. 1983, table of xgk, wgk, wg).
constexpr int kNodes = 15;
constexpr double kKronrodNodes[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                     0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                     0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                     0.207784955007898467600689403773245, 0.0};
constexpr double kKronrodWeights[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                       0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                       0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                       0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss weights of the nodes kKronrodNodes[1], [3], [5] and [7] (the centre).
constexpr double kGaussWeights[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                     0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/// |dC/dt| of one Bézier piece, 15 parameters at a time. A polynomial piece
/// of degree <= 5 in up to 4 dimensions (every cubic, the common case)
/// evaluates its derivative in power form by Horner's rule: one FMA per
/// coefficient, against de Casteljau's triangle through the batch kernel;
/// on [0, 1] the power form of a degree-4 polynomial loses at most a few ulps
/// of its Bernstein coefficients' size (the conversion multiplies them by
/// binomials <= 6), far below any tolerance arc_length accepts, and made W9
/// twice as fast. Other pieces evaluate the derivative curve through the
/// batch kernel; a rational one its homogeneous curve A and A' too, then
/// C' = (A' w - A w') / w^2.
class PieceSpeed {
 public:
  explicit PieceSpeed(const BezierCurve& piece) : dimension_(piece.dimension()), rational_(piece.is_rational()) {
    if (!rational_ && piece.degree() <= kPowerDegree + 1 && dimension_ <= kPowerDimension) {
      const BezierCurve derivative = derivative_curve(piece).value();
      const PointArray& h = derivative.control_points();
      const int m = derivative.degree();
      for (int j = 0; j < dimension_; ++j)
        for (int k = 0; k <= m; ++k) {
          // c_k = C(m, k) sum_{i <= k} (-1)^(k - i) C(k, i) h_i
          double sum = 0.0;
          for (int i = 0; i <= k; ++i) sum += ((k - i) % 2 ? -1.0 : 1.0) * binomial(k, i) * h[i][j];
          power_[j * (kPowerDegree + 1) + k] = binomial(m, k) * sum;
        }
      power_degree_ = m;
      return;
    }
    if (rational_) homogeneous_.emplace(BezierCurve::from_trusted(homogeneous_points(piece)));
    derivative_.emplace(derivative_curve(rational_ ? *homogeneous_ : piece).value());
    scratch_.resize(static_cast<std::size_t>(2 * kNodes) * (dimension_ + 1));
  }

  void at(std::span<const double> ts, double* speeds) const {
    const int d = dimension_;
    if (power_degree_ >= 0) {
      // Coordinates outside, parameters inside: the inner loops run over up
      // to 15 independent parameters, which the compiler vectorizes.
      assert(ts.size() <= static_cast<std::size_t>(kNodes));
      const std::size_t count = ts.size();
      double squares[kNodes] = {};
      for (int j = 0; j < d; ++j) {
        const double* c = power_.data() + j * (kPowerDegree + 1);
        double value[kNodes];
        for (std::size_t i = 0; i < count; ++i) value[i] = c[power_degree_];
        for (int k = power_degree_ - 1; k >= 0; --k)
          for (std::size_t i = 0; i < count; ++i) value[i] = value[i] * ts[i] + c[k];
        for (std::size_t i = 0; i < count; ++i) squares[i] += value[i] * value[i];
      }
      for (std::size_t i = 0; i < count; ++i) speeds[i] = std::sqrt(squares[i]);
      for (std::size_t i = 0; i < count; ++i)
        if (!(squares[i] > 1e-280 && squares[i] < 1e280)) speeds[i] = scaled_speed(ts[i]);
      return;
    }
    const int width = rational_ ? d + 1 : d;
    const std::span<double> slope(scratch_.data(), ts.size() * width);
    points_at(*derivative_, ts, slope);
    if (!rational_) {
      for (std::size_t i = 0; i < ts.size(); ++i) speeds[i] = norm(slope.subspan(i * d, d));
      return;
    }
    const std::span<double> point(scratch_.data() + kNodes * width, ts.size() * width);
    points_at(*homogeneous_, ts, point);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      double* a1 = slope.data() + i * width;
      const double* a0 = point.data() + i * width;
      const double w = a0[d], w1 = a1[d];
      for (int j = 0; j < d; ++j) a1[j] = (a1[j] * w - a0[j] * w1) / (w * w);
      speeds[i] = norm(std::span<const double>(a1, d));
    }
  }

  /// |dC/dt| at one parameter.
  double at(double t) const {
    double speed = 0.0;
    at(std::span<const double>(&t, 1), &speed);
    return speed;
  }

 private:
  /// The power-form speed at t by the overflow- and underflow-safe norm
  /// (squares outside [1e-280, 1e280]: a speed that is 0 or nearly so).
  double scaled_speed(double t) const {
    double slope[kPowerDimension];
    for (int j = 0; j < dimension_; ++j) {
      const double* c = power_.data() + j * (kPowerDegree + 1);
      double value = c[power_degree_];
      for (int k = power_degree_ - 1; k >= 0; --k) value = value * t + c[k];
      slope[j] = value;
    }
    return norm(std::span<const double>(slope, static_cast<std::size_t>(dimension_)));
  }

  static constexpr int kPowerDegree = 4;     // of the derivative
  static constexpr int kPowerDimension = 4;

  static double norm(std::span<const double> v) {
    // Valid coordinates are at most kMaxCoordinate = 1e100, so the squares of
    // a derivative's coordinates stay far from overflow; the scaled form is
    // kept for the underflow of tiny speeds only.
    double sum = 0.0;
    for (double c : v) sum += c * c;
    if (sum > 1e-280 && sum < 1e280) return std::sqrt(sum);
    double largest = 0.0;
    for (double c : v) largest = std::max(largest, std::abs(c));
    if (largest == 0.0) return 0.0;
    double scaled = 0.0;
    for (double c : v) scaled += (c / largest) * (c / largest);
    return largest * std::sqrt(scaled);
  }

  int dimension_;
  bool rational_;
  int power_degree_ = -1;  // >= 0: the power form below is used
  std::array<double, kPowerDimension*(kPowerDegree + 1)> power_{};
  std::optional<BezierCurve> homogeneous_;  // rational pieces: A
  std::optional<BezierCurve> derivative_;   // the other pieces: A' or C', through the batch kernel
  mutable std::vector<double> scratch_;
};

/// A Möbius map of [0, 1] onto itself, σ = (m00 s + m01) / (m10 s + m11): how
/// the parameter s of a balanced part of a rational piece (below) runs along
/// the piece's own parameter σ.
struct ParameterMap {
  double m00 = 1.0, m01 = 0.0, m10 = 0.0, m11 = 1.0;

  double operator()(double s) const { return (m00 * s + m01) / (m10 * s + m11); }
  double inverse(double sigma) const { return (m11 * sigma - m01) / (m00 - m10 * sigma); }
  /// This map after `inner` (first inner, then this), scaled to keep its entries near 1.
  ParameterMap then(const ParameterMap& inner) const {
    ParameterMap out{m00 * inner.m00 + m01 * inner.m10, m00 * inner.m01 + m01 * inner.m11,
                     m10 * inner.m00 + m11 * inner.m10, m10 * inner.m01 + m11 * inner.m11};
    const double largest = std::max({std::abs(out.m00), std::abs(out.m01), std::abs(out.m10), std::abs(out.m11)});
    out.m00 /= largest, out.m01 /= largest, out.m10 /= largest, out.m11 /= largest;
    return out;
  }
};

/// One part of a piece and the part of the piece's parameter it covers.
struct BalancedPart {
  BezierCurve curve;
  ParameterMap map;  // from the part's parameter to the piece's
};

/// A rational piece as parts whose weights in standard form differ by at most
/// tolerances::kArcLengthWeightRatio, so that quadrature in each part's own
/// parameter sees the whole of it: the weights made standard (w_i ρ^i with
/// ρ = (w_0 / w_n)^(1/n), the Möbius reparameterization σ = ρ s / (ρ s + 1 - s),
/// Farin §13.5, which keeps the curve and its points), then halved by de
/// Casteljau (split_at) until balanced. A piece already balanced is kept as it
/// is; polynomial pieces always are.
void balanced_parts(BezierCurve piece, const ParameterMap& map, int depth, std::vector<BalancedPart>& out) {
  const auto ratio = [](std::span<const double> w) {
    const auto [low, high] = std::minmax_element(w.begin(), w.end());
    return *high / *low;
  };
  if (!piece.is_rational() || (depth == 0 && ratio(piece.weights()) <= tolerances::kArcLengthWeightRatio)) {
    out.push_back({std::move(piece), map});
    return;
  }
  const std::span<const double> w = piece.weights();
  const int n = piece.degree();
  const double rho = std::pow(w[0] / w[n], 1.0 / n);
  std::vector<double> standard(w.size());
  // Weights as products of a power and a ratio, so that neither overflows.
  for (int i = 0; i <= n; ++i) standard[i] = w[i] / w[0] * std::pow(rho, i);
  const BezierCurve balanced = BezierCurve::from_trusted(piece.control_points(), standard);
  const ParameterMap reparameterized = map.then({rho, 0.0, rho - 1.0, 1.0});
  // 64 halvings take any ratio of valid weights (1e100 at most) to 1.
  if (ratio(standard) <= tolerances::kArcLengthWeightRatio || depth >= 64) {
    out.push_back({balanced, reparameterized});
    return;
  }
  auto [left, right] = split_at(balanced, 0.5).value();
  balanced_parts(left, reparameterized.then({0.5, 0.0, 0.0, 1.0}), depth + 1, out);
  balanced_parts(right, reparameterized.then({0.5, 0.5, 0.0, 1.0}), depth + 1, out);
}

/// A rational piece moved so that its first control point is the origin: the
/// length does not change, and the speed's numerator A' w - A w' no longer
/// cancels the piece's distance from the origin (issue 39: a unit circle at
/// (1e6, 1e6) had a speed known to 1e-10, and the default tolerance of 1e-12
/// of its size was never met). The differences are exact for control points
/// within a factor 2 of each other (Sterbenz), and within rounding of the
/// piece's own size otherwise. Polynomial pieces need nothing: their
/// derivative is made of differences already.
BezierCurve moved_to_origin(BezierCurve piece) {
  if (!piece.is_rational()) return piece;
  const PointArray& points = piece.control_points();
  const int d = points.dimension();
  std::vector<double> moved(points.coordinates().begin(), points.coordinates().end());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int j = 0; j < d; ++j) moved[i * d + j] -= points[0][j];
  return BezierCurve::from_trusted(PointArray::from_trusted(d, std::move(moved)),
                                   std::vector<double>(piece.weights().begin(), piece.weights().end()));
}

/// The curve's pieces (rational ones as balanced parts) with their speeds,
/// and the interval budget of one call. Part k covers span(k) of the curve's
/// parameter; integrate and speed take the part's own parameter s,
/// local(k, fraction of the span) and fraction(k, s) convert.
class Quadrature {
 public:
  explicit Quadrature(CurveView curve) {
    BezierPieces pieces = to_bezier_pieces(curve);
    std::vector<BalancedPart> parts;
    for (std::size_t k = 0; k < pieces.pieces.size(); ++k) {
      const std::size_t first = parts.size();
      balanced_parts(moved_to_origin(std::move(pieces.pieces[k])), {}, 0, parts);
      const Interval span{pieces.breakpoints[k], pieces.breakpoints[k + 1]};
      const double siblings = static_cast<double>(parts.size() - first);
      double lower = 0.0;  // where the part starts on the piece: where the one before ends
      for (std::size_t p = first; p < parts.size(); ++p) {
        const double upper = p + 1 == parts.size() ? 1.0 : std::clamp(parts[p].map(1.0), lower, 1.0);
        const ParameterMap& map = parts[p].map;
        const bool identity = map.m01 == 0.0 && map.m10 == 0.0 && map.m00 == map.m11;
        maps_.push_back({map, {lower, upper}, span, siblings, identity});
        lower = upper;
      }
    }
    speeds_.reserve(parts.size());
    for (const BalancedPart& part : parts) speeds_.emplace_back(part.curve);
  }

  std::size_t size() const { return maps_.size(); }
  /// The span of part k's piece on the curve, and the part of the piece's
  /// parameter (on [0, 1]) the part covers: [1, 1] for parts narrower than its
  /// resolution next to 1 (weights 1, 1e20, 1 put half the curve within 1e-21
  /// of a piece's end).
  Interval piece(std::size_t k) const { return maps_[k].piece; }
  Interval covers(std::size_t k) const { return maps_[k].covers; }
  const PieceSpeed& speed(std::size_t k) const { return speeds_[k]; }
  /// Part k's share of a tolerance over `range` of the curve's parameter
  /// (width > 0): its piece's share (the piece's width inside the range over
  /// the range's), divided evenly among the piece's parts, whose widths say
  /// nothing of their lengths.
  double share(std::size_t k, Interval range) const {
    const Interval piece = maps_[k].piece;
    const double inside = std::min(range.upper, piece.upper) - std::max(range.lower, piece.lower);
    return std::max(inside, 0.0) / range.length() / maps_[k].siblings;
  }
  /// Part k's parameter s at the piece's parameter σ (inside covers(k)).
  double local(std::size_t k, double sigma) const {
    const PartMap& m = maps_[k];
    const double s = m.map.inverse(sigma);
    // 0 / 0 where the map's entries have lost 1 - σ to rounding: the nearer end.
    if (std::isnan(s)) return sigma - m.covers.lower <= m.covers.upper - sigma ? 0.0 : 1.0;
    return std::clamp(s, 0.0, 1.0);
  }
  /// Part k's parameter nearest to s whose curve parameter is a double: s
  /// itself for parts of polynomial or balanced pieces kept whole.
  double representable(std::size_t k, double s) const {
    const PartMap& m = maps_[k];
    // Parts narrower than the parameter resolves have one parameter for all s.
    if (m.identity || m.covers.lower == m.covers.upper || s <= 0.0 || s >= 1.0) return s;
    const double sigma = (parameter(k, s) - m.piece.lower) / m.piece.length();
    return local(k, std::clamp(sigma, m.covers.lower, m.covers.upper));
  }
  /// The curve's parameter at part k's parameter s.
  double parameter(std::size_t k, double s) const {
    const PartMap& m = maps_[k];
    const double sigma = s <= 0.0 ? m.covers.lower : s >= 1.0 ? m.covers.upper : m.map(s);
    return sigma >= 1.0 ? m.piece.upper : m.piece.lerp(std::clamp(sigma, m.covers.lower, m.covers.upper));
  }

  /// The length of part k between its parameters a <= b, within tolerance.
  /// An interval is accepted when the Gauss and Kronrod rules agree within
  /// its share of the tolerance (K15 kept); otherwise its halves are
  /// computed, and their Kronrod sum is accepted when it agrees with the
  /// whole interval's Kronrod value within the share (the halves' sum being
  /// far more accurate than that difference: K15's error falls by 2^23 when
  /// the interval halves, for a smooth speed); else each half goes on with
  /// half the share, its two rules already known.
  Expected<double> integrate(std::size_t k, double a, double b, double tolerance) {
    const PieceSpeed& speed = speeds_[k];
    double total = 0.0;
    stack_.clear();
    stack_.push_back(rule(speed, a, b, tolerance));
    while (!stack_.empty()) {
      const Part part = stack_.back();
      stack_.pop_back();
      if (std::abs(part.kronrod - part.gauss) <= part.tolerance) {
        total += part.kronrod;
        continue;
      }
      const double centre = 0.5 * (part.a + part.b);
      // Not halvable in double precision: the interval is a few ulps wide and
      // its length below any tolerance this function accepts.
      if (!(part.a < centre && centre < part.b)) {
        total += part.kronrod;
        continue;
      }
      if ((intervals_ += 2) > tolerances::kMaxArcLengthIntervals)
        return Error{"the arc length needs more than " + std::to_string(tolerances::kMaxArcLengthIntervals) +
                     " quadrature intervals at this tolerance; ask for a larger one", ErrorKind::limit};
      const Part left = rule(speed, part.a, centre, 0.5 * part.tolerance);
      const Part right = rule(speed, centre, part.b, 0.5 * part.tolerance);
      if (std::abs(left.kronrod + right.kronrod - part.kronrod) <= part.tolerance) {
        total += left.kronrod + right.kronrod;
        continue;
      }
      stack_.push_back(right);
      stack_.push_back(left);
    }
    return total;
  }

 private:
  struct Part {
    double a, b, tolerance, kronrod, gauss;
  };

  /// Both rules on [a, b] (15 evaluations of the speed in one batch).
  static Part rule(const PieceSpeed& speed, double a, double b, double tolerance) {
    double ts[kNodes], f[kNodes];
    const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
    for (int i = 0; i < 7; ++i) {
      ts[2 * i] = centre - half * kKronrodNodes[i];
      ts[2 * i + 1] = centre + half * kKronrodNodes[i];
    }
    ts[14] = centre;
    speed.at(std::span<const double>(ts, kNodes), f);
    double kronrod = kKronrodWeights[7] * f[14], gauss = kGaussWeights[3] * f[14];
    for (int i = 0; i < 7; ++i) {
      const double pair = f[2 * i] + f[2 * i + 1];
      kronrod += kKronrodWeights[i] * pair;
      if (i % 2 == 1) gauss += kGaussWeights[i / 2] * pair;
    }
    return {a, b, tolerance, kronrod * half, gauss * half};
  }
  /// The part of the piece's parameter a part covers, [lower, upper], and
  /// how; the piece's span on the curve and its number of parts.
  struct PartMap {
    ParameterMap map;
    Interval covers;
    Interval piece;
    double siblings;
    bool identity;  // the piece kept whole: s is the piece's own parameter
  };
  std::vector<PartMap> maps_;
  std::vector<PieceSpeed> speeds_;
  std::vector<Part> stack_;
  long intervals_ = 0;
};

Status check_tolerance(CurveView curve, Tolerance tolerance) {
  const double e = tolerance.distance;
  if (!std::isfinite(e) || !(e > 0.0))
    return Error{"the arc-length tolerance is " + number_text(e) + ", it must be finite and > 0"};
  const double size = size_of(curve);
  if (e < tolerances::kMinArcLengthRelativeTolerance * size)
    return Error{"the arc-length tolerance " + number_text(e) + " is below " +
                 number_text(tolerances::kMinArcLengthRelativeTolerance) + " of the curve's size " +
                 number_text(size) + ", more than double precision can promise"};
  return {};
}

Status check_range(CurveView curve, Interval range) {
  const Interval domain = curve.domain();
  for (const auto& [value, name] : {std::pair{range.lower, "start"}, std::pair{range.upper, "end"}}) {
    if (auto ok = check_finite(value, std::string("the arc-length range's ") + name); !ok) return ok;
    if (!domain.contains(value))
      return Error{std::string("the arc-length range's ") + name + " " + number_text(value) +
                   " is outside the domain [" + number_text(domain.lower) + ", " + number_text(domain.upper) + "]", ErrorKind::out_of_domain};
  }
  if (range.lower > range.upper)
    return Error{"the arc-length range [" + number_text(range.lower) + ", " + number_text(range.upper) +
                 "] runs backwards"};
  return {};
}

/// The length over [range] with the tolerance shared among the pieces in
/// proportion to their parameter widths inside the range.
Expected<double> length_over(Quadrature& quadrature, Interval range, double tolerance) {
  double total = 0.0;
  const double width = range.length();
  if (width == 0.0) return 0.0;
  for (std::size_t k = 0; k < quadrature.size(); ++k) {
    // The range on the piece's parameter, then on the part's.
    const Interval span = quadrature.piece(k);
    if (range.upper < span.lower || range.lower > span.upper) continue;
    const double from = range.lower <= span.lower ? 0.0 : (range.lower - span.lower) / span.length();
    const double to = range.upper >= span.upper ? 1.0 : (range.upper - span.lower) / span.length();
    const Interval covers = quadrature.covers(k);
    double a = 0.0, b = 1.0;
    if (covers.lower == covers.upper) {
      // Narrower than the parameter resolves: in the range when its place is
      // in (from, to] (ranges that meet there count it once).
      if (!(from < covers.upper && covers.lower <= to)) continue;
    } else {
      const double lower = std::max(from, covers.lower), upper = std::min(to, covers.upper);
      if (!(lower < upper)) continue;
      if (lower > covers.lower) a = quadrature.local(k, lower);
      if (upper < covers.upper) b = quadrature.local(k, upper);
    }
    auto piece = quadrature.integrate(k, a, b, tolerance * quadrature.share(k, range));
    if (!piece) return piece;
    total += *piece;
  }
  return total;
}

/// Lengths of every whole piece (the tolerance shared by parameter width) and
/// their running sums: cumulative[k] = length before piece k.
struct Cumulative {
  std::vector<double> lengths, before;
  double total = 0.0;
};

Expected<Cumulative> cumulative_lengths(Quadrature& quadrature, Interval domain, double tolerance) {
  Cumulative result;
  for (std::size_t k = 0; k < quadrature.size(); ++k) {
    auto piece = quadrature.integrate(k, 0.0, 1.0, tolerance * quadrature.share(k, domain));
    if (!piece) return piece.error();
    result.before.push_back(result.total);
    result.lengths.push_back(*piece);
    result.total += *piece;
  }
  return result;
}

/// The global parameter at which the length from the start is s (0 <= s <= total),
/// |L - s| <= tolerance: the piece from the running sums, then safeguarded
/// Newton on g(t) = L(piece start, t) - r inside it (each L within tolerance / 4).
Expected<double> solve_for_length(Quadrature& quadrature, const Cumulative& sums, double s, double tolerance) {
  // The first part that reaches s within the tolerance: of parts too short
  // to matter (a corner turned within 1e-50 of the parameter), the one whose
  // parameter is still a double.
  std::size_t k = 0;
  while (k + 1 < sums.lengths.size() && sums.before[k] + sums.lengths[k] < s - tolerance / 4) ++k;
  const double r = std::clamp(s - sums.before[k], 0.0, sums.lengths[k]);
  if (sums.lengths[k] == 0.0) return quadrature.parameter(k, 0.0);
  double lo = 0.0, hi = 1.0, t = r / sums.lengths[k];
  for (int iteration = 0; iteration < 200; ++iteration) {
    // The length is measured to the parameter that will be returned: a
    // balanced part's parameter first rounded to the curve's.
    t = quadrature.representable(k, t);
    auto length = quadrature.integrate(k, 0.0, t, tolerance / 4);
    if (!length) return length.error();
    const double g = *length - r;
    if (std::abs(g) <= tolerance / 4) break;
    (g < 0.0 ? lo : hi) = t;
    const double speed = quadrature.speed(k).at(t);
    double next = speed > 0.0 ? t - g / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == t || !(lo < hi)) break;  // the bracket is down to one ulp
    t = next;
  }
  return quadrature.parameter(k, t);
}

}  // namespace

Expected<double> arc_length(CurveView curve, Tolerance tolerance) {
  return arc_length(curve, curve.domain(), tolerance);
}

Expected<double> arc_length(CurveView curve, Interval range, Tolerance tolerance) {
  if (auto ok = check_tolerance(curve, tolerance); !ok) return ok.error();
  if (auto ok = check_range(curve, range); !ok) return ok.error();
  Quadrature quadrature(curve);
  return length_over(quadrature, range, tolerance.distance);
}

Expected<double> parameter_at_length(CurveView curve, double length, Tolerance tolerance) {
  if (auto ok = check_tolerance(curve, tolerance); !ok) return ok.error();
  if (auto ok = check_finite(length, "the length"); !ok) return ok.error();
  Quadrature quadrature(curve);
  auto sums = cumulative_lengths(quadrature, curve.domain(), tolerance.distance / 4);
  if (!sums) return sums.error();
  if (length < 0.0 || length > sums->total + tolerance.distance)
    return Error{"the length " + number_text(length) + " is outside [0, " + number_text(sums->total) +
                 "], the curve's length", ErrorKind::out_of_domain};
  if (length >= sums->total) return curve.domain().upper;
  return solve_for_length(quadrature, *sums, length, tolerance.distance);
}

Expected<std::vector<double>> equal_arc_length_parameters(CurveView curve, std::size_t count, Tolerance tolerance) {
  if (count < 2 || count > tolerances::kMaxInputValues)
    return Error{"the number of equal-arc-length samples is " + std::to_string(count) + ", it must lie in 2.." +
                 std::to_string(tolerances::kMaxInputValues)};
  if (auto ok = check_tolerance(curve, tolerance); !ok) return ok.error();
  Quadrature quadrature(curve);
  const Interval domain = curve.domain();
  auto sums = cumulative_lengths(quadrature, domain, tolerance.distance / 4);
  if (!sums) return sums.error();
  std::vector<double> result{domain.lower};
  for (std::size_t i = 1; i + 1 < count; ++i) {
    const double s = sums->total * (static_cast<double>(i) / static_cast<double>(count - 1));
    auto u = solve_for_length(quadrature, *sums, s, tolerance.distance);
    if (!u) return u.error();
    result.push_back(std::max(*u, result.back()));
  }
  result.push_back(domain.upper);
  return result;
}

Tolerance default_arc_length_tolerance(CurveView curve) {
  const double size = size_of(curve);
  return Tolerance{size > 0.0 ? tolerances::kDefaultArcLengthRelativeTolerance * size : 1.0};
}

}  // namespace casteljau

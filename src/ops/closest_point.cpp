// The nearest point of a curve (closest_point.hpp): branch and bound on the
// Bernstein coefficients of |C - q|^2 per polynomial piece, roots of the
// derivative's numerator for the others, Newton polish on the curve.
#include "casteljau/ops/closest_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "bernstein_columns.hpp"

namespace casteljau {
namespace {

using detail::column;
using detail::derivative;

// Polynomial pieces up to this degree and dimension run the stack kernel
// (every piece of the curves people draw: degree <= 5, d <= 3).
constexpr int kStackDegree = 15;
constexpr int kStackDimension = 4;
constexpr int kStackCoefficients = 2 * kStackDegree + 1;
// Halvings of one piece at most: 2^-40 of a piece is below any distinct
// minima double precision can tell apart by their distances.
constexpr int kMaxDepth = 40;

/// C(m, k) for m <= 2 kStackDegree, exact in double (< 2^53).
struct Binomials {
  double c[kStackCoefficients][kStackCoefficients] = {};
};
constexpr Binomials make_binomials() {
  Binomials b;
  for (int m = 0; m < kStackCoefficients; ++m) {
    b.c[m][0] = b.c[m][m] = 1.0;
    for (int k = 1; k < m; ++k) b.c[m][k] = b.c[m - 1][k - 1] + b.c[m - 1][k];
  }
  return b;
}
constexpr Binomials kBinomials = make_binomials();

/// The curve's pieces and their control points' boxes, prepared once per call.
struct Prepared {
  int dimension = 0;
  BezierPieces pieces;
  std::vector<double> boxes;  // per piece: d lower then d upper coordinates
  std::vector<char> on_stack;  // the piece runs the stack kernel

  const double* box(std::size_t k) const { return boxes.data() + 2 * k * static_cast<std::size_t>(dimension); }
  double global(std::size_t k, double t) const { return Interval{pieces.breakpoints[k], pieces.breakpoints[k + 1]}.lerp(t); }
};

Prepared prepare(CurveView curve) {
  Prepared p;
  p.dimension = curve.dimension();
  p.pieces = to_bezier_pieces(curve);
  const std::size_t d = static_cast<std::size_t>(p.dimension);
  p.boxes.resize(2 * d * p.pieces.pieces.size());
  p.on_stack.resize(p.pieces.pieces.size());
  for (std::size_t k = 0; k < p.pieces.pieces.size(); ++k) {
    const BezierCurve& piece = p.pieces.pieces[k];
    double* lower = p.boxes.data() + 2 * k * d;
    double* upper = lower + d;
    std::fill(lower, lower + d, INFINITY);
    std::fill(upper, upper + d, -INFINITY);
    for (std::size_t i = 0; i < piece.control_points().size(); ++i)
      for (std::size_t j = 0; j < d; ++j) {
        lower[j] = std::min(lower[j], piece.control_points()[i][j]);
        upper[j] = std::max(upper[j], piece.control_points()[i][j]);
      }
    p.on_stack[k] = !piece.is_rational() && piece.degree() <= kStackDegree && p.dimension <= kStackDimension;
  }
  return p;
}

/// Squared distance from q to a box (0 inside): a lower bound of |C - q|^2 on
/// the piece, which lies in its control points' box.
double box_distance_squared(const double* box, const double* q, int d) {
  double sum = 0.0;
  for (int j = 0; j < d; ++j) {
    const double lower = box[j], upper = box[d + j];
    const double gap = q[j] < lower ? lower - q[j] : (q[j] > upper ? q[j] - upper : 0.0);
    sum += gap * gap;
  }
  return sum;
}

/// A point worth polishing: piece, local parameter, squared distance (from
/// the Bernstein coefficients, or the true one).
struct Candidate {
  std::size_t piece;
  double t;
  double g;
};

/// The search state of one query, reused over a batch (no allocation once
/// the candidate list has grown to its working size).
struct Search {
  double best = INFINITY;    // the lowest squared distance seen
  double margin = 0.0;       // rounding of the squared distances compared
  std::vector<Candidate> candidates;
  Point point, best_point;   // scratch for conclude()

  void consider(std::size_t piece, double t, double g) {
    if (g < best) best = g;
    if (g <= best + margin) candidates.push_back({piece, t, g});
  }
  bool beaten(double lower_bound) const { return lower_bound > best + margin; }
  void reset() {
    best = INFINITY;
    margin = 0.0;
    candidates.clear();
  }
};

int sign_changes(const double* b, int count) {
  int changes = 0;
  double last = 0.0;
  for (int i = 0; i < count; ++i) {
    if (b[i] == 0.0) continue;
    if (last != 0.0 && (b[i] > 0.0) != (last > 0.0)) ++changes;
    last = b[i];
  }
  return changes;
}

/// p(t) and p'(t) of count coefficients in Bernstein form (de Casteljau).
void value_and_slope(const double* b, int count, double t, double& value, double& slope) {
  double work[kStackCoefficients];
  std::copy(b, b + count, work);
  const int n = count - 1;
  const double s = 1.0 - t;
  slope = 0.0;
  for (int r = 1; r <= n; ++r) {
    if (r == n) slope = n * (work[1] - work[0]);
    for (int i = 0; i + r <= n; ++i) work[i] = s * work[i] + t * work[i + 1];
  }
  value = work[0];
}

/// The root in [0, 1] of a polynomial negative at 0 and positive at 1 (or
/// zero there): Newton inside the bracket, bisection when a step leaves it.
double rising_root(const double* b, int count) {
  double lo = 0.0, hi = 1.0, t = 0.5, value = 0.0, slope = 0.0;
  if (b[0] >= 0.0) return 0.0;
  if (b[count - 1] <= 0.0) return 1.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    value_and_slope(b, count, t, value, slope);
    if (value == 0.0) return t;
    (value > 0.0 ? hi : lo) = t;
    double next = slope > 0.0 ? t - value / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (!(lo < next && next < hi)) break;
    t = next;
  }
  return t;
}

/// The stack kernel: branch and bound on the 2n + 1 Bernstein coefficients of
/// g = |C - q|^2 on one polynomial piece (degree <= kStackDegree).
void search_polynomial_piece(const Prepared& prepared, std::size_t k, const double* q, Search& search) {
  const BezierCurve& piece = prepared.pieces.pieces[k];
  const PointArray& points = piece.control_points();
  const int n = piece.degree(), m = 2 * n, count = m + 1, d = prepared.dimension;
  // g_k = sum over i + l = k of C(n,i) C(n,l) / C(2n,k) (P_i - q).(P_l - q) (Farin §5.8).
  double g[kStackCoefficients] = {};
  for (int j = 0; j < d; ++j) {
    double difference[kStackDegree + 1];
    for (int i = 0; i <= n; ++i) difference[i] = kBinomials.c[n][i] * (points[static_cast<std::size_t>(i)][j] - q[j]);
    for (int i = 0; i <= n; ++i) {
      g[2 * i] += difference[i] * difference[i];
      for (int l = i + 1; l <= n; ++l) g[i + l] += 2.0 * difference[i] * difference[l];
    }
  }
  double largest = 0.0;
  for (int i = 0; i < count; ++i) {
    g[i] /= kBinomials.c[m][i];
    largest = std::max(largest, g[i]);
  }
  search.margin = std::max(search.margin, tolerances::kClosestPointTieSlack * count * largest);
  search.consider(k, 0.0, g[0]);
  search.consider(k, 1.0, g[m]);
  if (n == 0) return;

  struct Part {
    double a, b;
    int depth;
    double c[kStackCoefficients];
  };
  Part stack[kMaxDepth + 2];
  int top = 0;
  stack[top] = Part{0.0, 1.0, 0, {}};
  std::copy(g, g + count, stack[top].c);
  ++top;
  while (top > 0) {
    // The part's values are read into locals before its slot is reused by its halves.
    const Part& slot = stack[--top];
    const double a = slot.a, b = slot.b;
    const int depth = slot.depth;
    double c[kStackCoefficients];
    std::copy(slot.c, slot.c + count, c);
    double lowest = c[0];
    for (int i = 1; i < count; ++i) lowest = std::min(lowest, c[i]);
    if (search.beaten(lowest)) continue;
    double slope[kStackCoefficients];  // g' up to the factor m
    for (int i = 0; i < m; ++i) slope[i] = c[i + 1] - c[i];
    const int changes = sign_changes(slope, m);
    if (changes == 0) {  // monotone: its lower end
      if (c[0] <= c[m]) search.consider(k, a, c[0]);
      else search.consider(k, b, c[m]);
      continue;
    }
    if (changes == 1) {
      int first = 0, last = m - 1;
      while (slope[first] == 0.0) ++first;
      while (slope[last] == 0.0) --last;
      if (slope[first] < 0.0) {  // falls then rises: one minimum inside
        // Zero coefficients at the ends are roots of g' at a and b (C' = 0
        // there: a control point repeated at the end, as an SVG 'S' after a
        // line makes): divide them out, t^lead (1 - t)^trail q(t), so that
        // the bracket holds the sign change inside instead of stopping at
        // the end. q's coefficients are the remaining ones, rescaled to the
        // lower degree (positive factors: the signs stay).
        const int degree = m - 1, lead = first, trail = m - 1 - last, reduced = degree - lead - trail;
        double stripped[kStackCoefficients];
        for (int i = 0; i <= reduced; ++i)
          stripped[i] = slope[lead + i] * kBinomials.c[degree][lead + i] / kBinomials.c[reduced][i];
        const double s = rising_root(stripped, reduced + 1);
        double value = 0.0, unused = 0.0;
        value_and_slope(c, count, s, value, unused);
        search.consider(k, a + s * (b - a), value);
      } else {  // rises then falls: the lower end
        if (c[0] <= c[m]) search.consider(k, a, c[0]);
        else search.consider(k, b, c[m]);
      }
      continue;
    }
    const double middle = 0.5 * (a + b);
    if (depth >= kMaxDepth) {
      double value = 0.0, unused = 0.0;
      value_and_slope(c, count, 0.5, value, unused);
      search.consider(k, middle, value);
      continue;
    }
    // Halves by de Casteljau at 1/2; the right one below the left on the stack.
    Part& right = stack[top];
    Part& left = stack[top + 1];
    right.a = middle, right.b = b, right.depth = depth + 1;
    left.a = a, left.b = middle, left.depth = depth + 1;
    double* work = c;
    left.c[0] = work[0];
    right.c[m] = work[m];
    for (int r = 1; r <= m; ++r) {
      for (int i = 0; i + r <= m; ++i) work[i] = 0.5 * (work[i] + work[i + 1]);
      left.c[r] = work[0];
      right.c[m - r] = work[m - r];
    }
    top += 2;
  }
}

/// The Bernstein coefficients of a polynomial of the same sign as g' on the
/// piece: D . D' for a polynomial piece (D = C - q), and for a rational one
/// D . (D' w - D w') with D = A - q w the homogeneous difference (g' times
/// w^3 / 2). `magnitude` receives a bound of the terms summed, which
/// rounding errors are relative to (where they cancel, as on a circle about
/// q, the sum itself is only noise).
std::vector<double> slope_numerator(const BezierCurve& piece, const double* q, double& magnitude) {
  const int d = piece.dimension();
  const auto largest = [](const std::vector<double>& b) {
    double m = 0.0;
    for (const double x : b) m = std::max(m, std::abs(x));
    return m;
  };
  std::vector<double> sum;
  const auto add = [&](const std::vector<double>& term) {
    if (sum.empty()) sum.assign(term.size(), 0.0);
    for (std::size_t i = 0; i < term.size(); ++i) sum[i] += term[i];
  };
  magnitude = 0.0;
  if (!piece.is_rational()) {
    for (int j = 0; j < d; ++j) {
      std::vector<double> difference = column(piece.control_points(), j);
      for (double& x : difference) x -= q[j];
      const std::vector<double> slope = derivative(difference);
      magnitude += largest(difference) * largest(slope);
      add(bernstein_product(difference, slope));
    }
    return sum;
  }
  const PointArray h = homogeneous_points(piece);
  const std::vector<double> w = column(h, d), w1 = derivative(w);
  for (int j = 0; j < d; ++j) {
    std::vector<double> difference = column(h, j);
    for (std::size_t i = 0; i < difference.size(); ++i) difference[i] -= q[j] * w[i];
    const std::vector<double> slope = derivative(difference);
    const std::vector<double> a = bernstein_product(slope, w), b = bernstein_product(difference, w1);
    magnitude += largest(difference) * (largest(slope) * largest(w) + largest(difference) * largest(w1));
    std::vector<double> bracket(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) bracket[i] = a[i] - b[i];
    add(bernstein_product(difference, bracket));
  }
  return sum;
}

double squared_distance(std::span<const double> point, const double* q) {
  double sum = 0.0;
  for (std::size_t j = 0; j < point.size(); ++j) sum += (point[j] - q[j]) * (point[j] - q[j]);
  return sum;
}

/// Rational pieces and high degrees: ends and the roots of the slope numerator,
/// each at its true distance.
void search_general_piece(const Prepared& prepared, std::size_t k, const double* q, Search& search) {
  const BezierCurve& piece = prepared.pieces.pieces[k];
  double largest = 0.0;
  for (std::size_t i = 0; i < piece.control_points().size(); ++i)
    largest = std::max(largest, squared_distance(piece.control_points()[i], q));
  search.margin = std::max(search.margin, tolerances::kClosestPointTieSlack * (2 * piece.degree() + 1) * largest);
  search.consider(k, 0.0, squared_distance(point_at(piece, 0.0), q));
  search.consider(k, 1.0, squared_distance(point_at(piece, 1.0), q));
  if (piece.degree() == 0) return;
  double magnitude = 0.0;
  for (const BernsteinRoot& root : bernstein_roots(slope_numerator(piece, q, magnitude)))
    search.consider(k, root.t, squared_distance(point_at(piece, root.t), q));
}

void search_piece(const Prepared& prepared, std::size_t k, const double* q, Search& search) {
  if (prepared.on_stack[k]) search_polynomial_piece(prepared, k, q, search);
  else search_general_piece(prepared, k, q, search);
}

/// C, C', C'' of a piece at t: de Casteljau on the stack for the stack kernel's
/// pieces, derivatives_up_to otherwise.
void point_and_derivatives(const Prepared& prepared, std::size_t k, double t, double* c0, double* c1, double* c2) {
  const BezierCurve& piece = prepared.pieces.pieces[k];
  const int d = prepared.dimension, n = piece.degree();
  if (!prepared.on_stack[k]) {
    const std::vector<Point> derivatives = derivatives_up_to(piece, t, 2);
    std::copy(derivatives[0].begin(), derivatives[0].end(), c0);
    std::copy(derivatives[1].begin(), derivatives[1].end(), c1);
    std::copy(derivatives[2].begin(), derivatives[2].end(), c2);
    return;
  }
  double rows[(kStackDegree + 1) * kStackDimension];
  const std::span<const double> all = piece.control_points().coordinates();
  std::copy(all.begin(), all.end(), rows);
  const double s = 1.0 - t;
  // Down to three points: their second difference is C'' / (n (n - 1)).
  for (int r = 1; r <= n - 2; ++r)
    for (int i = 0; i + r <= n; ++i)
      for (int j = 0; j < d; ++j) rows[i * d + j] = s * rows[i * d + j] + t * rows[(i + 1) * d + j];
  for (int j = 0; j < d; ++j) c2[j] = n >= 2 ? n * (n - 1) * (rows[2 * d + j] - 2.0 * rows[d + j] + rows[j]) : 0.0;
  if (n >= 2)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < d; ++j) rows[i * d + j] = s * rows[i * d + j] + t * rows[(i + 1) * d + j];
  for (int j = 0; j < d; ++j) {
    c1[j] = n >= 1 ? n * (rows[d + j] - rows[j]) : 0.0;
    c0[j] = n >= 1 ? s * rows[j] + t * rows[d + j] : rows[j];
  }
}

/// Room for C, C', C'' of one point: on the stack up to kStackDimension, else on the heap.
class DerivativeScratch {
 public:
  explicit DerivativeScratch(int d) {
    if (d > kStackDimension) heap_.resize(3 * static_cast<std::size_t>(d));
  }
  double* data() { return heap_.empty() ? stack_ : heap_.data(); }

 private:
  double stack_[3 * kStackDimension];
  std::vector<double> heap_;
};

/// The candidate polished by Newton on f(t) = (C - q) . C' = 0 within [0, 1],
/// each step kept only when it brings the point nearer. Writes C(t).
double polish(const Prepared& prepared, std::size_t k, double t, const double* q, double* point, double& g) {
  const int d = prepared.dimension;
  DerivativeScratch scratch(d);
  double* c = scratch.data();
  double* c1 = c + d;
  double* c2 = c1 + d;
  point_and_derivatives(prepared, k, t, c, c1, c2);
  g = squared_distance({c, static_cast<std::size_t>(d)}, q);
  std::copy(c, c + d, point);
  for (int iteration = 0; iteration < 8; ++iteration) {
    double f = 0.0, slope = 0.0;
    for (int j = 0; j < d; ++j) {
      f += (c[j] - q[j]) * c1[j];
      slope += c1[j] * c1[j] + (c[j] - q[j]) * c2[j];
    }
    if (!(slope > 0.0) || f == 0.0) break;
    const double next = std::clamp(t - f / slope, 0.0, 1.0);
    if (next == t) break;
    point_and_derivatives(prepared, k, next, c, c1, c2);
    const double h = squared_distance({c, static_cast<std::size_t>(d)}, q);
    if (h > g) break;
    const bool settled = std::abs(next - t) <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t));
    t = next, g = h;
    std::copy(c, c + d, point);
    if (settled) break;
  }
  return t;
}

/// The best of the candidates within the margin, polished; ties to the
/// lowest parameter. The point goes to search.best_point.
NearestPoint conclude(const Prepared& prepared, const double* q, Search& search, std::size_t& piece, double& local) {
  const std::size_t d = static_cast<std::size_t>(prepared.dimension);
  search.point.resize(d);
  search.best_point.resize(d);
  NearestPoint best;
  double best_g = INFINITY;
  std::sort(search.candidates.begin(), search.candidates.end(), [](const Candidate& x, const Candidate& y) {
    return x.piece != y.piece ? x.piece < y.piece : x.t < y.t;
  });
  const Candidate* previous = nullptr;
  for (const Candidate& candidate : search.candidates) {
    if (candidate.g > search.best + search.margin) continue;
    if (previous != nullptr && previous->piece == candidate.piece && previous->t == candidate.t) continue;
    previous = &candidate;
    double g = 0.0;
    const double t = polish(prepared, candidate.piece, candidate.t, q, search.point.data(), g);
    const double u = prepared.global(candidate.piece, t);
    if (g < best_g || (g == best_g && u < best.parameter)) {
      best_g = g;
      best.parameter = u;
      std::swap(search.point, search.best_point);
      piece = candidate.piece;
      local = t;
    }
  }
  best.distance = std::sqrt(best_g);
  return best;
}

/// One query: the warm start's piece first (or the nearest box), then every
/// piece whose box is nearer than the best answer.
NearestPoint nearest(const Prepared& prepared, const double* q, Search& search, std::size_t& piece, double& local,
                     bool warm) {
  const int d = prepared.dimension;
  const std::size_t count = prepared.pieces.pieces.size();
  search.reset();
  std::size_t first = 0;
  if (warm) {
    // The previous answer bounds this one: |q - C(previous)|.
    first = piece;
    DerivativeScratch scratch(d);
    double* c = scratch.data();
    point_and_derivatives(prepared, piece, local, c, c + d, c + 2 * d);
    search.consider(piece, local, squared_distance({c, static_cast<std::size_t>(d)}, q));
  } else {
    double nearest_box = INFINITY;
    for (std::size_t k = 0; k < count; ++k) {
      const double bound = box_distance_squared(prepared.box(k), q, d);
      if (bound < nearest_box) nearest_box = bound, first = k;
    }
  }
  search_piece(prepared, first, q, search);
  for (std::size_t k = 0; k < count; ++k) {
    if (k == first || search.beaten(box_distance_squared(prepared.box(k), q, d))) continue;
    search_piece(prepared, k, q, search);
  }
  return conclude(prepared, q, search, piece, local);
}

Status check_query(std::span<const double> query, int dimension, const std::string& what) {
  if (static_cast<int>(query.size()) != dimension)
    return Error{what + " has " + std::to_string(query.size()) + " coordinates, the curve lives in R^" +
                 std::to_string(dimension)};
  for (std::size_t j = 0; j < query.size(); ++j)
    if (Status status = check_coordinate(query[j], "coordinate " + std::to_string(j) + " of " + what); !status)
      return status;
  return {};
}

int sign_of(double value, double noise) { return value > noise ? 1 : (value < -noise ? -1 : 0); }

}  // namespace

Expected<NearestPoint> closest_point(CurveView curve, std::span<const double> query) {
  if (Status status = check_query(query, curve.dimension(), "the query point"); !status) return status.error();
  const Prepared prepared = prepare(curve);
  Search search;
  std::size_t piece = 0;
  double local = 0.0;
  NearestPoint answer = nearest(prepared, query.data(), search, piece, local, false);
  answer.point = search.best_point;
  return answer;
}

Status closest_points(CurveView curve, std::span<const double> queries, std::span<double> parameters,
                      std::span<double> distances) {
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  if (queries.size() % d != 0)
    return Error{"the queries hold " + std::to_string(queries.size()) + " numbers, not a multiple of the dimension " +
                 std::to_string(d)};
  const std::size_t n = queries.size() / d;
  if (parameters.size() != n || distances.size() != n)
    return Error{"the outputs hold " + std::to_string(parameters.size()) + " parameters and " +
                 std::to_string(distances.size()) + " distances for " + std::to_string(n) + " queries"};
  for (std::size_t i = 0; i < n; ++i)
    if (Status status = check_query(queries.subspan(i * d, d), curve.dimension(), "query " + std::to_string(i));
        !status)
      return status;
  const Prepared prepared = prepare(curve);
  Search search;
  std::size_t piece = 0;
  double local = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double* q = queries.data() + i * d;
    const NearestPoint answer = nearest(prepared, q, search, piece, local, i > 0);
    parameters[i] = answer.parameter;
    distances[i] = answer.distance;
  }
  return {};
}

Expected<std::vector<NearestPoint>> local_closest_points(CurveView curve, std::span<const double> query) {
  if (Status status = check_query(query, curve.dimension(), "the query point"); !status) return status.error();
  const Prepared prepared = prepare(curve);
  const double* q = query.data();
  const std::size_t d = static_cast<std::size_t>(prepared.dimension);
  // Every critical point and end of every piece, with the sign of g' on the
  // stretch before and after it (0: constant within rounding; 2: no stretch,
  // the end of the domain).
  struct Event {
    std::size_t piece;
    double t;
    int before, after;
  };
  std::vector<Event> events;
  for (std::size_t k = 0; k < prepared.pieces.pieces.size(); ++k) {
    const BezierCurve& piece = prepared.pieces.pieces[k];
    if (piece.degree() == 0) {
      events.push_back({k, 0.0, 0, 0});
      continue;
    }
    double magnitude = 0.0;
    const std::vector<double> numerator = slope_numerator(piece, q, magnitude);
    const double noise = tolerances::kClosestPointTieSlack * static_cast<double>(numerator.size()) * magnitude;
    std::vector<double> ts{0.0};
    for (const BernsteinRoot& root : bernstein_roots(numerator))
      if (root.t > ts.back()) ts.push_back(root.t);
    if (ts.back() < 1.0) ts.push_back(1.0);
    std::vector<int> signs;  // of the stretch between ts[i] and ts[i + 1]
    for (std::size_t i = 0; i + 1 < ts.size(); ++i)
      signs.push_back(sign_of(bernstein_value(numerator, 0.5 * (ts[i] + ts[i + 1])), noise));
    for (std::size_t i = 0; i < ts.size(); ++i)
      events.push_back({k, ts[i], i == 0 ? 2 : signs[i - 1], i + 1 == ts.size() ? 2 : signs[i]});
  }
  // A piece's end and the next one's start are one point where the pieces
  // meet: the signs on both sides come from the two pieces.
  std::vector<Event> merged;
  for (const Event& event : events) {
    if (!merged.empty() && event.t == 0.0 && merged.back().t == 1.0 && merged.back().piece + 1 == event.piece) {
      const Point end = point_at(prepared.pieces.pieces[merged.back().piece], 1.0);
      const Point start = point_at(prepared.pieces.pieces[event.piece], 0.0);
      double gap = 0.0, size = 0.0;
      for (std::size_t j = 0; j < d; ++j) {
        gap = std::max(gap, std::abs(end[j] - start[j]));
        size = std::max({size, std::abs(end[j]), std::abs(q[j])});
      }
      if (gap <= tolerances::kJointRelativeGap * std::max(size, tolerances::kScaleFloor)) {
        merged.back().after = event.after;
        continue;
      }
    }
    merged.push_back(event);
  }
  std::vector<NearestPoint> result;
  Point point(d);
  for (const Event& event : merged) {
    const bool falls_in = event.before == 2 || event.before <= 0;
    const bool rises_out = event.after == 2 || event.after >= 0;
    if (!falls_in || !rises_out || (event.before == 0 && event.after == 0)) continue;
    double g = 0.0;
    const double t = polish(prepared, event.piece, event.t, q, point.data(), g);
    result.push_back({prepared.global(event.piece, t), std::sqrt(g), point});
  }
  if (result.empty()) {  // the whole curve at one distance (a circle about q, a point)
    const NearestPoint start = closest_point(curve, query).value();
    result.push_back(start);
  }
  // One minimum found twice (a root of the slope just before a knot, and the
  // knot): the nearer of the two is kept, at equal distances the first. Both
  // the points and the parameters must agree: a double point of the curve is
  // two minima at one point.
  double scale = std::max(size_of(curve), tolerances::kScaleFloor);
  for (std::size_t j = 0; j < d; ++j) scale = std::max(scale, std::abs(q[j]));
  const double width = curve.domain().length();
  std::vector<NearestPoint> distinct;
  for (NearestPoint& candidate : result) {
    if (!distinct.empty()) {
      NearestPoint& last = distinct.back();
      double gap = 0.0;
      for (std::size_t j = 0; j < d; ++j) gap = std::max(gap, std::abs(candidate.point[j] - last.point[j]));
      if (gap <= tolerances::kClosestPointSameMinimum * scale &&
          std::abs(candidate.parameter - last.parameter) <= tolerances::kClosestPointSameMinimum * width) {
        if (candidate.distance < last.distance) last = std::move(candidate);
        continue;
      }
    }
    distinct.push_back(std::move(candidate));
  }
  result = std::move(distinct);
  const auto global = std::min_element(result.begin(), result.end(), [](const NearestPoint& x, const NearestPoint& y) {
    return x.distance < y.distance || (x.distance == y.distance && x.parameter < y.parameter);
  });
  std::rotate(result.begin(), global, global + 1);
  return result;
}

}  // namespace casteljau

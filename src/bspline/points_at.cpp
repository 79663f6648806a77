// Batch evaluation of B-spline and NURBS curves: de Boor across parameters.
//
// Each SIMD lane holds one parameter and performs exactly the scalar
// operations of de_boor.hpp (point_at, and the point-and-derivative pair of
// points_and_derivatives_at): the same rows (homogeneous w*P if rational),
// the same coefficients a = (u - t_lower) * (1/(t_upper - t_lower)), the
// same lerp_step, the same projection. IEEE operations are correctly rounded
// per lane, so every lane's result equals the scalar one bit for bit.
//
// Two ways to feed the lanes, chosen per block of kLanes parameters:
//  - span block: all lanes lie in one span [t_k, t_{k+1}) (a sorted batch,
//    almost always: W1 has ~1000 parameters per span). The knots, the
//    reciprocals of their differences and the control rows of that span
//    were prepared once, in scalar code, and enter the lanes as broadcast
//    operands; no division and no gather per parameter.
//  - gather block: lanes in different spans (random order, or a block that
//    straddles a knot). Each lane's span comes from an interpolation guess
//    (exact for uniform knots) corrected by a short walk, with bisection as
//    the fallback; knots and control rows are gathered; the reciprocals are
//    SIMD divisions. Blocks with a lane at or beyond the right end of its
//    span (the end of the domain, extrapolation) also apply the u == t_upper
//    rule of de_boor_alpha; a lane whose result is not finite (only knots
//    closer than 2^-1024, where the scalar code divides) is recomputed by the
//    scalar code.
// Degrees 1..kMaxFixedDegree in dimensions 1..3 (rational or not) have
// unrolled kernels (degree, dimension as template arguments: the triangle of
// a cubic in 3D is 12 vectors in registers); every other case, and degree 0,
// runs the scalar code of de_boor.hpp per parameter. The last, partial block
// runs the same block code on padded copies. Outputs of 4 MiB and more are
// written with streaming stores (see src/bezier/points_at.cpp for why).
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/core/precondition.hpp"
#include "../core/workspace.hpp"
#include "de_boor.hpp"
#include "../bezier/simd_lanes.hpp"

namespace casteljau {
namespace {

using namespace detail::simd;

/// kLanes 64-bit integers: span indices, comparison masks.
typedef long long Lanes __attribute__((vector_size(kLanes * sizeof(long long))));

/// Degrees up to this get an unrolled kernel (W1 and W2 use 3).
constexpr int kMaxFixedDegree = 7;

/// detail::subtract_product lane by lane: b - a c.
inline Pack subtract_product_pack(Pack b, Pack a, Pack c) {
#if defined(__AVX512F__)
  return _mm512_fnmadd_pd(a, c, b);
#elif defined(__FMA__) && defined(__AVX__)
  return _mm256_fnmadd_pd(a, c, b);
#elif defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  Pack r;
  for (int l = 0; l < kLanes; ++l) r[l] = detail::subtract_product(b[l], a[l], c[l]);
  return r;
#else
  const Pack product = a * c;
  return b - product;
#endif
}

/// 0 in each lane where every pack's lane is finite, NaN where one is not
/// (x * 0 is 0 unless x is infinite or NaN).
template <int Count>
inline Pack finiteness(const Pack* c) {
  Pack z = c[0] * 0.0;
  for (int j = 1; j < Count; ++j) z += c[j] * 0.0;
  return z;
}

/// Whether some lane of a finiteness() sum is not 0.
inline bool any_lane_not_finite(Pack z) {
  const Lanes bad = z != 0.0;
  bool result = false;
  for (int l = 0; l < kLanes; ++l) result |= bad[l] != 0;
  return result;
}

/// Whether some lane of some pack is not finite.
template <int Count>
inline bool any_not_finite(const Pack* c) {
  return any_lane_not_finite(finiteness<Count>(c));
}

/// base[index[l]] in lane l.
inline Pack gather(const double* base, Lanes index) {
// The masked forms, with a defined pass-through value: g++ 12 warns that the
// unmasked intrinsics read an uninitialized register.
#if defined(__AVX512F__)
  return _mm512_mask_i64gather_pd(_mm512_setzero_pd(), 0xFF, (__m512i)index, base, 8);
#elif defined(__AVX2__)
  return _mm256_mask_i64gather_pd(_mm256_setzero_pd(), base, (__m256i)index, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), 8);
#else
  Pack v;
  for (int l = 0; l < kLanes; ++l) v[l] = base[index[l]];
  return v;
#endif
}

/// Lane-wise choice: yes where mask is set (all ones), otherwise no.
inline Pack select(Lanes mask, Pack yes, Pack no) {
  Lanes y, n;
  std::memcpy(&y, &yes, sizeof y);
  std::memcpy(&n, &no, sizeof n);
  const Lanes r = (y & mask) | (n & ~mask);
  Pack v;
  std::memcpy(&v, &r, sizeof v);
  return v;
}

inline bool any(Lanes mask) {
  bool result = false;
  for (int l = 0; l < kLanes; ++l) result |= mask[l] != 0;
  return result;
}

/// Whether every lane lies in [lower, upper).
inline bool all_within(Pack u, double lower, double upper) {
#if defined(__AVX512F__)
  const __mmask8 inside = _mm512_cmp_pd_mask(u, _mm512_set1_pd(lower), _CMP_GE_OQ) &
                          _mm512_cmp_pd_mask(u, _mm512_set1_pd(upper), _CMP_LT_OQ);
  return inside == 0xFF;
#else
  const Lanes inside = (u >= broadcast(lower)) & (u < broadcast(upper));
  bool all = true;
  for (int l = 0; l < kLanes; ++l) all &= inside[l] != 0;
  return all;
#endif
}

/// Whether every lane lies in the closed [lower, upper] (false for NaN): the
/// parameter check of points_at_within, on the pack the block loads anyway.
inline bool all_inside(Pack u, double lower, double upper) {
#if defined(__AVX512F__)
  const __mmask8 inside = _mm512_cmp_pd_mask(u, _mm512_set1_pd(lower), _CMP_GE_OQ) &
                          _mm512_cmp_pd_mask(u, _mm512_set1_pd(upper), _CMP_LE_OQ);
  return inside == 0xFF;
#else
  const Lanes inside = (u >= broadcast(lower)) & (u <= broadcast(upper));
  bool all = true;
  for (int l = 0; l < kLanes; ++l) all &= inside[l] != 0;
  return all;
#endif
}

// --- spans ---------------------------------------------------------------------

/// find_span's answer, found in O(1) for uniform knots: a guess from the
/// parameter's position in the domain, a short walk to the span, bisection
/// (find_span itself) if the walk is long.
class SpanFinder {
 public:
  SpanFinder(std::span<const double> knots, int degree) : knots_(knots), degree_(degree) {
    const int p = degree;
    last_index_ = static_cast<int>(knots.size()) - p - 2;
    lower_ = knots[static_cast<std::size_t>(p)];
    upper_ = knots[static_cast<std::size_t>(last_index_ + 1)];
    first_span_ = find_span(knots, p, lower_);
    last_span_ = find_span(knots, p, upper_);
    scale_ = static_cast<double>(last_index_ + 1 - p) / (upper_ - lower_);
    // Knots from make() keep this finite and (u - lower) * scale within
    // [0, n - p + 1] (validate_knots). A computed curve need only have
    // well-formed knots: a domain of subnormal width would make the scale
    // infinite and the guess NaN, which must never be cast to an index.
    // Scale 0 turns the guess off (bisection instead).
    if (!std::isfinite(scale_) || !std::isfinite(upper_ - lower_)) scale_ = 0.0;
  }

  int find(double u) const {
    if (!(u >= lower_)) return first_span_;
    if (u >= upper_) return last_span_;
    if (scale_ == 0.0) return find_span(knots_, degree_, u);
    // t_p <= u < t_{n+1}: exactly one span [t_i, t_{i+1}) holds u.
    const double* t = knots_.data();
    const double guess = (u - lower_) * scale_;
    int i = degree_ + static_cast<int>(std::min(guess, static_cast<double>(last_index_ - degree_)));
    for (int step = 0; step < 4; ++step) {
      if (u < t[i]) {
        --i;  // i > p here, since t_p <= u
      } else if (u >= t[i + 1]) {
        ++i;  // i < n here, since u < t_{n+1}
      } else {
        return i;
      }
    }
    return find_span(knots_, degree_, u);
  }

  /// The spans of all lanes at once when every lane lies in the domain and
  /// the interpolation guess is right for each (uniform knots): then true.
  bool guess(Pack u, Lanes* spans) const {
    if (scale_ == 0.0 || !all_within(u, lower_, upper_)) return false;
    const Pack g = (u - lower_) * scale_;
    const Pack limit = broadcast(static_cast<double>(last_index_ - degree_));
    const Lanes index = __builtin_convertvector(select(g < limit, g, limit), Lanes) + degree_;
    const double* t = knots_.data();
    const Pack low = gather(t, index), high = gather(t, index + 1);
    const Lanes inside = (u >= low) & (u < high);
    for (int l = 0; l < kLanes; ++l)
      if (inside[l] == 0) return false;
    *spans = index;
    return true;
  }

 private:
  std::span<const double> knots_;
  int degree_ = 0;
  int last_index_ = 0;  // n
  int first_span_ = 0, last_span_ = 0;
  double lower_ = 0.0, upper_ = 0.0, scale_ = 0.0;
};

// --- the scalar path -------------------------------------------------------------

/// What every kernel needs to know about the curve.
struct CurveData {
  std::span<const double> knots;
  const double* coordinates = nullptr;  // control points, row-major, d per point
  const double* weights = nullptr;      // null for a polynomial curve
  int degree = 0;
  int dimension = 0;
  Interval allowed{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
};

/// The index of the first of us[from..to) outside c.allowed, or `to`.
inline std::size_t first_outside(const CurveData& c, std::span<const double> us, std::size_t from, std::size_t to) {
  while (from < to && c.allowed.contains(us[from])) ++from;
  return from;
}

/// The p+1 rows of `span` as point_at loads them: P_i, or (w_i P_i, w_i).
inline void load_rows(const CurveData& c, int span, double* rows) {
  const int p = c.degree, d = c.dimension;
  const int width = c.weights ? d + 1 : d;
  for (int j = 0; j <= p; ++j) {
    const std::size_t i = static_cast<std::size_t>(span - p + j);
    const double* point = c.coordinates + i * static_cast<std::size_t>(d);
    double* row = rows + static_cast<std::ptrdiff_t>(j) * width;
    if (c.weights) {
      const double w = c.weights[i];
      for (int k = 0; k < d; ++k) row[k] = w * point[k];
      row[d] = w;
    } else {
      for (int k = 0; k < d; ++k) row[k] = point[k];
    }
  }
}

/// One parameter by the scalar code (point_at's arithmetic): the point into
/// `point`, and with `derivative` non-null the first derivative too.
void scalar_one(const CurveData& c, int span, double u, double* rows, double* point, double* derivative) {
  const int p = c.degree, d = c.dimension;
  const bool rational = c.weights != nullptr;
  load_rows(c, span, rows);
  if (derivative) {
    detail::de_boor_point_and_derivative(c.knots, p, span, u, rows, d, rational, point, derivative);
    return;
  }
  const int width = rational ? d + 1 : d;
  detail::de_boor_rounds(c.knots, p, span, u, 1, p, rows, width);
  const double* apex = rows + static_cast<std::ptrdiff_t>(p) * width;
  for (int k = 0; k < d; ++k) point[k] = rational ? apex[k] / apex[d] : apex[k];
}

/// Any degree and dimension, one parameter at a time; stops at the first
/// parameter outside c.allowed and returns its index (us.size() if none).
std::size_t scalar_run(const CurveData& c, std::span<const double> us, double* points, double* derivatives) {
  const SpanFinder finder(c.knots, c.degree);
  const int width = c.weights ? c.dimension + 1 : c.dimension;
  detail::Workspace<> space;
  double* rows = space.take(static_cast<std::size_t>(c.degree + 1) * static_cast<std::size_t>(width)).data();
  const std::size_t d = static_cast<std::size_t>(c.dimension);
  for (std::size_t i = 0; i < us.size(); ++i) {
    if (!c.allowed.contains(us[i])) return i;
    scalar_one(c, finder.find(us[i]), us[i], rows, points + i * d, derivatives ? derivatives + i * d : nullptr);
  }
  return us.size();
}

// --- fixed degree and dimension ---------------------------------------------------

/// Degree P, dimension D, rational or not; with Derivative the first
/// derivative too (else only points).
template <int P, int D, bool Rational, bool Derivative>
class Kernel {
 public:
  static constexpr int W = Rational ? D + 1 : D;

  Kernel(const CurveData& curve) : c_(curve), finder_(curve.knots, P) {}

  /// Every parameter of us; points (and derivatives) get us.size() * D
  /// doubles. Each block's parameters are first checked against c.allowed
  /// (two compares on the pack it loads anyway): at the first block with one
  /// outside, it stops and returns that parameter's index (us.size() if none).
  std::size_t run(std::span<const double> us, double* points, double* derivatives) {
    const std::size_t count = us.size();
    const double lower = c_.allowed.lower, upper = c_.allowed.upper;
    std::size_t k = 0;
    const std::size_t bytes = count * D * sizeof(double);
    if (kCanStream && bytes >= kStreamingBytes) {
      // Streaming stores need aligned packs: the first `head` points go
      // through a partial block so that later blocks start on a pack
      // boundary (of both outputs; no streaming if they disagree).
      std::size_t head = 0;
      while (head < kLanes && !aligned(points + head * D)) ++head;
      if (head < kLanes && (!Derivative || aligned(derivatives + head * D))) {
        if (const std::size_t bad = first_outside(c_, us, 0, head); bad < head) return bad;
        partial(us.data(), head, points, derivatives);
        for (k = head; k + kLanes <= count; k += kLanes) {
          if (!all_inside(load(us.data() + k), lower, upper)) break;
          block<true>(us.data() + k, points + k * D, at(derivatives, k));
        }
        end_streaming();
        if (k + kLanes <= count) return first_outside(c_, us, k, k + kLanes);
      }
    }
    for (; k + kLanes <= count; k += kLanes) {
      if (!all_inside(load(us.data() + k), lower, upper)) return first_outside(c_, us, k, k + kLanes);
      block<false>(us.data() + k, points + k * D, at(derivatives, k));
    }
    if (const std::size_t bad = first_outside(c_, us, k, count); bad < count) return bad;
    partial(us.data() + k, count - k, points + k * D, at(derivatives, k));
    return count;
  }

 private:
  static bool aligned(const double* p) { return reinterpret_cast<std::uintptr_t>(p) % sizeof(Pack) == 0; }
  static double* at(double* derivatives, std::size_t k) { return Derivative ? derivatives + k * D : nullptr; }

  /// The first `count` < kLanes parameters through a padded block.
  void partial(const double* us, std::size_t count, double* points, double* derivatives) {
    if (count == 0) return;
    double u[kLanes], p[kLanes * D], dp[kLanes * D];
    for (int l = 0; l < kLanes; ++l) u[l] = us[std::min<std::size_t>(l, count - 1)];
    block<false>(u, p, dp);
    std::copy(p, p + count * D, points);
    if (Derivative) std::copy(dp, dp + count * D, derivatives);
  }

  /// Prepares the span block data of span k (scalar, once per span).
  void enter_span(int k) {
    span_ = k;
    const double* t = c_.knots.data();
    lower_ = t[k];
    upper_ = t[k + 1];
    exotic_ = false;
    for (int j = 1; j <= P; ++j) left_[j] = t[k - P + j];
    for (int r = 1; r <= P; ++r)
      for (int j = P; j >= r; --j) {
        reciprocal_[r][j] = 1.0 / (t[k + 1 + j - r] - t[k - P + j]);
        exotic_ |= std::isinf(reciprocal_[r][j]);
      }
    factor_ = static_cast<double>(P) * reciprocal_[P][P];
    load_rows(c_, k, rows_);
  }

  /// kLanes parameters at us into kLanes points (and derivatives).
  template <bool Streaming>
  void block(const double* us, double* points, double* derivatives) {
    const Pack u = load(us);
    if (span_ < 0 || !all_within(u, lower_, upper_)) {
      const double* t = c_.knots.data();
      Lanes spans;
      bool ends = false;
      if (!finder_.guess(u, &spans)) {
        for (int l = 0; l < kLanes; ++l) spans[l] = finder_.find(u[l]);
        ends = any(u >= gather(t, spans + 1));
      }
      bool same = true;
      for (int l = 1; l < kLanes; ++l) same &= spans[l] == spans[0];
      if (!same || !all_within(u, t[spans[0]], t[spans[0] + 1])) {
        gather_block(u, spans, ends, points, derivatives);
        return;
      }
      enter_span(static_cast<int>(spans[0]));
    }
    if (exotic_) {
      scalar_block(us, points, derivatives);
      return;
    }
    span_block<Streaming>(u, points, derivatives);
  }

  /// The lanes by the scalar code (spans with subnormal knot differences).
  void scalar_block(const double* us, double* points, double* derivatives) {
    double rows[(P + 1) * W];
    for (int l = 0; l < kLanes; ++l)
      scalar_one(c_, finder_.find(us[l]), us[l], rows, points + l * D, Derivative ? derivatives + l * D : nullptr);
  }

  /// The apex (point) and, with Derivative, the derivative from the two
  /// rows q0, q1 of level P-1 (de_boor_point_and_derivative, lane by lane).
  template <bool Streaming>
  [[gnu::always_inline]] static bool finish(const Pack* q0, const Pack* q1, Pack s, Pack a, Pack factor, double* points,
                     double* derivatives) {
    Pack c[W];
    for (int j = 0; j < W; ++j) c[j] = lerp_pack(q0[j], q1[j], s, a);
    if constexpr (!Derivative) {
      if constexpr (Rational)
        for (int j = 0; j < D; ++j) c[j] = c[j] / c[D];
      store_points<D, Streaming>(c, points);
      return any_not_finite<D>(c);
    } else {
      Pack dc[W];
      for (int j = 0; j < W; ++j) dc[j] = (q1[j] - q0[j]) * factor;
      if constexpr (Rational) {
        for (int j = 0; j < D; ++j) {
          c[j] = c[j] / c[D];
          dc[j] = subtract_product_pack(dc[j], dc[D], c[j]) / c[D];
        }
      }
      store_points<D, Streaming>(c, points);
      store_points<D, Streaming>(dc, derivatives);
      return any_lane_not_finite(finiteness<D>(c) + finiteness<D>(dc));  // one reduction for both
    }
  }

  /// All lanes in the current span: knots, reciprocals and rows broadcast.
  template <bool Streaming>
  void span_block(Pack u, double* points, double* derivatives) {
    constexpr int kRounds = Derivative ? P - 1 : P;
    Pack row[P + 1][W];
    if constexpr (kRounds == 0) {
      for (int i = 0; i <= P; ++i)
        for (int k = 0; k < W; ++k) row[i][k] = broadcast(rows_[i * W + k]);
    } else {
      // Round 1 reads the span's rows as broadcast operands.
#pragma GCC unroll 8
      for (int j = P; j >= 1; --j) {
        const Pack a = (u - left_[j]) * reciprocal_[1][j];
        const Pack s = 1.0 - a;
#pragma GCC unroll 4
        for (int k = 0; k < W; ++k) row[j][k] = lerp_first(rows_[(j - 1) * W + k], rows_[j * W + k], s, a);
      }
    }
#pragma GCC unroll 8
    for (int r = 2; r <= kRounds; ++r) {
#pragma GCC unroll 8
      for (int j = P; j >= r; --j) {
        const Pack a = (u - left_[j]) * reciprocal_[r][j];
        const Pack s = 1.0 - a;
#pragma GCC unroll 4
        for (int k = 0; k < W; ++k) row[j][k] = lerp_pack(row[j - 1][k], row[j][k], s, a);
      }
    }
    if constexpr (Derivative) {
      const Pack a = (u - left_[P]) * reciprocal_[P][P];
      finish<Streaming>(row[P - 1], row[P], 1.0 - a, a, broadcast(factor_), points, derivatives);
    } else {
      store_apex<Streaming>(row[P], points);
    }
  }

  template <bool Streaming>
  [[gnu::always_inline]] static bool store_apex(Pack* apex, double* points) {
    if constexpr (Rational)
      for (int j = 0; j < D; ++j) apex[j] = apex[j] / apex[D];
    store_points<D, Streaming>(apex, points);
    return any_not_finite<D>(apex);
  }

  /// Lanes in different spans: gathered knots and rows, divided reciprocals.
  /// `ends`: some lane lies at or beyond the right end of its span.
  void gather_block(Pack u, Lanes spans, bool ends, double* points, double* derivatives) {
    const bool not_finite = ends ? compute<true>(u, spans, points, derivatives)
                                 : compute<false>(u, spans, points, derivatives);
    if (!not_finite) return;
    // A lane that came out non-finite may be one where the scalar code
    // divides (knots closer than 2^-1024): recompute such lanes there.
    for (int l = 0; l < kLanes; ++l) {
      bool finite = true;
      for (int j = 0; j < D; ++j) finite &= std::isfinite(points[l * D + j]);
      if constexpr (Derivative)
        for (int j = 0; j < D; ++j) finite &= std::isfinite(derivatives[l * D + j]);
      if (!finite) {
        double rows[(P + 1) * W];
        scalar_one(c_, static_cast<int>(spans[l]), u[l], rows, points + l * D,
                   Derivative ? derivatives + l * D : nullptr);
      }
    }
  }

  template <bool Ends>
  bool compute(Pack u, Lanes spans, double* points, double* derivatives) {
    constexpr int kRounds = Derivative ? P - 1 : P;
    const double* t = c_.knots.data();
    Pack left[P + 1], right[P + 1];
    for (int j = 1; j <= P; ++j) left[j] = gather(t, spans + (j - P));
    for (int m = 1; m <= P; ++m) right[m] = gather(t, spans + m);
    Pack row[P + 1][W];
    const Lanes first_row = spans - P;
    for (int i = 0; i <= P; ++i) {
      const Lanes index = (first_row + i) * D;
      if constexpr (Rational) {
        const Pack w = gather(c_.weights, first_row + i);
        for (int k = 0; k < D; ++k) row[i][k] = w * gather(c_.coordinates + k, index);
        row[i][D] = w;
      } else {
        for (int k = 0; k < D; ++k) row[i][k] = gather(c_.coordinates + k, index);
      }
    }
    const auto alpha = [&](int r, int j, Pack* reciprocal) {
      const Pack upper = right[j + 1 - r];
      *reciprocal = 1.0 / (upper - left[j]);
      const Pack a = (u - left[j]) * *reciprocal;
      if constexpr (Ends) return select(u == upper, broadcast(1.0), a);
      return a;
    };
#pragma GCC unroll 8
    for (int r = 1; r <= kRounds; ++r) {
#pragma GCC unroll 8
      for (int j = P; j >= r; --j) {
        Pack reciprocal;
        const Pack a = alpha(r, j, &reciprocal);
        const Pack s = 1.0 - a;
#pragma GCC unroll 4
        for (int k = 0; k < W; ++k) row[j][k] = lerp_pack(row[j - 1][k], row[j][k], s, a);
      }
    }
    if constexpr (Derivative) {
      Pack reciprocal;
      const Pack a = alpha(P, P, &reciprocal);
      return finish<false>(row[P - 1], row[P], 1.0 - a, a, static_cast<double>(P) * reciprocal, points,
                           derivatives);
    } else {
      return store_apex<false>(row[P], points);
    }
  }

  CurveData c_;
  SpanFinder finder_;
  int span_ = -1;
  bool exotic_ = false;
  double lower_ = 0.0, upper_ = 0.0, factor_ = 0.0;
  double left_[P + 1] = {};
  double reciprocal_[P + 1][P + 1] = {};
  double rows_[(P + 1) * W] = {};
};

template <int P, int D, bool Rational, bool Derivative>
std::size_t run_kernel(const CurveData& c, std::span<const double> us, double* points, double* derivatives) {
  Kernel<P, D, Rational, Derivative> kernel(c);
  return kernel.run(us, points, derivatives);
}

using Runner = std::size_t (*)(const CurveData&, std::span<const double>, double*, double*);

template <int D, bool Rational, bool Derivative, int... N>
constexpr auto runner_table(std::integer_sequence<int, N...>) {
  return std::array<Runner, sizeof...(N)>{&run_kernel<N + 1, D, Rational, Derivative>...};
}

template <bool Derivative>
Runner fixed_runner(int p, int d, bool rational) {
  if (p < 1 || p > kMaxFixedDegree || d < 1 || d > 3) return nullptr;
  using Degrees = std::make_integer_sequence<int, kMaxFixedDegree>;
  static constexpr std::array<std::array<Runner, kMaxFixedDegree>, 6> tables = {
      runner_table<1, false, Derivative>(Degrees{}), runner_table<2, false, Derivative>(Degrees{}),
      runner_table<3, false, Derivative>(Degrees{}), runner_table<1, true, Derivative>(Degrees{}),
      runner_table<2, true, Derivative>(Degrees{}),  runner_table<3, true, Derivative>(Degrees{})};
  return tables[static_cast<std::size_t>((rational ? 3 : 0) + d - 1)][static_cast<std::size_t>(p - 1)];
}

CurveData data_of(const BSplineCurve& curve) {
  CurveData c;
  c.knots = curve.knots();
  c.coordinates = curve.control_points().coordinates().data();
  c.weights = curve.is_rational() ? curve.weights().data() : nullptr;
  c.degree = curve.degree();
  c.dimension = curve.dimension();
  return c;
}

/// Points (and derivatives, if non-null) of every parameter, up to the first
/// one outside `allowed` (whose index it returns; us.size() if none).
std::size_t evaluate_batch(const BSplineCurve& curve, std::span<const double> us, double* points, double* derivatives,
                           Interval allowed = {-std::numeric_limits<double>::infinity(),
                                               std::numeric_limits<double>::infinity()}) {
  if (us.empty()) return 0;
  CurveData c = data_of(curve);
  c.allowed = allowed;
  const Runner run = derivatives ? fixed_runner<true>(c.degree, c.dimension, curve.is_rational())
                                 : fixed_runner<false>(c.degree, c.dimension, curve.is_rational());
  return run ? run(c, us, points, derivatives) : scalar_run(c, us, points, derivatives);
}

}  // namespace

void points_at(const BSplineCurve& curve, std::span<const double> us, std::span<double> out) {
  detail::require(out.size() == us.size() * static_cast<std::size_t>(curve.dimension()), "points_at",
                  "out must hold us.size() * dimension() values");
  evaluate_batch(curve, us, out.data(), nullptr);
}

std::size_t points_at_within(const BSplineCurve& curve, std::span<const double> us, Interval allowed,
                             std::span<double> out) {
  detail::require(out.size() == us.size() * static_cast<std::size_t>(curve.dimension()), "points_at_within",
                  "out must hold us.size() * dimension() values");
  return evaluate_batch(curve, us, out.data(), nullptr, allowed);
}

void points_and_derivatives_at(const BSplineCurve& curve, std::span<const double> us, std::span<double> points,
                               std::span<double> derivatives) {
  const std::size_t size = us.size() * static_cast<std::size_t>(curve.dimension());
  detail::require(points.size() == size && derivatives.size() == size, "points_and_derivatives_at",
                  "points and derivatives must each hold us.size() * dimension() values");
  (void)size;
  evaluate_batch(curve, us, points.data(), derivatives.data());
}

void derivatives_at(const BSplineCurve& curve, std::span<const double> us, int order, std::span<double> out) {
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  detail::require(order >= 0, "derivatives_at", "the derivative order must be >= 0");
  detail::require(out.size() == us.size() * d, "derivatives_at", "out must hold us.size() * dimension() values");
  if (order == 0) {
    points_at(curve, us, out);
    return;
  }
  if (order == 1) {
    // The derivative kernel, the points going to a scratch block that is
    // reused chunk by chunk (no allocation).
    const std::size_t kChunk = std::max<std::size_t>(1, 1024 / d);
    detail::Workspace<1024> space;
    const std::span<double> scratch = space.take(kChunk * d);
    for (std::size_t i = 0; i < us.size(); i += kChunk) {
      const std::size_t n = std::min(kChunk, us.size() - i);
      evaluate_batch(curve, us.subspan(i, n), scratch.data(), out.data() + i * d);
    }
    return;
  }
  for (std::size_t i = 0; i < us.size(); ++i) {
    const Point value = derivative_at(curve, us[i], order);
    std::copy(value.begin(), value.end(), out.begin() + static_cast<std::ptrdiff_t>(i * d));
  }
}

}  // namespace casteljau

// Batch evaluation of Bézier curves: de Casteljau across parameters.
//
// Each SIMD lane holds one parameter and performs exactly the scalar
// algorithm of point_at: the same rows (homogeneous if rational), the same
// rounds in the same order, the same lerp_step (fma(t, b, s a) with FMA,
// s a + t b without), the same final division. IEEE operations are
// correctly rounded per lane, so every lane's result equals point_at's bit
// for bit; the speed comes only from doing 8 (AVX-512), 4 (AVX) or 2
// parameters per instruction.
//
// Three paths, all with that arithmetic:
//  - fixed degree 1..kMaxFixedDegree and width (coordinates, +1 if
//    rational) 1..4: the degree is a template argument, the loops unroll and
//    the whole triangle of one coordinate lives in registers (degree 15 needs
//    16 vectors, AVX-512 has 32); the first round reads the control points
//    as broadcast operands; the lanes are interleaved into the caller's
//    (point, coordinate) layout with two-source shuffles.
//  - any other degree or width: the same lanes over a stack triangle (heap
//    above tolerances::kMaxStackDegree: one workspace per call).
//  - the last, partial block of parameters runs the same block code on
//    padded copies, so results do not depend on where a parameter falls.
#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/precondition.hpp"
#include "../core/workspace.hpp"
#include "checked_batch.hpp"
#include "de_casteljau.hpp"
#include "simd_lanes.hpp"

namespace casteljau {
namespace {

/// Degrees up to this get an unrolled kernel each (W3 uses 3, 7 and 15).
constexpr int kMaxFixedDegree = 16;

using namespace detail::simd;


// --- fixed degree and width --------------------------------------------------

/// kLanes parameters ts[0..kLanes) of a curve of degree N >= 1 whose rows
/// (control points, homogeneous if Rational) have W doubles each.
template <int N, int W, bool Rational, bool Streaming = false>
inline void fixed_block(const double* rows, const double* ts, double* out) {
  constexpr int D = Rational ? W - 1 : W;
  const Pack t = load(ts);
  const Pack s = 1.0 - t;
  Pack c[W];
#pragma GCC unroll 4
  for (int j = 0; j < W; ++j) {
    Pack a[N];
#pragma GCC unroll 32
    for (int i = 0; i < N; ++i) a[i] = lerp_first(rows[i * W + j], rows[(i + 1) * W + j], s, t);
#pragma GCC unroll 32
    for (int r = 2; r <= N; ++r)
#pragma GCC unroll 32
      for (int i = 0; i <= N - r; ++i) a[i] = lerp_pack(a[i], a[i + 1], s, t);
    c[j] = a[0];
  }
  if constexpr (Rational) {
    for (int j = 0; j < D; ++j) c[j] = c[j] / c[D];
  }
  store_points<D, Streaming>(c, out);
}

/// The first `count` < kLanes parameters, through a padded block (the padding
/// repeats the last parameter; its results are dropped).
template <int N, int W, bool Rational>
void fixed_partial(const double* rows, const double* ts, std::size_t count, double* out) {
  constexpr int D = Rational ? W - 1 : W;
  if (count == 0) return;
  double t[kLanes], p[kLanes * D];
  for (int l = 0; l < kLanes; ++l) t[l] = ts[std::min<std::size_t>(l, count - 1)];
  fixed_block<N, W, Rational>(rows, t, p);
  std::copy(p, p + count * D, out);
}

template <int N, int W, bool Rational>
void fixed_run(const double* rows, std::span<const double> ts, double* out) {
  constexpr int D = Rational ? W - 1 : W;
  const std::size_t count = ts.size();
  std::size_t k = 0;
  if (kCanStream && count * D * sizeof(double) >= kStreamingBytes) {
    // Streaming stores need aligned packs: the first `head` points go through
    // a partial block so that every later block starts on a pack boundary
    // (impossible only if out is not 16-byte aligned in 2D; then no streaming).
    std::size_t head = 0;
    while (head < kLanes && reinterpret_cast<std::uintptr_t>(out + head * D) % sizeof(Pack) != 0) ++head;
    if (head < kLanes) {
      fixed_partial<N, W, Rational>(rows, ts.data(), head, out);
      for (k = head; k + kLanes <= count; k += kLanes)
        fixed_block<N, W, Rational, true>(rows, ts.data() + k, out + k * D);
      end_streaming();
    }
  }
  for (; k + kLanes <= count; k += kLanes) fixed_block<N, W, Rational>(rows, ts.data() + k, out + k * D);
  fixed_partial<N, W, Rational>(rows, ts.data() + k, count - k, out + k * D);
}

using Runner = void (*)(const double*, std::span<const double>, double*);

template <int W, bool Rational, int... N>
constexpr auto runner_table(std::integer_sequence<int, N...>) {
  return std::array<Runner, sizeof...(N)>{&fixed_run<N + 1, W, Rational>...};
}

/// The unrolled kernel for degree n and width w, or null.
Runner fixed_runner(int n, int width, bool rational) {
  if (n < 1 || n > kMaxFixedDegree) return nullptr;
  using Degrees = std::make_integer_sequence<int, kMaxFixedDegree>;
  static constexpr auto p1 = runner_table<1, false>(Degrees{});
  static constexpr auto p2 = runner_table<2, false>(Degrees{});
  static constexpr auto p3 = runner_table<3, false>(Degrees{});
  static constexpr auto r2 = runner_table<2, true>(Degrees{});
  static constexpr auto r3 = runner_table<3, true>(Degrees{});
  static constexpr auto r4 = runner_table<4, true>(Degrees{});
  const auto& table = rational ? (width == 2 ? r2 : width == 3 ? r3 : r4) : (width == 1 ? p1 : width == 2 ? p2 : p3);
  if (rational ? (width < 2 || width > 4) : (width < 1 || width > 3)) return nullptr;
  return table[n - 1];
}

// --- any degree, any width ----------------------------------------------------

/// kLanes parameters of a curve of any degree n and row width; `work` holds
/// n+1 packs, `c` holds width packs. Writes kLanes points of d coordinates.
void general_block(const double* rows, int n, int width, bool rational, const double* ts, Pack* work, Pack* c,
                   double* out) {
  const int d = rational ? width - 1 : width;
  const Pack t = load(ts);
  const Pack s = 1.0 - t;
  for (int j = 0; j < width; ++j) {
    if (n == 0) {
      for (int l = 0; l < kLanes; ++l) c[j][l] = rows[j];
      continue;
    }
    for (int i = 0; i < n; ++i) work[i] = lerp_first(rows[i * width + j], rows[(i + 1) * width + j], s, t);
    for (int r = 2; r <= n; ++r)
      for (int i = 0; i <= n - r; ++i) work[i] = lerp_pack(work[i], work[i + 1], s, t);
    c[j] = work[0];
  }
  if (rational)
    for (int j = 0; j < d; ++j) c[j] = c[j] / c[d];
  for (int l = 0; l < kLanes; ++l)
    for (int j = 0; j < d; ++j) out[l * d + j] = c[j][l];
}

}  // namespace

void points_at(const BezierCurve& curve, std::span<const double> ts, std::span<double> out) {
  const int d = curve.dimension(), n = curve.degree();
  detail::require(out.size() == ts.size() * static_cast<std::size_t>(d), "points_at",
                  "out must hold ts.size() * dimension() values");
  if (ts.empty()) return;
  const bool rational = curve.is_rational();
  const int width = rational ? d + 1 : d;
  const std::size_t row_count = static_cast<std::size_t>(n + 1) * width;

  // The rows point_at runs de Casteljau on: the control points, or
  // (w P, w) with the same product w * P for rational curves.
  const double* rows = curve.control_points().coordinates().data();
  detail::Workspace<> homogeneous_space;
  if (rational) {
    const std::span<double> homogeneous = homogeneous_space.take(row_count);
    const auto& p = curve.control_points();
    for (int i = 0; i <= n; ++i) {
      const double w = curve.weights()[i];
      for (int j = 0; j < d; ++j) homogeneous[i * width + j] = w * p[i][j];
      homogeneous[i * width + d] = w;
    }
    rows = homogeneous.data();
  }

  if (const Runner run = fixed_runner(n, width, rational)) {
    run(rows, ts, out.data());
    return;
  }

  // General path: n+1 packs of triangle, width packs of result, one block of
  // padded parameters and output for the tail. On the stack up to
  // kMaxStackDegree and small widths, else in one allocation for the call.
  constexpr std::size_t kStackPacks = tolerances::kMaxStackDegree + 1 + 8;
  const std::size_t packs = static_cast<std::size_t>(n + 1) + width;
  const std::size_t tail = static_cast<std::size_t>(kLanes) * (d + 1);
  Pack stack_packs[kStackPacks];
  std::vector<Pack> heap_packs;
  Pack* work = stack_packs;
  if (packs > kStackPacks) {
    heap_packs.resize(packs);
    work = heap_packs.data();
  }
  Pack* c = work + (n + 1);
  detail::Workspace<256> tail_space;
  const std::span<double> tail_buffer = tail_space.take(tail);
  const std::size_t full = ts.size() / kLanes * kLanes;
  for (std::size_t k = 0; k < full; k += kLanes)
    general_block(rows, n, width, rational, ts.data() + k, work, c, out.data() + k * d);
  if (const std::size_t rest = ts.size() - full; rest > 0) {
    double* t = tail_buffer.data();
    double* p = t + kLanes;
    for (int l = 0; l < kLanes; ++l) t[l] = ts[full + std::min<std::size_t>(l, rest - 1)];
    general_block(rows, n, width, rational, t, work, c, p);
    std::copy(p, p + rest * d, out.data() + full * d);
  }
}

std::size_t points_at_within(const BezierCurve& curve, std::span<const double> ts, Interval allowed,
                             std::span<double> out) {
  detail::require(out.size() == ts.size() * static_cast<std::size_t>(curve.dimension()), "points_at_within",
                  "out must hold ts.size() * dimension() values");
  return detail::evaluate_within(ts, allowed, static_cast<std::size_t>(curve.dimension()), out,
                                 [&](std::span<const double> block, std::span<double> rows) {
                                   if (!block.empty()) points_at(curve, block, rows);
                                 });
}

}  // namespace casteljau

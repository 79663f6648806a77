#pragma once
// SIMD lanes for the batch evaluators (src/bezier/points_at.cpp,
// src/bspline/points_at.cpp): one parameter per lane of the widest vector
// the target has, the lerp_step of de_casteljau.hpp lane by lane (so lanes
// compute exactly what the scalar code computes), streaming stores for big
// outputs, and the interleaving of coordinate vectors into the caller's
// (point, coordinate) layout. GCC/clang vector extensions: g++, clang and
// em++ compile it; without SSE2/AVX the portable branches run. Internal to src/.

#include <cstddef>
#include <cstring>
#include <utility>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "de_casteljau.hpp"

namespace casteljau::detail::simd {

// The widest vector the target has: passing wider GCC vectors than the ISA
// supports changes the ABI (and warns), and gains nothing.
#if defined(__AVX512F__)
constexpr int kLanes = 8;
#elif defined(__AVX__)
constexpr int kLanes = 4;
#else
constexpr int kLanes = 2;
#endif

/// kLanes doubles, one parameter each (GCC/clang vector extension: works in
/// g++, clang and em++; operations are elementwise IEEE operations).
typedef double Pack __attribute__((vector_size(kLanes * sizeof(double))));

inline Pack load(const double* p) {
  Pack v;
  std::memcpy(&v, p, sizeof v);  // unaligned load
  return v;
}

/// Whether this target has non-temporal (streaming) vector stores.
#if defined(__AVX512F__) || defined(__AVX__) || defined(__SSE2__)
constexpr bool kCanStream = true;
#else
constexpr bool kCanStream = false;
#endif

/// Outputs at least this large (bytes) are written with streaming stores.
/// A batch this big has overwritten the per-core caches (1-2 MiB of L2 on
/// current x86) before the caller reads its beginning back, so keeping it in
/// cache buys nothing, while ordinary stores first read every output line
/// from memory (read for ownership) and halve the store bandwidth: on the
/// W3 machine 1e6 2D points are written in 3.3 ms with ordinary stores and
/// 1.6 ms with streaming ones. Smaller outputs stay in cache for the caller.
constexpr std::size_t kStreamingBytes = std::size_t{4} << 20;

/// Stores one pack at p; Streaming requires p aligned to sizeof(Pack).
template <bool Streaming = false>
inline void store(double* p, Pack v) {
  if constexpr (Streaming) {
#if defined(__AVX512F__)
    _mm512_stream_pd(p, v);
#elif defined(__AVX__)
    _mm256_stream_pd(p, v);
#elif defined(__SSE2__)
    _mm_stream_pd(p, v);
#else
    std::memcpy(p, &v, sizeof v);
#endif
  } else {
    std::memcpy(p, &v, sizeof v);  // unaligned store
  }
}

/// Orders streaming stores before whatever the caller does next.
inline void end_streaming() {
#if defined(__SSE2__) || defined(__AVX__) || defined(__AVX512F__)
  _mm_sfence();
#endif
}

/// lerp_step lane by lane: the same operations as detail::lerp_step.
inline Pack lerp_pack(Pack a, Pack b, Pack s, Pack t) {
#if defined(__AVX512F__)
  return _mm512_fmadd_pd(t, b, s * a);
#elif defined(__FMA__) && defined(__AVX__)
  return _mm256_fmadd_pd(t, b, s * a);
#elif defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  Pack r;
  for (int l = 0; l < kLanes; ++l) r[l] = detail::lerp_step(a[l], b[l], s[l], t[l]);
  return r;
#else
  // Two statements: a compiler that contracts within one expression
  // (clang's default) must not fuse these into an FMA the scalar code lacks.
  const Pack sa = s * a;
  const Pack tb = t * b;
  return sa + tb;
#endif
}

/// lerp_step with scalar end points (broadcast): the first round, straight
/// from the control points.
inline Pack lerp_first(double a, double b, Pack s, Pack t) {
#if defined(__AVX512F__)
  return _mm512_fmadd_pd(t, _mm512_set1_pd(b), s * a);
#elif defined(__FMA__) && defined(__AVX__)
  return _mm256_fmadd_pd(t, _mm256_set1_pd(b), s * a);
#else
  Pack va, vb;
  for (int l = 0; l < kLanes; ++l) {
    va[l] = a;
    vb[l] = b;
  }
  return lerp_pack(va, vb, s, t);
#endif
}

// --- interleaving lanes into (point, coordinate) order ----------------------
// Output vector V, element E holds global index g = V*kLanes + E, that is
// point g / D, coordinate g % D, found in lane g / D of coordinate vector g % D.

constexpr int point_of(int v, int e, int d) { return (v * kLanes + e) / d; }
constexpr int coordinate_of(int v, int e, int d) { return (v * kLanes + e) % d; }

/// Picks from coordinates 0 and 1 (index into the concatenation c0 ++ c1).
constexpr int from_first_two(int v, int e, int d) {
  return coordinate_of(v, e, d) == 1 ? kLanes + point_of(v, e, d)
         : coordinate_of(v, e, d) == 0 ? point_of(v, e, d) : 0;
}
/// Keeps element e of the partial vector, or picks from coordinate 2.
constexpr int with_third(int v, int e, int d) {
  return coordinate_of(v, e, d) == 2 ? kLanes + point_of(v, e, d) : e;
}

template <int D, bool Streaming, int V, std::size_t... E>
inline void store_vector(const Pack* c, double* out, std::index_sequence<E...>) {
  if constexpr (D == 2) {
    const Pack v = __builtin_shufflevector(c[0], c[1], from_first_two(V, E, 2)...);
    store<Streaming>(out + V * kLanes, v);
  } else {
    static_assert(D == 3);
    const Pack u = __builtin_shufflevector(c[0], c[1], from_first_two(V, E, 3)...);
    const Pack v = __builtin_shufflevector(u, c[2], with_third(V, E, 3)...);
    store<Streaming>(out + V * kLanes, v);
  }
}

template <int D, bool Streaming, std::size_t... V>
inline void store_interleaved(const Pack* c, double* out, std::index_sequence<V...>) {
  (store_vector<D, Streaming, static_cast<int>(V)>(c, out, std::make_index_sequence<kLanes>{}), ...);
}

/// Writes kLanes points of D coordinates: out[l*D + j] = c[j][l].
/// (The two stores are marked for gcovr: at -O0 the shuffle indices, constant
/// expressions, are counted as hundreds of branches per instantiation.)
template <int D, bool Streaming>
[[gnu::always_inline]] inline void store_points(const Pack* c, double* out) {
  if constexpr (D == 1) {
    store<Streaming>(out, c[0]);  // GCOVR_EXCL_BR_LINE
  } else if constexpr (D == 2 || D == 3) {
    store_interleaved<D, Streaming>(c, out, std::make_index_sequence<D>{});  // GCOVR_EXCL_BR_LINE
  } else {
    for (int l = 0; l < kLanes; ++l)
      for (int j = 0; j < D; ++j) out[l * D + j] = c[j][l];
  }
}


/// x in every lane.
inline Pack broadcast(double x) {
#if defined(__AVX512F__)
  return _mm512_set1_pd(x);
#elif defined(__AVX__)
  return _mm256_set1_pd(x);
#elif defined(__SSE2__)
  return _mm_set1_pd(x);
#else
  Pack v;
  for (int l = 0; l < kLanes; ++l) v[l] = x;
  return v;
#endif
}

}  // namespace casteljau::detail::simd

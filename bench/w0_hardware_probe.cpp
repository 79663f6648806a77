// The hardware limits the W1..W6 rows are compared with, measured in the same
// run and on the same pinned core (bench/run.sh runs this binary first):
//
//   HW/fma/<isa>          double-precision FMA throughput: 16 independent
//                         accumulators of the widest vector (AVX-512: 8 lanes,
//                         AVX2: 4, else scalar std::fma), so neither latency
//                         nor loads limit it. items_per_second = FMAs per
//                         second counted per lane (one 8-lane FMA = 8).
//   HW/store-24MB/<how>   store bandwidth into a 24 MB buffer, the size of the
//                         W1 and W5 outputs (10^6 3D points): "streaming" with
//                         non-temporal stores (what casteljau's batches use
//                         above 4 MiB), "ordinary" with plain vector stores.
//                         bytes_per_second is the rate.
//
// bench/report.py turns these into a limit per workload: the lower of
// (FMA rate / FMAs per point) and (store rate / bytes stored per point), with
// the per-point costs of each workload written there. Each row checks what
// it computed (the accumulators' closed form; the buffer's contents) and
// fails if it differs, so an optimized-away loop cannot report a rate.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#if defined(__AVX512F__) || defined(__AVX2__) || defined(__SSE2__)
#include <immintrin.h>
#endif

namespace {

constexpr int kAccumulators = 16;
constexpr std::int64_t kFmaRounds = 4'000'000;   // per iteration: 16 x rounds vector FMAs
constexpr std::size_t kStoreBytes = 24'000'000;  // 10^6 points x 3 doubles
constexpr double kMultiplier = 0.5;              // acc = 0.5 acc + 1 -> 2, exactly, in a few rounds
constexpr double kAddend = 1.0;

#if defined(__AVX512F__)
constexpr const char* kIsa = "avx512";
constexpr int kLanes = 8;
using Vector = __m512d;
inline Vector broadcast(double x) { return _mm512_set1_pd(x); }
inline Vector fma(Vector a, Vector b, Vector c) { return _mm512_fmadd_pd(a, b, c); }
inline double first_lane(Vector v) { return _mm512_cvtsd_f64(v); }
#elif defined(__AVX2__) && defined(__FMA__)
constexpr const char* kIsa = "avx2";
constexpr int kLanes = 4;
using Vector = __m256d;
inline Vector broadcast(double x) { return _mm256_set1_pd(x); }
inline Vector fma(Vector a, Vector b, Vector c) { return _mm256_fmadd_pd(a, b, c); }
inline double first_lane(Vector v) { return _mm256_cvtsd_f64(v); }
#else
constexpr const char* kIsa = "scalar";
constexpr int kLanes = 1;
using Vector = double;
inline Vector broadcast(double x) { return x; }
inline Vector fma(Vector a, Vector b, Vector c) { return std::fma(a, b, c); }
inline double first_lane(Vector v) { return v; }
#endif

/// kFmaRounds rounds of acc_i = 0.5 acc_i + 1 on 16 independent registers.
/// Every accumulator starts at 0 and converges to 2 exactly (0.5 x 2 + 1 is
/// exact), so the result is known without running the loop. The compiler
/// cannot skip rounds (floating-point recurrences are not folded), and with
/// no barrier in the loop the accumulators stay in registers (a barrier such
/// as DoNotOptimize would spill them each round and time the stores).
double run_fma_rounds() {
  Vector acc[kAccumulators];
  for (Vector& a : acc) a = broadcast(0.0);
  const Vector m = broadcast(kMultiplier), b = broadcast(kAddend);
  for (std::int64_t r = 0; r < kFmaRounds; ++r) {
    for (Vector& a : acc) a = fma(a, m, b);
  }
  double sum = 0.0;
  for (const Vector& a : acc) sum += first_lane(a);
  return sum;
}

void fma_row(benchmark::State& state) {
  double sum = 0.0;
  for (auto _ : state) {
    sum = run_fma_rounds();
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kFmaRounds * kAccumulators * kLanes);
  state.counters["lanes"] = kLanes;
  if (sum != 2.0 * kAccumulators)
    state.SkipWithError(("the FMA accumulators sum to " + std::to_string(sum) + ", not their fixed point").c_str());
}

/// A 24 MB buffer aligned for the widest vector.
struct Buffer {
  double* data;
  std::size_t count;
  Buffer() : data(static_cast<double*>(std::aligned_alloc(64, kStoreBytes))), count(kStoreBytes / sizeof(double)) {}
  ~Buffer() { std::free(data); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
};

template <bool Streaming>
void store_all(double* out, std::size_t count, double value) {
#if defined(__AVX512F__)
  const __m512d v = _mm512_set1_pd(value);
  for (std::size_t i = 0; i + 8 <= count; i += 8) {
    if constexpr (Streaming) _mm512_stream_pd(out + i, v); else _mm512_store_pd(out + i, v);
  }
#elif defined(__AVX__)
  const __m256d v = _mm256_set1_pd(value);
  for (std::size_t i = 0; i + 4 <= count; i += 4) {
    if constexpr (Streaming) _mm256_stream_pd(out + i, v); else _mm256_store_pd(out + i, v);
  }
#elif defined(__SSE2__)
  const __m128d v = _mm_set1_pd(value);
  for (std::size_t i = 0; i + 2 <= count; i += 2) {
    if constexpr (Streaming) _mm_stream_pd(out + i, v); else _mm_store_pd(out + i, v);
  }
#else
  for (std::size_t i = 0; i < count; ++i) out[i] = value;
#endif
#if defined(__SSE2__)
  if constexpr (Streaming) _mm_sfence();
#endif
}

template <bool Streaming>
void store_row(benchmark::State& state) {
  Buffer buffer;
  double value = 0.0;
  for (auto _ : state) {
    value += 1.0;  // a different value each pass: no pass can be skipped
    store_all<Streaming>(buffer.data, buffer.count, value);
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(kStoreBytes));
  for (std::size_t i = 0; i < buffer.count; i += 4099) {
    if (buffer.data[i] != value) {
      state.SkipWithError(("the buffer does not hold the last value at index " + std::to_string(i)).c_str());
      return;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RegisterBenchmark((std::string("HW/fma/") + kIsa).c_str(), fma_row)->UseRealTime();
  benchmark::RegisterBenchmark("HW/store-24MB/streaming", store_row<true>)->UseRealTime();
  benchmark::RegisterBenchmark("HW/store-24MB/ordinary", store_row<false>)->UseRealTime();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

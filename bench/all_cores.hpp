#pragma once
// The all-core rows of W1 and W5 (`W1/<order>/casteljau-all-cores`,
// `W5/grid/casteljau-all-cores`): the same batch cut into one contiguous
// chunk per usable CPU, each chunk handed to casteljau's batch function on its
// own thread. bench/run.sh runs each binary twice: pinned to one core for the
// per-core rows, then unpinned with CASTELJAU_BENCH_ALL_CORES=1, when the
// binaries register only their all-core rows.
//
// The threads are started in every iteration (std::jthread): about 0.05 ms
// for two threads against the 2-5 ms of a W1 or W5 batch, a cost a caller
// without a pool pays too.

#include <sched.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

namespace casteljau::bench {

/// Whether this process is the all-core run (CASTELJAU_BENCH_ALL_CORES=1).
inline bool all_cores_run() {
  const char* value = std::getenv("CASTELJAU_BENCH_ALL_CORES");
  return value != nullptr && std::strcmp(value, "1") == 0;
}

/// The CPUs this process may run on (its affinity mask, so `taskset` is
/// honoured), at least 1.
inline int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

/// Calls work(begin, end) on `threads` threads for contiguous chunks covering
/// [0, count); chunk boundaries are multiples of `grain` (so SIMD blocks and
/// grid rows stay whole). Returns when every chunk is done.
template <class Work>
void run_chunks(std::size_t count, std::size_t grain, int threads, const Work& work) {
  const std::size_t blocks = (count + grain - 1) / grain;
  const std::size_t per_thread = (blocks + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads);
  std::vector<std::jthread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) {
    const std::size_t begin = std::min(count, static_cast<std::size_t>(t) * per_thread * grain);
    const std::size_t end = std::min(count, begin + per_thread * grain);
    if (begin < end) pool.emplace_back([&work, begin, end] { work(begin, end); });
  }
}  // the jthreads join here

}  // namespace casteljau::bench

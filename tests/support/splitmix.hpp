#pragma once
// splitmix64 (Steele, Lea & Flood 2014): a fixed, portable stream of random
// numbers for tests and benchmarks. std distributions differ between
// standard libraries; this does not, so seeded data is the same everywhere.

#include <cstdint>

namespace casteljau::test {

struct SplitMix {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1) with 53 random bits.
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }
  /// Uniform in {0, ..., n-1} (n > 0; the modulo bias is below 2^-40 for small n).
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
};

}  // namespace casteljau::test

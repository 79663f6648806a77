#pragma once
// The parameter check of points_at_within for the kinds whose kernels do not
// compare parameters themselves (Bézier, piecewise Bézier): the parameters
// are taken in blocks small enough to stay in L1 cache; each block is
// scanned for the first one outside the interval just before the kernel
// reads it, so the check costs one compare per parameter and no second
// pass over memory. (The B-spline kernel compares inside its SIMD loop:
// src/bspline/points_at.cpp.)
#include <cstddef>
#include <span>

#include "casteljau/core/interval.hpp"

namespace casteljau::detail {

/// Parameters per checked block: 4 KiB of them.
inline constexpr std::size_t kCheckedBlock = 512;

/// Runs evaluate(block, out_block) on the blocks of `us` up to the first
/// parameter outside `allowed`; returns its index, or us.size().
template <class Evaluate>
std::size_t evaluate_within(std::span<const double> us, Interval allowed, std::size_t dimension,
                            std::span<double> out, Evaluate&& evaluate) {
  for (std::size_t start = 0; start < us.size(); start += kCheckedBlock) {
    const std::size_t count = us.size() - start < kCheckedBlock ? us.size() - start : kCheckedBlock;
    std::size_t inside = 0;
    while (inside < count && allowed.contains(us[start + inside])) ++inside;
    evaluate(us.subspan(start, inside), out.subspan(start * dimension, inside * dimension));
    if (inside < count) return start + inside;
  }
  return us.size();
}

}  // namespace casteljau::detail

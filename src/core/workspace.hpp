#pragma once
// Scratch storage for kernels: on the stack up to a fixed size, one heap block
// beyond it (only for degrees above tolerances::kMaxStackDegree or very high
// dimensions). Internal to src/.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace casteljau::detail {

template <std::size_t StackDoubles = 2048>
class Workspace {
 public:
  /// `count` doubles of scratch, valid until the next call or destruction.
  std::span<double> take(std::size_t count) {
    if (count <= StackDoubles) return {stack_.data(), count};
    heap_.resize(count);
    return heap_;
  }

 private:
  std::array<double, StackDoubles> stack_;
  std::vector<double> heap_;
};

}  // namespace casteljau::detail

#pragma once
// Preconditions that protect memory, checked in every build type: an output
// span shorter than the batch it receives, a negative derivative order. They
// are the caller's mistakes, not bad data (that is Expected's job), and an
// unchecked one writes past a buffer; so a failed one prints what was
// required to stderr and aborts, like the misuse of an Expected. One test
// per call, before the kernel's loops, which stay unchecked (the cost is in
// docs/benchmarks.md, "Checks in every build").

#include <cstdio>
#include <cstdlib>

namespace casteljau::detail {

/// Prints "casteljau: <function>: <requirement>" and aborts.
[[noreturn]] inline void precondition_failed(const char* function, const char* requirement) {
  std::fprintf(stderr, "casteljau: %s: %s\n", function, requirement);
  std::fflush(stderr);
  std::abort();
}

/// Aborts with the message unless `holds`.
inline void require(bool holds, const char* function, const char* requirement) {
  if (!holds) [[unlikely]]
    precondition_failed(function, requirement);
}

}  // namespace casteljau::detail

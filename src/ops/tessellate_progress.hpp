#pragma once
// Internal to tessellate (ops/tessellate.hpp): the caller's Progress, called
// at most tolerances::kMeshProgressReports + 1 times with non-decreasing
// fractions, the last one 1. The stages of the work (refinement, each
// assembly pass) map their own fractions into the part of [0, 1] they own.
#include <algorithm>

#include "casteljau/core/progress.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau::tessellation {

/// Throttled, monotone progress of one tessellation.
class TessellationProgress {
 public:
  explicit TessellationProgress(Progress progress) : progress_(progress) {}

  /// `fraction` of the stage [from, to] of the whole work is done.
  void report(double from, double to, double fraction) {
    const double done = std::clamp(from + (to - from) * std::clamp(fraction, 0.0, 1.0), 0.0, 1.0);
    if (done >= 1.0) return finish();
    if (done < last_ + 1.0 / tolerances::kMeshProgressReports) return;
    last_ = done;
    progress_(done);
  }
  /// The work is done: reports 1 (once).
  void finish() {
    if (last_ >= 1.0) return;
    last_ = 1.0;
    progress_(1.0);
  }

 private:
  Progress progress_;
  double last_ = 0.0;
};

}  // namespace casteljau::tessellation

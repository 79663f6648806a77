#pragma once
// A part of a caller's progress: the work of one stage (a panel's curves, one
// gallery figure) reported as its slice [begin, end] of the whole.
// Internal to src/render.

#include <algorithm>

#include "casteljau/core/progress.hpp"

namespace casteljau::render::detail {

/// Reports begin + (end - begin) * fraction, kept inside [begin, end], to
/// `whole`, never less than it reported before (a stage done twice, like a
/// panel flattened again for a refitted frame, reports nothing new until it
/// passes its first round). Parts that share a bound meet exactly there.
class ProgressPart {
 public:
  ProgressPart(Progress whole, double begin, double end) : whole_(whole), begin_(begin), end_(end) {}
  ProgressPart(const ProgressPart&) = delete;
  ProgressPart& operator=(const ProgressPart&) = delete;

  void operator()(double fraction) {
    const double value = std::clamp(begin_ + (end_ - begin_) * fraction, begin_, end_);
    if (value > reported_) reported_ = value, whole_(value);
  }

  /// This part as a Progress for a function that takes one (valid while it lives).
  Progress callback() {
    return Progress{[](void* self, double fraction) { (*static_cast<ProgressPart*>(self))(fraction); }, this};
  }

 private:
  Progress whole_;
  double begin_, end_, reported_ = -1.0;
};

}  // namespace casteljau::render::detail

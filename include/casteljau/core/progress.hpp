#pragma once
// Progress of a long computation (a fine tessellation, a big plot, the
// gallery, a fit of millions of points), reported to whoever called it. The
// core does no I/O: it calls back with the fraction done, and the front end
// decides what to show (cli/progress.hpp: a line on a terminal's stderr once
// the work has run for a second; nothing in a pipe or a test).
#include <algorithm>

namespace casteljau {

/// A caller's progress callback: a plain function and its context (no heap,
/// no exceptions, usable from em++). Called from the computing thread with
/// the fraction done in [0, 1], non-decreasing, at most a few hundred times
/// per computation; a default-constructed Progress does nothing.
struct Progress {
  void (*report)(void* context, double fraction) = nullptr;
  void* context = nullptr;

  void operator()(double fraction) const {
    if (report != nullptr) report(context, fraction);
  }
};

/// One stage of a computation as its slice [begin, end] of a caller's
/// Progress: a fraction f of the stage reports begin + (end - begin) f, kept
/// inside the slice and never below what was reported before (a stage done
/// twice, like a panel flattened again for a refitted frame, reports nothing
/// new until it passes its first round). Reports closer than `step` to the
/// previous one are dropped, except the slice's end, reported once; so a
/// stage of n reports calls the caller at most 1/step + 1 times. Stages that
/// share a bound meet exactly there.
class ProgressPart {
 public:
  ProgressPart(Progress whole, double begin = 0.0, double end = 1.0, double step = 0.0)
      : whole_(whole), begin_(begin), end_(end), step_(step) {}
  ProgressPart(const ProgressPart&) = delete;
  ProgressPart& operator=(const ProgressPart&) = delete;

  /// `fraction` of this stage is done.
  void operator()(double fraction) {
    const double value = std::clamp(begin_ + (end_ - begin_) * fraction, begin_, end_);
    if (value >= end_ ? reported_ < end_ : value > reported_ && value >= reported_ + step_) {
      reported_ = value;
      whole_(value);
    }
  }
  /// `fraction` of the sub-stage [from, to] of this stage (both in [0, 1]) is done.
  void operator()(double from, double to, double fraction) {
    (*this)(from + (to - from) * std::clamp(fraction, 0.0, 1.0));
  }
  /// The stage is done: reports its end (once).
  void finish() { (*this)(1.0); }

  /// This stage as a Progress for a function that takes one (valid while it lives).
  Progress callback() {
    return Progress{[](void* self, double fraction) { (*static_cast<ProgressPart*>(self))(fraction); }, this};
  }

 private:
  Progress whole_;
  double begin_, end_, step_;
  double reported_ = -1.0;
};

}  // namespace casteljau

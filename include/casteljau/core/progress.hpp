#pragma once
// Progress of a long computation (a fine tessellation, a big plot, the
// gallery, a fit of millions of points), reported to whoever called it. The
// core does no I/O: it calls back with the fraction done, and the front end
// decides what to show (cli/progress.hpp: a line on a terminal's stderr once
// the work has run for a second; nothing in a pipe or a test).

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

}  // namespace casteljau

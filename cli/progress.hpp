#pragma once
// Progress of long commands on standard error (docs/cli.md, "Progress"): a
// line "casteljau tessellate: 42 %" rewritten in place, shown only when
// standard error is a terminal and the work has already taken more than a
// second, and erased when the work ends. Pipes, files and tests see nothing,
// unless CASTELJAU_PROGRESS=always (which the CLI tests use to check it).

#include <chrono>
#include <string>

#include "casteljau/core/progress.hpp"

namespace casteljau::cli {

/// Erases the progress line now on the terminal, if any, so that a message
/// (an error, a summary) starts on a clean line; the reporter draws it again
/// at its next update. fail() and write_summary() call it.
void erase_progress_line();

/// Reports one command's progress; erases its line when destroyed. One at a
/// time: a reporter made while another lives takes the line over until it ends.
class TerminalProgress {
 public:
  /// `label` names the work: "tessellate", "gallery: figure 12 of 40".
  explicit TerminalProgress(std::string label);
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;
  ~TerminalProgress();

  /// Shows `fraction` (0..1) done, at most ten times a second.
  void update(double fraction);
  /// A new label for the same line (the next stage of the work).
  void relabel(std::string label);
  /// The library's view of this reporter: pass it to tessellate, plot_figure...
  Progress callback();

  /// Erases this reporter's line if it is shown (erase_progress_line).
  void erase();

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_shown_;
  bool enabled_ = false;
  bool shown_ = false;
  TerminalProgress* previous_ = nullptr;  ///< the reporter this one took the line from
};

}  // namespace casteljau::cli

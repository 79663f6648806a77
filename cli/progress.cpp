// Progress on a terminal's standard error (progress.hpp).
#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace casteljau::cli {
namespace {

/// Work shorter than this shows nothing: a progress line that flashes is noise.
constexpr auto kQuietStart = std::chrono::seconds(1);
/// The line is rewritten at most this often.
constexpr auto kRefresh = std::chrono::milliseconds(100);

/// The reporter that owns the terminal's progress line, if any.
TerminalProgress* active = nullptr;

bool progress_wanted() {
  const char* forced = std::getenv("CASTELJAU_PROGRESS");
  if (forced != nullptr && std::strcmp(forced, "always") == 0) return true;
  if (forced != nullptr && std::strcmp(forced, "never") == 0) return false;
  return ::isatty(STDERR_FILENO) == 1;
}

}  // namespace

void erase_progress_line() {
  if (active != nullptr) active->erase();
}

TerminalProgress::TerminalProgress(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), last_shown_(start_),
      enabled_(progress_wanted()), previous_(active) {
  active = this;
}

TerminalProgress::~TerminalProgress() {
  // Erase the line so that the command's own messages start on a clean one.
  erase();
  active = previous_;
}

void TerminalProgress::erase() {
  if (!shown_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  shown_ = false;
}

void TerminalProgress::relabel(std::string label) { label_ = std::move(label); }

void TerminalProgress::update(double fraction) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < kQuietStart || (shown_ && now - last_shown_ < kRefresh)) return;
  // NaN (a caller's 0/0) shows as 0 %, not "nan %".
  const double percent = fraction >= 0.0 ? std::floor(100.0 * std::min(fraction, 1.0)) : 0.0;
  std::fprintf(stderr, "\r\033[Kcasteljau %s: %.0f %%", label_.c_str(), percent);
  std::fflush(stderr);
  last_shown_ = now;
  shown_ = true;
}

Progress TerminalProgress::callback() {
  return Progress{[](void* self, double fraction) { static_cast<TerminalProgress*>(self)->update(fraction); }, this};
}

}  // namespace casteljau::cli

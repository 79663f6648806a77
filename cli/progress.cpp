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

bool progress_wanted() {
  const char* forced = std::getenv("CASTELJAU_PROGRESS");
  if (forced != nullptr && std::strcmp(forced, "always") == 0) return true;
  if (forced != nullptr && std::strcmp(forced, "never") == 0) return false;
  return ::isatty(STDERR_FILENO) == 1;
}

}  // namespace

TerminalProgress::TerminalProgress(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), last_shown_(start_),
      enabled_(progress_wanted()) {}

TerminalProgress::~TerminalProgress() {
  // Erase the line so that the command's own messages start on a clean one.
  if (shown_) std::fputs("\r\033[K", stderr);
}

void TerminalProgress::relabel(std::string label) { label_ = std::move(label); }

void TerminalProgress::update(double fraction) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < kQuietStart || (shown_ && now - last_shown_ < kRefresh)) return;
  const double percent = std::floor(100.0 * std::clamp(fraction, 0.0, 1.0));
  std::fprintf(stderr, "\r\033[Kcasteljau %s: %.0f %%", label_.c_str(), percent);
  std::fflush(stderr);
  last_shown_ = now;
  shown_ = true;
}

Progress TerminalProgress::callback() {
  return Progress{[](void* self, double fraction) { static_cast<TerminalProgress*>(self)->update(fraction); }, this};
}

}  // namespace casteljau::cli

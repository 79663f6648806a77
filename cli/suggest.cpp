// Mistyped names and their messages (suggest.hpp).
#include "suggest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace casteljau::cli {
namespace {

/// The names of the app's subcommands, in the order they were added.
std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  return names;
}

/// "eval, plot, bernstein": names for a message.
std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

/// The text as a message quotes it: at most 60 characters (a pasted paragraph
/// stays one short line).
std::string shown(std::string_view text) { return std::string(text.substr(0, 60)); }

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows: two back for a transposition.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before[j - 2] + 1);
      }
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& candidates) {
  // Options are compared without their dashes: "--x" is not near "--at".
  const auto bare = [](std::string_view name) {
    return name.substr(std::min(name.find_first_not_of('-'), name.size()));
  };
  const std::string_view typed = bare(word);
  const std::string* best = nullptr;
  std::size_t best_distance = 0;
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(typed, bare(candidate));
    if (best == nullptr || distance < best_distance) {
      best = &candidate;
      best_distance = distance;
    }
  }
  if (best == nullptr) return std::nullopt;
  const std::size_t longer = std::max(typed.size(), bare(*best).size());
  if (best_distance <= std::max<std::size_t>(1, longer / 3)) return *best;
  for (const auto& candidate : candidates) {
    const std::string_view name = bare(candidate);
    const std::string_view shorter = typed.size() < name.size() ? typed : name;
    const std::string_view other = typed.size() < name.size() ? name : typed;
    if (shorter.size() >= 3 && other.substr(0, shorter.size()) == shorter) return candidate;
  }
  return std::nullopt;
}

std::optional<std::string> unknown_subcommand(const CLI::App& app, int argc, const char* const* argv) {
  // The app's own options (--help, --help-all, --version) are flags: the
  // first word that is not an option is where the subcommand must be.
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word.empty() || word[0] == '-') continue;
    const auto names = subcommand_names(app);
    if (std::find(names.begin(), names.end(), word) != names.end()) return std::nullopt;
    if (const auto near = nearest_name(word, names)) {
      return fmt::format("unknown subcommand '{}'; did you mean '{}'?", shown(word), *near);
    }
    return fmt::format("unknown subcommand '{}' (the subcommands: {})", shown(word), listed(names));
  }
  return std::nullopt;
}

std::optional<std::string> unexpected_arguments(const CLI::App& app) {
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  std::vector<const CLI::App*> holders(parsed.begin(), parsed.end());
  holders.push_back(&app);  // the extras of `casteljau --bogus eval ...` are the app's own
  for (const CLI::App* holder : holders) {
    const std::vector<std::string> extras = holder->remaining();
    if (extras.empty()) continue;
    const bool top = holder == &app;
    const std::string name = top ? "casteljau" : holder->get_name();
    const std::string help = top ? "casteljau --help" : "casteljau " + name + " --help";
    for (const auto& extra : extras) {
      if (extra.size() < 2 || extra[0] != '-') continue;
      const std::string option = extra.substr(0, extra.find('='));  // --at=0.5 is --at
      std::optional<std::string> near;
      if (option.rfind("--", 0) == 0) {
        std::vector<std::string> long_names;
        for (const CLI::Option* known : holder->get_options())
          for (const auto& long_name : known->get_lnames()) long_names.push_back("--" + long_name);
        near = nearest_name(option, long_names);
      }
      if (near) return fmt::format("unknown option '{}' for {}; did you mean '{}'?", shown(option), name, *near);
      return fmt::format("unknown option '{}' for {} ({} lists them)", shown(option), name, help);
    }
    if (top) continue;  // a word before the subcommand is unknown_subcommand's
    return fmt::format("unexpected argument '{}' for {} ({} shows its usage)", shown(extras.front()), name, help);
  }
  return std::nullopt;
}

std::string missing_subcommand(const CLI::App& app) {
  return fmt::format("a subcommand is required: {} (casteljau --help says what each does)",
                     listed(subcommand_names(app)));
}

}  // namespace casteljau::cli

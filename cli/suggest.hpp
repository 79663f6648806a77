#pragma once
// Names the user mistyped: the nearest known name by edit distance, and the
// one-line messages for an unknown subcommand or option that use it
// ("unknown subcommand 'evaluate'; did you mean 'eval'?").

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::cli {

/// The number of single-character insertions, deletions, substitutions and
/// transpositions of neighbours that turn `a` into `b`: the optimal string
/// alignment distance (Damerau 1964's edits, Wagner & Fischer 1974's dynamic
/// programme), O(|a| |b|) time, three rows of memory. Bytes, not characters.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate the user most likely meant by `word`, if any is close
/// (leading dashes set aside on both sides): the nearest by edit_distance
/// (the first of equals) when that distance is at most 1 or a third of the
/// longer name, else a candidate that begins with the word or that the word
/// begins with, the shorter of the two having 3 characters or more:
/// "evaluate" -> "eval", "fti" -> "fit", "tesselate" -> "tessellate",
/// "interp" -> "interpolate", "--atx" -> "--at"; "bogus" and "--x" -> none.
std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& candidates);

/// When the first word of the command line that is not an option is not a
/// subcommand of `app`: "unknown subcommand 'evaluate'; did you mean 'eval'?"
/// (or the list of subcommands when none is near). Empty otherwise.
std::optional<std::string> unknown_subcommand(const CLI::App& app, int argc, const char* const* argv);

/// The message for arguments the parsed subcommand, or the app itself, did
/// not expect (after CLI11's ExtrasError or RequiredError): "unknown option
/// '--atx' for eval; did you mean '--at'?", "unknown option '--bogus' for eval
/// (casteljau eval --help lists them)", "unknown option '--verison' for
/// casteljau; did you mean '--version'?", "unexpected argument 'extra' for
/// eval (casteljau eval --help shows its usage)". Empty when no extras are
/// left (CLI11's own message is kept).
std::optional<std::string> unexpected_arguments(const CLI::App& app);

/// "a subcommand is required: eval, plot, ... (casteljau --help says what each does)".
std::string missing_subcommand(const CLI::App& app);

}  // namespace casteljau::cli

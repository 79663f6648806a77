#pragma once
// Small text helpers shared by the io readers (private to src/io).

#include <string>
#include <string_view>

#include "casteljau/core/expected.hpp"

namespace casteljau::io_detail {

/// `text` fit for a one-line error message: control characters, DEL and
/// bytes that are not well-formed UTF-8 are written as \xNN (a stray "\r"
/// or an escaped "\n" in a JSON key must not break the "one line on stderr"
/// rule), and text longer than `limit` bytes is cut, at a character
/// boundary, with "..." (a megabyte of garbage in one field should not
/// become a megabyte of message).
std::string printable(std::string_view text, std::size_t limit = 60);

/// "'text'" after printable().
std::string in_quotes(std::string_view text, std::size_t limit = 60);

/// The code points of UTF-8 text; an error (ErrorKind::parse) names the
/// first byte that is not part of a well-formed sequence (RFC 3629).
Expected<std::u32string> code_points(std::string_view text);

/// Skips a UTF-8 byte order mark at the start of `text` (spreadsheet
/// programs write one).
std::string_view without_byte_order_mark(std::string_view text);

/// True when `path` ends with `extension` (".json"), ignoring ASCII case.
bool has_extension(std::string_view path, std::string_view extension);

}  // namespace casteljau::io_detail

// Model JSON, step 1: the text becomes a JSON document. nlohmann's SAX parser
// drives our own document builder, which knows where it is (for messages),
// refuses duplicate keys (the DOM parser silently keeps the last one) and
// stops early on huge inputs (tolerances::kMaxInputValues values,
// tolerances::kMaxControlPoints elements in one array). No field is checked
// here: that is model_json_values.cpp and the types' make().
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <utility>

#include "model_json_reader.hpp"
#include "text.hpp"

namespace casteljau::io_detail {
namespace {

/// A failure found while parsing, before any field is checked.
struct SyntaxFailure {
  std::size_t offset = 0;  // byte offset of the offending character
  std::string path;        // where in the document, when known
  std::string what;
};

/// The 1-based "line L, column C" of a byte offset; the column counts UTF-8
/// characters (continuation bytes 10xxxxxx are not counted), as editors do.
std::string line_and_column(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  std::size_t column = 1;
  for (std::size_t i = line_start; i < offset; ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++column;
  return fmt::format("line {}, column {}", line, column);
}

class DocumentBuilder {
 public:
  json root;
  std::optional<SyntaxFailure> failure;

  // nlohmann's SAX interface (nlohmann::json_sax<json>), by duck typing.
  bool null() { return add(json(nullptr)); }
  bool boolean(bool value) { return add(json(value)); }
  bool number_integer(json::number_integer_t value) { return add(json(value)); }
  bool number_unsigned(json::number_unsigned_t value) { return add(json(value)); }
  bool number_float(json::number_float_t value, const std::string&) { return add(json(value)); }
  bool string(std::string& value) { return add(json(std::move(value))); }
  bool binary(json::binary_t&) { return fail_here("binary values are not JSON"); }  // never for JSON text
  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& name) {
    Frame& frame = stack_.back();
    if (frame.container->contains(name)) {
      frame.key = name;
      return fail_here("the key " + in_quotes(name) + " appears twice in the same object");
    }
    frame.key = std::move(name);
    return true;
  }
  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& error) {
    // `position` counts the bytes read, the offending one included, so the
    // offending byte is at position - 1 (at the end of the text for an
    // unexpected end of input).
    const std::size_t offset = position > 0 ? position - 1 : 0;
    if (error.id == 406) {  // out_of_range.406: a number beyond the range of double
      // The whole number token has been read: point at its first character.
      const std::size_t start = position >= last_token.size() ? position - last_token.size() : 0;
      failure = SyntaxFailure{start, pending_path(),
                              "the number " + in_quotes(last_token) + " overflows to infinity, numbers must be finite"};
      return false;
    }
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line
    // 1, column 4: syntax error while parsing ...": keep what follows "column N: ".
    std::string_view text = error.what();
    if (const auto column = text.find(", column "); column != text.npos) {
      if (const auto colon = text.find(": ", column); colon != text.npos) text.remove_prefix(colon + 2);
    } else if (const auto bracket = text.find("] "); bracket != text.npos) {
      text.remove_prefix(bracket + 2);
    }
    failure = SyntaxFailure{offset, {}, printable(text, 200)};
    return false;
  }

 private:
  struct Frame {
    json* container;
    std::string key;  // objects: the key of the member being read
  };

  /// Where the next value goes: the path of the value that is about to be
  /// added (failures are found before it is).
  std::string pending_path() const {
    std::string out;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Frame& frame = stack_[i];
      const bool top = i + 1 == stack_.size();
      if (frame.container->is_array()) {
        const std::size_t size = frame.container->size();
        out += fmt::format("[{}]", top ? size : size - 1);
      } else {
        if (!out.empty()) out += '.';
        out += printable(frame.key);
      }
    }
    return out;
  }

  bool fail_here(std::string what) {
    failure = SyntaxFailure{offset_hint_, pending_path(), std::move(what)};
    return false;
  }

  /// Adds a value where the parser is; returns where it lives, or nullptr
  /// when a limit refuses it.
  json* place(json&& value) {
    if (++values_ > tolerances::kMaxInputValues) {
      fail_here(fmt::format("more than {} JSON values, the limit for one model file", tolerances::kMaxInputValues));
      return nullptr;
    }
    if (stack_.empty()) {
      root = std::move(value);
      return &root;
    }
    Frame& frame = stack_.back();
    if (frame.container->is_array()) {
      if (frame.container->size() >= tolerances::kMaxControlPoints) {
        fail_here(
            fmt::format("an array of more than {} elements, the limit for one model", tolerances::kMaxControlPoints));
        return nullptr;
      }
      frame.container->push_back(std::move(value));
      return &frame.container->back();
    }
    json& slot = (*frame.container)[frame.key];
    slot = std::move(value);
    return &slot;
  }

  bool add(json&& value) { return place(std::move(value)) != nullptr; }

  bool open(json&& container) {
    json* where = place(std::move(container));
    if (where == nullptr) return false;
    stack_.push_back(Frame{where, {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  std::vector<Frame> stack_;
  std::size_t values_ = 0;
  // Failures found by the builder itself (duplicate keys, limits) carry no
  // byte offset from the parser; they are reported by path only.
  std::size_t offset_hint_ = std::string_view::npos;
};

}  // namespace

Expected<json> parse_json_document(std::string_view text, const std::string& source) {
  DocumentBuilder builder;
  bool parsed = false;
  try {
    // strict: nothing but blanks may follow the document.
    parsed = json::sax_parse(text.begin(), text.end(), &builder, json::input_format_t::json, true);
  } catch (const json::exception& error) {
    // sax_parse reports through parse_error(); this is only a safety net so
    // that no exception leaves the library.
    return Error{source + ": " + printable(error.what(), 200), ErrorKind::parse};
  }
  if (!parsed) {
    if (!builder.failure) return Error{source + ": the JSON text could not be parsed", ErrorKind::parse};
    const SyntaxFailure& failure = *builder.failure;
    std::string where = source;
    if (failure.offset != std::string_view::npos) where += ", " + line_and_column(text, failure.offset);
    if (!failure.path.empty()) where += ", " + failure.path;
    return Error{where + ": " + failure.what, ErrorKind::parse};
  }
  return std::move(builder.root);
}

}  // namespace casteljau::io_detail

#pragma once
// The lexical layer every SVG attribute reader shares (path data, transform
// lists, points, viewBox, lengths): SVG's white space and comma-wsp, and its
// number grammar (SVG 1.1 §8.3.9, the same for every attribute), each error
// naming the attribute and the character it stops at.

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/csv.hpp"

namespace casteljau::io_detail {

/// SVG's white space (SVG 1.1 wsp: space, tab, LF, CR; SVG 2 adds FF).
inline bool is_svg_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
inline bool is_svg_digit(char c) { return c >= '0' && c <= '9'; }

/// Reads an attribute's text left to right. `label` names the attribute in
/// errors ("path data", "transform", "points"): "<label>, character 12 ('x'):
/// <what>", or "<label>, at its end: <what>".
class SvgScanner {
 public:
  SvgScanner(std::string_view data, std::string_view label) : data_(data), label_(label) {}

  bool done() const { return at_ >= data_.size(); }
  char peek() const { return data_[at_]; }
  std::size_t position() const { return at_; }
  void advance() { ++at_; }
  std::string_view rest() const { return data_.substr(at_); }
  void skip_spaces() {
    while (!done() && is_svg_space(peek())) ++at_;
  }
  /// comma-wsp? of the grammar: spaces, at most one comma, spaces.
  void skip_separator() {
    skip_spaces();
    if (!done() && peek() == ',') {
      ++at_;
      skip_spaces();
    }
  }
  /// True when a number starts here (sign, digit or a point before a digit).
  bool at_number() const {
    if (done()) return false;
    const char c = peek();
    if (is_svg_digit(c)) return true;
    const std::size_t next = at_ + 1;
    if (c == '.') return next < data_.size() && is_svg_digit(data_[next]);
    if (c == '+' || c == '-') {
      if (next >= data_.size()) return false;
      return is_svg_digit(data_[next]) ||
             (data_[next] == '.' && next + 1 < data_.size() && is_svg_digit(data_[next + 1]));
    }
    return false;
  }

  /// number: sign? (digits ('.' digits?)? | '.' digits) exponent?, the
  /// longest such text (so "1.5.5" is 1.5 then .5, "1-2" is 1 then -2).
  /// Errors: "expected a number" (the caller may say what it takes after
  /// it), not finite ("'1e999' overflows to infinity"), beyond
  /// tolerances::kMaxCoordinate.
  Expected<double> number() {
    if (!at_number()) return error("expected a number");
    const std::size_t first = at_;
    if (peek() == '+' || peek() == '-') ++at_;
    while (!done() && is_svg_digit(peek())) ++at_;
    if (!done() && peek() == '.') {
      ++at_;
      while (!done() && is_svg_digit(peek())) ++at_;
    }
    if (!done() && (peek() == 'e' || peek() == 'E')) {
      std::size_t e = at_ + 1;
      if (e < data_.size() && (data_[e] == '+' || data_[e] == '-')) ++e;
      if (e < data_.size() && is_svg_digit(data_[e])) {
        at_ = e;
        while (!done() && is_svg_digit(peek())) ++at_;
      }
    }
    const std::string_view text = data_.substr(first, at_ - first);
    auto value = parse_number(text);
    if (!value) return error_at(first, value.error().message);
    if (std::abs(*value) > tolerances::kMaxCoordinate)
      return error_at(first, fmt::format("'{}' is beyond {:g}, the largest coordinate casteljau takes", text,
                                         tolerances::kMaxCoordinate));
    return *value;
  }

  /// The letters (a-z, A-Z, '%') that follow, as a unit or keyword.
  std::string_view word() {
    const std::size_t first = at_;
    while (!done() && ((peek() >= 'a' && peek() <= 'z') || (peek() >= 'A' && peek() <= 'Z') || peek() == '%'))
      ++at_;
    return data_.substr(first, at_ - first);
  }

  Error error(const std::string& what) const { return error_at(at_, what); }
  Error error_at(std::size_t where, const std::string& what) const {
    if (where >= data_.size()) return Error{fmt::format("{}, at its end: {}", label_, what), ErrorKind::parse};
    const unsigned char c = static_cast<unsigned char>(data_[where]);
    const std::string shown =
        c >= 0x20 && c < 0x7f ? fmt::format("'{}'", static_cast<char>(c)) : fmt::format("byte 0x{:02x}", c);
    return Error{fmt::format("{}, character {} ({}): {}", label_, where + 1, shown, what), ErrorKind::parse};
  }

 private:
  std::string_view data_;
  std::string_view label_;
  std::size_t at_ = 0;
};

}  // namespace casteljau::io_detail

#pragma once
// Expected<T>: the result of anything that reads untrusted data (style rule 5).
// C++20 has no std::expected and the core throws no exceptions (it must build
// with em++ without -fexceptions), so this small value type carries either a
// T or an Error whose message names what is wrong and where.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace casteljau {

/// Why untrusted input was refused: one sentence, "<what>, <where>", e.g.
/// "coordinate 1 of control point 3 is NaN". Front ends print it unchanged.
struct Error {
  std::string message;
};

/// Either a value of type T or an Error. Checked access: value() asserts.
template <class T>
class [[nodiscard]] Expected {
 public:
  Expected(T value) : state_(std::in_place_index<0>, std::move(value)) {}  // NOLINT: implicit by design
  Expected(Error error) : state_(std::in_place_index<1>, std::move(error)) {}  // NOLINT

  bool has_value() const noexcept { return state_.index() == 0; }
  explicit operator bool() const noexcept { return has_value(); }

  const T& value() const& { assert(has_value()); return *std::get_if<0>(&state_); }
  T& value() & { assert(has_value()); return *std::get_if<0>(&state_); }
  T&& value() && { assert(has_value()); return std::move(*std::get_if<0>(&state_)); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  T&& operator*() && { return std::move(*this).value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

  const Error& error() const { assert(!has_value()); return *std::get_if<1>(&state_); }

 private:
  std::variant<T, Error> state_;
};

/// Success or an Error, for operations that return nothing.
template <>
class [[nodiscard]] Expected<void> {
 public:
  Expected() = default;
  Expected(Error error) : error_(std::move(error)), failed_(true) {}  // NOLINT
  bool has_value() const noexcept { return !failed_; }
  explicit operator bool() const noexcept { return !failed_; }
  const Error& error() const { assert(failed_); return error_; }

 private:
  Error error_{};
  bool failed_ = false;
};

using Status = Expected<void>;

/// Prefixes an error's message with where it happened: "in 'x.json': <message>".
inline Error with_context(Error error, const std::string& where) {
  error.message = where + ": " + error.message;
  return error;
}

}  // namespace casteljau

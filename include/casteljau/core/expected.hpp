#pragma once
// Expected<T>: the result of anything that reads untrusted data (style rule 5).
// C++20 has no std::expected and the core throws no exceptions (it must build
// with em++ without -fexceptions), so this small value type carries either a
// T or an Error whose message names what is wrong and where. Its vocabulary
// is C++23's std::expected's: has_value, value, error, value_or, and_then,
// transform, or_else, transform_error, so code moves to the standard type by
// renaming.
//
// Misuse is a program error, not bad input: value() (and *, ->) on an error,
// or error() on a value, prints what was asked and the error's message to
// stderr and aborts, in every build type ("casteljau: Expected::value() on an
// error: weight 2 is -1, weights must be > 0"), where an unchecked access
// would read a variant's other alternative. Not an exception: the library
// builds without them, and a caller that wants to recover tests has_value()
// or uses value_or / or_else.

#include <cassert>  // kept: files that assert have long found it here
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace casteljau {

/// What kind of refusal an Error is, for callers that branch on it (the
/// message stays the thing to show). Every error has exactly one kind.
enum class ErrorKind {
  invalid_argument,  ///< a value or shape the operation does not accept (the default)
  out_of_domain,     ///< a parameter outside the curve's or surface's domain
  parse,             ///< text that is not a valid CSV table, model JSON, number...
  io,                ///< a file that cannot be opened, read or written
  limit,             ///< a size or count beyond casteljau's limits (the tolerance.hpp of core or of the layer)
  singular,          ///< a linear system without a unique solution (interpolation, fits)
};

/// The kind's name as written above ("out_of_domain"), for logs and messages.
constexpr const char* name_of(ErrorKind kind) noexcept {
  switch (kind) {
    case ErrorKind::invalid_argument: return "invalid_argument";
    case ErrorKind::out_of_domain: return "out_of_domain";
    case ErrorKind::parse: return "parse";
    case ErrorKind::io: return "io";
    case ErrorKind::limit: return "limit";
    case ErrorKind::singular: return "singular";
  }
  return "invalid_argument";
}

/// Why untrusted input was refused: one sentence, "<what>, <where>", e.g.
/// "coordinate 1 of control point 3 is NaN", and its kind. Front ends print
/// the message unchanged.
struct Error {
  std::string message;
  ErrorKind kind = ErrorKind::invalid_argument;
};

template <class T>
class Expected;

namespace detail {

/// The misuse of an Expected: what was asked, and the error's message when
/// there is one, on stderr; then abort (every build type).
[[noreturn]] inline void expected_misuse(const char* what, const Error* error) {
  std::fprintf(stderr, "casteljau: %s%s%s\n", what, error ? ": " : "", error ? error->message.c_str() : "");
  std::fflush(stderr);
  std::abort();
}

template <class>
inline constexpr bool is_expected = false;
template <class T>
inline constexpr bool is_expected<Expected<T>> = true;

/// The Expected a transform's function result makes (Expected<void> for void).
template <class U>
using transformed_t = Expected<std::remove_cvref_t<U>>;

}  // namespace detail

/// Either a value of type T or an Error (std::expected<T, Error>'s
/// vocabulary). Access is checked in every build: see the file's comment.
template <class T>
class [[nodiscard]] Expected {
 public:
  using value_type = T;

  Expected(T value) : state_(std::in_place_index<0>, std::move(value)) {}  // NOLINT: implicit by design
  Expected(Error error) : state_(std::in_place_index<1>, std::move(error)) {}  // NOLINT

  bool has_value() const noexcept { return state_.index() == 0; }
  explicit operator bool() const noexcept { return has_value(); }

  /// The value; on an error, aborts with its message.
  const T& value() const& {
    if (!has_value()) detail::expected_misuse("Expected::value() on an error", std::get_if<1>(&state_));
    return *std::get_if<0>(&state_);
  }
  T& value() & {
    if (!has_value()) detail::expected_misuse("Expected::value() on an error", std::get_if<1>(&state_));
    return *std::get_if<0>(&state_);
  }
  /// On a temporary, the value moved out (not a reference into the dying
  /// Expected): `const auto& c = *make(...)` and `for (auto p : *make(...))`
  /// keep it alive instead of dangling.
  T value() && { return std::move(value()); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  T operator*() && { return std::move(value()); }
  /// Member access on a named Expected. Deleted on a temporary: the pointer
  /// would outlive it (`for (double x : make(...)->coordinates())` read freed
  /// memory); name the result, or write make(...).value().member().
  const T* operator->() const& { return &value(); }
  T* operator->() & { return &value(); }
  const T* operator->() const&& = delete;  // dangles: name the result, or .value()

  /// The error; on a value, aborts.
  const Error& error() const {
    if (has_value()) detail::expected_misuse("Expected::error() on a value", nullptr);
    return *std::get_if<1>(&state_);
  }

  /// The value, or `fallback` converted to T on an error.
  template <class U>
  T value_or(U&& fallback) const& {
    return has_value() ? value() : static_cast<T>(std::forward<U>(fallback));
  }
  template <class U>
  T value_or(U&& fallback) && {
    return has_value() ? std::move(value()) : static_cast<T>(std::forward<U>(fallback));
  }

  /// f(value) (an Expected<U>), or this error as an Expected<U>.
  template <class F>
  auto and_then(F&& f) const& {
    using Result = std::remove_cvref_t<std::invoke_result_t<F, const T&>>;
    static_assert(detail::is_expected<Result>, "and_then: the function must return an Expected");
    return has_value() ? std::invoke(std::forward<F>(f), value()) : Result(error());
  }
  template <class F>
  auto and_then(F&& f) && {
    using Result = std::remove_cvref_t<std::invoke_result_t<F, T&&>>;
    static_assert(detail::is_expected<Result>, "and_then: the function must return an Expected");
    return has_value() ? std::invoke(std::forward<F>(f), std::move(value())) : Result(error());
  }

  /// Expected<U>(f(value)) (Expected<void> when f returns nothing), or this error.
  template <class F>
  auto transform(F&& f) const& {
    using Result = detail::transformed_t<std::invoke_result_t<F, const T&>>;
    if (!has_value()) return Result(error());
    if constexpr (std::is_void_v<typename Result::value_type>) {
      std::invoke(std::forward<F>(f), value());
      return Result();
    } else {
      return Result(std::invoke(std::forward<F>(f), value()));
    }
  }
  template <class F>
  auto transform(F&& f) && {
    using Result = detail::transformed_t<std::invoke_result_t<F, T&&>>;
    if (!has_value()) return Result(error());
    if constexpr (std::is_void_v<typename Result::value_type>) {
      std::invoke(std::forward<F>(f), std::move(value()));
      return Result();
    } else {
      return Result(std::invoke(std::forward<F>(f), std::move(value())));
    }
  }

  /// This value, or f(error) (an Expected<T>: a recovery or another error).
  template <class F>
  Expected or_else(F&& f) const& {
    static_assert(std::is_same_v<std::remove_cvref_t<std::invoke_result_t<F, const Error&>>, Expected>,
                  "or_else: the function must return the same Expected");
    return has_value() ? *this : std::invoke(std::forward<F>(f), error());
  }
  template <class F>
  Expected or_else(F&& f) && {
    static_assert(std::is_same_v<std::remove_cvref_t<std::invoke_result_t<F, const Error&>>, Expected>,
                  "or_else: the function must return the same Expected");
    return has_value() ? std::move(*this) : std::invoke(std::forward<F>(f), error());
  }

  /// This value, or the error f(error) (an Error: context added, say).
  template <class F>
  Expected transform_error(F&& f) const& {
    return has_value() ? *this : Expected(Error(std::invoke(std::forward<F>(f), error())));
  }

 private:
  std::variant<T, Error> state_;
};

/// Success or an Error, for operations that return nothing.
template <>
class [[nodiscard]] Expected<void> {
 public:
  using value_type = void;

  Expected() = default;
  Expected(Error error) : error_(std::move(error)), failed_(true) {}  // NOLINT
  bool has_value() const noexcept { return !failed_; }
  explicit operator bool() const noexcept { return !failed_; }

  /// Nothing on success; on an error, aborts with its message.
  void value() const {
    if (failed_) detail::expected_misuse("Expected::value() on an error", &error_);
  }
  /// The error; on success, aborts.
  const Error& error() const {
    if (!failed_) detail::expected_misuse("Expected::error() on a value", nullptr);
    return error_;
  }

  /// f() (an Expected<U>), or this error as an Expected<U>.
  template <class F>
  auto and_then(F&& f) const {
    using Result = std::remove_cvref_t<std::invoke_result_t<F>>;
    static_assert(detail::is_expected<Result>, "and_then: the function must return an Expected");
    return failed_ ? Result(error_) : std::invoke(std::forward<F>(f));
  }
  /// Expected<U>(f()) (Expected<void> when f returns nothing), or this error.
  template <class F>
  auto transform(F&& f) const {
    using Result = detail::transformed_t<std::invoke_result_t<F>>;
    if (failed_) return Result(error_);
    if constexpr (std::is_void_v<typename Result::value_type>) {
      std::invoke(std::forward<F>(f));
      return Result();
    } else {
      return Result(std::invoke(std::forward<F>(f)));
    }
  }
  /// Success, or f(error) (an Expected<void>).
  template <class F>
  Expected or_else(F&& f) const {
    return failed_ ? std::invoke(std::forward<F>(f), error_) : *this;
  }
  /// Success, or the error f(error).
  template <class F>
  Expected transform_error(F&& f) const {
    return failed_ ? Expected(Error(std::invoke(std::forward<F>(f), error_))) : *this;
  }

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

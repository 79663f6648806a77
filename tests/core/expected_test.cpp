// Expected<T>'s std::expected vocabulary (value_or, and_then, transform,
// or_else, transform_error, on values and errors, for T and void) and its
// misuse: value() on an error and error() on a value abort with the message
// in every build type (death tests; this binary is also built without
// assertions, so they do not lean on assert).
#include "casteljau/core/expected.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace casteljau {
namespace {

Expected<int> parse_digit(char c) {
  if (c < '0' || c > '9') return Error{std::string("'") + c + "' is not a digit"};
  return c - '0';
}

Expected<int> reciprocal_percent(int x) {
  if (x == 0) return Error{"0 has no reciprocal"};
  return 100 / x;
}

TEST(Expected, ChainsLikeStdExpected) {
  EXPECT_EQ(parse_digit('4').and_then(reciprocal_percent).value(), 25);
  EXPECT_EQ(parse_digit('0').and_then(reciprocal_percent).error().message, "0 has no reciprocal");
  EXPECT_EQ(parse_digit('x').and_then(reciprocal_percent).error().message, "'x' is not a digit");
  const Expected<std::string> text = parse_digit('7').transform([](int d) { return std::to_string(d * 2); });
  EXPECT_EQ(*text, "14");
  EXPECT_EQ(parse_digit('y').transform([](int d) { return d * 2.0; }).error().message, "'y' is not a digit");
  int seen = 0;
  const Status done = parse_digit('3').transform([&](int d) { seen = d; });
  EXPECT_TRUE(done.has_value());
  EXPECT_EQ(seen, 3);
  EXPECT_EQ(parse_digit('z').value_or(-1), -1);
  EXPECT_EQ(parse_digit('5').value_or(-1), 5);
  EXPECT_EQ(parse_digit('z').or_else([](const Error&) { return Expected<int>(0); }).value(), 0);
  EXPECT_EQ(parse_digit('z').transform_error([](const Error& e) { return with_context(e, "in 'x.json'"); }).error().message,
            "in 'x.json': 'z' is not a digit");
  // Move-only values travel through and_then and transform.
  auto owned = Expected<std::unique_ptr<int>>(std::make_unique<int>(9)).transform([](std::unique_ptr<int> p) {
    return *p + 1;
  });
  EXPECT_EQ(owned.value(), 10);
}

TEST(Expected, VoidChains) {
  const Status ok;
  const Status failed = Error{"the file is empty"};
  EXPECT_EQ(ok.and_then([] { return parse_digit('8'); }).value(), 8);
  EXPECT_EQ(failed.and_then([] { return parse_digit('8'); }).error().message, "the file is empty");
  EXPECT_EQ(ok.transform([] { return 2; }).value(), 2);
  EXPECT_TRUE(failed.or_else([](const Error&) { return Status(); }).has_value());
  EXPECT_EQ(failed.transform_error([](const Error& e) { return with_context(e, "reading") ; }).error().message,
            "reading: the file is empty");
  ok.value();  // success: nothing happens
}

// Each operation on both sides, on a named Expected and on a temporary: a
// value passes through the error handlers untouched, an error through the
// value handlers, and the handler of the other side is never called.
TEST(Expected, EveryOperationOnBothSides) {
  int calls = 0;
  const auto never = [&calls](const Error& e) {
    ++calls;
    return e;
  };
  // A value: or_else and transform_error return it, on a name and a temporary.
  const Expected<int> five = parse_digit('5');
  EXPECT_EQ(five.or_else([&](const Error&) { ++calls; return Expected<int>(0); }).value(), 5);
  EXPECT_EQ(parse_digit('5').or_else([&](const Error&) { ++calls; return Expected<int>(0); }).value(), 5);
  EXPECT_EQ(five.transform_error(never).value(), 5);
  EXPECT_EQ(std::move(parse_digit('6')).value_or(0), 6);
  // An error: and_then and transform keep it, on a temporary and for void results.
  EXPECT_EQ(Expected<std::unique_ptr<int>>(Error{"no value"})
                .and_then([&](std::unique_ptr<int> p) { ++calls; return Expected<int>(*p); })
                .error()
                .message,
            "no value");
  EXPECT_EQ(parse_digit('z').transform([&](int) { ++calls; }).error().message, "'z' is not a digit");
  EXPECT_EQ(Expected<std::unique_ptr<int>>(Error{"gone"}).transform([&](std::unique_ptr<int>) { ++calls; }).error().message,
            "gone");
  EXPECT_EQ(std::move(parse_digit('z')).value_or(-1), -1);
  const Expected<int> bad = parse_digit('q');
  EXPECT_EQ(bad.or_else([](const Error&) { return Expected<int>(7); }).value(), 7);
  // Status: success passes or_else and transform_error; failure passes transform.
  const Status ok, failed = Error{"disk full"};
  EXPECT_TRUE(ok.or_else([&](const Error&) { ++calls; return Status(Error{"x"}); }).has_value());
  EXPECT_TRUE(ok.transform_error(never).has_value());
  EXPECT_EQ(failed.transform([&] { ++calls; }).error().message, "disk full");
  EXPECT_EQ(failed.transform([&] { ++calls; return 1; }).error().message, "disk full");
  int ran = 0;
  EXPECT_TRUE(ok.transform([&] { ++ran; }).has_value());
  EXPECT_TRUE(ok.and_then([&] { ++ran; return Status(); }).has_value());
  EXPECT_EQ(ran, 2);
  EXPECT_EQ(calls, 0);
}

TEST(ExpectedDeathTest, ValueOnAnErrorSaysTheError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH((void)parse_digit('q').value(), "casteljau: Expected::value\\(\\) on an error: 'q' is not a digit");
  EXPECT_DEATH((void)*parse_digit('q'), "Expected::value\\(\\) on an error: 'q' is not a digit");
  EXPECT_DEATH(Status(Error{"no such file"}).value(), "Expected::value\\(\\) on an error: no such file");
  EXPECT_DEATH((void)parse_digit('1').error(), "casteljau: Expected::error\\(\\) on a value");
  EXPECT_DEATH((void)Status().error(), "Expected::error\\(\\) on a value");
}

}  // namespace
}  // namespace casteljau

#pragma once
// Helpers shared by the io tests: a private temporary folder, file writing,
// arbitrary finite doubles (every bit pattern, not a grid), bitwise equality,
// the message of a make() that refuses (what a reader must pass on), and
// model JSON texts read or refused.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <stdlib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/model_numbers.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"

namespace casteljau::test {

/// A fresh folder under the system's temporary folder, removed with its contents.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "casteljau-io-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::uint64_t bits_of(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

/// Any finite double, every bit pattern equally likely (so subnormals, -0,
/// huge and tiny exponents all appear), plus a share of "plain" values.
inline rc::Gen<double> any_finite_double() {
  const auto from_bits = rc::gen::map(rc::gen::arbitrary<std::uint64_t>(), [](std::uint64_t bits) {
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return std::isfinite(x) ? x : 0.5;
  });
  const auto plain = rc::gen::map(rc::gen::inRange(-100000, 100001), [](int i) { return i / 64.0; });
  return rc::gen::oneOf(from_bits, plain,
                        rc::gen::element(0.0, -0.0, 0.1, 1e-320, 1.7976931348623157e308, -2.2250738585072014e-308));
}

/// any_finite_double() within the range of model coordinates (core/
/// model_numbers.hpp, which make() enforces): values beyond it are scaled by
/// 2^-800, exactly, so every mantissa, subnormals and -0 still appear.
inline rc::Gen<double> any_model_coordinate() {
  return rc::gen::map(any_finite_double(), [](double x) { return is_valid_coordinate(x) ? x : std::ldexp(x, -800); });
}

/// A knot of every mantissa and sign, 0 included, its binary exponent folded
/// into [-330, 330): within the range of knots and never closer to 0 than
/// the narrowest knot span (2^-331 > 1e-100), so that sorted random knots are
/// rarely closer together than it.
inline rc::Gen<double> any_model_knot() {
  return rc::gen::map(any_finite_double(), [](double x) {
    int e = 0;
    const double m = std::frexp(x, &e);
    return m == 0.0 ? x : std::ldexp(m, ((e % 660) + 660) % 660 - 330);
  });
}

/// A weight of every mantissa, its binary exponent folded into [-150, 150):
/// within [kMinWeight, kMaxWeight] (2^-151 > 1e-50, 2^150 < 1e50).
inline rc::Gen<double> any_model_weight() {
  return rc::gen::map(any_finite_double(), [](double x) {
    int e = 0;
    const double m = std::frexp(std::abs(x), &e);
    return m == 0.0 ? 1.0 : std::ldexp(m, ((e % 300) + 300) % 300 - 150);
  });
}

/// The message with which `made` (a make() given bad values) refuses them;
/// "accepted" if it did not refuse, which no expectation contains. The
/// readers add only a location to it, so tests compare against it rather
/// than against words that belong to make().
template <class T>
std::string refusal(const Expected<T>& made) {
  return made ? std::string("accepted") : made.error().message;
}

/// The one model of a model JSON text; a test failure (and a one-point curve)
/// when the text is refused or holds another number of models.
inline Model parse_one_model(const std::string& text) {
  auto models = parse_models_json(text, "m.json");
  EXPECT_TRUE(models.has_value()) << (models ? "" : models.error().message);
  if (!models || models->size() != 1) {
    ADD_FAILURE() << "expected one model: " << text;
    return Model{BezierCurve::make(PointArray::from_trusted(1, {0})).value()};
  }
  return models->front();
}

/// The message with which a model JSON text is refused; a test failure (and
/// "") when it is read.
inline std::string json_error(const std::string& text) {
  const auto models = parse_models_json(text, "m.json");
  EXPECT_FALSE(models.has_value()) << text;
  return models ? std::string{} : models.error().message;
}

/// The lines of a text, without their line ends.
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace casteljau::test

// What the surface constructions share (internal): see construction_support.hpp.
#include "construction_support.hpp"

#include <cassert>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "../core/number_text.hpp"

namespace casteljau::detail {

Expected<std::vector<double>> averaged_parameters(const std::vector<PointArray>& lines, Parameterization kind,
                                                  const char* noun) {
  assert(!lines.empty());
  const std::size_t count = lines[0].size();
  assert(count >= 2);
  const std::size_t steps = count - 1;
  std::vector<double> t(count, 0.0);
  if (kind == Parameterization::uniform) {
    for (std::size_t k = 1; k < steps; ++k) t[k] = static_cast<double>(k) / static_cast<double>(steps);
    t[steps] = 1.0;
    return t;
  }
  const bool centripetal = kind == Parameterization::centripetal;
  std::size_t used = 0;
  std::vector<double> step(steps);
  for (const PointArray& line : lines) {
    assert(line.size() == count);
    double total = 0.0;
    for (std::size_t k = 0; k < steps; ++k) {
      const double length = distance(line[k], line[k + 1]);
      step[k] = centripetal ? std::sqrt(length) : length;
      total += step[k];
    }
    if (!(total > 0.0)) continue;
    ++used;
    double running = 0.0;
    for (std::size_t k = 0; k + 1 < steps; ++k) {
      running += step[k];
      t[k + 1] += running / total;
    }
  }
  const std::string what = centripetal ? "centripetal" : "chord-length";
  if (used == 0) {
    return Error{std::string("all the ") + noun + "s coincide, " + what + " parameters need distinct " + noun + "s"};
  }
  for (std::size_t k = 1; k < steps; ++k) t[k] /= static_cast<double>(used);
  t[steps] = 1.0;
  for (std::size_t k = 1; k < count; ++k) {
    if (!(t[k] > t[k - 1])) {
      return Error{std::string(noun) + "s " + std::to_string(k - 1) + " and " + std::to_string(k) + " coincide, " + what +
                   " parameters need distinct " + noun + "s"};
    }
  }
  return t;
}

std::string point_text(std::span<const double> point) {
  std::string text = "(";
  for (std::size_t c = 0; c < point.size(); ++c) {
    if (c > 0) text += ", ";
    text += number_text(point[c]);
  }
  return text + ")";
}

}  // namespace casteljau::detail

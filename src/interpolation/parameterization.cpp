// Parameter values for interpolation (The NURBS Book §9.2.1; Lee 1989).

#include "casteljau/interpolation/parameterization.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "input_checks.hpp"

namespace casteljau {

namespace {

// |P_b − P_a| / scale: dividing by the scale first keeps the squares away
// from overflow (coordinates near 1e200) and underflow (near 1e-200); the
// common factor cancels when the steps are normalized.
double scaled_distance(std::span<const double> a, std::span<const double> b, double inverse_scale) {
  double sum = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double difference = (b[k] - a[k]) * inverse_scale;
    sum += difference * difference;
  }
  return std::sqrt(sum);
}

// The two points of step i; the closing step of a closed set runs from the
// last point back to the first.
std::string step_name(std::size_t i, std::size_t count, bool closed) {
  if (closed && i + 1 == count) return "the last point " + std::to_string(i) + " and the first point 0";
  return "points " + std::to_string(i) + " and " + std::to_string(i + 1);
}

/// The cumulative steps into parameters[1..], computed on coordinates
/// divided by their scale (no overflow near 1e300, no underflow near
/// 1e-300; the common factor cancels when the steps are normalized), after
/// checking that every coordinate is finite and no step is zero.
Status scaled_steps(const PointArray& points, Parameterization kind, bool closed, std::vector<double>& parameters) {
  if (auto finite = detail::check_coordinates(points); !finite) return finite.error();
  const std::size_t count = points.size();
  const std::size_t steps = closed ? count : count - 1;
  const double scale = scale_of(points);
  if (scale == 0.0) {
    return Error{step_name(0, count, closed) + " coincide, " + std::string(name_of(kind)) +
                 " parameters need distinct consecutive points"};
  }
  const double inverse_scale = 1.0 / scale;
  double total = 0.0;
  for (std::size_t i = 0; i < steps; ++i) {
    const std::size_t next = (i + 1) % count;
    const double length = scaled_distance(points[i], points[next], inverse_scale);
    if (length == 0.0) {
      return Error{step_name(i, count, closed) + " coincide, " + std::string(name_of(kind)) +
                   " parameters need distinct consecutive points"};
    }
    total += kind == Parameterization::centripetal ? std::sqrt(length) : length;
    parameters[i + 1] = total;
  }
  return {};
}

}  // namespace

std::string_view name_of(Parameterization kind) noexcept {
  switch (kind) {
    case Parameterization::uniform: return "uniform";
    case Parameterization::chord_length: return "chord";
    case Parameterization::centripetal: return "centripetal";
  }
  return "uniform";
}

Expected<Parameterization> parameterization_from_name(std::string_view name) {
  if (name == "uniform") return Parameterization::uniform;
  if (name == "chord" || name == "chord-length") return Parameterization::chord_length;
  if (name == "centripetal") return Parameterization::centripetal;
  return Error{"unknown parameterization '" + std::string(name) +
               "', expected uniform, chord (or chord-length) or centripetal"};
}

Expected<std::vector<double>> parameter_values(const PointArray& points, Parameterization kind, Closure closure) {
  const bool closed = closure == Closure::closed;
  const std::size_t count = points.size();
  if (count < 2) {
    return Error{"interpolation needs at least 2 points, got " + std::to_string(count)};
  }
  const std::size_t steps = closed ? count : count - 1;
  std::vector<double> parameters(steps + 1, 0.0);
  if (kind == Parameterization::uniform) {
    if (auto finite = detail::check_coordinates(points); !finite) return finite.error();
    for (std::size_t i = 1; i < steps; ++i) parameters[i] = static_cast<double>(i) / static_cast<double>(steps);
    parameters[steps] = 1.0;
    return parameters;
  }
  // One pass in the common case: plain squared distances, as long as each
  // sum of squares is a normal number (neither zero, subnormal, infinite nor
  // NaN). Coincident points, NaN, infinities and lengths beyond 1e±150 fall
  // to the careful pass below, which checks, scales and names the culprit.
  const std::size_t d = static_cast<std::size_t>(points.dimension());
  const double* const coordinates = points.coordinates().data();
  const bool centripetal = kind == Parameterization::centripetal;
  double total = 0.0;
  bool plain = true;
  for (std::size_t i = 0; i < steps && plain; ++i) {
    const double* const a = coordinates + i * d;
    const double* const b = i + 1 == count ? coordinates : a + d;
    double sum = 0.0;
    for (std::size_t k = 0; k < d; ++k) sum += (b[k] - a[k]) * (b[k] - a[k]);
    plain = std::isnormal(sum);
    const double length = std::sqrt(sum);
    total += centripetal ? std::sqrt(length) : length;
    parameters[i + 1] = total;
  }
  if (!plain || !std::isfinite(total)) {
    if (auto careful = scaled_steps(points, kind, closed, parameters); !careful) return careful.error();
    total = parameters[steps];
  }
  for (std::size_t i = 1; i < steps; ++i) {
    parameters[i] /= total;
    // A step below one ulp of the total length cannot be told apart from
    // its neighbour: refuse rather than hand the solver equal parameters.
    if (!(parameters[i] > parameters[i - 1])) {
      return Error{step_name(i - 1, count, closed) + " are too close together (" +
                   std::string(name_of(kind)) + " step below the rounding of the total length)"};
    }
  }
  parameters[steps] = 1.0;
  if (!(parameters[steps] > parameters[steps - 1])) {
    return Error{step_name(steps - 1, count, closed) + " are too close together (" +
                 std::string(name_of(kind)) + " step below the rounding of the total length)"};
  }
  return parameters;
}

Expected<std::vector<double>> function_parameters(const PointArray& points) {
  if (points.dimension() < 2) {
    return Error{"a function y(x) needs at least 2 columns (x and y), got " + std::to_string(points.dimension())};
  }
  if (points.size() < 2) {
    return Error{"interpolation needs at least 2 points, got " + std::to_string(points.size())};
  }
  std::vector<double> parameters(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i][0];
    if (!std::isfinite(x)) {
      return Error{"x of point " + std::to_string(i) + " is " + (std::isnan(x) ? "NaN" : "infinite")};
    }
    if (i > 0 && !(x > parameters[i - 1])) {
      return Error{"x must increase strictly: point " + std::to_string(i) + " has x = " + detail::number_text(x) +
                   ", point " + std::to_string(i - 1) + " has x = " + detail::number_text(parameters[i - 1])};
    }
    parameters[i] = x;
  }
  return parameters;
}

PointArray without_closing_duplicate(const PointArray& points) {
  const std::size_t count = points.size();
  if (count < 2) return points;
  const double gap = distance(points[0], points[count - 1]);
  if (!(gap <= tolerances::kJointRelativeGap * std::max(scale_of(points), tolerances::kScaleFloor))) return points;
  std::vector<double> kept(points.coordinates().begin(),
                           points.coordinates().end() - points.dimension());
  return PointArray::from_trusted(points.dimension(), std::move(kept));
}

}  // namespace casteljau

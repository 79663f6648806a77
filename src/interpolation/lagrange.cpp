// Barycentric Lagrange interpolation (Berrut & Trefethen 2004) and its
// conversion to a Bézier curve (see lagrange.hpp).
#include "casteljau/interpolation/lagrange.hpp"
#include "casteljau/interpolation/tolerance.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

#include "../core/number_text.hpp"
#include "input_checks.hpp"

namespace casteljau {
namespace {

constexpr std::size_t kMaxNodes = static_cast<std::size_t>(tolerances::kMaxLagrangeDegree) + 1;

// w_j = 1 / Π_{k≠j} (t_j − t_k), scaled so that max |w_j| = 1. Each product
// is kept as a mantissa in [0.5, 1) and a binary exponent: for n in the
// thousands the plain product over- or underflows (Berrut & Trefethen §3
// rescale by 4/(b − a); the exponent bookkeeping makes that unnecessary).
std::vector<double> product_weights(std::span<const double> nodes) {
  const std::size_t count = nodes.size();
  std::vector<double> mantissas(count);
  std::vector<long> exponents(count);
  for (std::size_t j = 0; j < count; ++j) {
    double mantissa = 1.0;
    long exponent = 0;
    for (std::size_t k = 0; k < count; ++k) {
      if (k == j) continue;
      int e = 0;
      mantissa = std::frexp(mantissa * (nodes[j] - nodes[k]), &e);
      exponent += e;
    }
    mantissas[j] = mantissa;
    exponents[j] = exponent;
  }
  // The largest weight has the smallest product.
  const long smallest = *std::min_element(exponents.begin(), exponents.end());
  std::vector<double> weights(count);
  double largest = 0.0;
  for (std::size_t j = 0; j < count; ++j) {
    const long shift = smallest - exponents[j];  // <= 0
    weights[j] = shift < -2000 ? 0.0 : std::ldexp(1.0 / mantissas[j], static_cast<int>(shift));
    largest = std::max(largest, std::abs(weights[j]));
  }
  for (double& w : weights) w /= largest;
  return weights;
}

// Σ w_j P_j/(t − t_j) / Σ w_j/(t − t_j) into out (d values).
void evaluate(const BarycentricInterpolant& interpolant, double t, double* out) {
  const std::size_t d = static_cast<std::size_t>(interpolant.values.dimension());
  const std::size_t count = interpolant.nodes.size();
  assert(count >= 1 && interpolant.weights.size() == count && interpolant.values.size() == count);
  for (std::size_t j = 0; j < count; ++j) {
    if (t == interpolant.nodes[j]) {
      std::copy_n(interpolant.values[j].data(), d, out);
      return;
    }
  }
  std::fill_n(out, d, 0.0);
  double denominator = 0.0;
  for (std::size_t j = 0; j < count; ++j) {
    const double c = interpolant.weights[j] / (t - interpolant.nodes[j]);
    if (!std::isfinite(c)) {  // t within an underflow of t_j: p(t) = P_j to double precision
      std::copy_n(interpolant.values[j].data(), d, out);
      return;
    }
    const auto value = interpolant.values[j];
    for (std::size_t k = 0; k < d; ++k) out[k] += c * value[k];
    denominator += c;
  }
  for (std::size_t k = 0; k < d; ++k) out[k] /= denominator;
}

}  // namespace

Expected<std::vector<double>> chebyshev_parameters(std::size_t count, Interval domain) {
  if (count < 2) return Error{"Chebyshev parameters need a count of at least 2, got " + std::to_string(count)};
  if (count > kMaxNodes)
    return Error{"Chebyshev parameters: count " + std::to_string(count) + " is above the limit of " +
                 std::to_string(kMaxNodes), ErrorKind::limit};
  if (!std::isfinite(domain.lower) || !std::isfinite(domain.upper) || !(domain.lower < domain.upper))
    return Error{"Chebyshev parameters need a finite interval with lower < upper, got [" +
                 detail::number_text(domain.lower) + ", " + detail::number_text(domain.upper) + "]"};
  const double n = static_cast<double>(count - 1);
  const double middle = 0.5 * domain.lower + 0.5 * domain.upper;  // no overflow for huge ends
  const double half = 0.5 * domain.upper - 0.5 * domain.lower;
  std::vector<double> parameters(count);
  for (std::size_t j = 0; j < count; ++j)
    parameters[j] = middle + half * std::sin(std::numbers::pi * (2.0 * static_cast<double>(j) - n) / (2.0 * n));
  parameters.front() = domain.lower;
  parameters.back() = domain.upper;
  return parameters;
}

Expected<BarycentricInterpolant> interpolate_lagrange(const PointArray& points, std::span<const double> parameters) {
  const std::size_t count = points.size();
  if (count < 2) return Error{"Lagrange interpolation needs at least 2 points, got " + std::to_string(count)};
  if (count > kMaxNodes)
    return Error{"Lagrange interpolation of " + std::to_string(count) + " points is above the limit of " +
                 std::to_string(kMaxNodes) + " (degree " + std::to_string(tolerances::kMaxLagrangeDegree) + ")", ErrorKind::limit};
  if (parameters.size() != count)
    return Error{"Lagrange interpolation needs one parameter per point: " + std::to_string(count) + " points, " +
                 std::to_string(parameters.size()) + " parameters"};
  if (auto increasing = detail::check_increasing(parameters); !increasing) return increasing.error();
  if (auto finite = detail::check_coordinates(points); !finite) return finite.error();
  // Differences of the nodes stay finite: check_increasing keeps each within
  // +-tolerances::kMaxKnot.

  BarycentricInterpolant result;
  result.nodes.assign(parameters.begin(), parameters.end());
  result.values = points;
  const auto chebyshev = chebyshev_parameters(count, {parameters.front(), parameters.back()});
  if (chebyshev && std::equal(chebyshev->begin(), chebyshev->end(), parameters.begin())) {
    result.weights.resize(count);
    for (std::size_t j = 0; j < count; ++j) result.weights[j] = (j % 2 == 0 ? 1.0 : -1.0);
    result.weights.front() *= 0.5;
    result.weights.back() *= 0.5;
  } else {
    result.weights = product_weights(parameters);
  }
  return result;
}

Point point_at(const BarycentricInterpolant& interpolant, double t) {
  Point point(static_cast<std::size_t>(interpolant.values.dimension()));
  evaluate(interpolant, t, point.data());
  return point;
}

void points_at(const BarycentricInterpolant& interpolant, std::span<const double> ts, std::span<double> out) {
  const std::size_t d = static_cast<std::size_t>(interpolant.values.dimension());
  assert(out.size() == ts.size() * d);
  for (std::size_t i = 0; i < ts.size(); ++i) evaluate(interpolant, ts[i], out.data() + i * d);
}

Expected<BezierCurve> to_bezier(const BarycentricInterpolant& interpolant) {
  const int n = static_cast<int>(interpolant.nodes.size()) - 1;
  if (n > tolerances::kMaxLagrangeBezierDegree)
    return Error{"converting a Lagrange interpolant of degree " + std::to_string(n) +
                 " to a Bézier curve is refused above degree " +
                 std::to_string(tolerances::kMaxLagrangeBezierDegree) +
                 " (the Bernstein-Vandermonde system is too ill-conditioned); evaluate it in barycentric form"};
  const int d = interpolant.values.dimension();
  if (n == 0) return BezierCurve::from_trusted(interpolant.values);  // a constant
  const Interval domain = interpolant.domain();
  // Sample p at the Chebyshev points s_j of [0, 1], whatever the nodes: the
  // Bernstein-Vandermonde matrix there is far better conditioned than at
  // equispaced nodes (Runge at n = 40: 6e-9 against 8e-2 relative error),
  // and the barycentric values are accurate to the interpolant's own condition.
  const std::vector<double> samples = chebyshev_parameters(static_cast<std::size_t>(n) + 1).value();
  // A(j, k) = B_{n,k}(s_j), by the de Casteljau-like triangle of the basis
  // (B_{r,k} = (1 − s) B_{r−1,k} + s B_{r−1,k−1}): no binomials, no powers.
  Eigen::MatrixXd basis(n + 1, n + 1);
  std::vector<double> row(static_cast<std::size_t>(n) + 1);
  for (int j = 0; j <= n; ++j) {
    const double s = samples[static_cast<std::size_t>(j)];
    std::fill(row.begin(), row.end(), 0.0);
    row[0] = 1.0;
    for (int r = 1; r <= n; ++r)
      for (int k = r; k >= 0; --k) row[k] = (1.0 - s) * row[k] + (k > 0 ? s * row[k - 1] : 0.0);
    for (int k = 0; k <= n; ++k) basis(j, k) = row[static_cast<std::size_t>(k)];
  }
  Eigen::MatrixXd values(n + 1, d);
  std::vector<double> point(static_cast<std::size_t>(d));
  for (int j = 0; j <= n; ++j) {
    evaluate(interpolant, domain.lerp(samples[static_cast<std::size_t>(j)]), point.data());
    for (int k = 0; k < d; ++k) values(j, k) = point[static_cast<std::size_t>(k)];
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(basis);
  Eigen::MatrixXd control = lu.solve(values);
  // Iterative refinement: the residual at the samples is what the curve
  // misses there; two rounds bring it to the rounding of the basis evaluation.
  for (int round = 0; round < 2; ++round) control += lu.solve(values - basis * control);
  std::vector<double> coordinates(static_cast<std::size_t>((n + 1) * d));
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k < d; ++k) {
      const double c = control(i, k);
      if (!std::isfinite(c))
        return Error{"the Bézier control points of the Lagrange interpolant overflow (control point " +
                     std::to_string(i) + ")"};
      coordinates[static_cast<std::size_t>(i * d + k)] = c;
    }
  // The ends are interpolated exactly by definition: keep the data there.
  for (int k = 0; k < d; ++k) {
    coordinates[static_cast<std::size_t>(k)] = interpolant.values[0][static_cast<std::size_t>(k)];
    coordinates[static_cast<std::size_t>(n * d + k)] = interpolant.values[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)];
  }
  return BezierCurve::from_trusted(PointArray::from_trusted(d, std::move(coordinates)));
}

}  // namespace casteljau

// B-spline basis functions (The NURBS Book, chapter 2).
#include "casteljau/bspline/basis.hpp"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

#include "../core/workspace.hpp"
#include "casteljau/core/precondition.hpp"

namespace casteljau {

int find_span(std::span<const double> knots, int degree, double u) {
  assert(degree >= 0 && knots.size() >= 2 * static_cast<std::size_t>(degree) + 2);
  const int p = degree;
  const int n = static_cast<int>(knots.size()) - p - 2;
  // Below the domain (and NaN, which then evaluates to NaN): the first
  // non-empty span, so the first polynomial piece extrapolates.
  if (!(u >= knots[p])) {
    int i = p;
    while (knots[i] == knots[i + 1]) ++i;
    return i;
  }
  // At or beyond the end: the last non-empty span, closed at the end of the
  // domain. Testing u == t_{n+1} alone would pick the empty span after it
  // when the end knot is repeated (clamped knots), where every basis
  // function is zero: the bug this branch exists for.
  if (u >= knots[n + 1]) {
    int i = n;
    while (knots[i] == knots[i + 1]) --i;
    return i;
  }
  // t_p <= u < t_{n+1}: the first knot greater than u lies in (p, n+1], and
  // the one before it starts a non-empty span containing u (A2.1's bisection).
  const auto first = knots.begin() + p + 1;
  const auto last = knots.begin() + n + 2;
  return static_cast<int>(std::upper_bound(first, last, u) - knots.begin()) - 1;
}

void basis_functions(std::span<const double> knots, int degree, int span, double u, std::span<double> out) {
  const int p = degree;
  detail::require(p >= 0 && out.size() == static_cast<std::size_t>(p) + 1, "basis_functions",
                  "out must hold degree + 1 values");
  detail::require(span >= p && static_cast<std::size_t>(span) + static_cast<std::size_t>(p) < knots.size(),
                  "basis_functions", "span must index a knot interval with degree knots on each side");
  detail::Workspace<512> workspace;
  const std::span<double> scratch = workspace.take(2 * static_cast<std::size_t>(p) + 2);
  double* left = scratch.data();
  double* right = scratch.data() + p + 1;
  out[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - knots[span + 1 - j];
    right[j] = knots[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      // right[r+1] + left[j-r] = t_{span+r+1} - t_{span+1-j+r}: a knot
      // difference that contains the non-empty span, so never zero.
      const double temp = out[r] / (right[r + 1] + left[j - r]);
      out[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    out[j] = saved;
  }
}

void basis_function_derivatives(std::span<const double> knots, int degree, int span, double u, int order,
                                std::span<double> out) {
  const int p = degree;
  const std::size_t width = static_cast<std::size_t>(p) + 1;
  detail::require(p >= 0 && order >= 0 && out.size() == (static_cast<std::size_t>(order) + 1) * width,
                  "basis_function_derivatives", "order must be >= 0 and out must hold (order + 1) * (degree + 1) values");
  detail::require(span >= p && static_cast<std::size_t>(span) + static_cast<std::size_t>(p) < knots.size(),
                  "basis_function_derivatives", "span must index a knot interval with degree knots on each side");
  detail::Workspace<1024> workspace;
  const std::span<double> scratch = workspace.take(width * width + 4 * width);
  // ndu, (p+1) x (p+1) as in A2.3: its upper triangle ndu[r][j] (r <= j)
  // holds the basis functions of degree j, N_{span-j+r, j}(u); its strict
  // lower triangle ndu[j][r] (r < j) the knot differences right[r+1] + left[j-r].
  double* ndu = scratch.data();
  double* left = ndu + width * width;
  double* right = left + width;
  double* a0 = right + width;
  double* a1 = a0 + width;
  const auto at = [&](int row, int column) -> double& { return ndu[static_cast<std::size_t>(row) * width + column]; };
  at(0, 0) = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - knots[span + 1 - j];
    right[j] = knots[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      at(j, r) = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = at(r, j - 1) / at(j, r);
      at(r, j) = saved + right[r + 1] * temp;  // upper triangle: basis values
      saved = left[j - r] * temp;
    }
    at(j, j) = saved;
  }
  std::fill(out.begin(), out.end(), 0.0);
  for (int j = 0; j <= p; ++j) out[j] = at(j, p);
  // Derivatives (A2.3): a0/a1 hold the coefficients of the current and the
  // previous order, swapped each round.
  for (int r = 0; r <= p; ++r) {
    double* previous = a0;
    double* current = a1;
    previous[0] = 1.0;
    for (int k = 1; k <= std::min(order, p); ++k) {
      double d = 0.0;
      const int rk = r - k;
      const int pk = p - k;
      if (r >= k) {
        current[0] = previous[0] / at(pk + 1, rk);
        d = current[0] * at(rk, pk);
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = r - 1 <= pk ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        current[j] = (previous[j] - previous[j - 1]) / at(pk + 1, rk + j);
        d += current[j] * at(rk + j, pk);
      }
      if (r <= pk) {
        current[k] = -previous[k - 1] / at(pk + 1, r);
        d += current[k] * at(r, pk);
      }
      out[static_cast<std::size_t>(k) * width + r] = d;
      std::swap(previous, current);
    }
  }
  // Multiply by p!/(p-k)!.
  double factor = p;
  for (int k = 1; k <= std::min(order, p); ++k) {
    for (std::size_t j = 0; j < width; ++j) out[static_cast<std::size_t>(k) * width + j] *= factor;
    factor *= p - k;
  }
}

double basis_function(std::span<const double> knots, int degree, int index, double u) {
  const int p = degree;
  const int n = static_cast<int>(knots.size()) - p - 2;
  assert(index >= 0 && index <= n);
  const std::size_t i = static_cast<std::size_t>(index);
  // N_{i,p} is supported on [t_i, t_{i+p+1}] (The NURBS Book P2.1).
  if (!(u >= knots[i] && u <= knots[i + static_cast<std::size_t>(p) + 1])) return 0.0;
  // Degree 0, half-open, except at the end of the domain t_{n+1}, which
  // belongs to the last non-empty span (the convention of find_span).
  int last_span = n;
  while (knots[static_cast<std::size_t>(last_span)] == knots[static_cast<std::size_t>(last_span) + 1]) --last_span;
  const bool at_end = u == knots[static_cast<std::size_t>(last_span) + 1];
  std::vector<double> values(static_cast<std::size_t>(p) + 1);  // for figures and tests: one allocation is fine
  for (int j = 0; j <= p; ++j) {
    const std::size_t k = i + static_cast<std::size_t>(j);
    const bool on = at_end ? static_cast<int>(k) == last_span : (knots[k] <= u && u < knots[k + 1]);
    values[static_cast<std::size_t>(j)] = on ? 1.0 : 0.0;
  }
  // The triangle of A2.4: raise the degree one step at a time, skipping the
  // 0/0 terms of repeated knots (their functions are zero).
  for (int k = 1; k <= p; ++k) {
    const double first_width = knots[i + static_cast<std::size_t>(k)] - knots[i];
    double saved = values[0] == 0.0 ? 0.0 : (u - knots[i]) * values[0] / first_width;
    for (int j = 0; j <= p - k; ++j) {
      const double left = knots[i + static_cast<std::size_t>(j) + 1];
      const double right = knots[i + static_cast<std::size_t>(j + k) + 1];
      const double next = values[static_cast<std::size_t>(j) + 1];
      if (next == 0.0) {
        values[static_cast<std::size_t>(j)] = saved;
        saved = 0.0;
      } else {
        const double temp = next / (right - left);
        values[static_cast<std::size_t>(j)] = saved + (right - u) * temp;
        saved = (u - left) * temp;
      }
    }
  }
  return values[0];
}

}  // namespace casteljau

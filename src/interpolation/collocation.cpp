// Collocation systems of B-spline interpolation (see collocation.hpp).
#include "collocation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "../core/number_text.hpp"
#include "banded_system.hpp"
#include "input_checks.hpp"
#include "casteljau/bspline/basis.hpp"

namespace casteljau::detail {

namespace {

/// column < 0: the singularity showed only as non-finite results.
std::string singular_message(long column) {
  return "the interpolation system is singular" +
         (column >= 0 ? " at unknown " + std::to_string(column) : std::string()) +
         " (the parameters or end conditions do not determine the spline)";
}

/// Solves the small dense system M X = R in place (K x K, K x width, both
/// row-major) by Gaussian elimination with partial pivoting. False when M is
/// singular.
bool solve_dense(std::vector<double>& matrix, std::vector<double>& rhs, std::size_t size, std::size_t width) {
  for (std::size_t j = 0; j < size; ++j) {
    std::size_t pivot = j;
    for (std::size_t i = j + 1; i < size; ++i)
      if (std::abs(matrix[i * size + j]) > std::abs(matrix[pivot * size + j])) pivot = i;
    if (!(std::abs(matrix[pivot * size + j]) > 0.0)) return false;
    if (pivot != j) {
      for (std::size_t k = 0; k < size; ++k) std::swap(matrix[j * size + k], matrix[pivot * size + k]);
      for (std::size_t k = 0; k < width; ++k) std::swap(rhs[j * width + k], rhs[pivot * width + k]);
    }
    for (std::size_t i = j + 1; i < size; ++i) {
      const double l = matrix[i * size + j] / matrix[j * size + j];
      if (l == 0.0) continue;
      for (std::size_t k = j; k < size; ++k) matrix[i * size + k] -= l * matrix[j * size + k];
      for (std::size_t k = 0; k < width; ++k) rhs[i * width + k] -= l * rhs[j * width + k];
    }
  }
  for (std::size_t j = size; j-- > 0;) {
    for (std::size_t k = 0; k < width; ++k) {
      double value = rhs[j * width + k];
      for (std::size_t i = j + 1; i < size; ++i) value -= matrix[j * size + i] * rhs[i * width + k];
      rhs[j * width + k] = value / matrix[j * size + j];
    }
  }
  return true;
}

bool all_finite(std::span<const double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

Status check_interpolation_input(const PointArray& points, std::span<const double> parameters, std::size_t count,
                                 std::size_t needed_points, const std::string& method) {
  const std::size_t m = points.size();
  if (m < needed_points) {
    return Error{method + " needs at least " + std::to_string(needed_points) + " points, got " + std::to_string(m)};
  }
  if (parameters.size() != count) {
    return Error{std::to_string(parameters.size()) + " parameter values for " + std::to_string(m) + " points, " +
                 method + " needs " + std::to_string(count)};
  }
  if (auto increasing = check_increasing(parameters); !increasing) return increasing.error();
  if (auto finite = check_coordinates(points); !finite) return finite.error();
  return {};
}

std::optional<SiteGap> schoenberg_whitney_gap(std::span<const double> knots, int degree,
                                              std::span<const std::size_t> columns, std::span<const double> sites,
                                              std::span<const double> weights) {
  assert(weights.empty() || weights.size() == sites.size());
  const auto p = static_cast<std::size_t>(degree);
  const auto counts = [&](std::size_t i) { return weights.empty() || weights[i] > 0.0; };
  std::size_t usable = 0;
  for (std::size_t i = 0; i < sites.size(); ++i) usable += counts(i) ? 1 : 0;
  // As many sites as columns: each column must take the very next site.
  const bool square = usable == columns.size();
  const auto nonzero = [&](std::size_t j, double s) {
    const double low = knots[j], high = knots[j + p + 1];
    if (low < s && s < high) return true;
    if (s < low || s > high) return false;
    return basis_function(knots, degree, static_cast<int>(j), s) != 0.0;
  };
  std::size_t site = 0;
  for (const std::size_t j : columns) {
    for (;; ++site) {
      if (site >= sites.size()) return SiteGap{j, std::nullopt};
      if (!counts(site)) continue;
      if (nonzero(j, sites[site])) break;
      if (square) return SiteGap{j, site};
      // Past the support (N_j vanishes from here on): no later site helps.
      if (sites[site] >= knots[j + p + 1]) return SiteGap{j, std::nullopt};
    }
    ++site;
  }
  return std::nullopt;
}

Error schoenberg_whitney_error(std::span<const double> knots, int degree, std::span<const double> sites,
                               const SiteGap& gap, std::size_t first_parameter, bool weighted,
                               const std::string& consequence) {
  const std::size_t j = gap.basis_function;
  const std::string support =
      "[" + number_text(knots[j]) + ", " + number_text(knots[j + static_cast<std::size_t>(degree) + 1]) + ")";
  const std::string what =
      gap.site ? "parameter " + std::to_string(*gap.site + first_parameter) + " (" + number_text(sites[*gap.site]) +
                     ") is not inside the support " + support + " of basis function " + std::to_string(j)
               : std::string("no point ") + (weighted ? "of positive weight " : "") + "is left for basis function " +
                     std::to_string(j) + " (support " + support + ")";
  return Error{what + ": the knots and parameters violate the Schoenberg–Whitney condition, " + consequence};
}

Expected<PointArray> solve_collocation(int degree, std::span<const double> knots, std::span<const double> sites,
                                       const PointArray& points, std::span<const EndConstraint> constraints) {
  const int p = degree;
  const std::size_t width = static_cast<std::size_t>(p) + 1;
  assert(p >= 1 && knots.size() >= 2 * width);
  const std::size_t unknowns = knots.size() - width;  // n + 1
  assert(unknowns == sites.size() + constraints.size());
  assert(sites.size() == points.size() && sites.size() >= 2);
  assert(sites.front() == knots[static_cast<std::size_t>(p)] && sites.back() == knots[unknowns]);
  const std::size_t d = static_cast<std::size_t>(points.dimension());

  // Constraints in row order: start ones by increasing order, end ones by
  // decreasing order (the rows whose columns reach furthest in sit nearest
  // the interior rows, which keeps the band narrow).
  std::vector<EndConstraint> start, end;
  for (const EndConstraint& c : constraints) (c.at_end ? end : start).push_back(c);
  std::sort(start.begin(), start.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  std::sort(end.begin(), end.end(), [](const auto& a, const auto& b) { return a.order > b.order; });

  // The rows of C(s_0), C(s_m) and the constraints first (a few rows), in
  // compact form: their non-zero pattern is found from their values.
  const std::size_t start_rows = 1 + start.size();
  const std::size_t end_rows = 1 + end.size();
  struct EdgeRow {
    std::size_t row;
    int first;  // column of values[0]
    std::vector<double> values;
    std::vector<double> rhs;
  };
  std::vector<EdgeRow> edges;
  const auto edge_row = [&](std::size_t row, int order, double u, std::span<const double> value) {
    const int span = find_span(knots, p, u);
    std::vector<double> all((static_cast<std::size_t>(order) + 1) * width);
    basis_function_derivatives(knots, p, span, u, order, all);
    // Scale derivative rows by h^k: basis derivatives of order k are
    // O(p^k / h^k), and the pivot search compares rows.
    const double h = knots[static_cast<std::size_t>(span) + 1] - knots[static_cast<std::size_t>(span)];
    const double scale = order == 0 ? 1.0 : std::pow(h, order);
    EdgeRow e{row, span - p, std::vector<double>(width), std::vector<double>(d, 0.0)};
    for (std::size_t r = 0; r < width; ++r) e.values[r] = all[static_cast<std::size_t>(order) * width + r] * scale;
    for (std::size_t k = 0; k < value.size(); ++k) e.rhs[k] = value[k] * scale;
    edges.push_back(std::move(e));
  };
  edge_row(0, 0, sites.front(), points[0]);
  for (std::size_t j = 0; j < start.size(); ++j) edge_row(1 + j, start[j].order, sites.front(), start[j].value);
  for (std::size_t j = 0; j < end.size(); ++j)
    edge_row(unknowns - end_rows + j, end[j].order, sites.back(), end[j].value);
  edge_row(unknowns - 1, 0, sites.back(), points[sites.size() - 1]);

  // Band widths. Edge rows: their values with exact zeros trimmed. Interior
  // sites: the p+1 columns span-p..span of their span, less the last one
  // when the site is the knot t_span (N_span vanishes there exactly, so a
  // site at every knot gives a band of width p rather than p+1: tridiagonal
  // for the natural and clamped cubic).
  std::int64_t lower = 0, upper = 0;
  for (const EdgeRow& e : edges) {
    std::size_t a = 0, b = width;
    while (a < b && e.values[a] == 0.0) ++a;
    while (b > a && e.values[b - 1] == 0.0) --b;
    if (a == b) return Error{singular_message(static_cast<long>(e.row)), ErrorKind::singular};
    const std::int64_t index = static_cast<std::int64_t>(e.row);
    lower = std::max(lower, index - (e.first + static_cast<std::int64_t>(a)));
    upper = std::max(upper, e.first + static_cast<std::int64_t>(b) - 1 - index);
  }
  const int last_span = static_cast<int>(unknowns) - 1;
  const std::size_t interior_end = sites.size() - 1;
  {
    int span = p;
    for (std::size_t i = 1; i < interior_end; ++i) {
      const double u = sites[i];
      // Sites increase: the span advances (A2.1 done incrementally, O(1)
      // amortized) to the last one with t_span <= u, never past n.
      while (span < last_span && knots[static_cast<std::size_t>(span) + 1] <= u) ++span;
      const std::int64_t index = static_cast<std::int64_t>(start_rows + i - 1);
      const std::int64_t last = span - (u == knots[static_cast<std::size_t>(span)] ? 1 : 0);
      lower = std::max(lower, index - (span - p));
      upper = std::max(upper, last - index);
    }
  }
  BandedSystem system(unknowns, static_cast<int>(lower), static_cast<int>(upper));
  std::vector<double> rhs(unknowns * d);
  for (const EdgeRow& e : edges) {
    for (std::size_t k = 0; k < width; ++k)
      if (e.values[k] != 0.0) system.at(e.row, static_cast<std::size_t>(e.first) + k) = e.values[k];
    std::copy(e.rhs.begin(), e.rhs.end(), rhs.begin() + static_cast<std::ptrdiff_t>(e.row * d));
  }
  // Interior rows straight into the band, the points straight into the
  // right-hand side: one pass, no per-row allocation.
  {
    int span = p;
    // The cubic's hot path is the tridiagonal sweep (cubic_sweep.hpp); this
    // general path calls the library's A2.2 as it is.
    std::vector<double> basis(width);
    const std::span<const double> coordinates = points.coordinates();
    for (std::size_t i = 1; i < interior_end; ++i) {
      const double u = sites[i];
      while (span < last_span && knots[static_cast<std::size_t>(span) + 1] <= u) ++span;
      basis_functions(knots, p, span, u, basis);
      const std::size_t row = start_rows + i - 1;
      const std::size_t last = static_cast<std::size_t>(span) - (u == knots[static_cast<std::size_t>(span)] ? 1 : 0);
      for (std::size_t c = static_cast<std::size_t>(span - p), k = 0; c <= last; ++c, ++k) system.at(row, c) = basis[k];
      std::copy_n(coordinates.begin() + static_cast<std::ptrdiff_t>(i * d), d,
                  rhs.begin() + static_cast<std::ptrdiff_t>(row * d));
    }
  }
  if (const long bad = system.factor(); bad >= 0) return Error{singular_message(bad), ErrorKind::singular};
  system.solve(rhs, d);
  if (!all_finite(rhs)) return Error{singular_message(-1), ErrorKind::singular};
  return PointArray::from_trusted(static_cast<int>(d), std::move(rhs));
}

Expected<PointArray> solve_periodic_collocation(int degree, std::span<const double> knots, const PointArray& points) {
  const int p = degree;
  const std::size_t width = static_cast<std::size_t>(p) + 1;
  const std::size_t m = points.size();
  assert(p >= 1 && m >= static_cast<std::size_t>(p) && knots.size() == m + 2 * static_cast<std::size_t>(p) + 1);
  const std::size_t d = static_cast<std::size_t>(points.dimension());
  // Row i (site t_i = knots[p+i], span p+i) has the basis values of the
  // original columns i..i+p (mod m). Shifting the columns by s centres the
  // band: column c' = c - s.
  const std::int64_t s = (p - 1) / 2;
  const std::int64_t lower = s, upper = p - s;
  const std::int64_t size = static_cast<std::int64_t>(m);
  BandedSystem system(m, static_cast<int>(lower), static_cast<int>(upper));
  struct Corner {
    std::size_t row;
    std::size_t column;
    double value;
  };
  std::vector<Corner> corners;
  std::vector<double> rhs(points.coordinates().begin(), points.coordinates().end());
  std::vector<double> basis(width);
  for (std::size_t i = 0; i < m; ++i) {
    const int span = p + static_cast<int>(i);
    basis_functions(knots, p, span, knots[static_cast<std::size_t>(span)], basis);
    for (std::size_t r = 0; r < width; ++r) {
      if (basis[r] == 0.0) continue;
      const std::int64_t column = static_cast<std::int64_t>(i) + static_cast<std::int64_t>(r) - s;
      if (column >= 0 && column < size) {
        system.at(i, static_cast<std::size_t>(column)) += basis[r];
      } else {
        corners.push_back({i, static_cast<std::size_t>((column + size) % size), basis[r]});
      }
    }
  }
  if (const long bad = system.factor(); bad >= 0) return Error{singular_message(bad), ErrorKind::singular};
  // Woodbury: A = B + U V^T, one column of U per distinct corner column c_k
  // (its corner entries), V^T x = x[c_k]. x = Y - Z (I + V^T Z)^{-1} V^T Y
  // with B Y = b and B Z = U.
  std::vector<std::size_t> columns;
  for (const Corner& c : corners)
    if (std::find(columns.begin(), columns.end(), c.column) == columns.end()) columns.push_back(c.column);
  const std::size_t rank = columns.size();
  system.solve(rhs, d);
  if (rank > 0) {
    std::vector<double> z(m * rank, 0.0);
    for (const Corner& c : corners) {
      const std::size_t k = static_cast<std::size_t>(std::find(columns.begin(), columns.end(), c.column) - columns.begin());
      z[c.row * rank + k] += c.value;
    }
    system.solve(z, rank);
    std::vector<double> capacitance(rank * rank, 0.0), w(rank * d);
    for (std::size_t k = 0; k < rank; ++k) {
      for (std::size_t l = 0; l < rank; ++l) capacitance[k * rank + l] = (k == l ? 1.0 : 0.0) + z[columns[k] * rank + l];
      for (std::size_t j = 0; j < d; ++j) w[k * d + j] = rhs[columns[k] * d + j];
    }
    if (!solve_dense(capacitance, w, rank, d)) return Error{singular_message(-1), ErrorKind::singular};
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t k = 0; k < rank; ++k) {
        const double zik = z[i * rank + k];
        if (zik == 0.0) continue;
        for (std::size_t j = 0; j < d; ++j) rhs[i * d + j] -= zik * w[k * d + j];
      }
  }
  if (!all_finite(rhs)) return Error{singular_message(-1), ErrorKind::singular};
  // Undo the shift: unknown c' is the control point of original column c' + s.
  std::vector<double> result(m * d);
  for (std::size_t c = 0; c < m; ++c) {
    const std::size_t original = (c + static_cast<std::size_t>(s)) % m;
    std::copy_n(rhs.begin() + static_cast<std::ptrdiff_t>(c * d), d,
                result.begin() + static_cast<std::ptrdiff_t>(original * d));
  }
  return PointArray::from_trusted(static_cast<int>(d), std::move(result));
}

}  // namespace casteljau::detail

// The C² cubic interpolant in one tridiagonal sweep (see cubic_sweep.hpp).

#include "cubic_sweep.hpp"

#include <cassert>
#include <cmath>
#include <memory>

#include "casteljau/bspline/basis.hpp"

namespace casteljau::detail {

namespace {

/// Row j of a tridiagonal system: a x_{j-1} + b x_j + c x_{j+1} = rhs.
struct Coefficients {
  double a = 0.0, b = 1.0, c = 0.0;
};

/// The three cubic B-splines that do not vanish at a simple knot u = U[s]
/// (s its span): N_{s-3}(u), N_{s-2}(u), N_{s-1}(u); N_s(u) = 0. The NURBS
/// Book A2.2 worked by hand with u - U[s] = 0, which removes a third of its
/// operations; the three values sum to one.
inline Coefficients cubic_basis_at_knot(const double* knots, std::size_t span) {
  const double u = knots[span];
  const double r1 = knots[span + 1] - u, r2 = knots[span + 2] - u;
  const double l2 = u - knots[span - 1], l3 = u - knots[span - 2];
  const double first = 1.0 / (r1 + l2);
  const double left = r1 * first / (r1 + l3);   // N^2_{s-2} / (r1 + l3)
  const double right = l2 * first / (r2 + l2);  // N^2_{s-1} / (r2 + l2)
  return {r1 * left, l3 * left + r2 * right, l2 * right};
}

/// LU without pivoting of a tridiagonal matrix given row by row, and the
/// solution of its systems: `row(j, coefficients, rhs)` fills row j (a of row
/// 0 and c of the last row are ignored) and its `width` right-hand-side
/// values; `x` receives the solution, rows x width, row-major; `upper` is
/// scratch for the eliminated superdiagonal. When `extra` is not null, a
/// second right-hand side extra_rhs(j) is solved in the same sweep into it.
/// False when a pivot is zero or not finite, or the solution is not finite.
/// `Width` fixes the width at compile time (0: run time).
template <std::size_t Width, class RowFunction, class ExtraFunction>
bool tridiagonal_sweep(std::size_t rows, std::size_t width, RowFunction&& row, ExtraFunction&& extra_rhs,
                       double* x, double* upper, double* extra) {
  const std::size_t w = Width != 0 ? Width : width;
  std::unique_ptr<double[]> rhs(new double[w]);
  for (std::size_t j = 0; j < rows; ++j) {
    Coefficients m;
    row(j, m, rhs.get());
    const double a = j == 0 ? 0.0 : m.a;
    const double pivot = j == 0 ? m.b : m.b - a * upper[j - 1];
    if (!(std::isfinite(pivot) && pivot != 0.0)) return false;
    const double inverse = 1.0 / pivot;
    upper[j] = m.c * inverse;
    double* const xj = x + j * w;
    if (j == 0) {
      for (std::size_t k = 0; k < w; ++k) xj[k] = rhs[k] * inverse;
      if (extra) extra[0] = extra_rhs(0) * inverse;
    } else {
      const double* const xp = xj - w;
      for (std::size_t k = 0; k < w; ++k) xj[k] = (rhs[k] - a * xp[k]) * inverse;
      if (extra) extra[j] = (extra_rhs(j) - a * extra[j - 1]) * inverse;
    }
  }
  // Any NaN or infinity in the solution turns `guard` into NaN.
  double guard = 0.0;
  for (std::size_t k = 0; k < w; ++k) guard += x[(rows - 1) * w + k] * 0.0;
  for (std::size_t j = rows - 1; j-- > 0;) {
    double* const xj = x + j * w;
    const double* const xn = xj + w;
    for (std::size_t k = 0; k < w; ++k) {
      xj[k] -= upper[j] * xn[k];
      guard += xj[k] * 0.0;
    }
    if (extra) extra[j] -= upper[j] * extra[j + 1];
  }
  return guard == 0.0;
}

/// Runs the sweep with the width fixed at compile time for curves in the
/// plane and in space, the common cases.
template <class RowFunction, class ExtraFunction>
bool sweep(std::size_t rows, std::size_t width, RowFunction&& row, ExtraFunction&& extra_rhs, double* x,
           double* extra) {
  std::unique_ptr<double[]> upper(new double[rows]);  // uninitialized: written before read
  switch (width) {
    case 2: return tridiagonal_sweep<2>(rows, width, row, extra_rhs, x, upper.get(), extra);
    case 3: return tridiagonal_sweep<3>(rows, width, row, extra_rhs, x, upper.get(), extra);
    default: return tridiagonal_sweep<0>(rows, width, row, extra_rhs, x, upper.get(), extra);
  }
}

double no_extra(std::size_t) { return 0.0; }

}  // namespace

bool sweep_cubic_at_knots(std::span<const double> knots, const PointArray& points, const CubicEnds& ends,
                          std::span<double> control) {
  const std::size_t m = points.size() - 1;
  const std::size_t d = static_cast<std::size_t>(points.dimension());
  assert(knots.size() == m + 7 && control.size() == (m + 3) * d);
  const double* const u = knots.data();
  const double* const p = points.coordinates().data();
  const bool clamped = ends.condition == EndCondition::clamped;
  const std::size_t n = m + 2;  // last control point
  const auto row = [&](std::size_t j, Coefficients& r, double* rhs) {
    if (j >= 2 && j <= m) {  // C(t_{j-1}) = P_{j-1}; t_{j-1} = u[j + 2]
      r = cubic_basis_at_knot(u, j + 2);
      const double* const point = p + (j - 1) * d;
      for (std::size_t k = 0; k < d; ++k) rhs[k] = point[k];
    } else if (j == 0 || j == n) {  // the end points
      r = {0.0, 1.0, 0.0};
      const double* const point = p + (j == 0 ? 0 : m * d);
      for (std::size_t k = 0; k < d; ++k) rhs[k] = point[k];
    } else if (clamped) {
      // C'(t_0) = 3 (P_1 - P_0) / (t_1 - t_0); C'(t_m) = 3 (P_n - P_{n-1}) / (t_m - t_{m-1}).
      const bool start = j == 1;
      const double step = start ? u[4] - u[3] : u[n + 3] - u[n];
      const std::span<const double> tangent = start ? ends.start_tangent : ends.end_tangent;
      r = start ? Coefficients{-1.0, 1.0, 0.0} : Coefficients{0.0, -1.0, 1.0};
      for (std::size_t k = 0; k < d; ++k) rhs[k] = step / 3.0 * tangent[k];
    } else {
      // C''(t_0) = 0: (P_2 - P_1)/(u_5 - u_2) = (P_1 - P_0)/(u_4 - u_1), times (u_4 - u_1);
      // C''(t_m) = 0 likewise with the last three control points.
      if (j == 1) {
        const double ratio = (u[4] - u[1]) / (u[5] - u[2]);
        r = {1.0, -(1.0 + ratio), ratio};
      } else {
        const double ratio = (u[n + 3] - u[n]) / (u[n + 2] - u[n - 1]);
        r = {ratio, -(1.0 + ratio), 1.0};
      }
      for (std::size_t k = 0; k < d; ++k) rhs[k] = 0.0;
    }
  };
  return sweep(m + 3, d, row, no_extra, control.data(), nullptr);
}

bool sweep_cubic_not_a_knot(std::span<const double> knots, std::span<const double> parameters,
                            const PointArray& points, std::span<double> control) {
  const std::size_t m = points.size() - 1;
  const std::size_t d = static_cast<std::size_t>(points.dimension());
  assert(m + 1 >= kSweepMinimumPoints && knots.size() == m + 5 && control.size() == (m + 1) * d);
  const double* const u = knots.data();
  const double* const p = points.coordinates().data();
  // The rows of t_1 and t_{m-1} have four non-zeros; each loses its outer
  // one against the row of its neighbouring knot t_2 or t_{m-2}.
  double first[4], last[4];
  basis_functions(knots, 3, 3, parameters[1], first);                          // N_0..N_3 (t_1)
  basis_functions(knots, 3, static_cast<int>(m), parameters[m - 1], last);    // N_{m-3}..N_m (t_{m-1})
  const Coefficients second = cubic_basis_at_knot(u, 4);                      // t_2: N_1..N_3
  const Coefficients before_last = cubic_basis_at_knot(u, m);                 // t_{m-2}: N_{m-3}..N_{m-1}
  const double first_factor = first[3] / second.c;
  const double last_factor = last[0] / before_last.a;
  const auto row = [&](std::size_t j, Coefficients& r, double* rhs) {
    const double* const point = p + j * d;
    if (j >= 2 && j + 2 <= m) {  // C(t_j) = P_j at the knot t_j = u[j + 2]
      r = cubic_basis_at_knot(u, j + 2);
      for (std::size_t k = 0; k < d; ++k) rhs[k] = point[k];
    } else if (j == 0 || j == m) {
      r = {0.0, 1.0, 0.0};
      for (std::size_t k = 0; k < d; ++k) rhs[k] = point[k];
    } else if (j == 1) {  // row(t_1) - f row(t_2)
      r = {first[0], first[1] - first_factor * second.a, first[2] - first_factor * second.b};
      for (std::size_t k = 0; k < d; ++k) rhs[k] = point[k] - first_factor * point[d + k];
    } else {  // j = m - 1: row(t_{m-1}) - f row(t_{m-2})
      r = {last[1] - last_factor * before_last.b, last[2] - last_factor * before_last.c, last[3]};
      for (std::size_t k = 0; k < d; ++k) rhs[k] = point[k] - last_factor * point[k - d];
    }
  };
  return sweep(m + 1, d, row, no_extra, control.data(), nullptr);
}

bool sweep_cubic_periodic(std::span<const double> knots, const PointArray& points, std::span<double> control) {
  const std::size_t count = points.size();  // M
  const std::size_t d = static_cast<std::size_t>(points.dimension());
  assert(count >= 3 && knots.size() == count + 7 && control.size() == (count + 3) * d);
  const double* const u = knots.data();
  const double* const p = points.coordinates().data();
  // Equation i: a_i Q_i + b_i Q_{i+1} + c_i Q_{i+2} = P_i (indices mod M).
  // With y_i = Q_{i+1} it is cyclic tridiagonal; Sherman–Morrison removes
  // the corners a_0 (row 0, column M-1) and c_{M-1} (row M-1, column 0):
  // A = T + w v^T, w = (g, 0.., c_{M-1}), v = (1, 0.., a_0 / g), g = -b_0.
  const Coefficients head = cubic_basis_at_knot(u, 3);
  const Coefficients tail = cubic_basis_at_knot(u, count + 2);
  const double gamma = -head.b;
  const auto row = [&](std::size_t i, Coefficients& r, double* rhs) {
    r = cubic_basis_at_knot(u, i + 3);
    if (i == 0) r.b -= gamma;
    if (i + 1 == count) r.b -= head.a * tail.c / gamma;
    const double* const point = p + i * d;
    for (std::size_t k = 0; k < d; ++k) rhs[k] = point[k];
  };
  const auto correction_rhs = [&](std::size_t i) { return i == 0 ? gamma : i + 1 == count ? tail.c : 0.0; };
  std::unique_ptr<double[]> z(new double[count]);
  double* const y = control.data() + d;  // y_i = Q_{i+1} lands in row i + 1; y_{M-1} = Q_0 in row M
  if (!sweep(count, d, row, correction_rhs, y, z.get())) return false;
  const double denominator = 1.0 + z[0] + head.a / gamma * z[count - 1];
  if (!(std::isfinite(denominator) && denominator != 0.0)) return false;
  // x = y - z (v·y) / (1 + v·z), one pass over the rows.
  std::unique_ptr<double[]> projection(new double[d]);
  for (std::size_t k = 0; k < d; ++k)
    projection[k] = (y[k] + head.a / gamma * y[(count - 1) * d + k]) / denominator;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < d; ++k) y[i * d + k] -= projection[k] * z[i];
  for (std::size_t k = 0; k < d; ++k) {
    control[k] = control[count * d + k];                  // Q_0
    control[(count + 1) * d + k] = control[d + k];        // Q_1 again
    control[(count + 2) * d + k] = control[2 * d + k];    // Q_2 again
  }
  for (double value : control)
    if (!std::isfinite(value)) return false;
  return true;
}

}  // namespace casteljau::detail

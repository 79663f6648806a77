// Points, partial derivatives and normals of B-spline (NURBS) and Bézier
// surfaces, one at a time and in batches (surfaces/evaluate.hpp).
#include "casteljau/surfaces/evaluate.hpp"

#include <cassert>
#include <cmath>
#include <cstring>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"
#include "casteljau/core/precondition.hpp"
#include "../bezier/de_casteljau.hpp"
#include "../core/workspace.hpp"
#include "surface_basis.hpp"

namespace casteljau {
namespace {

using detail::Workspace;

/// Width of one control point in the sums: d, or d+1 homogeneous (w P, w).
int width_of(const BSplineSurface& surface) { return surface.dimension() + (surface.is_rational() ? 1 : 0); }

/// Control point (i, j) of the sums: P_ij, or (w_ij P_ij, w_ij), into out.
inline void load_point(const BSplineSurface& surface, std::size_t i, std::size_t j, double* out) {
  const ControlNet& net = surface.control_net();
  const auto point = net(i, j);
  const int d = surface.dimension();
  if (!surface.is_rational()) {
    for (int c = 0; c < d; ++c) out[c] = point[static_cast<std::size_t>(c)];
    return;
  }
  const double w = surface.weights()[i * net.columns() + j];
  for (int c = 0; c < d; ++c) out[c] = w * point[static_cast<std::size_t>(c)];
  out[d] = w;
}

/// S(u,v) into out[0..d): spans by A2.1, bases with exact clamped ends, then
/// sum_l N_l(v) (sum_k N_k(u) P_{i0+k, j0+l}) on the homogeneous points
/// (The NURBS Book A3.5 / A4.3). `scratch` is reused across calls.
template <class Scratch>
void evaluate_point(const BSplineSurface& surface, double u, double v, double* out, Scratch& scratch) {
  const int p = surface.degree_u(), q = surface.degree_v();
  const int w = width_of(surface);
  const int d = surface.dimension();
  const auto ku = surface.knots_u(), kv = surface.knots_v();
  const int su = find_span(ku, p, u), sv = find_span(kv, q, v);
  const int larger = p > q ? p : q;
  const std::size_t need = static_cast<std::size_t>((p + 1) + (q + 1) + 2 * (larger + 1) + 3 * w);
  double* base = scratch.take(need).data();
  double* nu = base;
  double* nv = nu + p + 1;
  double* tmp = nv + q + 1;  // 2 (max(p, q) + 1): what surface_basis needs
  double* sum = tmp + 2 * (larger + 1);
  double* row = sum + w;
  double* point = row + w;
  detail::surface_basis(ku, p, su, u, nu, tmp);
  detail::surface_basis(kv, q, sv, v, nv, tmp);
  for (int c = 0; c < w; ++c) sum[c] = 0.0;
  const std::size_t i0 = static_cast<std::size_t>(su - p), j0 = static_cast<std::size_t>(sv - q);
  for (int l = 0; l <= q; ++l) {
    for (int c = 0; c < w; ++c) row[c] = 0.0;
    for (int k = 0; k <= p; ++k) {
      load_point(surface, i0 + static_cast<std::size_t>(k), j0 + static_cast<std::size_t>(l), point);
      for (int c = 0; c < w; ++c) row[c] += nu[k] * point[c];
    }
    for (int c = 0; c < w; ++c) sum[c] += nv[l] * row[c];
  }
  if (surface.is_rational()) {
    for (int c = 0; c < d; ++c) out[c] = sum[c] / sum[d];
  } else {
    for (int c = 0; c < d; ++c) out[c] = sum[c];
  }
}

/// S(t, s) of a Bézier patch by de Casteljau: each row i reduced at s (the v
/// parameter) to one point, then that column reduced at t (the u parameter).
template <class Scratch>
void evaluate_bezier_point(const BezierSurface& surface, double t, double s, double* out, Scratch& scratch) {
  const ControlNet& net = surface.control_net();
  const std::size_t rows = net.rows(), columns = net.columns();
  const int d = surface.dimension();
  const bool rational = surface.is_rational();
  const int w = d + (rational ? 1 : 0);
  const std::size_t width = static_cast<std::size_t>(w);
  double* row = scratch.take(columns * width + rows * width).data();
  double* column = row + columns * width;
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < columns; ++j) {
      const auto point = net(i, j);
      const double weight = rational ? surface.weights()[i * columns + j] : 1.0;
      for (int c = 0; c < d; ++c) row[j * width + static_cast<std::size_t>(c)] = weight * point[static_cast<std::size_t>(c)];
      if (rational) row[j * width + static_cast<std::size_t>(d)] = weight;
    }
    detail::de_casteljau_in_place(row, static_cast<int>(columns) - 1, w, s);
    for (int c = 0; c < w; ++c) column[i * width + static_cast<std::size_t>(c)] = row[c];
  }
  detail::de_casteljau_in_place(column, static_cast<int>(rows) - 1, w, t);
  for (int c = 0; c < d; ++c) out[c] = rational ? column[c] / column[d] : column[c];
}

/// Binomial coefficients C(n, 0..n) as doubles (Pascal's triangle).
std::vector<std::vector<double>> binomials(int n) {
  std::vector<std::vector<double>> b(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    b[static_cast<std::size_t>(i)].assign(static_cast<std::size_t>(i) + 1, 1.0);
    for (int j = 1; j < i; ++j)
      b[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          b[static_cast<std::size_t>(i) - 1][static_cast<std::size_t>(j) - 1] +
          b[static_cast<std::size_t>(i) - 1][static_cast<std::size_t>(j)];
  }
  return b;
}

/// The derivatives d^(k+l) S / du^k dv^l for every (k, l) with k <= K,
/// l <= L and k + l <= T (others left empty): the homogeneous ones by
/// The NURBS Book A3.6 (basis derivatives by A2.3), then for a NURBS surface
/// the Leibniz rule solved for S^(k,l) (eq. 4.20, A4.4):
///   S^(k,l) = (A^(k,l) - sum_{i=1..k} C(k,i) w^(i,0) S^(k-i,l)
///              - sum_{j=1..l} C(l,j) w^(0,j) S^(k,l-j)
///              - sum_{i=1..k} sum_{j=1..l} C(k,i) C(l,j) w^(i,j) S^(k-i,l-j)) / w.
/// Order (0,0) uses the exact-end basis, so it equals point_at.
std::vector<std::vector<Point>> derivative_table(const BSplineSurface& surface, double u, double v, int K, int L,
                                                 int T) {
  const int p = surface.degree_u(), q = surface.degree_v();
  const int d = surface.dimension();
  const int w = width_of(surface);
  const bool rational = surface.is_rational();
  const auto ku = surface.knots_u(), kv = surface.knots_v();
  const int su = find_span(ku, p, u), sv = find_span(kv, q, v);
  // Polynomial: basis derivatives beyond the degree vanish.
  const int du = K < p ? K : p, dv = L < q ? L : q;
  const std::size_t pu = static_cast<std::size_t>(p) + 1, qv = static_cast<std::size_t>(q) + 1;
  std::vector<double> nu((static_cast<std::size_t>(du) + 1) * pu), nv((static_cast<std::size_t>(dv) + 1) * qv);
  basis_function_derivatives(ku, p, su, u, du, nu);
  basis_function_derivatives(kv, q, sv, v, dv, nv);
  std::vector<double> tmp(2 * (pu > qv ? pu : qv));
  detail::surface_basis(ku, p, su, u, nu.data(), tmp.data());
  detail::surface_basis(kv, q, sv, v, nv.data(), tmp.data());

  const std::size_t i0 = static_cast<std::size_t>(su - p), j0 = static_cast<std::size_t>(sv - q);
  const std::size_t width = static_cast<std::size_t>(w);
  // The homogeneous points of the (p+1) x (q+1) block, once.
  std::vector<double> block(pu * qv * width);
  for (std::size_t r = 0; r < pu; ++r)
    for (std::size_t s = 0; s < qv; ++s) load_point(surface, i0 + r, j0 + s, block.data() + (r * qv + s) * width);

  std::vector<std::vector<Point>> a(static_cast<std::size_t>(K) + 1);
  std::vector<double> temp(qv * width);
  for (int k = 0; k <= K; ++k) {
    const int lmax = (T - k) < L ? (T - k) : L;
    a[static_cast<std::size_t>(k)].assign(static_cast<std::size_t>(lmax < 0 ? 0 : lmax + 1), Point(width, 0.0));
    if (k > du || lmax < 0) continue;
    // temp[s] = sum_r N^(k)_r(u) P_{i0+r, j0+s}.
    for (double& x : temp) x = 0.0;
    for (std::size_t r = 0; r < pu; ++r) {
      const double n = nu[static_cast<std::size_t>(k) * pu + r];
      for (std::size_t s = 0; s < qv; ++s)
        for (std::size_t c = 0; c < width; ++c) temp[s * width + c] += n * block[(r * qv + s) * width + c];
    }
    for (int l = 0; l <= lmax && l <= dv; ++l) {
      Point& out = a[static_cast<std::size_t>(k)][static_cast<std::size_t>(l)];
      for (std::size_t s = 0; s < qv; ++s) {
        const double n = nv[static_cast<std::size_t>(l) * qv + s];
        for (std::size_t c = 0; c < width; ++c) out[c] += n * temp[s * width + c];
      }
    }
  }
  if (!rational) return a;

  const int top = K > L ? K : L;
  const auto choose = binomials(top);
  std::vector<std::vector<Point>> s(a.size());
  const std::size_t dd = static_cast<std::size_t>(d);
  for (std::size_t k = 0; k < a.size(); ++k) {
    s[k].assign(a[k].size(), Point(dd, 0.0));
    for (std::size_t l = 0; l < a[k].size(); ++l) {
      Point value(a[k][l].begin(), a[k][l].begin() + d);
      for (std::size_t i = 0; i <= k; ++i) {
        for (std::size_t j = 0; j <= l; ++j) {
          if (i == 0 && j == 0) continue;
          const double factor = choose[k][i] * choose[l][j] * a[i][j][dd];
          const Point& lower = s[k - i][l - j];
          for (std::size_t c = 0; c < dd; ++c) value[c] -= factor * lower[c];
        }
      }
      for (std::size_t c = 0; c < dd; ++c) value[c] /= a[0][0][dd];
      s[k][l] = std::move(value);
    }
  }
  return s;
}

// --- grid kernels ------------------------------------------------------------------

/// Basis table of one direction: first control index and the p+1 values of
/// every parameter.
struct BasisTable {
  std::vector<int> first;
  std::vector<double> values;
  /// Maximal runs of consecutive parameters on the same span: run k covers
  /// parameters run_start[k] .. run_start[k+1]-1 (sorted parameters give one
  /// run per span, so the span's control rows stay in registers).
  std::vector<std::size_t> run_start;
  /// For the fast kernel: every basis value repeated 4 times (value l of
  /// parameter b at (b (p+1) + l) * 4), so that a grid point is 4-wide
  /// multiplies of whole registers with no shuffle (a broadcast of one value
  /// into a register costs a shuffle, the bottleneck of this loop).
  std::vector<double> broadcast;
};

BasisTable basis_table(std::span<const double> knots, int p, std::span<const double> ts) {
  BasisTable table;
  const std::size_t count = static_cast<std::size_t>(p) + 1;
  table.first.resize(ts.size());
  table.values.resize(ts.size() * count);
  std::vector<double> tmp(2 * count);
  for (std::size_t b = 0; b < ts.size(); ++b) {
    const int span = find_span(knots, p, ts[b]);
    table.first[b] = span - p;
    detail::surface_basis(knots, p, span, ts[b], table.values.data() + b * count, tmp.data());
    if (b == 0 || table.first[b] != table.first[b - 1]) table.run_start.push_back(b);
  }
  table.run_start.push_back(ts.size());
  return table;
}

/// a * b + c, fused (one rounding) where the target has FMA, as the curve
/// kernels do (src/bspline/de_boor.hpp): the build turns off automatic
/// contraction, so the fast kernel asks for it.
inline double multiply_add(double a, double b, double c) {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  return std::fma(a, b, c);
#else
  return a * b + c;
#endif
}

/// The fast grid kernel: one u-contracted row `row` of 4 doubles per column
/// (the homogeneous point padded with zeros), q = Q, d = D, rational = R.
/// Each grid point is the (Q+1)-term combination of 4-wide rows: with AVX2
/// g++ makes it one broadcast multiply and Q fused multiply-adds on a
/// 256-bit register. The 4-wide store also writes the next point's first
/// coordinate, overwritten right after (only the last point of the whole
/// output stores D values).
template <int Q, int D, bool R>
void grid_row_fast(const double* row, const BasisTable& v, std::size_t count, double* out, bool last_row) {
  static_assert(D + (R ? 1 : 0) <= 4, "padded rows hold 4 doubles");
  const double* basis = v.values.data();
  const double* wide = v.broadcast.data();
  const std::size_t runs = v.run_start.size() - 1;
  for (std::size_t k = 0; k < runs; ++k) {
    const std::size_t begin = v.run_start[k];
    std::size_t end = v.run_start[k + 1];
    // The Q+1 control rows of this span, loaded once for the run.
    double r[Q + 1][4];
    const double* source = row + 4 * static_cast<std::ptrdiff_t>(v.first[begin]);
    for (int l = 0; l <= Q; ++l)
      for (int c = 0; c < 4; ++c) r[l][c] = source[4 * l + c];
    const bool tail = last_row && end == count;
    if (tail) --end;
    for (std::size_t b = begin; b < end; ++b) {
      const double* n = wide + 4 * (Q + 1) * b;
      double acc[4];
      for (int c = 0; c < 4; ++c) acc[c] = n[c] * r[0][c];
      for (int l = 1; l <= Q; ++l)
        for (int c = 0; c < 4; ++c) acc[c] = multiply_add(n[4 * l + c], r[l][c], acc[c]);
      if constexpr (R) {
        const double inverse = 1.0 / acc[D];
        for (int c = 0; c < 4; ++c) acc[c] *= inverse;
      }
      if constexpr (D == 3) {
        std::memcpy(out + 3 * b, acc, sizeof acc);
      } else {
        for (int c = 0; c < D; ++c) out[D * b + static_cast<std::size_t>(c)] = acc[c];
      }
    }
    if (tail) {
      // The very last point of the output: D values only.
      const double* n = basis + (Q + 1) * end;
      double acc[4] = {0.0, 0.0, 0.0, 0.0};
      for (int l = 0; l <= Q; ++l)
        for (int c = 0; c < 4; ++c) acc[c] = multiply_add(n[l], r[l][c], acc[c]);
      for (int c = 0; c < D; ++c) out[D * end + static_cast<std::size_t>(c)] = R ? acc[c] / acc[D] : acc[c];
    }
  }
}

using FastKernel = void (*)(const double*, const BasisTable&, std::size_t, double*, bool);

template <int D, bool R>
FastKernel fast_kernel_for_degree(int q) {
  switch (q) {
    case 1: return &grid_row_fast<1, D, R>;
    case 2: return &grid_row_fast<2, D, R>;
    case 3: return &grid_row_fast<3, D, R>;
    default: return nullptr;
  }
}

FastKernel fast_kernel(int q, int d, bool rational) {
  if (d == 3) return rational ? fast_kernel_for_degree<3, true>(q) : fast_kernel_for_degree<3, false>(q);
  if (d == 2) return rational ? fast_kernel_for_degree<2, true>(q) : fast_kernel_for_degree<2, false>(q);
  return nullptr;
}

}  // namespace

Point point_at(const BSplineSurface& surface, double u, double v) {
  Workspace<512> scratch;
  Point out(static_cast<std::size_t>(surface.dimension()));
  evaluate_point(surface, u, v, out.data(), scratch);
  return out;
}

Point point_at(const BezierSurface& surface, double u, double v) {
  Workspace<2048> scratch;
  Point out(static_cast<std::size_t>(surface.dimension()));
  evaluate_bezier_point(surface, u, v, out.data(), scratch);
  return out;
}

Point partial_derivative_at(const BSplineSurface& surface, double u, double v, int order_u, int order_v) {
  detail::require(order_u >= 0 && order_v >= 0, "partial_derivative_at", "the derivative orders must be >= 0");
  if (!surface.is_rational() && (order_u > surface.degree_u() || order_v > surface.degree_v())) {
    return Point(static_cast<std::size_t>(surface.dimension()), 0.0);
  }
  auto table = derivative_table(surface, u, v, order_u, order_v, order_u + order_v);
  return std::move(table[static_cast<std::size_t>(order_u)][static_cast<std::size_t>(order_v)]);
}

Point partial_derivative_at(const BezierSurface& surface, double u, double v, int order_u, int order_v) {
  return partial_derivative_at(to_bspline_surface(surface), u, v, order_u, order_v);
}

std::vector<std::vector<Point>> partial_derivatives_up_to(const BSplineSurface& surface, double u, double v,
                                                       int max_order) {
  detail::require(max_order >= 0, "partial_derivatives_up_to", "max_order must be >= 0");
  return derivative_table(surface, u, v, max_order, max_order, max_order);
}

Point normal_at(const BSplineSurface& surface, double u, double v) {
  detail::require(surface.dimension() == 3, "normal_at", "the surface must lie in 3D (dimension() == 3)");
  const auto table = derivative_table(surface, u, v, 1, 1, 2);
  const Vec3 su = Vec3::from(table[1][0]);
  const Vec3 sv = Vec3::from(table[0][1]);
  const Vec3 suv = Vec3::from(table[1][1]);
  // A first derivative vanishes when its change across the whole domain is
  // negligible against the control points' size (the curves' criterion).
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  const double scale = scale_of(surface.control_net().points());
  const double floor = tolerances::kVanishingDerivative * (scale > 0.0 ? scale : 1.0);
  const bool u_vanishes = norm(su) * du.length() <= floor;
  const bool v_vanishes = norm(sv) * dv.length() <= floor;
  Vec3 n{};
  if (!u_vanishes && !v_vanishes) {
    n = cross(su, sv);
  } else if (v_vanishes && !u_vanishes) {
    // S_v(u + h, v) = S_v(u, v) + h S_uv + O(h^2): from inside the domain the
    // normal tends to +-(S_u x S_uv), the sign of h (negative at the upper end).
    n = cross(su, suv);
    if (u >= du.upper) n = -n;
  } else if (u_vanishes && !v_vanishes) {
    n = cross(suv, sv);
    if (v >= dv.upper) n = -n;
  } else {
    return Point(3, 0.0);
  }
  const double length = norm(n);
  const double reference = (norm(su) + norm(suv)) * (norm(sv) + norm(suv));
  if (!(length > tolerances::kVanishingDerivative * reference)) return Point(3, 0.0);
  for (double& c : n.coordinates) c /= length;
  return Point(n.coordinates.begin(), n.coordinates.end());
}

Point normal_at(const BezierSurface& surface, double u, double v) {
  return normal_at(to_bspline_surface(surface), u, v);
}

void points_at(const BSplineSurface& surface, std::span<const double> us, std::span<const double> vs,
               std::span<double> out) {
  const std::size_t d = static_cast<std::size_t>(surface.dimension());
  detail::require(us.size() == vs.size(), "points_at", "us and vs must have one size");
  detail::require(out.size() == us.size() * d, "points_at", "out must hold us.size() * dimension() values");
  Workspace<2048> scratch;
  for (std::size_t k = 0; k < us.size(); ++k) evaluate_point(surface, us[k], vs[k], out.data() + k * d, scratch);
}

void points_at(const BezierSurface& surface, std::span<const double> us, std::span<const double> vs,
               std::span<double> out) {
  const std::size_t d = static_cast<std::size_t>(surface.dimension());
  detail::require(us.size() == vs.size(), "points_at", "us and vs must have one size");
  detail::require(out.size() == us.size() * d, "points_at", "out must hold us.size() * dimension() values");
  Workspace<2048> scratch;
  for (std::size_t k = 0; k < us.size(); ++k)
    evaluate_bezier_point(surface, us[k], vs[k], out.data() + k * d, scratch);
}

void grid_points_at(const BSplineSurface& surface, std::span<const double> us, std::span<const double> vs,
                    std::span<double> out) {
  const int p = surface.degree_u(), q = surface.degree_v();
  const int d = surface.dimension();
  const bool rational = surface.is_rational();
  const std::size_t dd = static_cast<std::size_t>(d);
  detail::require(out.size() == us.size() * vs.size() * dd, "grid_points_at",
                  "out must hold us.size() * vs.size() * dimension() values");
  if (us.empty() || vs.empty()) return;
  const ControlNet& net = surface.control_net();
  const std::size_t columns = net.columns();
  const BasisTable tu = basis_table(surface.knots_u(), p, us);
  BasisTable tv = basis_table(surface.knots_v(), q, vs);
  const FastKernel fast = fast_kernel(q, d, rational);
  if (fast) {
    tv.broadcast.resize(tv.values.size() * 4);
    for (std::size_t k = 0; k < tv.values.size(); ++k)
      for (std::size_t c = 0; c < 4; ++c) tv.broadcast[4 * k + c] = tv.values[k];
  }
  // The u-contracted row: 4 doubles per column on the fast path (padded), w otherwise.
  const int w = width_of(surface);
  const std::size_t stride = fast ? 4 : static_cast<std::size_t>(w);
  // The homogeneous net laid out with the row stride, so contraction is one
  // multiply-add per coordinate.
  std::vector<double> hnet(net.rows() * columns * stride, 0.0);
  for (std::size_t i = 0; i < net.rows(); ++i)
    for (std::size_t j = 0; j < columns; ++j) load_point(surface, i, j, hnet.data() + (i * columns + j) * stride);
  std::vector<double> row(columns * stride);
  std::vector<double> sum(static_cast<std::size_t>(w));
  const std::size_t pu = static_cast<std::size_t>(p) + 1, qv = static_cast<std::size_t>(q) + 1;
  const std::size_t line = columns * stride;
  for (std::size_t a = 0; a < us.size(); ++a) {
    const double* nu = tu.values.data() + a * pu;
    const double* first_row = hnet.data() + static_cast<std::size_t>(tu.first[a]) * line;
    for (std::size_t x = 0; x < line; ++x) row[x] = nu[0] * first_row[x];
    for (std::size_t k = 1; k < pu; ++k) {
      const double n = nu[k];
      const double* source = first_row + k * line;
      for (std::size_t x = 0; x < line; ++x) row[x] += n * source[x];
    }
    double* target = out.data() + a * vs.size() * dd;
    if (fast) {
      fast(row.data(), tv, vs.size(), target, a + 1 == us.size());
      continue;
    }
    for (std::size_t b = 0; b < vs.size(); ++b) {
      const double* nv = tv.values.data() + b * qv;
      const double* r = row.data() + static_cast<std::size_t>(tv.first[b]) * stride;
      for (double& s : sum) s = 0.0;
      for (std::size_t l = 0; l < qv; ++l)
        for (std::size_t c = 0; c < stride; ++c) sum[c] += nv[l] * r[l * stride + c];
      for (std::size_t c = 0; c < dd; ++c) target[b * dd + c] = rational ? sum[c] / sum[dd] : sum[c];
    }
  }
}

void grid_points_at(const BezierSurface& surface, std::span<const double> us, std::span<const double> vs,
                    std::span<double> out) {
  grid_points_at(to_bspline_surface(surface), us, vs, out);
}

}  // namespace casteljau

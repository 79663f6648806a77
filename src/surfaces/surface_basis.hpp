#pragma once
// The non-zero B-spline basis functions of one surface direction, computed
// so that the ends of a clamped domain are exact. Internal to src/surfaces.
//
// The NURBS Book A2.2 forms N_r <- saved + right * (N_r / (right + left)),
// which at u = t_p of a clamped knot vector gives right * (1/right), one ulp
// below 1 for many knot spacings. Here each step multiplies by the ratios
// right/(right+left) and left/(right+left) instead: at a clamped end one of
// the two differences is exactly zero and the other ratio is exactly one, so
// the basis is exactly (1, 0, ..., 0) or (0, ..., 0, 1) and a clamped surface
// interpolates its corner control points bit for bit. The values still sum
// to one up to rounding (each step splits N_r into two parts that add up to
// it within an ulp). Same recursion and O(p^2) cost, twice the divisions;
// only basis tables and single points use it, never a per-point batch loop.
#include <cstddef>
#include <span>

namespace casteljau::detail {

/// N_{span-p,p}(u) .. N_{span,p}(u) into out[0..p]; `scratch` holds 2(p+1) doubles.
inline void surface_basis(std::span<const double> knots, int p, int span, double u, double* out,
                          double* scratch) {
  double* left = scratch;
  double* right = scratch + p + 1;
  out[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - knots[static_cast<std::size_t>(span + 1 - j)];
    right[j] = knots[static_cast<std::size_t>(span + j)] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      // t_{span+r+1} - t_{span+1-j+r} contains the non-empty span: never zero.
      const double width = right[r + 1] + left[j - r];
      const double value = out[r];
      out[r] = saved + value * (right[r + 1] / width);
      saved = value * (left[j - r] / width);
    }
    out[j] = saved;
  }
}

}  // namespace casteljau::detail

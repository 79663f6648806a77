#pragma once
// The de Casteljau step shared by every evaluator, so that point_at,
// points_at, split_at and the construction perform the same floating-point
// operations and agree bit for bit. Internal to src/.

#include <cmath>
#include <span>

namespace casteljau::detail {

/// (1-t) a + t b with s = 1 - t precomputed. Exact at t = 0 (gives a) and
/// t = 1 (gives b), so curves interpolate their end points exactly. One fused
/// multiply-add where the target has FMA (the same choice in every kernel of
/// one build, so all evaluators still agree bit for bit).
inline double lerp_step(double a, double b, double s, double t) {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  return std::fma(t, b, s * a);
#else
  return s * a + t * b;
#endif
}

/// In-place de Casteljau on n+1 rows of `width` doubles (row-major): after the
/// call, row 0 holds the curve point. Rows are overwritten by the triangle.
inline void de_casteljau_in_place(double* rows, int n, int width, double t) {
  const double s = 1.0 - t;
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i) {
      double* a = rows + i * width;
      const double* b = a + width;
      for (int j = 0; j < width; ++j) a[j] = lerp_step(a[j], b[j], s, t);
    }
  }
}

}  // namespace casteljau::detail

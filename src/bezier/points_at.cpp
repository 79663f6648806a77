// Batch evaluation of Bézier curves: de Casteljau on blocks of parameters.
// Each lane of a block runs exactly the scalar algorithm of point_at (same
// lerp_step, same order), so results agree bit for bit; the lanes let the
// compiler use SIMD registers across parameters.
#include <algorithm>
#include <array>
#include <cassert>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/core/tolerance.hpp"
#include "de_casteljau.hpp"

namespace casteljau {
namespace {

constexpr int kLanes = 8;

/// Evaluates `count` (<= kLanes) parameters of one coordinate row set:
/// `source` holds n+1 rows of `width`; writes width values per parameter.
template <int Width>
void block(const double* source, int n, const double* ts, int count, double* work, double* out) {
  // work layout: [(n+1) * Width][kLanes]
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < Width; ++j)
      for (int l = 0; l < kLanes; ++l) work[(i * Width + j) * kLanes + l] = source[i * Width + j];
  std::array<double, kLanes> t{}, s{};
  for (int l = 0; l < kLanes; ++l) {
    t[l] = ts[std::min(l, count - 1)];
    s[l] = 1.0 - t[l];
  }
  for (int r = 1; r <= n; ++r)
    for (int i = 0; i <= n - r; ++i)
      for (int j = 0; j < Width; ++j) {
        double* a = work + (i * Width + j) * kLanes;
        const double* b = work + ((i + 1) * Width + j) * kLanes;
        for (int l = 0; l < kLanes; ++l) a[l] = detail::lerp_step(a[l], b[l], s[l], t[l]);
      }
  for (int l = 0; l < count; ++l)
    for (int j = 0; j < Width; ++j) out[l * Width + j] = work[j * kLanes + l];
}

template <int Width>
void evaluate_all(const double* rows, int n, std::span<const double> ts, double* out, double* work) {
  for (std::size_t start = 0; start < ts.size(); start += kLanes) {
    const int count = static_cast<int>(std::min<std::size_t>(kLanes, ts.size() - start));
    block<Width>(rows, n, ts.data() + start, count, work, out + start * Width);
  }
}

}  // namespace

void points_at(const BezierCurve& curve, std::span<const double> ts, std::span<double> out) {
  const int d = curve.dimension(), n = curve.degree();
  assert(out.size() == ts.size() * static_cast<std::size_t>(d));
  const bool rational = curve.is_rational();
  const int width = rational ? d + 1 : d;
  if (!rational && (width == 2 || width == 3) && n <= tolerances::kMaxStackDegree) {
    alignas(64) std::array<double, (tolerances::kMaxStackDegree + 1) * 3 * kLanes> work;
    const double* rows = curve.control_points().coordinates().data();
    if (width == 2) evaluate_all<2>(rows, n, ts, out.data(), work.data());
    else evaluate_all<3>(rows, n, ts, out.data(), work.data());
    return;
  }
  // General path (any dimension, rational): point by point with one workspace.
  std::vector<double> rows(static_cast<std::size_t>(n + 1) * width), base;
  base.reserve(rows.size());
  const auto& p = curve.control_points();
  for (int i = 0; i <= n; ++i) {
    const double w = rational ? curve.weights()[i] : 1.0;
    for (int j = 0; j < d; ++j) base.push_back(rational ? w * p[i][j] : p[i][j]);
    if (rational) base.push_back(w);
  }
  for (std::size_t k = 0; k < ts.size(); ++k) {
    std::copy(base.begin(), base.end(), rows.begin());
    detail::de_casteljau_in_place(rows.data(), n, width, ts[k]);
    for (int j = 0; j < d; ++j) out[k * d + j] = rational ? rows[j] / rows[d] : rows[j];
  }
}

}  // namespace casteljau

// The cells a tessellation needs at least (tessellate_estimate.hpp).
#include "tessellate_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "casteljau/ops/tolerance.hpp"


namespace casteljau::tessellation {
namespace {

/// Distance from the middle sample of a line to the chord of its ends.
double chord_deviation(const double* a, const double* middle, const double* b) {
  const Vec3 chord{{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}};
  return norm(Vec3{{middle[0], middle[1], middle[2]}} - chord);
}

}  // namespace

CellEstimate::CellEstimate(const std::vector<Patch>& patches) {
  std::size_t spans = 0;
  for (const Patch& patch : patches) spans += (patch.breaks_u.size() - 1) * (patch.breaks_v.size() - 1);
  const double per_span = static_cast<double>(tolerances::kMeshEstimateSubcells) / static_cast<double>(spans);
  m_ = std::max(1, static_cast<int>(std::sqrt(per_span)));
  const int n = 2 * m_ + 1;  // samples per span and direction: subcell edges and middles
  // The samples of one span [a, b]: k / (n - 1) of the way, b itself last.
  const auto span_samples = [n](double a, double b, double* out) {
    for (int k = 0; k < n; ++k) out[k] = k == n - 1 ? b : a + (b - a) * (static_cast<double>(k) / (n - 1));
  };
  // The m x m subcells of one span, its samples read through at(a, b).
  const auto add_subcells = [this](const auto& at) {
    for (int i = 0; i < m_; ++i) {
      for (int j = 0; j < m_; ++j) {
        double bend_u = 0.0, bend_v = 0.0;
        for (int k = 0; k < 3; ++k) {  // the subcell's lines at fractions 0, 1/2 and 1
          const int a = 2 * i, b = 2 * j;
          bend_u += std::sqrt(chord_deviation(at(a, b + k), at(a + 1, b + k), at(a + 2, b + k)));
          bend_v += std::sqrt(chord_deviation(at(a + k, b), at(a + k, b + 1), at(a + k, b + 2)));
        }
        bend_u_.push_back(bend_u / 3);
        bend_v_.push_back(bend_v / 3);
      }
    }
  };
  root_begin_.push_back(0);
  for (const Patch& patch : patches) {
    // One grid batch per knot span in u over the samples of up to kBatch
    // spans in v (a few hundred kB at most).
    constexpr std::size_t kBatch = 256;
    const std::size_t spans_u = patch.breaks_u.size() - 1, spans_v = patch.breaks_v.size() - 1;
    const std::size_t width = static_cast<std::size_t>(n);
    std::vector<double> us(width), vs(spans_v * width), grid(width * std::min(spans_v, kBatch) * width * 3);
    for (std::size_t j = 0; j < spans_v; ++j) span_samples(patch.breaks_v[j], patch.breaks_v[j + 1], &vs[j * width]);
    for (std::size_t i = 0; i < spans_u; ++i) {
      span_samples(patch.breaks_u[i], patch.breaks_u[i + 1], us.data());
      for (std::size_t first = 0; first < spans_v; first += kBatch) {
        const std::size_t count = std::min(kBatch, spans_v - first), columns = count * width;
        const std::span<double> out(grid.data(), width * columns * 3);
        patch.surface.grid_points_at(us, std::span<const double>(vs).subspan(first * width, columns), out);
        for (std::size_t j = 0; j < count; ++j) {
          // Sample (a, b) of span (i, first + j): row a of the batch, column j n + b.
          const auto at = [&grid, columns, width, j](int a, int b) {
            return grid.data() + (static_cast<std::size_t>(a) * columns + j * width + static_cast<std::size_t>(b)) * 3;
          };
          add_subcells(at);
          root_begin_.push_back(bend_u_.size());
        }
      }
    }
  }
}

namespace {

/// sum over subcells [first, last) of max(bend_u x, f) max(bend_v x, f):
/// the cells at 1/sqrt(eps) = x.
double cells_at(const std::vector<double>& bend_u, const std::vector<double>& bend_v, std::size_t first,
                std::size_t last, double x, double f) {
  double cells = 0.0;
  for (std::size_t s = first; s < last; ++s) cells += std::max(bend_u[s] * x, f) * std::max(bend_v[s] * x, f);
  return cells;
}

/// 1 / sqrt(eps) for a tessellation tolerance, eps the bound on each sampled deviation.
double inverse_root_deviation(double tolerance) {
  return 1.0 / std::sqrt(tolerances::kMeshSampledDeviationFraction * tolerance);
}

}  // namespace

double CellEstimate::root_cells(std::size_t root, double tolerance) const {
  return cells_at(bend_u_, bend_v_, root_begin_[root], root_begin_[root + 1], inverse_root_deviation(tolerance),
                  1.0 / m_);
}

double CellEstimate::cells(double tolerance) const {
  return cells_at(bend_u_, bend_v_, 0, bend_u_.size(), inverse_root_deviation(tolerance), 1.0 / m_);
}

double CellEstimate::tolerance_for(double cells) const {
  // As the tolerance grows, x = 1/sqrt(eps) falls to 0 and the count to one
  // cell per root; it grows without bound with x unless nothing bends.
  if (static_cast<double>(roots()) > cells) return std::numeric_limits<double>::infinity();
  const double f = 1.0 / m_;
  const auto count = [&](double x) { return cells_at(bend_u_, bend_v_, 0, bend_u_.size(), x, f); };
  double low = 0.0, high = 1.0;
  while (count(high) <= cells) {
    if (high > 1e300) return 0.0;  // flat: every tolerance fits
    low = high;
    high *= 2.0;
  }
  while (high - low > 1e-7 * high) {
    const double middle = 0.5 * (low + high);
    (count(middle) <= cells ? low : high) = middle;
  }
  // count(low) <= cells: eps = 1 / low^2.
  return 1.0 / (low * low) / tolerances::kMeshSampledDeviationFraction;
}

}  // namespace casteljau::tessellation

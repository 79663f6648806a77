// B-spline approximation of point sets: least squares (The NURBS Book
// §9.4.1), smoothing with a second-derivative penalty and GCV (Craven & Wahba
// 1979; Hutchinson & de Hoog 1985 for the trace), and refinement to a
// tolerance. See interpolation/fit.hpp.
//
// All three share one linear problem (FitSystem): the design rows N_j(t_k)
// rotated into a banded R once (banded_qr.hpp), the penalty Ω = (∫ N_j'' N_k'')
// as rows r_q at Gauss nodes; for a given λ the rows √λ r_q are merged with
// R's, and R Q = Qᵀ P̃ solved for the d coordinates together. The Gram matrix
// G = BᵀWB and Ω are kept for the trace of the hat matrix (GCV) and the scale
// λ₀ = tr G / tr Ω only: the normal equations (G + λ Ω) Q = Bᵀ P̃ − λ K, which
// square the design's condition number, are never solved (issue 43).

#include "casteljau/interpolation/fit.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/interpolation/tolerance.hpp"
#include "../core/number_text.hpp"
#include "collocation.hpp"
#include "banded_qr.hpp"
#include "fit_banded.hpp"
#include "input_checks.hpp"

namespace casteljau {

namespace {

using detail::BandedQr;
using detail::number_text;
using detail::SymmetricBand;

constexpr double kNotANumber = std::numeric_limits<double>::quiet_NaN();

// --- input checks ------------------------------------------------------------------

/// Checks what every fit needs: matching counts, finite coordinates and
/// parameters, strictly increasing parameters, a degree in range and at
/// least p+1 points.
Status check_fit_input(const PointArray& points, std::span<const double> parameters, int degree) {
  if (points.empty()) return Error{"a fit needs points, got none"};
  if (parameters.size() != points.size()) {
    return Error{"a fit needs one parameter per point: " + std::to_string(parameters.size()) +
                 " parameters for " + std::to_string(points.size()) + " points"};
  }
  if (degree < 1 || degree > tolerances::kMaxBSplineDegree) {
    return Error{"degree " + std::to_string(degree) + " is outside 1.." +
                 std::to_string(tolerances::kMaxBSplineDegree)};
  }
  if (auto finite = detail::check_coordinates(points); !finite) return finite.error();
  if (auto increasing = detail::check_increasing(parameters); !increasing) return increasing.error();
  const std::size_t needed = static_cast<std::size_t>(degree) + 1;
  if (points.size() < needed) {
    return Error{"a fit of degree " + std::to_string(degree) + " needs at least " + std::to_string(needed) +
                 " points, got " + std::to_string(points.size())};
  }
  return {};
}

/// Checks a weighted fit's weights: none (all 1), or one finite w_i >= 0 per point.
Status check_weights(std::span<const double> weights, std::size_t point_count) {
  if (weights.empty()) return {};
  if (weights.size() != point_count) {
    return Error{std::to_string(weights.size()) + " weights for " + std::to_string(point_count) +
                 " points, a weighted fit needs one weight per point"};
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (auto finite = check_finite(weights[i], "weight " + std::to_string(i)); !finite) return finite.error();
    if (weights[i] < 0.0) {
      return Error{"weight " + std::to_string(i) + " is " + number_text(weights[i]) + ", weights must be >= 0"};
    }
  }
  return {};
}

/// Checks n+1 control points of degree p against m+1 points.
Status check_control_point_count(std::size_t count, int degree, std::size_t point_count) {
  const std::size_t needed = static_cast<std::size_t>(degree) + 1;
  if (count < needed) {
    return Error{"a fit of degree " + std::to_string(degree) + " needs at least " + std::to_string(needed) +
                 " control points, got " + std::to_string(count)};
  }
  if (count > point_count) {
    return Error{std::to_string(count) + " control points for " + std::to_string(point_count) +
                 " points: a least-squares fit takes at most as many control points as points"};
  }
  return {};
}

// --- knots -------------------------------------------------------------------------

/// p+1 copies of t_0, the interior knots, p+1 copies of t_m.
std::vector<double> clamped_knots(std::span<const double> parameters, int degree,
                                  std::span<const double> interior) {
  std::vector<double> knots;
  knots.reserve(interior.size() + 2 * static_cast<std::size_t>(degree) + 2);
  knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, parameters.front());
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), static_cast<std::size_t>(degree) + 1, parameters.back());
  return knots;
}

/// The fit's rows and free columns: interpolated ends fix Q_0 = P_0 and
/// Q_n = P_m and leave the columns 1..n−1 and the rows 1..m−1 (The NURBS
/// Book eq. 9.63–9.67); free ends leave all of them.
struct FreePart {
  std::size_t first_row = 0, end_row = 0;
  std::vector<std::size_t> columns;
};
FreePart free_part(std::size_t knot_count, int degree, std::size_t point_count, FitEnds ends) {
  const std::size_t n = knot_count - static_cast<std::size_t>(degree) - 2;
  const bool clamp = ends == FitEnds::interpolated;
  FreePart part;
  part.first_row = clamp ? 1 : 0;
  part.end_row = clamp ? point_count - 1 : point_count;
  if (clamp && n < 2) return part;  // Q_0 and Q_n fixed, nothing free
  for (std::size_t j = clamp ? 1 : 0; j <= (clamp ? n - 1 : n); ++j) part.columns.push_back(j);
  return part;
}

/// The Schoenberg–Whitney condition of a fit's free columns and rows
/// (detail::schoenberg_whitney_gap), as the error naming the basis function
/// left without a point; then BᵀB is singular.
Status check_schoenberg_whitney(std::span<const double> knots, int degree, std::span<const double> parameters,
                                std::span<const double> weights, FitEnds ends) {
  const FreePart part = free_part(knots.size(), degree, parameters.size(), ends);
  const std::size_t rows = part.end_row - part.first_row;
  const std::span<const double> sites = parameters.subspan(part.first_row, rows);
  const std::span<const double> row_weights = weights.empty() ? weights : weights.subspan(part.first_row, rows);
  if (const auto gap = detail::schoenberg_whitney_gap(knots, degree, part.columns, sites, row_weights)) {
    return detail::schoenberg_whitney_error(knots, degree, sites, *gap, part.first_row, !weights.empty(),
                                            "the fit's normal equations are singular");
  }
  return {};
}

// --- Gauss–Legendre ------------------------------------------------------------------

/// Nodes and weights of the q-point Gauss–Legendre rule on [-1, 1] (exact for
/// polynomials of degree 2q − 1), by Newton's method on P_q from the
/// asymptotic guesses cos(π (i + 3/4) / (q + 1/2)) (Abramowitz & Stegun 22.16;
/// Numerical Recipes' gauleg). Converges to rounding in a few steps.
void gauss_legendre(int count, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(static_cast<std::size_t>(count), 0.0);
  weights.assign(static_cast<std::size_t>(count), 0.0);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < (count + 1) / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (count + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = 0.0;  // P_j(x), P_{j-1}(x) by Bonnet's recursion
      for (int j = 1; j <= count; ++j) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p2) / j;
      }
      derivative = count * (x * p0 - p1) / (x * x - 1.0);
      const double step = p0 / derivative;
      x -= step;
      if (std::abs(step) <= 4e-16) break;
    }
    const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    const auto low = static_cast<std::size_t>(i), high = static_cast<std::size_t>(count - 1 - i);
    nodes[low] = -x;
    nodes[high] = x;
    weights[low] = weight;
    weights[high] = weight;
  }
  if (count % 2 == 1) nodes[static_cast<std::size_t>(count / 2)] = 0.0;  // exact middle node
}

/// The penalty Ω_jk = ∫_{t_0}^{t_m} N_j''(u) N_k''(u) du over all n+1 basis
/// functions as a sum of rows, Ω = Σ_q r_q r_qᵀ with r_q = √w_q N''(u_q) at
/// the nodes u_q of the p−1 point Gauss–Legendre rule on each non-empty knot
/// span (exact there: N_j'' N_k'' is a polynomial of degree 2p − 4). The rows
/// go into the least-squares problem beside the data's, scaled by √λ, so that
/// the penalized fit is solved by rotations too. Row q's p+1 values are for
/// the columns first[q] .. first[q] + p. O(n p²).
struct PenaltyRows {
  std::vector<std::size_t> first;
  std::vector<double> values;
};
PenaltyRows penalty_rows(std::span<const double> knots, int degree) {
  const auto p = static_cast<std::size_t>(degree);
  const std::size_t count = knots.size() - p - 1;
  PenaltyRows rows;
  std::vector<double> nodes, weights;
  gauss_legendre(std::max(degree - 1, 1), nodes, weights);
  std::vector<double> derivatives(3 * (p + 1));
  for (std::size_t span = p; span < count; ++span) {
    const double a = knots[span], b = knots[span + 1];
    if (!(a < b)) continue;
    const double half = 0.5 * (b - a), middle = 0.5 * (a + b);
    for (std::size_t g = 0; g < nodes.size(); ++g) {
      basis_function_derivatives(knots, degree, static_cast<int>(span), middle + half * nodes[g], 2, derivatives);
      const double root = std::sqrt(half * weights[g]);
      rows.first.push_back(span - p);
      for (std::size_t r = 0; r <= p; ++r) rows.values.push_back(root * derivatives[2 * (p + 1) + r]);
    }
  }
  return rows;
}

// --- the linear problem ------------------------------------------------------------

/// One solve at a given λ: the control points and what GCV needs.
struct Solution {
  PointArray control_points;
  double residual_sum = 0.0;  ///< Σ ‖C(t_k) − P_k‖² from the design rows
  double trace = 0.0;         ///< tr H
};

/// What GCV needs of one λ: the residual and tr H, without the curve.
struct Score {
  double residual_sum = 0.0;
  double trace = 0.0;
};

/// The storage of one solve, kept across the λ of a GCV search: for 10⁶
/// points each solve would otherwise allocate (and page in) some 50 MB.
struct SolveBuffers {
  BandedQr qr{0, 1, 1};
  SymmetricBand matrix{0, 1};  // RᵀR = L D Lᵀ, for the trace
  std::vector<double> norms;   // the diagonal of G + λΩ
  std::vector<double> rhs;
};

/// The least-squares / smoothing problem on fixed knots (see the file comment).
/// Interpolated ends fix Q_0 = P_0 and Q_n = P_m, leave the free columns
/// 1..n−1 and the rows 1..m−1 with P̃_k = P_k − N_0(t_k) P_0 − N_n(t_k) P_m
/// (The NURBS Book eq. 9.63–9.67); free ends leave every column and row.
/// The data rows are rotated into R once (BandedQr); each λ adds the penalty
/// rows √λ r_q to a copy, their fixed columns' share moved to the right side
/// as the data's is.
class FitSystem {
 public:
  /// `weights`: empty (all 1) or one w_k >= 0 per point, multiplying row k's
  /// squared residual (its row scaled by √w_k).
  FitSystem(const PointArray& points, std::span<const double> parameters, int degree, std::vector<double> knots,
            FitEnds ends, bool with_penalty, std::span<const double> weights = {})
      : points_(points), weights_(weights.begin(), weights.end()), degree_(degree), knots_(std::move(knots)),
        count_(knots_.size() - static_cast<std::size_t>(degree) - 1), clamp_(ends == FitEnds::interpolated),
        first_row_(clamp_ ? 1 : 0), end_row_(clamp_ ? points.size() - 1 : points.size()),
        first_column_(clamp_ ? 1 : 0), free_count_(clamp_ ? count_ - 2 : count_),
        gram_(free_count_, degree), data_(free_count_, degree, static_cast<std::size_t>(points.dimension())) {
    const auto p = static_cast<std::size_t>(degree);
    const auto d = static_cast<std::size_t>(points.dimension());
    const std::size_t rows = end_row_ - first_row_;
    spans_.resize(rows);
    basis_.resize(rows * (p + 1));
    targets_.resize(rows * d);
    std::vector<double> values(p + 1);
    for (std::size_t k = first_row_; k < end_row_; ++k) {
      const std::size_t row = k - first_row_;
      const int span = find_span(knots_, degree, parameters[k]);
      spans_[row] = static_cast<std::size_t>(span);
      basis_functions(knots_, degree, span, parameters[k], std::span<double>(basis_.data() + row * (p + 1), p + 1));
      double* target = targets_.data() + row * d;
      for (std::size_t c = 0; c < d; ++c) target[c] = points[k][c];
      const std::size_t first = free_row(spans_[row] - p, basis_.data() + row * (p + 1), target, values);
      const double weight = weight_of(row);
      if (weight == 0.0) continue;
      data_.add_row(first, values, std::span<const double>(target, d), std::sqrt(weight));
      gram_.add_outer_product(first, values, weight);
    }
    if (with_penalty) {
      const PenaltyRows all = penalty_rows(knots_, degree);
      free_penalty_ = SymmetricBand(free_count_, degree);
      std::vector<double> target(d);
      for (std::size_t q = 0; q < all.first.size(); ++q) {
        std::fill(target.begin(), target.end(), 0.0);  // 0 − the fixed columns' share
        const std::size_t first = free_row(all.first[q], all.values.data() + q * (p + 1), target.data(), values);
        penalty_first_.push_back(first);
        penalty_values_.insert(penalty_values_.end(), values.begin(), values.end());
        penalty_targets_.insert(penalty_targets_.end(), target.begin(), target.end());
        free_penalty_.add_outer_product(first, values, 1.0);
      }
    }
  }

  std::span<const double> knots() const noexcept { return knots_; }
  std::size_t control_point_count() const noexcept { return count_; }
  std::size_t free_count() const noexcept { return free_count_; }

  /// λ₀ = tr G / tr Ω over the free columns: where data and penalty weigh alike.
  double smoothing_scale() const noexcept {
    const double g = data_trace(), omega = penalty_trace();
    return g > 0.0 && omega > 0.0 ? g / omega : 1.0;
  }
  /// tr G = tr(BᵀWB) and tr Ω over the free columns.
  double data_trace() const noexcept { return gram_.trace(); }
  double penalty_trace() const noexcept { return free_penalty_.trace(); }

  /// The fit at λ (0: plain least squares); nothing when the system is
  /// singular. `with_trace`: also tr H by the band of the inverse (for λ = 0
  /// it is the number of control points exactly).
  std::optional<Solution> solve(double lambda, bool with_trace) const {
    SolveBuffers buffers;
    const auto score = solve_into(lambda, with_trace, buffers);
    if (!score) return std::nullopt;
    const auto d = static_cast<std::size_t>(points_.dimension());
    std::vector<double> all(count_ * d);
    if (clamp_) {
      std::copy(points_[0].begin(), points_[0].end(), all.begin());
      std::copy(points_[points_.size() - 1].begin(), points_[points_.size() - 1].end(),
                all.begin() + static_cast<std::ptrdiff_t>((count_ - 1) * d));
    }
    std::copy(buffers.rhs.begin(), buffers.rhs.end(), all.begin() + static_cast<std::ptrdiff_t>(first_column_ * d));
    return Solution{PointArray::from_trusted(points_.dimension(), std::move(all)), score->residual_sum, score->trace};
  }

  /// The residual and tr H at λ > 0 for GCV, in `buffers` (reused from one
  /// λ to the next); nothing when the system is singular.
  std::optional<Score> score(double lambda, SolveBuffers& buffers) const { return solve_into(lambda, true, buffers); }

 private:
  /// Rotates the penalty rows (λ > 0) into a copy of the data's R and solves
  /// for the free control points into buffers.rhs; nothing where a pivot of
  /// RᵀR = G + λΩ is not above kFitSingularPivot times its diagonal entry.
  std::optional<Score> solve_into(double lambda, bool with_trace, SolveBuffers& buffers) const {
    const auto p = static_cast<std::size_t>(degree_);
    const auto d = static_cast<std::size_t>(points_.dimension());
    buffers.norms.resize(free_count_);
    for (std::size_t i = 0; i < free_count_; ++i) buffers.norms[i] = gram_.at(i, i);
    if (lambda > 0.0) {
      // The data's R row by row, merged with the penalty rows √λ r_q by
      // first column (BandedQr's order): O((n + penalty rows) p²) per λ,
      // whatever the number of points.
      const double root = std::sqrt(lambda);
      buffers.qr.reset(free_count_, degree_, d);
      std::size_t q = 0;
      const auto add_penalty_rows_to = [&](std::size_t column) {
        for (; q < penalty_first_.size() && penalty_first_[q] <= column; ++q)
          buffers.qr.add_row(penalty_first_[q], std::span<const double>(penalty_values_.data() + q * (p + 1), p + 1),
                             std::span<const double>(penalty_targets_.data() + q * d, d), root);
      };
      for (std::size_t j = 0; j < free_count_; ++j) {
        add_penalty_rows_to(j);
        buffers.qr.add_row(j, data_.row(j), data_.right_side(j), 1.0);
      }
      add_penalty_rows_to(free_count_);
      for (std::size_t i = 0; i < free_count_; ++i) buffers.norms[i] += lambda * free_penalty_.at(i, i);
    } else {
      buffers.qr = data_;
    }
    if (!buffers.qr.regular(buffers.norms)) return std::nullopt;
    buffers.rhs.resize(free_count_ * d);
    buffers.qr.solve(buffers.rhs);
    Score score;
    score.residual_sum = residual_sum(buffers.rhs);
    const std::size_t fixed = count_ - free_count_;
    if (lambda == 0.0) {
      score.trace = static_cast<double>(count_);
    } else if (with_trace) {
      buffers.qr.factored_normal_matrix(buffers.matrix);
      score.trace = static_cast<double>(fixed) + buffers.matrix.trace_of_inverse_times(gram_);
    } else {
      score.trace = kNotANumber;
    }
    return score;
  }

  /// A row of p+1 values for the columns column0 .. column0 + p over all
  /// n+1 control points, as the free columns see it: `free_values` for the
  /// free columns from the one returned on, and the fixed columns' share
  /// (interpolated ends: value × P_0 or P_m) taken off `target` (d values).
  std::size_t free_row(std::size_t column0, const double* values, double* target,
                       std::vector<double>& free_values) const {
    const auto p = static_cast<std::size_t>(degree_);
    const auto d = static_cast<std::size_t>(points_.dimension());
    const std::size_t first = column0 < first_column_ ? 0 : column0 - first_column_;
    std::fill(free_values.begin(), free_values.end(), 0.0);
    for (std::size_t r = 0; r <= p; ++r) {
      const std::size_t column = column0 + r;
      if (column >= first_column_ && column < first_column_ + free_count_) {
        free_values[column - first_column_ - first] = values[r];
      } else if (values[r] != 0.0) {  // a fixed end control point
        const auto fixed = column == 0 ? points_[0] : points_[points_.size() - 1];
        for (std::size_t c = 0; c < d; ++c) target[c] -= values[r] * fixed[c];
      }
    }
    return first;
  }

  /// The weight of design row `row` (1 without weights).
  double weight_of(std::size_t row) const noexcept { return weights_.empty() ? 1.0 : weights_[row + first_row_]; }

  /// Σ_k w_k ‖P̃_k − Σ_free N_j(t_k) Q_j‖² for the free control points Q
  /// (free_count rows of d values; rows 0 and m of interpolated ends are exact).
  double residual_sum(std::span<const double> free) const {
    const auto p = static_cast<std::size_t>(degree_);
    const auto d = static_cast<std::size_t>(points_.dimension());
    double sum = 0.0;
    for (std::size_t row = 0; row < spans_.size(); ++row) {
      const double* values = basis_.data() + row * (p + 1);
      const std::size_t column0 = spans_[row] - p;
      // The free columns of the row's p+1 (interpolated ends drop the first and last).
      const std::size_t first = std::max(column0, first_column_);
      const std::size_t end = std::min(column0 + p + 1, first_column_ + free_count_);
      const double weight = weight_of(row);
      for (std::size_t c = 0; c < d; ++c) {
        double fitted = 0.0;  // in a register: Σ_r N_r(t) Q_r, coordinate c
        for (std::size_t a = first; a < end; ++a) fitted += values[a - column0] * free[(a - first_column_) * d + c];
        const double r = targets_[row * d + c] - fitted;
        sum += weight * r * r;
      }
    }
    return sum;
  }

  const PointArray& points_;
  std::vector<double> weights_;  // empty: all 1
  int degree_;
  std::vector<double> knots_;
  std::size_t count_;         // n+1 control points
  bool clamp_;
  std::size_t first_row_, end_row_;
  std::size_t first_column_, free_count_;
  std::vector<std::size_t> spans_;
  std::vector<double> basis_;    // rows x (p+1)
  std::vector<double> targets_;  // rows x d: P̃_k
  SymmetricBand gram_;           // G = BᵀWB over the free columns
  BandedQr data_;                // the data rows rotated into R
  SymmetricBand free_penalty_{0, 1};    // Ω over the free columns
  std::vector<std::size_t> penalty_first_;  // the penalty rows over the free columns
  std::vector<double> penalty_values_, penalty_targets_;
};

/// GCV(λ) from a solution: (RSS / N) / (1 − tr H / N)², NaN when tr H >= N.
double gcv_score(double residual_sum, double trace, std::size_t point_count) {
  const double n = static_cast<double>(point_count);
  const double denominator = 1.0 - trace / n;
  if (!(denominator > 0.0)) return kNotANumber;
  return residual_sum / n / (denominator * denominator);
}

/// The BSplineFit of a solution: the curve, its errors at the parameters
/// (evaluated on the curve itself, not from the design rows), λ and GCV (from
/// the weighted residuals, as the search weighs them, Craven & Wahba 1979;
/// scipy 1.10's GCV leaves them unweighted).
BSplineFit make_result(const FitSystem& system, Solution solution, const PointArray& points,
                       std::span<const double> parameters, int degree, double lambda,
                       std::span<const double> weights = {}) {
  BSplineCurve curve = BSplineCurve::from_trusted(degree, std::vector<double>(system.knots().begin(), system.knots().end()),
                                                  std::move(solution.control_points));
  const auto d = static_cast<std::size_t>(points.dimension());
  std::vector<double> fitted(points.size() * d);
  points_at(curve, parameters, fitted);
  std::vector<double> errors(points.size());
  double max_error = 0.0, sum = 0.0, weighted = 0.0;
  std::size_t worst = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    errors[i] = distance(points[i], std::span<const double>(fitted.data() + i * d, d));
    sum += errors[i] * errors[i];
    weighted += (weights.empty() ? 1.0 : weights[i]) * errors[i] * errors[i];
    if (errors[i] > max_error) {
      max_error = errors[i];
      worst = i;
    }
  }
  const double rms = std::sqrt(sum / static_cast<double>(points.size()));
  const double trace = solution.trace;
  return BSplineFit{std::move(curve), std::move(errors), max_error, worst, rms, lambda, trace,
                    gcv_score(weighted, trace, points.size()), false};
}

Error singular_error(std::size_t control_points, double lambda) {
  std::string message = "the fit's normal equations are singular with " + std::to_string(control_points) +
                        " control points";
  if (lambda > 0.0) message += " and λ = " + number_text(lambda);
  return Error{message + ": the data do not determine the control points"};
}

/// A number to three significant digits, for the approximate values of a hint.
std::string rounded_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// Why a smoothing fit with a given λ is singular, and which λ would do.
/// The system G + λΩ loses G in rounding once λ tr Ω outweighs tr G by about
/// 1 / tolerances::kFitSingularPivot (Ω alone is singular on straight lines
/// with free ends); below λ₀ the data alone must determine the control
/// points, which more control points than points (knots at every parameter)
/// do not. The useful range is the one GCV searches: from λ₀ 10^-10 (all but
/// interpolating) to λ₀ 10^6 (heavily smoothed), λ₀ = tr G / tr Ω.
Error smoothing_singular_error(const FitSystem& system, double lambda, std::size_t point_count) {
  const double scale = system.smoothing_scale();
  // log10(λ tr Ω / tr G) without forming the product, which overflows for λ near 1e308.
  const double g = system.data_trace(), omega = system.penalty_trace();
  const double decades = g > 0.0 && omega > 0.0 ? std::log10(lambda) + std::log10(omega) - std::log10(g) : 0.0;
  const std::string power = "10^" + std::to_string(static_cast<long>(std::lround(decades)));
  std::string message = "the smoothing λ = " + number_text(lambda);
  if (lambda >= scale) {
    message += " is too large for these data: λ·tr(Ω) outweighs tr(BᵀB) by about " + power +
               ", the data are lost in rounding and";
  } else {
    message += " is too small for these data: λ·tr(Ω) is about " + power + " of tr(BᵀB), too little to determine " +
               std::to_string(system.control_point_count()) + " control points from " + std::to_string(point_count) +
               " points:";
  }
  return Error{message + " the fit's normal equations are singular; λ from about " +
               rounded_text(scale * std::pow(10.0, -tolerances::kGcvSearchDecadesBelow)) + " (nearly interpolating) to " +
               rounded_text(scale * std::pow(10.0, tolerances::kGcvSearchDecadesAbove)) +
               " (heavily smoothed, towards a straight line) is the range GCV searches here (λ₀·10^-" +
               rounded_text(tolerances::kGcvSearchDecadesBelow) + " to λ₀·10^" +
               rounded_text(tolerances::kGcvSearchDecadesAbove) + ", λ₀ = tr(BᵀB)/tr(Ω) = " + rounded_text(scale) +
               "): give a λ there, or let GCV choose it", ErrorKind::singular};
}

// --- GCV search ----------------------------------------------------------------------

/// The number of steps of the GCV grid over log10 λ.
int grid_steps() {
  return static_cast<int>(
      std::lround((tolerances::kGcvSearchDecadesAbove + tolerances::kGcvSearchDecadesBelow) / tolerances::kGcvGridStepDecades));
}

/// One GCV search's evaluations, reported as the fraction of those it makes
/// at most: the grid, its extension beyond an edge, Brent's search and the
/// final solve.
class GcvProgress {
 public:
  GcvProgress(Progress progress, int grid_points) : progress_(progress) {
    const double beyond = tolerances::kGcvSearchDecadesBeyond / tolerances::kGcvGridStepDecades;
    total_ = static_cast<double>(grid_points) + beyond + tolerances::kGcvBrentEvaluations + 1.0;
  }
  void step() {
    done_ += 1.0;
    progress_(std::min(done_ / total_, 1.0));
  }

 private:
  Progress progress_;
  double done_ = 0.0, total_ = 1.0;
};

/// GCV at λ = λ₀ 10^x, +∞ where the system is singular, GCV undefined, or
/// the fit (nearly) interpolates.
double gcv_at(const FitSystem& system, double scale, double x, std::size_t point_count, SolveBuffers& buffers,
              GcvProgress& progress) {
  const auto solution = system.score(scale * std::pow(10.0, x), buffers);
  progress.step();
  if (!solution) return std::numeric_limits<double>::infinity();
  if (static_cast<double>(point_count) - solution->trace < tolerances::kGcvNearInterpolation)
    return std::numeric_limits<double>::infinity();  // (near) interpolation: GCV is rounding noise there
  const double score = gcv_score(solution->residual_sum, solution->trace, point_count);
  return std::isnan(score) ? std::numeric_limits<double>::infinity() : score;
}

/// The minimum of f on [a, b] to within `width`, from a point x inside with
/// f(x) = fx below f at both ends: Brent's method (Brent 1973, "Algorithms for
/// Minimization without Derivatives", ch. 5; the form of Numerical Recipes,
/// 3rd ed., §10.3): a parabola through the three best points where it falls
/// inside the bracket and shrinks it, a golden-section step otherwise. The
/// minimizer and its value; at most `evaluations` calls of f.
template <class F>
std::pair<double, double> brent_minimum(F&& f, double a, double b, double x, double fx, double width,
                                        int evaluations) {
  constexpr double kGolden = 0.3819660112501051;  // (3 − √5) / 2
  const double tol1 = 0.25 * width, tol2 = 2.0 * tol1;
  double w = x, v = x, fw = fx, fv = fx, d = 0.0, e = 0.0;
  for (int i = 0; i < evaluations; ++i) {
    const double middle = 0.5 * (a + b);
    if (std::abs(x - middle) <= tol2 - 0.5 * (b - a)) break;
    bool golden = true;
    if (std::abs(e) > tol1) {  // a parabola through x, w, v
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      const double previous = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * previous) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        golden = false;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = middle >= x ? tol1 : -tol1;
      }
    }
    if (golden) {
      e = x >= middle ? a - x : b - x;
      d = kGolden * e;
    }
    const double u = std::abs(d) >= tol1 ? x + d : x + (d >= 0.0 ? tol1 : -tol1);
    const double fu = f(u);
    if (fu <= fx) {
      (u >= x ? a : b) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return {x, fx};
}

/// The λ minimizing GCV: the best point of a grid over log10 λ (extended
/// beyond the top of the range while GCV keeps falling there, by up to
/// kGcvSearchDecadesBeyond: smooth data whose minimum lies above λ₀ 10^6,
/// scipy's gcvspl case at λ = 0.39 where the range ended at 0.021; an
/// interior local minimum before one at the bottom edge), then Brent's
/// method in the bracket of its two neighbours. Nothing when GCV is
/// undefined at every grid point.
std::optional<double> gcv_smoothing(const FitSystem& system, std::size_t point_count, GcvProgress& progress) {
  const double scale = system.smoothing_scale();
  const double step = tolerances::kGcvGridStepDecades;
  const double low = -tolerances::kGcvSearchDecadesBelow;
  const int steps = grid_steps();
  SolveBuffers buffers;
  const auto at = [&](double x) { return gcv_at(system, scale, x, point_count, buffers, progress); };
  std::vector<double> scores;
  for (int i = 0; i <= steps; ++i) scores.push_back(at(low + i * step));
  auto best = std::min_element(scores.begin(), scores.end());
  if (!std::isfinite(*best)) return std::nullopt;
  const double lower = low;
  double upper = low + steps * step;
  // Beyond the top edge where the best score lies there: on while GCV falls
  // (the first point where it rises again closes the bracket).
  const int beyond = static_cast<int>(std::lround(tolerances::kGcvSearchDecadesBeyond / step));
  if (best == scores.end() - 1) {
    for (int i = 0; i < beyond; ++i) {
      const double score = at(upper + step);
      const bool falling = score < scores.back();
      upper += step;
      scores.push_back(score);
      if (!falling) break;
    }
  }
  best = std::min_element(scores.begin(), scores.end());
  // At the bottom edge GCV may fall on towards interpolation, the 0/0 limit
  // of RSS / (n − tr H)² as λ → 0, below the true minimum (222 noisy points
  // with two 7.5e-5 apart: 0.151 at 221.999 degrees of freedom against 0.241
  // at the minimum, 21.6): an interior local minimum of the grid is taken
  // before it; without one (data without noise) interpolation is the answer.
  // The bottom edge is the lowest λ with a score (those below interpolate
  // within kGcvNearInterpolation: +∞).
  const auto bottom = std::find_if(scores.begin(), scores.end(), [](double score) { return std::isfinite(score); });
  if (best == bottom) {
    for (auto i = bottom + 1; i + 1 < scores.end(); ++i)
      if (*i <= *(i - 1) && *i <= *(i + 1) && (best == bottom || *i < *best)) best = i;
  }
  const double best_x = lower + static_cast<double>(best - scores.begin()) * step;
  const double a = std::max(best_x - step, lower), b = std::min(best_x + step, upper);
  const auto [x, value] = brent_minimum(at, a, b, best_x, *best, tolerances::kGcvRefinementDecades,
                                        tolerances::kGcvBrentEvaluations);
  return scale * std::pow(10.0, value <= *best ? x : best_x);
}

}  // namespace

std::vector<double> approximation_knots(std::span<const double> parameters, int degree,
                                        std::size_t control_point_count) {
  const auto p = static_cast<std::size_t>(degree);
  assert(degree >= 1 && control_point_count >= p + 1 && control_point_count <= parameters.size());
  const std::size_t n = control_point_count - 1, m = parameters.size() - 1;
  const std::size_t pieces = n - p + 1;  // n − p + 1 knot spans
  std::vector<double> interior;
  interior.reserve(n - p);
  for (std::size_t j = 1; j <= n - p; ++j) {
    // j d = j (m+1) / (n−p+1) in integers, so i and α are exact (eq. 9.69).
    const std::size_t numerator = j * (m + 1);
    const std::size_t i = numerator / pieces;
    const double alpha = static_cast<double>(numerator % pieces) / static_cast<double>(pieces);
    interior.push_back((1.0 - alpha) * parameters[i - 1] + alpha * parameters[i]);
  }
  return clamped_knots(parameters, degree, interior);
}

Expected<BSplineFit> fit_least_squares(const PointArray& points, std::span<const double> parameters, int degree,
                                       std::size_t control_point_count, FitEnds ends) {
  if (auto valid = check_fit_input(points, parameters, degree); !valid) return valid.error();
  if (auto valid = check_control_point_count(control_point_count, degree, points.size()); !valid) {
    return valid.error();
  }
  const FitSystem system(points, parameters, degree, approximation_knots(parameters, degree, control_point_count),
                         ends, false);
  auto solution = system.solve(0.0, false);
  if (!solution) return singular_error(control_point_count, 0.0);
  return make_result(system, std::move(*solution), points, parameters, degree, 0.0);
}

Expected<BSplineFit> fit_least_squares_on_knots(const PointArray& points, std::span<const double> parameters,
                                                int degree, std::vector<double> knots, std::span<const double> weights,
                                                FitEnds ends) {
  if (auto valid = check_fit_input(points, parameters, degree); !valid) return valid.error();
  const std::size_t width = static_cast<std::size_t>(degree) + 1;
  if (knots.size() < 2 * width) {
    return Error{std::to_string(knots.size()) + " knots given, a B-spline of degree " + std::to_string(degree) +
                 " needs at least " + std::to_string(2 * width) + " (degree + 1 control points)"};
  }
  const std::size_t count = knots.size() - width;  // n + 1
  if (auto valid = validate_knots(knots, degree, count); !valid) return valid.error();
  if (auto valid = check_weights(weights, points.size()); !valid) return valid.error();
  const double lower = knots[width - 1], upper = knots[count];
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (parameters[i] < lower || parameters[i] > upper) {
      return Error{"parameter " + std::to_string(i) + " (" + number_text(parameters[i]) +
                   ") is outside the knots' domain [" + number_text(lower) + ", " + number_text(upper) + "]"};
    }
  }
  if (ends == FitEnds::interpolated) {
    // Q_0 = P_0 and Q_n = P_m put the curve through the end points only on
    // knots clamped there.
    const bool clamped_start = knots.front() == parameters.front() && knots[width - 1] == parameters.front();
    const bool clamped_end = knots.back() == parameters.back() && knots[count] == parameters.back();
    if (!clamped_start || !clamped_end) {
      return Error{"a fit with interpolated ends needs knots clamped at the first and last parameters (" +
                   number_text(parameters.front()) + " and " + number_text(parameters.back()) + ", degree + 1 = " +
                   std::to_string(width) + " copies each)"};
    }
  }
  if (auto ok = check_schoenberg_whitney(knots, degree, parameters, weights, ends); !ok) return ok.error();
  const FitSystem system(points, parameters, degree, std::move(knots), ends, false, weights);
  auto solution = system.solve(0.0, false);
  if (!solution) return singular_error(count, 0.0);
  return make_result(system, std::move(*solution), points, parameters, degree, 0.0, weights);
}

Expected<BSplineFit> fit_smoothing(const PointArray& points, std::span<const double> parameters,
                                   const SmoothingOptions& options, Progress progress) {
  const int degree = options.degree;
  if (auto valid = check_fit_input(points, parameters, degree); !valid) return valid.error();
  if (degree < 2) {
    return Error{"smoothing needs degree 2 or more (the penalty integrates C''), got degree " +
                 std::to_string(degree)};
  }
  if (auto valid = check_weights(options.weights, points.size()); !valid) return valid.error();
  if (options.smoothing) {
    const double lambda = *options.smoothing;
    if (auto finite = check_finite(lambda, "the smoothing λ"); !finite) return finite.error();
    if (lambda < 0.0) return Error{"the smoothing λ is " + number_text(lambda) + ", it must be >= 0"};
  }
  std::vector<double> knots;
  if (options.control_point_count == 0) {
    // A simple knot at every interior parameter: m + p control points.
    knots = clamped_knots(parameters, degree, parameters.subspan(1, parameters.size() - 2));
  } else {
    if (auto valid = check_control_point_count(options.control_point_count, degree, points.size()); !valid) {
      return valid.error();
    }
    knots = approximation_knots(parameters, degree, options.control_point_count);
  }
  const FitSystem system(points, parameters, degree, std::move(knots), options.ends, true, options.weights);
  const std::size_t count = system.control_point_count();
  double lambda = 0.0;
  bool from_gcv = false;
  if (options.smoothing) {
    lambda = *options.smoothing;
    if (lambda == 0.0 && count > points.size()) {
      return Error{"the smoothing λ = 0 leaves " + std::to_string(count) + " control points (knots at every "
                   "parameter) for " + std::to_string(points.size()) +
                   " points: give λ > 0 or fewer control points"};
    }
  } else {
    GcvProgress evaluations(progress, grid_steps() + 1);
    const auto chosen = gcv_smoothing(system, points.size(), evaluations);
    if (!chosen) return Error{"GCV cannot choose λ: the fit's normal equations are singular for every λ tried", ErrorKind::singular};
    lambda = *chosen;
    from_gcv = true;
  }
  auto solution = system.solve(lambda, true);
  if (!solution) {
    if (!from_gcv) return smoothing_singular_error(system, lambda, points.size());
    return singular_error(count, lambda);
  }
  BSplineFit fit = make_result(system, std::move(*solution), points, parameters, degree, lambda, options.weights);
  fit.smoothing_from_gcv = from_gcv;
  progress(1.0);
  return fit;
}

Expected<BSplineFit> fit_to_tolerance(const PointArray& points, std::span<const double> parameters, int degree,
                                      Tolerance tolerance, FitEnds ends, Progress progress) {
  if (auto valid = check_fit_input(points, parameters, degree); !valid) return valid.error();
  if (auto finite = check_finite(tolerance.distance, "the tolerance"); !finite) return finite.error();
  if (!(tolerance.distance > 0.0)) {
    return Error{"the tolerance is " + number_text(tolerance.distance) + ", it must be > 0"};
  }
  struct Span {
    std::size_t first, end;  // its points: t_first .. t_{end-1}
    double lower, upper;     // its knots
    double worst;            // largest error of its points
  };
  struct Candidate {
    double error;
    double knot;
  };
  std::vector<double> interior;  // interior knots, increasing
  std::vector<double> fallback;  // the last round's knots with only its worst new knot
  std::optional<BSplineFit> previous;
  double reported = 0.0;  // the fraction last given to progress
  const auto not_reached = [&](const BSplineFit& fit, const char* why) {
    return Error{"the tolerance " + number_text(tolerance.distance) + " is not reached: max error " +
                 number_text(fit.max_error) + " at point " + std::to_string(fit.worst_point) + " with " +
                 std::to_string(fit.curve.control_points().size()) + " control points (" + why + ")"};
  };
  while (true) {
    const FitSystem system(points, parameters, degree, clamped_knots(parameters, degree, interior), ends, false);
    const std::size_t count = system.control_point_count();
    auto solution = system.solve(0.0, false);
    if (!solution) {
      // Schoenberg–Whitney holds, so only rounding makes the system singular:
      // the knots crowd the points too closely for double precision.
      if (!previous) return singular_error(count, 0.0);
      if (!fallback.empty()) {  // the last round added several knots: add only its worst one
        interior = std::move(fallback);
        fallback.clear();
        continue;
      }
      return not_reached(*previous, "more control points make the normal equations singular in double precision");
    }
    BSplineFit fit = make_result(system, std::move(*solution), points, parameters, degree, 0.0);
    if (fit.max_error <= tolerance.distance) {
      progress(1.0);
      return fit;
    }
    // Progress: the share of points already within the tolerance (the best so far).
    const auto within = std::count_if(fit.errors.begin(), fit.errors.end(),
                                      [&](double e) { return e <= tolerance.distance; });
    reported = std::max(reported, static_cast<double>(within) / static_cast<double>(points.size()));
    progress(reported);

    // The knot spans with their points (a point at a knot belongs to the span on its right).
    std::vector<Span> spans;
    const std::span<const double> knots = system.knots();
    std::size_t first = 0;
    for (std::size_t s = static_cast<std::size_t>(degree); s < count; ++s) {
      const double upper = knots[s + 1];
      if (!(knots[s] < upper)) continue;
      std::size_t end = first;  // points with t < upper (all remaining in the last span)
      while (end < points.size() && (parameters[end] < upper || s + 1 == count)) ++end;
      double worst = 0.0;
      for (std::size_t i = first; i < end; ++i) worst = std::max(worst, fit.errors[i]);
      spans.push_back({first, end, knots[s], upper, worst});
      first = end;
    }
    // For each span whose worst error exceeds the tolerance, a knot in the
    // nearest span with two points or more (itself first): at the middle of
    // its points, or, in a neighbour, between its two points nearest to the
    // offending span, so the new freedom lands where the error is. Every span
    // keeps a point, which (with p+1 <= n+1 <= m+1) is the Schoenberg–Whitney
    // condition for clamped knots; it is still checked below.
    std::vector<Candidate> candidates;
    for (std::size_t s = 0; s < spans.size(); ++s) {
      if (!(spans[s].worst > tolerance.distance)) continue;
      for (std::size_t reach = 0; reach < spans.size(); ++reach) {
        std::optional<double> knot;
        for (int side : {0, -1, 1}) {
          if ((reach == 0) != (side == 0)) continue;
          if (side < 0 && reach > s) continue;
          const std::size_t other = side < 0 ? s - reach : s + reach;
          if (other >= spans.size()) continue;
          const Span& span = spans[other];
          if (span.end - span.first < 2) continue;
          const std::size_t split = side == 0 ? span.first + (span.end - span.first) / 2
                                    : side < 0 ? span.end - 1
                                               : span.first + 1;
          const double value = 0.5 * (parameters[split - 1] + parameters[split]);
          if (span.lower < value && value < span.upper) {
            knot = value;
            break;
          }
        }
        if (knot) {
          candidates.push_back({spans[s].worst, *knot});
          break;
        }
      }
    }
    // Worst first; one knot per value.
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.error > b.error; });
    std::vector<Candidate> unique;
    for (const Candidate& candidate : candidates) {
      const bool seen = std::any_of(unique.begin(), unique.end(),
                                    [&](const Candidate& other) { return other.knot == candidate.knot; });
      if (!seen) unique.push_back(candidate);
    }
    const std::size_t room = points.size() - count;  // control points may grow up to the point count
    if (unique.size() > room) unique.resize(room);

    auto with_knots = [&](std::span<const Candidate> chosen) {
      std::vector<double> more = interior;
      for (const Candidate& candidate : chosen) more.push_back(candidate.knot);
      std::sort(more.begin(), more.end());
      return more;
    };
    std::vector<double> next;
    if (!unique.empty()) {
      next = with_knots(unique);
      if (!check_schoenberg_whitney(clamped_knots(parameters, degree, next), degree, parameters, {}, ends)) {
        next.clear();
        for (const Candidate& candidate : unique) {  // one knot at a time, worst first
          std::vector<double> single = with_knots(std::span<const Candidate>(&candidate, 1));
          if (check_schoenberg_whitney(clamped_knots(parameters, degree, single), degree, parameters, {}, ends)) {
            next = std::move(single);
            break;
          }
        }
      }
    }
    if (next.empty()) {
      return not_reached(fit, room == 0 ? "the limit: as many control points as points"
                                        : "no knot can be added");
    }
    fallback.clear();
    if (next.size() > interior.size() + 1) fallback = with_knots(std::span<const Candidate>(unique.data(), 1));
    interior = std::move(next);
    previous = std::move(fit);
  }
}

}  // namespace casteljau

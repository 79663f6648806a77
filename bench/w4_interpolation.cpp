// W4 (shared/docs/performance.md): C² cubic interpolation of n = 10^4 and
// 10^6 points in 3D, chord-length parameters; one benchmark iteration is one
// whole fit: the parameters, the solve, and the curve object each library
// returns. Rows: W4/n<N>/<implementation>-<end condition>.
//
// Data: a random walk with drift, P_{i+1} = P_i + (0.1, 0.05, -0.02) + U,
// U uniform in [-1,1)^3 from a fixed splitmix64 stream (consecutive points
// distinct, checked). The closed variant for the periodic rows is the same
// walk with its linear trend removed, so that it returns to its start: a
// random-walk bridge Q_i = P_i - (i/(n-1))(P_{n-1} - P_0) without its last
// point (equal to Q_0); the closing step goes from Q_{n-2} back to Q_0.
// Clamped rows take the end derivatives (P_1 - P_0)/(t_1 - t_0) and
// (P_m - P_{m-1})/(t_m - t_{m-1}), computed once outside the timing.
//
// Checks (after timing, every row): the fitted curve is evaluated at the
// data parameters and at the midpoints of the parameter intervals, on the
// first and last 32 intervals (where the end conditions act) and on every
// (n/2000)-th interval. It must reproduce the data points (data_error_rel),
// and at the midpoints it must equal an independent reference of the same
// end condition (mid_error_rel): the textbook spline of second derivatives
// ("moments", a tridiagonal or cyclic tridiagonal solve, written below and
// sharing no code with casteljau's B-spline collocation). The textbook rows
// are checked against casteljau in the same way. Errors are relative to the
// scale (largest absolute coordinate); above 1e-9 the row fails
// (SkipWithError), so a fast wrong answer cannot pass.
//
// Rows (peers optional, each in its own row):
//   casteljau          parameter_values(chord_length) + interpolate_cubic,
//                      natural, clamped, not-a-knot, periodic
//   textbook-moments   the reference above, timed as a plain baseline
//   gsl-cspline        gsl_spline (gsl_interp_cspline: natural; and
//                      gsl_interp_cspline_periodic), once per coordinate
//   sisl-s1357         s1357, given parameters, order 4: natural
//                      (zero curvature at both ends) and periodic
//   occt-GeomAPI_Interpolate  with parameters: clamped (end tangents given,
//                      unscaled) and periodic. OpenCASCADE's periodic curve
//                      is only C¹ at the seam, where it imposes the tangent
//                      of the cubic through the first four points; its row
//                      is checked against that spline (seam_reference).
// Every peer row computes the chord-length parameters itself (a plain loop)
// and converts the points to the layout its library takes, inside the timing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"
#include "support/splitmix.hpp"

#if defined(CASTELJAU_HAVE_GSL)
#include <gsl/gsl_errno.h>
#include <gsl/gsl_spline.h>
#endif

#if defined(CASTELJAU_HAVE_OCCT_GEOMALGO)
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#endif

#if defined(CASTELJAU_HAVE_SISL)
#include <sisl.h>
#endif

namespace {

constexpr std::size_t kEndIntervals = 32;
constexpr std::size_t kSamples = 2000;
/// Far above rounding (at most 3e-13 of the scale here, from the rounding
/// of the chord lengths), far below any wrong answer: natural and
/// not-a-knot differ at the first midpoints by 6e-4 of the scale at
/// n = 10^4 and 8e-8 at n = 10^6 (the scale grows with the walk).
constexpr double kRelativeBound = 1e-9;

enum class Condition { natural, clamped, not_a_knot, periodic };

const char* name_of(Condition c) {
  switch (c) {
    case Condition::natural: return "natural";
    case Condition::clamped: return "clamped";
    case Condition::not_a_knot: return "not-a-knot";
    case Condition::periodic: return "periodic";
  }
  return "?";
}

// --- data --------------------------------------------------------------------------

/// Normalized chord-length parameters of `count` 3D points (closed: one more
/// value for the step from the last point back to the first).
std::vector<double> chord_parameters(const double* p, std::size_t count, bool closed) {
  const std::size_t values = closed ? count + 1 : count;
  std::vector<double> t(values);
  t[0] = 0.0;
  for (std::size_t i = 1; i < values; ++i) {
    const double* a = p + 3 * (i - 1);
    const double* b = p + 3 * (i % count);
    const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    t[i] = t[i - 1] + std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  const double total = t[values - 1];
  for (std::size_t i = 1; i + 1 < values; ++i) t[i] /= total;
  t[values - 1] = 1.0;
  return t;
}

/// The textbook C² cubic through (t_i, P_i) by its second derivatives M_i
/// (de Boor, A Practical Guide to Splines, ch. IV; Burden & Faires §3.5):
/// on [t_i, t_{i+1}] with h = t_{i+1} - t_i, a = t_{i+1} - t, b = t - t_i,
///   S(t) = (M_i a³ + M_{i+1} b³)/(6h) + (P_i/h - M_i h/6) a + (P_{i+1}/h - M_{i+1} h/6) b.
/// Closed: node count+1 repeats node 0.
struct MomentSpline {
  std::vector<double> t;  // nodes
  std::vector<double> p;  // 3 per node
  std::vector<double> m;  // 3 per node

  void evaluate(double u, double* out) const {
    const std::size_t last = t.size() - 1;
    std::size_t i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), u) - t.begin());
    i = i == 0 ? 0 : std::min(i - 1, last - 1);
    const double h = t[i + 1] - t[i], a = t[i + 1] - u, b = u - t[i];
    for (std::size_t j = 0; j < 3; ++j) {
      const double mi = m[3 * i + j], mk = m[3 * (i + 1) + j];
      out[j] = (mi * a * a * a + mk * b * b * b) / (6 * h) + (p[3 * i + j] / h - mi * h / 6) * a +
               (p[3 * (i + 1) + j] / h - mk * h / 6) * b;
    }
  }
};

/// Solves the tridiagonal rows lo..hi of sub/diag/super · x = rhs (3 right-hand
/// sides, x in place of rhs) by elimination without pivoting (Thomas).
void solve_tridiagonal(std::vector<double>& sub, std::vector<double>& diag, std::vector<double>& super,
                       std::vector<double>& rhs, std::size_t lo, std::size_t hi) {
  for (std::size_t i = lo + 1; i <= hi; ++i) {
    const double w = sub[i] / diag[i - 1];
    diag[i] -= w * super[i - 1];
    for (std::size_t j = 0; j < 3; ++j) rhs[3 * i + j] -= w * rhs[3 * (i - 1) + j];
  }
  for (std::size_t j = 0; j < 3; ++j) rhs[3 * hi + j] /= diag[hi];
  for (std::size_t i = hi; i-- > lo;) {
    for (std::size_t j = 0; j < 3; ++j) rhs[3 * i + j] = (rhs[3 * i + j] - super[i] * rhs[3 * (i + 1) + j]) / diag[i];
  }
}

/// The moments of the C² cubic with the given end condition. Open: points
/// 0..m at t_0..t_m; periodic: points 0..m at t_0..t_m and the closing
/// parameter t_{m+1}.
MomentSpline moment_spline(const double* points, std::size_t count, std::vector<double> t, Condition condition,
                           const double* start_tangent, const double* end_tangent) {
  MomentSpline s;
  const bool closed = condition == Condition::periodic;
  const std::size_t nodes = closed ? count + 1 : count;  // with the repeated node
  s.p.assign(points, points + 3 * count);
  if (closed) s.p.insert(s.p.end(), points, points + 3);
  s.t = std::move(t);
  const std::size_t m = nodes - 1;  // intervals
  std::vector<double> h(m), slope(3 * m);
  for (std::size_t i = 0; i < m; ++i) {
    h[i] = s.t[i + 1] - s.t[i];
    for (std::size_t j = 0; j < 3; ++j) slope[3 * i + j] = (s.p[3 * (i + 1) + j] - s.p[3 * i + j]) / h[i];
  }
  // Unknowns M_0..M_m (closed: M_0..M_{m-1}, M_m = M_0).
  const std::size_t unknowns = closed ? m : m + 1;
  std::vector<double> sub(unknowns, 0.0), diag(unknowns, 1.0), super(unknowns, 0.0), rhs(3 * unknowns, 0.0);
  auto interior = [&](std::size_t i, std::size_t before) {  // row i, interval `before` = i-1 (cyclic)
    sub[i] = h[before];
    diag[i] = 2 * (h[before] + h[i]);
    super[i] = h[i];
    for (std::size_t j = 0; j < 3; ++j) rhs[3 * i + j] = 6 * (slope[3 * i + j] - slope[3 * before + j]);
  };
  if (closed) {
    for (std::size_t i = 0; i < m; ++i) interior(i, i == 0 ? m - 1 : i - 1);
    // Cyclic: row 0 has sub[0] at column m-1, row m-1 has super[m-1] at
    // column 0. Sherman–Morrison: A = T + u vᵀ with u = (γ, 0.., corner),
    // v = (1, 0.., sub[0]/γ), T's corners of the diagonal adjusted.
    const double gamma = -diag[0];
    const double corner_top = sub[0], corner_bottom = super[m - 1];
    diag[0] -= gamma;
    diag[m - 1] -= corner_bottom * corner_top / gamma;
    std::vector<double> z(3 * m, 0.0);
    for (std::size_t j = 0; j < 3; ++j) {
      z[j] = gamma;
      z[3 * (m - 1) + j] = corner_bottom;
    }
    std::vector<double> d2 = diag, sub2 = sub, super2 = super;
    solve_tridiagonal(sub, diag, super, rhs, 0, m - 1);
    solve_tridiagonal(sub2, d2, super2, z, 0, m - 1);
    for (std::size_t j = 0; j < 3; ++j) {
      const double factor = (rhs[j] + corner_top * rhs[3 * (m - 1) + j] / gamma) /
                            (1 + z[j] + corner_top * z[3 * (m - 1) + j] / gamma);
      for (std::size_t i = 0; i < m; ++i) rhs[3 * i + j] -= factor * z[3 * i + j];
    }
    s.m.assign(rhs.begin(), rhs.end());
    s.m.insert(s.m.end(), rhs.begin(), rhs.begin() + 3);
    return s;
  }
  for (std::size_t i = 1; i < m; ++i) interior(i, i - 1);
  std::size_t lo = 0, hi = m;
  if (condition == Condition::clamped) {
    diag[0] = 2 * h[0];
    super[0] = h[0];
    sub[m] = h[m - 1];
    diag[m] = 2 * h[m - 1];
    for (std::size_t j = 0; j < 3; ++j) {
      rhs[j] = 6 * (slope[j] - start_tangent[j]);
      rhs[3 * m + j] = 6 * (end_tangent[j] - slope[3 * (m - 1) + j]);
    }
  } else if (condition == Condition::not_a_knot) {
    // M''' continuous at t_1: M_0 = (1 + r) M_1 - r M_2 with r = h_0/h_1;
    // substituted into row 1 (likewise M_m into row m-1).
    const double r0 = h[0] / h[1], r1 = h[m - 1] / h[m - 2];
    diag[1] += h[0] * (1 + r0);
    super[1] -= h[0] * r0;
    diag[m - 1] += h[m - 1] * (1 + r1);
    sub[m - 1] -= h[m - 1] * r1;
    lo = 1;
    hi = m - 1;
  }
  solve_tridiagonal(sub, diag, super, rhs, lo, hi);
  if (condition == Condition::not_a_knot) {
    const double r0 = h[0] / h[1], r1 = h[m - 1] / h[m - 2];
    for (std::size_t j = 0; j < 3; ++j) {
      rhs[j] = (1 + r0) * rhs[3 + j] - r0 * rhs[6 + j];
      rhs[3 * m + j] = (1 + r1) * rhs[3 * (m - 1) + j] - r1 * rhs[3 * (m - 2) + j];
    }
  }
  s.m = std::move(rhs);
  return s;
}

struct Case {
  std::size_t n = 0;
  std::vector<double> open, closed;                     // 3n coordinates each
  casteljau::PointArray open_points, closed_points;     // the same, for casteljau
  std::vector<double> open_parameters, closed_parameters;  // bench's own, for checks
  double start_tangent[3] = {0, 0, 0}, end_tangent[3] = {0, 0, 0};
  double scale = 0.0;
  std::vector<int> point_types;  // SISL: n ordinary points
  std::map<Condition, MomentSpline> references;

  /// OpenCASCADE's periodic interpolation fixes the tangent at the seam to
  /// the derivative at t_0 of the cubic through the first four points (the
  /// Lagrange form) and is C² elsewhere but only C¹ there: the clamped
  /// spline of the closed chain P_0..P_{m}, P_0 with that tangent at both ends.
  const MomentSpline& seam_reference() {
    if (!seam) {
      const std::vector<double>& t = closed_parameters;
      double tangent[3] = {0, 0, 0};
      for (std::size_t k = 0; k < 4; ++k) {  // d/dt of the Lagrange basis l_k at t_0
        double weight = 0.0;
        if (k == 0) {
          for (std::size_t i = 1; i < 4; ++i) weight += 1.0 / (t[0] - t[i]);
        } else {
          weight = 1.0 / (t[k] - t[0]);
          for (std::size_t i = 1; i < 4; ++i)
            if (i != k) weight *= (t[0] - t[i]) / (t[k] - t[i]);
        }
        for (std::size_t j = 0; j < 3; ++j) tangent[j] += weight * closed[3 * k + j];
      }
      std::vector<double> chain = closed;
      chain.insert(chain.end(), closed.begin(), closed.begin() + 3);
      seam = std::make_unique<MomentSpline>(moment_spline(chain.data(), n, t, Condition::clamped, tangent, tangent));
    }
    return *seam;
  }
  std::unique_ptr<MomentSpline> seam;

  const MomentSpline& reference(Condition c) {
    auto found = references.find(c);
    if (found == references.end()) {
      const bool cl = c == Condition::periodic;
      found = references.emplace(c, moment_spline(cl ? closed.data() : open.data(), cl ? n - 1 : n,
                                                  cl ? closed_parameters : open_parameters, c, start_tangent,
                                                  end_tangent)).first;
    }
    return found->second;
  }
};

Case make_case(std::size_t n) {
  Case c;
  c.n = n;
  casteljau::test::SplitMix random{0x57344u + n};
  const double drift[3] = {0.1, 0.05, -0.02};
  c.open.resize(3 * n);
  for (std::size_t j = 0; j < 3; ++j) c.open[j] = 0.0;
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t j = 0; j < 3; ++j) c.open[3 * i + j] = c.open[3 * (i - 1) + j] + (drift[j] + (2 * random.unit() - 1));
  c.closed.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = static_cast<double>(i) / static_cast<double>(n - 1);
    for (std::size_t j = 0; j < 3; ++j) c.closed[3 * i + j] = c.open[3 * i + j] - w * (c.open[3 * (n - 1) + j] - c.open[j]);
  }
  // Drop the bridge's last point (it equals the first): the closed variant
  // keeps n - 1 points, and its closing step is the bridge's last step.
  c.closed.resize(3 * (n - 1));
  for (const std::vector<double>* set : {&c.open, &c.closed}) {
    const std::size_t count = set->size() / 3;
    for (std::size_t i = 0; i < count; ++i) {
      const double* a = set->data() + 3 * i;
      const double* b = set->data() + 3 * ((i + 1) % count);
      if (i + 1 == count && set == &c.open) break;
      if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) std::abort();  // never for these seeds
    }
    for (double x : *set) c.scale = std::max(c.scale, std::abs(x));
  }
  c.open_points = casteljau::PointArray::from_trusted(3, c.open);
  c.closed_points = casteljau::PointArray::from_trusted(3, c.closed);
  c.open_parameters = chord_parameters(c.open.data(), n, false);
  c.closed_parameters = chord_parameters(c.closed.data(), n - 1, true);
  const std::vector<double>& t = c.open_parameters;
  for (std::size_t j = 0; j < 3; ++j) {
    c.start_tangent[j] = (c.open[3 + j] - c.open[j]) / (t[1] - t[0]);
    c.end_tangent[j] = (c.open[3 * (n - 1) + j] - c.open[3 * (n - 2) + j]) / (t[n - 1] - t[n - 2]);
  }
  c.point_types.assign(n, 1);
  return c;
}

Case& data(std::size_t n) {
  static std::map<std::size_t, Case> cases;
  auto found = cases.find(n);
  if (found == cases.end()) found = cases.emplace(n, make_case(n)).first;
  return found->second;
}

// --- implementations ------------------------------------------------------------------

/// A fitted curve, as each library returns it; evaluated only by the checks.
struct Fit {
  virtual ~Fit() = default;
  virtual void evaluate(double t, double* out) const = 0;
  /// The parameters the fit computed itself, if it keeps them: the data
  /// check then uses these (rounding differences in the chord lengths
  /// shift them by ~1e-13 at n = 10^6), otherwise the bench's own.
  virtual const std::vector<double>* own_parameters() const { return nullptr; }
};

/// One implementation: the whole fit (parameters, solve, curve) of a case
/// under an end condition; null if the library reported a failure.
using Fitter = std::unique_ptr<Fit> (*)(const Case& c, Condition condition);

/// What a row's midpoints are compared with.
enum class Reference { textbook, casteljau, occt_seam };

// casteljau ---------------------------------------------------------------------------

struct CasteljauFit final : Fit {
  casteljau::BSplineCurve curve;
  std::vector<double> parameters;
  CasteljauFit(casteljau::BSplineCurve c, std::vector<double> t) : curve(std::move(c)), parameters(std::move(t)) {}
  void evaluate(double t, double* out) const override {
    const casteljau::Point p = casteljau::point_at(curve, t);
    std::copy(p.begin(), p.end(), out);
  }
  const std::vector<double>* own_parameters() const override { return &parameters; }
};

std::unique_ptr<Fit> fit_casteljau(const Case& c, Condition condition) {
  const bool closed = condition == Condition::periodic;
  const casteljau::PointArray& points = closed ? c.closed_points : c.open_points;
  auto parameters = casteljau::parameter_values(points, casteljau::Parameterization::chord_length,
                                                  closed ? casteljau::Closure::closed : casteljau::Closure::open);
  if (!parameters) return nullptr;
  casteljau::CubicEnds ends;
  switch (condition) {
    case Condition::natural: ends.condition = casteljau::EndCondition::natural; break;
    case Condition::clamped:
      ends.condition = casteljau::EndCondition::clamped;
      ends.start_tangent.assign(c.start_tangent, c.start_tangent + 3);
      ends.end_tangent.assign(c.end_tangent, c.end_tangent + 3);
      break;
    case Condition::not_a_knot: ends.condition = casteljau::EndCondition::not_a_knot; break;
    case Condition::periodic: ends.condition = casteljau::EndCondition::periodic; break;
  }
  auto curve = casteljau::interpolate_cubic(points, *parameters, ends);
  if (!curve) return nullptr;
  return std::make_unique<CasteljauFit>(std::move(*curve), std::move(*parameters));
}

// textbook moments (the reference, timed as a plain baseline) ------------------------

struct MomentFit final : Fit {
  MomentSpline spline;
  explicit MomentFit(MomentSpline s) : spline(std::move(s)) {}
  void evaluate(double t, double* out) const override { spline.evaluate(t, out); }
};

std::unique_ptr<Fit> fit_textbook(const Case& c, Condition condition) {
  const bool closed = condition == Condition::periodic;
  const std::size_t count = closed ? c.n - 1 : c.n;
  const double* p = closed ? c.closed.data() : c.open.data();
  return std::make_unique<MomentFit>(
      moment_spline(p, count, chord_parameters(p, count, closed), condition, c.start_tangent, c.end_tangent));
}

// GSL 2.7 -------------------------------------------------------------------------------

#if defined(CASTELJAU_HAVE_GSL)
struct GslFit final : Fit {
  gsl_spline* spline[3] = {nullptr, nullptr, nullptr};
  ~GslFit() override {
    for (gsl_spline* s : spline) gsl_spline_free(s);
  }
  void evaluate(double t, double* out) const override {
    for (int j = 0; j < 3; ++j) out[j] = gsl_spline_eval(spline[j], t, nullptr);
  }
};

/// gsl_interp_cspline (natural) or gsl_interp_cspline_periodic, one spline
/// per coordinate on the chord-length parameters (GSL splines are scalar).
std::unique_ptr<Fit> fit_gsl(const Case& c, Condition condition) {
  const bool closed = condition == Condition::periodic;
  const std::size_t count = closed ? c.n - 1 : c.n;
  const double* p = closed ? c.closed.data() : c.open.data();
  const std::vector<double> t = chord_parameters(p, count, closed);
  const std::size_t size = t.size();
  std::vector<double> y(size);
  auto fit = std::make_unique<GslFit>();
  for (std::size_t j = 0; j < 3; ++j) {
    for (std::size_t i = 0; i < size; ++i) y[i] = p[3 * (i % count) + j];
    fit->spline[j] = gsl_spline_alloc(closed ? gsl_interp_cspline_periodic : gsl_interp_cspline, size);
    if (fit->spline[j] == nullptr || gsl_spline_init(fit->spline[j], t.data(), y.data(), size) != GSL_SUCCESS)
      return nullptr;
  }
  return fit;
}
#endif

// SISL 4.6 -------------------------------------------------------------------------------

#if defined(CASTELJAU_HAVE_SISL)
struct SislFit final : Fit {
  SISLCurve* curve = nullptr;
  ~SislFit() override {
    if (curve) freeCurve(curve);
  }
  void evaluate(double t, double* out) const override {
    int left = 0, status = 0;
    s1221(curve, 0, t, &left, out, &status);
  }
};

/// s1357: interpolation with given parameters, order 4; natural: zero
/// curvature at both ends (icnsta = icnend = 1); periodic: iopen = -1 with
/// the closing parameter.
std::unique_ptr<Fit> fit_sisl(const Case& c, Condition condition) {
  const bool closed = condition == Condition::periodic;
  const std::size_t count = closed ? c.n - 1 : c.n;
  const double* p = closed ? c.closed.data() : c.open.data();
  std::vector<double> t = chord_parameters(p, count, closed);
  std::vector<double> points(p, p + 3 * count);  // s1357 takes non-const arrays
  std::vector<int> types(c.point_types.begin(), c.point_types.begin() + static_cast<std::ptrdiff_t>(count));
  double end_parameter = 0.0;
  double* distinct = nullptr;
  int distinct_count = 0, status = 0;
  auto fit = std::make_unique<SislFit>();
  const int natural = closed ? 0 : 1;
  s1357(points.data(), static_cast<int>(count), 3, types.data(), t.data(), natural, natural, closed ? -1 : 1, 4,
        t[0], &end_parameter, &fit->curve, &distinct, &distinct_count, &status);
  std::free(distinct);
  if (status < 0 || fit->curve == nullptr) return nullptr;
  return fit;
}
#endif

// OpenCASCADE 7.6 ------------------------------------------------------------------------

#if defined(CASTELJAU_HAVE_OCCT_GEOMALGO)
struct OcctFit final : Fit {
  Handle(Geom_BSplineCurve) curve;
  void evaluate(double t, double* out) const override {
    gp_Pnt p;
    curve->D0(t, p);
    out[0] = p.X();
    out[1] = p.Y();
    out[2] = p.Z();
  }
};

/// GeomAPI_Interpolate with the parameters: clamped (Load of the end
/// tangents, Scale = false, so they are derivatives in the parameter) or
/// periodic (PeriodicFlag, n + 1 parameters).
std::unique_ptr<Fit> fit_occt(const Case& c, Condition condition) {
  const bool closed = condition == Condition::periodic;
  const std::size_t count = closed ? c.n - 1 : c.n;
  const double* p = closed ? c.closed.data() : c.open.data();
  const std::vector<double> t = chord_parameters(p, count, closed);
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, static_cast<int>(count));
  for (std::size_t i = 0; i < count; ++i) points->SetValue(static_cast<int>(i) + 1, gp_Pnt(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
  Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, static_cast<int>(t.size()));
  for (std::size_t i = 0; i < t.size(); ++i) parameters->SetValue(static_cast<int>(i) + 1, t[i]);
  try {
    GeomAPI_Interpolate interpolate(points, parameters, closed ? Standard_True : Standard_False, 1e-12);
    if (condition == Condition::clamped) {
      interpolate.Load(gp_Vec(c.start_tangent[0], c.start_tangent[1], c.start_tangent[2]),
                       gp_Vec(c.end_tangent[0], c.end_tangent[1], c.end_tangent[2]), Standard_False);
    }
    interpolate.Perform();
    if (!interpolate.IsDone()) return nullptr;
    auto fit = std::make_unique<OcctFit>();
    fit->curve = interpolate.Curve();
    return fit;
  } catch (const Standard_Failure&) {
    return nullptr;
  }
}
#endif

// --- rows ---------------------------------------------------------------------------------

struct Check {
  double data = 0.0;  // at the data parameters, relative to the scale
  double mid = 0.0;   // at the midpoints, against the reference
};

/// The sampled intervals: the first and last kEndIntervals, and a stride.
std::vector<std::size_t> sampled_intervals(std::size_t intervals) {
  std::vector<std::size_t> s;
  const std::size_t stride = std::max<std::size_t>(1, intervals / kSamples);
  for (std::size_t i = 0; i < intervals; ++i) {
    if (i < kEndIntervals || i + kEndIntervals >= intervals || i % stride == 0) s.push_back(i);
  }
  return s;
}

double difference(const double* a, const double* b) {
  double e = 0.0;
  for (int j = 0; j < 3; ++j) e = std::max(e, std::isfinite(a[j]) ? std::abs(a[j] - b[j]) : INFINITY);
  return e;
}

Check check(Case& c, Condition condition, const Fit& fit, const Fit& reference) {
  const bool closed = condition == Condition::periodic;
  const std::vector<double>& t = closed ? c.closed_parameters : c.open_parameters;
  const std::vector<double>& own = fit.own_parameters() ? *fit.own_parameters() : t;
  const std::vector<double>& p = closed ? c.closed : c.open;
  const std::size_t count = p.size() / 3;
  Check result;
  double value[3], expected[3];
  if (own.size() != t.size()) return {INFINITY, INFINITY};
  for (std::size_t i : sampled_intervals(t.size() - 1)) {
    for (std::size_t k = i; k <= i + 1; ++k) {
      fit.evaluate(own[k], value);
      result.data = std::max(result.data, difference(value, p.data() + 3 * (k % count)) / c.scale);
    }
    const double middle = 0.5 * (t[i] + t[i + 1]);
    fit.evaluate(middle, value);
    reference.evaluate(middle, expected);
    result.mid = std::max(result.mid, difference(value, expected) / c.scale);
  }
  return result;
}

void run_row(benchmark::State& state, std::size_t n, Condition condition, Fitter fitter, Reference kind) {
  Case& c = data(n);
  std::unique_ptr<Fit> fit;
  for (auto _ : state) {
    fit = fitter(c, condition);
    benchmark::DoNotOptimize(fit.get());
    benchmark::ClobberMemory();
  }
  if (!fit) {
    state.SkipWithError("the library reported a failure");
    return;
  }
  // The textbook rows are checked against casteljau, every other row
  // against the textbook spline.
  std::unique_ptr<Fit> reference;
  if (kind == Reference::occt_seam) {
    reference = std::make_unique<MomentFit>(c.seam_reference());
  } else if (kind == Reference::casteljau) {
    reference = fit_casteljau(c, condition);
    if (!reference) {
      state.SkipWithError("casteljau failed to produce the reference");
      return;
    }
  } else {
    reference = std::make_unique<MomentFit>(c.reference(condition));
  }
  const Check result = check(c, condition, *fit, *reference);
  state.counters["data_error_rel"] = result.data;
  state.counters["mid_error_rel"] = result.mid;
  state.counters["points"] = static_cast<double>(condition == Condition::periodic ? n - 1 : n);
  if (!(result.data <= kRelativeBound)) {
    state.SkipWithError(("misses the data points by " + std::to_string(result.data) + " of the scale").c_str());
  } else if (!(result.mid <= kRelativeBound)) {
    state.SkipWithError(("differs from the reference by " + std::to_string(result.mid) + " of the scale").c_str());
  }
}

void register_rows() {
  for (std::size_t n : {std::size_t{10'000}, std::size_t{1'000'000}}) {
    const std::string prefix = "W4/n" + std::to_string(n) + "/";
    auto add = [&](const std::string& name, Condition condition, Fitter fitter,
                   Reference reference = Reference::textbook) {
      benchmark::RegisterBenchmark((prefix + name + "-" + name_of(condition)).c_str(),
                                   [=](benchmark::State& state) { run_row(state, n, condition, fitter, reference); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    };
    for (Condition condition : {Condition::natural, Condition::clamped, Condition::not_a_knot, Condition::periodic}) {
      add("casteljau", condition, &fit_casteljau);
      add("textbook-moments", condition, &fit_textbook, Reference::casteljau);
    }
#if defined(CASTELJAU_HAVE_GSL)
    add("gsl-cspline", Condition::natural, &fit_gsl);
    add("gsl-cspline", Condition::periodic, &fit_gsl);
#endif
#if defined(CASTELJAU_HAVE_SISL)
    add("sisl-s1357", Condition::natural, &fit_sisl);
    add("sisl-s1357", Condition::periodic, &fit_sisl);
#endif
#if defined(CASTELJAU_HAVE_OCCT_GEOMALGO)
    add("occt-GeomAPI_Interpolate", Condition::clamped, &fit_occt);
    add("occt-GeomAPI_Interpolate", Condition::periodic, &fit_occt, Reference::occt_seam);
#endif
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
#if defined(CASTELJAU_HAVE_GSL)
  gsl_set_error_handler_off();  // failures come back as status codes
#endif
  register_rows();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

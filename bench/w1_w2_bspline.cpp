// W1 and W2 (shared/docs/performance.md): a cubic B-spline curve in 3D with
// 1000 control points in [0,100)^3 and clamped uniform knots on [0,1];
// 10^6 parameters uniform in [0,1), (a) sorted, (b) in drawn (random)
// order; W1 writes the points, W2 the points and first derivatives, into
// preallocated arrays. Data from fixed splitmix64 streams.
// Rows: W1/sorted/<impl>, W1/random/<impl>, W2/sorted/<impl>, W2/random/<impl>;
// with CASTELJAU_BENCH_ALL_CORES=1 only W1/<order>/casteljau-all-cores
// (bench/all_cores.hpp).
//
// Every row checks its output after timing on every 1000th parameter against
// the exact point (and first derivative), computed once in GMP rationals from
// the exact values of the doubles (tests/support/exact_bspline.hpp: de Boor;
// the derivative by de Boor on the exact hodograph, NURBS Book eq. 3.8), and
// fails (SkipWithError) if a coordinate differs by more than kRelativeBound
// times the scale (100 for points; the largest derivative coordinate of the
// sample for derivatives). The row reports the largest difference as
// max_error_rel. The casteljau rows must also equal the scalar point_at /
// derivative_at(u, 1) bit for bit. Without GMP the scalar functions are the
// reference.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "all_cores.hpp"
#include "w1_curve.hpp"
#include "support/splitmix.hpp"

#if defined(CASTELJAU_HAVE_GMP)
#include "support/exact.hpp"
#include "support/exact_bspline.hpp"
#endif

#if __has_include(<unsupported/Eigen/Splines>)
#include <unsupported/Eigen/Splines>
#define CASTELJAU_HAVE_EIGEN_SPLINES 1
#endif

#if defined(CASTELJAU_HAVE_OCCT)
#include <BSplCLib.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#endif

#if defined(CASTELJAU_HAVE_SISL)
#include <sisl.h>
#endif

namespace {

using casteljau::BSplineCurve;

constexpr int kDegree = casteljau::bench::kW1Degree;
constexpr std::size_t kControlPoints = casteljau::bench::kW1ControlPoints;
constexpr std::size_t kParameters = 1'000'000;
constexpr std::size_t kCheckStride = 1000;
constexpr double kScale = casteljau::bench::kW1Scale;
/// Far above rounding (1e-13 of the scale), far below any wrong answer.
constexpr double kRelativeBound = 1e-9;

using Random = casteljau::test::SplitMix;

struct Data {
  std::vector<double> control;  // kControlPoints x 3
  std::vector<double> knots;    // clamped uniform, n + p + 2
  BSplineCurve curve;
  std::vector<double> sorted, random;
  std::vector<double> points, derivatives;
};

Data make_data() {
  std::vector<double> control = casteljau::bench::w1_control_points();
  std::vector<double> knots = casteljau::clamped_uniform_knots(kDegree, kControlPoints);
  BSplineCurve curve = casteljau::bench::w1_curve();
  Random parameter_random{4242u};
  std::vector<double> random(kParameters);
  for (double& u : random) u = parameter_random.unit();
  std::vector<double> sorted = random;
  std::sort(sorted.begin(), sorted.end());
  return Data{std::move(control), std::move(knots), std::move(curve), std::move(sorted), std::move(random),
              std::vector<double>(kParameters * 3), std::vector<double>(kParameters * 3)};
}

Data& data() {
  static Data d = make_data();
  return d;
}

/// One implementation: evaluates the points (and, if derivatives is
/// non-null, the first derivatives) of every parameter of us.
using Implementation = void (*)(const std::vector<double>& us, double* points, double* derivatives);

// --- casteljau --------------------------------------------------------------------

void run_casteljau(const std::vector<double>& us, double* points, double* derivatives) {
  const BSplineCurve& curve = data().curve;
  if (derivatives) {
    casteljau::points_and_derivatives_at(curve, us, {points, us.size() * 3}, {derivatives, us.size() * 3});
  } else {
    casteljau::points_at(curve, us, {points, us.size() * 3});
  }
}

/// The same batch on every usable core: one contiguous chunk of parameters
/// per thread, each through points_at (chunks are whole 64-parameter blocks).
void run_casteljau_all_cores(const std::vector<double>& us, double* points, double*) {
  const BSplineCurve& curve = data().curve;
  static const int threads = casteljau::bench::usable_cpus();
  casteljau::bench::run_chunks(us.size(), 64, threads, [&](std::size_t begin, std::size_t end) {
    casteljau::points_at(curve, std::span<const double>(us).subspan(begin, end - begin),
                         {points + 3 * begin, 3 * (end - begin)});
  });
}

// --- textbook: The NURBS Book A2.1 (span), A2.2 / A2.3 (basis), A3.1 / A3.2 ---------

void run_textbook(const std::vector<double>& us, double* points, double* derivatives) {
  const std::vector<double>& t = data().knots;
  const double* P = data().control.data();
  constexpr int p = kDegree;
  const int n = static_cast<int>(kControlPoints) - 1;
  for (std::size_t k = 0; k < us.size(); ++k) {
    const double u = us[k];
    // A2.1: binary search, the end of the domain closed.
    int span;
    if (u >= t[static_cast<std::size_t>(n + 1)]) {
      span = n;
    } else {
      int low = p, high = n + 1;
      span = (low + high) / 2;
      while (u < t[static_cast<std::size_t>(span)] || u >= t[static_cast<std::size_t>(span + 1)]) {
        if (u < t[static_cast<std::size_t>(span)]) high = span; else low = span;
        span = (low + high) / 2;
      }
    }
    // A2.3 up to the first derivative (A2.2 when only points are needed).
    double left[p + 1], right[p + 1], ndu[p + 1][p + 1];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
      left[j] = u - t[static_cast<std::size_t>(span + 1 - j)];
      right[j] = t[static_cast<std::size_t>(span + j)] - u;
      double saved = 0.0;
      for (int r = 0; r < j; ++r) {
        ndu[j][r] = right[r + 1] + left[j - r];
        const double temp = ndu[r][j - 1] / ndu[j][r];
        ndu[r][j] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      ndu[j][j] = saved;
    }
    double x = 0, y = 0, z = 0;
    for (int j = 0; j <= p; ++j) {
      const double* q = P + 3 * (span - p + j);
      const double N = ndu[j][p];
      x += N * q[0];
      y += N * q[1];
      z += N * q[2];
    }
    points[3 * k] = x;
    points[3 * k + 1] = y;
    points[3 * k + 2] = z;
    if (derivatives) {
      // N'_{i,p} = p (N_{i,p-1}/(t_{i+p} - t_i) - N_{i+1,p-1}/(t_{i+p+1} - t_{i+1})), from ndu's column p-1.
      double dx = 0, dy = 0, dz = 0;
      for (int j = 0; j <= p; ++j) {
        double dN = 0.0;
        if (j >= 1) dN += ndu[j - 1][p - 1] / ndu[p][j - 1];
        if (j <= p - 1) dN -= ndu[j][p - 1] / ndu[p][j];
        dN *= p;
        const double* q = P + 3 * (span - p + j);
        dx += dN * q[0];
        dy += dN * q[1];
        dz += dN * q[2];
      }
      derivatives[3 * k] = dx;
      derivatives[3 * k + 1] = dy;
      derivatives[3 * k + 2] = dz;
    }
  }
}

// --- Eigen 3.4 unsupported/Eigen/Splines --------------------------------------------

#if defined(CASTELJAU_HAVE_EIGEN_SPLINES)
using EigenSpline = Eigen::Spline<double, 3, kDegree>;
const EigenSpline& eigen_spline() {
  static const EigenSpline spline = [] {
    Eigen::Array<double, 1, Eigen::Dynamic> knots(static_cast<Eigen::Index>(data().knots.size()));
    for (std::size_t i = 0; i < data().knots.size(); ++i) knots(static_cast<Eigen::Index>(i)) = data().knots[i];
    Eigen::Matrix<double, 3, Eigen::Dynamic> control(3, static_cast<Eigen::Index>(kControlPoints));
    for (std::size_t i = 0; i < kControlPoints; ++i)
      for (int j = 0; j < 3; ++j) control(j, static_cast<Eigen::Index>(i)) = data().control[3 * i + static_cast<std::size_t>(j)];
    return EigenSpline(knots, control);
  }();
  return spline;
}

void run_eigen(const std::vector<double>& us, double* points, double* derivatives) {
  const EigenSpline& spline = eigen_spline();
  for (std::size_t k = 0; k < us.size(); ++k) {
    if (derivatives) {
      const auto both = spline.derivatives<1>(us[k]);
      for (int j = 0; j < 3; ++j) {
        points[3 * k + static_cast<std::size_t>(j)] = both(j, 0);
        derivatives[3 * k + static_cast<std::size_t>(j)] = both(j, 1);
      }
    } else {
      const auto p = spline(us[k]);
      for (int j = 0; j < 3; ++j) points[3 * k + static_cast<std::size_t>(j)] = p(j);
    }
  }
}
#endif

// --- OpenCASCADE 7.6 ------------------------------------------------------------------

#if defined(CASTELJAU_HAVE_OCCT)
using Occt = casteljau::bench::OcctW1;
const Occt& occt() { return casteljau::bench::occt_w1(); }

/// GeomAdaptor_Curve::D0 / D1: OpenCASCADE's cached evaluation (per-span
/// power-basis cache, rebuilt when the parameter leaves the cached span).
void run_occt_adaptor(const std::vector<double>& us, double* points, double* derivatives) {
  GeomAdaptor_Curve adaptor(occt().curve);
  gp_Pnt p;
  gp_Vec v;
  for (std::size_t k = 0; k < us.size(); ++k) {
    if (derivatives) {
      adaptor.D1(us[k], p, v);
      derivatives[3 * k] = v.X();
      derivatives[3 * k + 1] = v.Y();
      derivatives[3 * k + 2] = v.Z();
    } else {
      adaptor.D0(us[k], p);
    }
    points[3 * k] = p.X();
    points[3 * k + 1] = p.Y();
    points[3 * k + 2] = p.Z();
  }
}

/// BSplCLib::LocateParameter then BSplCLib::D0 / D1: the uncached kernel.
void run_occt_bsplclib(const std::vector<double>& us, double* points, double* derivatives) {
  const Occt& o = occt();
  gp_Pnt p;
  gp_Vec v;
  for (std::size_t k = 0; k < us.size(); ++k) {
    Standard_Integer index = 0;
    Standard_Real u = 0.0;
    BSplCLib::LocateParameter(kDegree, o.knots, &o.mults, us[k], Standard_False, index, u);
    if (derivatives) {
      BSplCLib::D1(u, index, kDegree, Standard_False, o.poles, nullptr, o.knots, &o.mults, p, v);
      derivatives[3 * k] = v.X();
      derivatives[3 * k + 1] = v.Y();
      derivatives[3 * k + 2] = v.Z();
    } else {
      BSplCLib::D0(u, index, kDegree, Standard_False, o.poles, nullptr, o.knots, &o.mults, p);
    }
    points[3 * k] = p.X();
    points[3 * k + 1] = p.Y();
    points[3 * k + 2] = p.Z();
  }
}
#endif

// --- SISL 4.6 -----------------------------------------------------------------------------

#if defined(CASTELJAU_HAVE_SISL)
SISLCurve* sisl_curve() { return casteljau::bench::sisl_w1(); }

/// s1221: value and derivatives from the right, with the span hint ileft
/// carried from one parameter to the next (as a sorted caller would).
void run_sisl(const std::vector<double>& us, double* points, double* derivatives) {
  SISLCurve* curve = sisl_curve();
  int left = 0, status = 0;
  double out[6];
  const int order = derivatives ? 1 : 0;
  for (std::size_t k = 0; k < us.size(); ++k) {
    s1221(curve, order, us[k], &left, out, &status);
    points[3 * k] = out[0];
    points[3 * k + 1] = out[1];
    points[3 * k + 2] = out[2];
    if (derivatives) {
      derivatives[3 * k] = out[3];
      derivatives[3 * k + 1] = out[4];
      derivatives[3 * k + 2] = out[5];
    }
  }
}
#endif

// --- rows ---------------------------------------------------------------------------------

/// The reference at every kCheckStride-th parameter: coordinates of the
/// points, then of the first derivatives, as exact rationals when GMP is
/// there, else the scalar point_at / derivative_at(u, 1).
struct Reference {
#if defined(CASTELJAU_HAVE_GMP)
  using Value = mpq_class;
#else
  using Value = double;
#endif
  std::vector<Value> points, derivatives;  // 3 per sample
  double derivative_scale = 0.0;           // the largest |derivative coordinate| of the sample
};

Reference make_reference(const std::vector<double>& us) {
  Reference r;
  const BSplineCurve& curve = data().curve;
#if defined(CASTELJAU_HAVE_GMP)
  const casteljau::test::ExactBSpline exact = casteljau::test::ExactBSpline::of(curve);
  const casteljau::test::ExactBSpline hodograph = exact.derivative();
#endif
  for (std::size_t k = 0; k < us.size(); k += kCheckStride) {
#if defined(CASTELJAU_HAVE_GMP)
    for (mpq_class& x : exact.point_at(mpq_class(us[k]))) r.points.push_back(std::move(x));
    for (mpq_class& x : hodograph.point_at(mpq_class(us[k]))) {
      r.derivative_scale = std::max(r.derivative_scale, std::abs(x.get_d()));
      r.derivatives.push_back(std::move(x));
    }
#else
    for (double x : casteljau::point_at(curve, us[k])) r.points.push_back(x);
    for (double x : casteljau::derivative_at(curve, us[k], 1)) {
      r.derivative_scale = std::max(r.derivative_scale, std::abs(x));
      r.derivatives.push_back(x);
    }
#endif
  }
  return r;
}

const Reference& reference(bool sorted) {
  static const Reference sorted_reference = make_reference(data().sorted);
  static const Reference random_reference = make_reference(data().random);
  return sorted ? sorted_reference : random_reference;
}

double difference(double value, const Reference::Value& exact) {
  if (!std::isfinite(value)) return INFINITY;
#if defined(CASTELJAU_HAVE_GMP)
  return casteljau::test::error_of(value, exact);
#else
  return std::abs(value - exact);
#endif
}

/// Largest difference from the reference on the sample, relative to the
/// scale, and whether every sampled coordinate equals the scalar functions'
/// bit for bit.
struct Check {
  double error = 0.0;
  bool bitwise = true;
};

Check check(bool sorted, const double* points, const double* derivatives) {
  const std::vector<double>& us = sorted ? data().sorted : data().random;
  const Reference& r = reference(sorted);
  Check result;
  std::size_t sample = 0;
  for (std::size_t k = 0; k < us.size(); k += kCheckStride, ++sample) {
    const casteljau::Point point = casteljau::point_at(data().curve, us[k]);
    const casteljau::Point slope = derivatives ? casteljau::derivative_at(data().curve, us[k], 1) : casteljau::Point{};
    for (std::size_t j = 0; j < 3; ++j) {
      result.error = std::max(result.error, difference(points[3 * k + j], r.points[3 * sample + j]) / kScale);
      result.bitwise &= points[3 * k + j] == point[j];
      if (derivatives) {
        result.error = std::max(result.error,
                                difference(derivatives[3 * k + j], r.derivatives[3 * sample + j]) / r.derivative_scale);
        result.bitwise &= derivatives[3 * k + j] == slope[j];
      }
    }
  }
  return result;
}

void run_row(benchmark::State& state, bool derivative, bool sorted, Implementation implementation, bool bitwise) {
  Data& d = data();
  const std::vector<double>& us = sorted ? d.sorted : d.random;
  std::fill(d.points.begin(), d.points.end(), NAN);
  std::fill(d.derivatives.begin(), d.derivatives.end(), NAN);
  double* derivatives = derivative ? d.derivatives.data() : nullptr;
  for (auto _ : state) {
    implementation(us, d.points.data(), derivatives);
    benchmark::DoNotOptimize(d.points.data());
    benchmark::DoNotOptimize(d.derivatives.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(us.size()));
  const Check c = check(sorted, d.points.data(), derivatives);
  state.counters["max_error_rel"] = c.error;
  if (!(c.error <= kRelativeBound)) {
    state.SkipWithError(("relative error " + std::to_string(c.error) + " exceeds the bound").c_str());
  } else if (bitwise && !c.bitwise) {
    state.SkipWithError("batch result differs from the scalar functions");
  }
}

/// CASTELJAU_BENCH_ALL_CORES=1: the all-core rows, unpinned (bench/run.sh).
void register_all_core_rows() {
  for (int sorted = 1; sorted >= 0; --sorted) {
    const std::string name = std::string("W1/") + (sorted ? "sorted" : "random") + "/casteljau-all-cores";
    benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
      run_row(state, false, sorted == 1, &run_casteljau_all_cores, true);
      state.counters["threads"] = casteljau::bench::usable_cpus();
    })->Unit(benchmark::kMillisecond)->UseRealTime();
  }
}

void register_rows() {
  for (int derivative = 0; derivative <= 1; ++derivative) {
    for (int sorted = 1; sorted >= 0; --sorted) {
      const std::string prefix = std::string(derivative ? "W2/" : "W1/") + (sorted ? "sorted/" : "random/");
      auto add = [&](const char* name, Implementation implementation, bool bitwise = false) {
        benchmark::RegisterBenchmark((prefix + name).c_str(), [=](benchmark::State& state) {
          run_row(state, derivative == 1, sorted == 1, implementation, bitwise);
        })->Unit(benchmark::kMillisecond)->UseRealTime();
      };
      add("casteljau", &run_casteljau, true);
      add("textbook-A3.1", &run_textbook);
#if defined(CASTELJAU_HAVE_EIGEN_SPLINES)
      add("eigen-spline", &run_eigen);
#endif
#if defined(CASTELJAU_HAVE_OCCT)
      add("occt-adaptor", &run_occt_adaptor);
      add("occt-bsplclib", &run_occt_bsplclib);
#endif
#if defined(CASTELJAU_HAVE_SISL)
      add("sisl-s1221", &run_sisl);
#endif
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  if (casteljau::bench::all_cores_run()) {
    register_all_core_rows();
  } else {
    register_rows();
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

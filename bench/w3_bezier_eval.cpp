// W3 (shared/docs/performance.md): one Bézier curve of degree 3, 7 and 15 in
// 2D and 3D, control points in [0,100)^d, 1e6 random parameters in [0,1),
// all from fixed seeds; every implementation writes the points into one
// preallocated array. Rows: W3/deg<N>-<d>d/<implementation>.
//
// Every row checks its output after timing: on a subsample of 20,000
// parameters it measures the largest coordinate error against the exact
// value (GMP integers: the doubles are converted exactly, de Casteljau is
// done without rounding, the difference is rounded once) and fails the row
// (SkipWithError) if that error exceeds kErrorBound times the data's scale.
// The error itself is reported as the counters max_error (model units),
// max_error_rel (divided by the scale, 100) and mean_error (the mean over
// the subsample's coordinates, model units). The casteljau row also checks
// that points_at equals point_at bit for bit on the subsample.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "support/splitmix.hpp"

#if defined(CASTELJAU_HAVE_GMP)
#include "support/exact.hpp"
#endif

#if defined(CASTELJAU_HAVE_2GEOM)
#include <2geom/bezier-curve.h>
#endif

#if defined(CASTELJAU_HAVE_OCCT)
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BezierCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#endif

namespace {

using casteljau::BezierCurve;

constexpr std::size_t kParameters = 1'000'000;
constexpr std::size_t kSubsampleStride = 50;  // 20,000 checked parameters
constexpr double kScale = 100.0;              // control points in [0, 100)
/// A row fails when its largest error exceeds this fraction of the scale: far
/// above any rounding error (the power basis at degree 15 loses about 1e-10
/// of the scale), far below any wrong answer.
constexpr double kErrorBound = 1e-7;

using Random = casteljau::test::SplitMix;

/// One W3 configuration: its curve, its parameters, the output array shared
/// by its rows, and the exact points at the subsample.
struct Case {
  int degree = 0, dimension = 0;
  std::vector<double> control;  // (degree+1) x dimension, row-major
  BezierCurve curve = BezierCurve::from_trusted(casteljau::PointArray::zeros(1, 1));
  std::vector<double> ts;
  std::vector<double> out;
#if defined(CASTELJAU_HAVE_GMP)
  std::vector<std::vector<casteljau::test::Dyadic>> exact;  // per subsample point
#endif
};

Case& case_for(int degree, int dimension) {
  static std::map<std::pair<int, int>, std::unique_ptr<Case>> cases;
  auto& slot = cases[{degree, dimension}];
  if (slot) return *slot;
  slot = std::make_unique<Case>();
  Case& c = *slot;
  c.degree = degree;
  c.dimension = dimension;
  Random control_random{20260300u + static_cast<std::uint64_t>(degree) * 10u + dimension};
  for (int i = 0; i < (degree + 1) * dimension; ++i) c.control.push_back(kScale * control_random.unit());
  c.curve = BezierCurve::from_trusted(casteljau::PointArray::from_trusted(dimension, c.control));
  Random parameter_random{777u};
  c.ts.resize(kParameters);
  for (double& t : c.ts) t = parameter_random.unit();
  c.out.assign(kParameters * dimension, 0.0);
#if defined(CASTELJAU_HAVE_GMP)
  for (std::size_t k = 0; k < kParameters; k += kSubsampleStride)
    c.exact.push_back(casteljau::test::exact_point(c.curve, c.ts[k]));
#endif
  return c;
}

// --- implementations ---------------------------------------------------------

/// Textbook de Casteljau, scalar, one parameter at a time: copy the
/// polygon, n rounds of (1-t) a + t b. Degree and dimension are template
/// arguments so the compiler may unroll, as a hand-written kernel would.
template <int N, int D>
void decasteljau_plain(Case& c) {
  for (std::size_t k = 0; k < c.ts.size(); ++k) {
    const double t = c.ts[k];
    double work[N + 1][D];
    for (int i = 0; i <= N; ++i)
      for (int j = 0; j < D; ++j) work[i][j] = c.control[i * D + j];
    for (int r = 1; r <= N; ++r)
      for (int i = 0; i <= N - r; ++i)
        for (int j = 0; j < D; ++j) work[i][j] = (1.0 - t) * work[i][j] + t * work[i + 1][j];
    for (int j = 0; j < D; ++j) c.out[k * D + j] = work[0][j];
  }
}

/// Power basis a_k = C(n,k) Delta^k P_0, then Horner: fast, but the
/// conversion's cancellation costs accuracy that grows with the degree.
template <int N, int D>
void horner_power(const Case& c, std::vector<double>& out) {
  std::array<std::array<double, D>, N + 1> a{};
  std::array<std::array<double, D>, N + 1> diff{};
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j < D; ++j) diff[i][j] = c.control[i * D + j];
  double binomial = 1.0;
  for (int k = 0; k <= N; ++k) {
    for (int j = 0; j < D; ++j) a[k][j] = binomial * diff[0][j];
    for (int i = 0; i + k < N; ++i)
      for (int j = 0; j < D; ++j) diff[i][j] = diff[i + 1][j] - diff[i][j];
    binomial = binomial * (N - k) / (k + 1);
  }
  for (std::size_t p = 0; p < c.ts.size(); ++p) {
    const double t = c.ts[p];
    for (int j = 0; j < D; ++j) {
      double v = a[N][j];
      for (int k = N - 1; k >= 0; --k) v = v * t + a[k][j];
      out[p * D + j] = v;
    }
  }
}

using Implementation = void (*)(Case&);

void run_casteljau(Case& c) { casteljau::points_at(c.curve, c.ts, c.out); }

void run_point_at(Case& c) {
  const int d = c.dimension;
  for (std::size_t k = 0; k < c.ts.size(); ++k) {
    const casteljau::Point p = casteljau::point_at(c.curve, c.ts[k]);
    for (int j = 0; j < d; ++j) c.out[k * d + j] = p[j];
  }
}

/// point_at<D>: one point per call as a Vec<D>, no allocation (the batch
/// kernel on one parameter); the row beside casteljau-point_at shows what
/// the heap Point of the general call costs.
template <int N, int D>
struct FixedPointAt {
  static void run(Case& c) {
    for (std::size_t k = 0; k < c.ts.size(); ++k) {
      const casteljau::Vec<D> p = casteljau::point_at<D>(c.curve, c.ts[k]);
      for (int j = 0; j < D; ++j) c.out[k * D + j] = p[j];
    }
  }
};

/// The instance of a degree/dimension template for W3's degrees.
template <template <int, int> class F>
Implementation for_w3(int n, int d) {
  if (d == 2) return n == 3 ? &F<3, 2>::run : n == 7 ? &F<7, 2>::run : &F<15, 2>::run;
  return n == 3 ? &F<3, 3>::run : n == 7 ? &F<7, 3>::run : &F<15, 3>::run;
}
template <int N, int D>
struct Plain {
  static void run(Case& c) { decasteljau_plain<N, D>(c); }
};
template <int N, int D>
struct Horner {
  static void run(Case& c) { horner_power<N, D>(c, c.out); }
};

#if defined(CASTELJAU_HAVE_2GEOM)
void run_2geom(Case& c) {
  static std::map<int, std::unique_ptr<Geom::BezierCurve>> curves;
  auto& curve = curves[c.degree];
  if (!curve) {
    std::vector<Geom::Point> points;
    for (int i = 0; i <= c.degree; ++i) points.emplace_back(c.control[2 * i], c.control[2 * i + 1]);
    curve.reset(Geom::BezierCurve::create(points));  // BezierCurveN<N> for N <= 3
  }
  const Geom::BezierCurve& b = *curve;
  for (std::size_t k = 0; k < c.ts.size(); ++k) {
    const Geom::Point p = b.pointAt(c.ts[k]);
    c.out[2 * k] = p[Geom::X];
    c.out[2 * k + 1] = p[Geom::Y];
  }
}
#endif

#if defined(CASTELJAU_HAVE_OCCT)
Handle(Geom_BezierCurve) occt_curve(const Case& c) {
  TColgp_Array1OfPnt poles(1, c.degree + 1);
  for (int i = 0; i <= c.degree; ++i)
    poles.SetValue(i + 1, gp_Pnt(c.control[3 * i], c.control[3 * i + 1], c.control[3 * i + 2]));
  return new Geom_BezierCurve(poles);
}
Handle(Geom2d_BezierCurve) occt_curve_2d(const Case& c) {
  TColgp_Array1OfPnt2d poles(1, c.degree + 1);
  for (int i = 0; i <= c.degree; ++i) poles.SetValue(i + 1, gp_Pnt2d(c.control[2 * i], c.control[2 * i + 1]));
  return new Geom2d_BezierCurve(poles);
}

/// Geom_BezierCurve::D0 / Geom2d_BezierCurve::D0: the curve object's own evaluation.
void run_occt(Case& c) {
  if (c.dimension == 2) {
    const Handle(Geom2d_BezierCurve) curve = occt_curve_2d(c);
    gp_Pnt2d p;
    for (std::size_t k = 0; k < c.ts.size(); ++k) {
      curve->D0(c.ts[k], p);
      c.out[2 * k] = p.X();
      c.out[2 * k + 1] = p.Y();
    }
    return;
  }
  const Handle(Geom_BezierCurve) curve = occt_curve(c);
  gp_Pnt p;
  for (std::size_t k = 0; k < c.ts.size(); ++k) {
    curve->D0(c.ts[k], p);
    c.out[3 * k] = p.X();
    c.out[3 * k + 1] = p.Y();
    c.out[3 * k + 2] = p.Z();
  }
}

/// GeomAdaptor_Curve::D0: OpenCASCADE's cached (power basis) evaluation.
void run_occt_adaptor(Case& c) {
  if (c.dimension == 2) {
    Geom2dAdaptor_Curve adaptor(occt_curve_2d(c));
    gp_Pnt2d p;
    for (std::size_t k = 0; k < c.ts.size(); ++k) {
      adaptor.D0(c.ts[k], p);
      c.out[2 * k] = p.X();
      c.out[2 * k + 1] = p.Y();
    }
    return;
  }
  GeomAdaptor_Curve adaptor(occt_curve(c));
  gp_Pnt p;
  for (std::size_t k = 0; k < c.ts.size(); ++k) {
    adaptor.D0(c.ts[k], p);
    c.out[3 * k] = p.X();
    c.out[3 * k + 1] = p.Y();
    c.out[3 * k + 2] = p.Z();
  }
}
#endif

// --- checking ----------------------------------------------------------------

struct Errors {
  double max = 0.0;   // largest coordinate error
  double mean = 0.0;  // mean coordinate error
};

/// Coordinate errors of c.out against the exact points (subsample).
Errors errors_of(const Case& c) {
  Errors e;
  std::size_t count = 0;
  for (std::size_t s = 0; s * kSubsampleStride < c.ts.size(); ++s) {
    const std::size_t k = s * kSubsampleStride;
#if defined(CASTELJAU_HAVE_GMP)
    const auto& exact = c.exact[s];
#else
    // Without GMP: against point_at (de Casteljau), so at least a wrong answer fails.
    const casteljau::Point exact = casteljau::point_at(c.curve, c.ts[k]);
#endif
    for (int j = 0; j < c.dimension; ++j) {
      const double value = c.out[k * c.dimension + j];
      if (!std::isfinite(value)) return {INFINITY, INFINITY};
#if defined(CASTELJAU_HAVE_GMP)
      const double error = casteljau::test::error_of(value, exact[j]);
#else
      const double error = std::abs(value - exact[j]);
#endif
      e.max = std::max(e.max, error);
      e.mean += error;
      ++count;
    }
  }
  e.mean /= static_cast<double>(count);
  return e;
}

bool equals_point_at(const Case& c) {
  for (std::size_t k = 0; k < c.ts.size(); k += kSubsampleStride) {
    const casteljau::Point p = casteljau::point_at(c.curve, c.ts[k]);
    for (int j = 0; j < c.dimension; ++j)
      if (c.out[k * c.dimension + j] != p[j]) return false;
  }
  return true;
}

void run_row(benchmark::State& state, int degree, int dimension, Implementation implementation, bool bitwise) {
  Case& c = case_for(degree, dimension);
  std::fill(c.out.begin(), c.out.end(), NAN);
  for (auto _ : state) {
    implementation(c);
    benchmark::DoNotOptimize(c.out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kParameters));
  const Errors errors = errors_of(c);
  const double error = errors.max;
  state.counters["max_error"] = error;
  state.counters["max_error_rel"] = error / kScale;
  state.counters["mean_error"] = errors.mean;
  if (!(error <= kErrorBound * kScale)) {
    state.SkipWithError(("max error " + std::to_string(error) + " exceeds the bound").c_str());
  } else if (bitwise && !equals_point_at(c)) {
    state.SkipWithError("points_at differs from point_at");
  }
}

void register_rows() {
  for (int dimension : {2, 3}) {
    for (int degree : {3, 7, 15}) {
      const std::string prefix = "W3/deg" + std::to_string(degree) + "-" + std::to_string(dimension) + "d/";
      auto add = [&](const char* name, Implementation implementation, bool bitwise = false) {
        benchmark::RegisterBenchmark((prefix + name).c_str(), [=](benchmark::State& state) {
          run_row(state, degree, dimension, implementation, bitwise);
        })->Unit(benchmark::kMillisecond)->UseRealTime();
      };
      add("casteljau", &run_casteljau, true);
      add("casteljau-point_at", &run_point_at);
      add("casteljau-point_at-fixed", for_w3<FixedPointAt>(degree, dimension), true);
      add("decasteljau-plain", for_w3<Plain>(degree, dimension));
#if defined(CASTELJAU_HAVE_2GEOM)
      if (dimension == 2) add("lib2geom", &run_2geom);
#endif
#if defined(CASTELJAU_HAVE_OCCT)
      add("occt", &run_occt);
      add("occt-adaptor", &run_occt_adaptor);
#endif
      add("horner-power", for_w3<Horner>(degree, dimension));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  register_rows();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

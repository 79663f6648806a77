// W5 (shared/docs/performance.md): a bicubic B-spline surface in 3D with a
// 100 x 100 control net P_ij = (i, j, 10 r), r uniform in [0,1) from a fixed
// splitmix64 stream, clamped uniform knots on [0,1] in both directions,
// evaluated on a 1000 x 1000 grid of (u, v) evenly spaced over the domain
// (u_a = a/999, v_b = b/999, the ends exact); one iteration writes the 10^6
// points (3 doubles each, u the slow index) into a preallocated buffer.
// Rows: W5/grid/<implementation>; with CASTELJAU_BENCH_ALL_CORES=1 only
// W5/grid/casteljau-all-cores (bench/all_cores.hpp).
//
// Every row checks its output after timing on every 997th grid point (a
// stride prime to 1000, so the sample visits every row and column position)
// against the exact point, computed once in GMP rationals from the
// definition (tests/support/exact_surface.hpp; without GMP, casteljau's
// scalar point_at), and fails (SkipWithError) if a coordinate differs by
// more than kRelativeBound times the scale (99, the largest coordinate); the
// row reports the largest difference as max_error_rel.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "all_cores.hpp"
#include "support/splitmix.hpp"

#if defined(CASTELJAU_HAVE_GMP)
#include "support/exact.hpp"
#include "support/exact_surface.hpp"
#endif

#if defined(CASTELJAU_HAVE_OCCT)
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#endif

#if defined(CASTELJAU_HAVE_SISL)
#include <sisl.h>
#endif

namespace {

using casteljau::BSplineSurface;

constexpr int kDegree = 3;
constexpr std::size_t kNet = 100;
constexpr std::size_t kGrid = 1000;
constexpr std::size_t kCheckStride = 997;
constexpr double kScale = 99.0;
/// Far above rounding (1e-13 of the scale), far below any wrong answer.
constexpr double kRelativeBound = 1e-9;

struct Data {
  std::vector<double> net;    // kNet x kNet x 3, row by row (i along u)
  std::vector<double> knots;  // clamped uniform, the same in u and v
  BSplineSurface surface;
  std::vector<double> us, vs;
  std::vector<double> points;  // kGrid * kGrid * 3
  std::vector<double> scattered_us, scattered_vs;
};

Data make_data() {
  casteljau::test::SplitMix random{20261122u};
  std::vector<double> net(kNet * kNet * 3);
  for (std::size_t i = 0; i < kNet; ++i)
    for (std::size_t j = 0; j < kNet; ++j) {
      double* p = net.data() + 3 * (i * kNet + j);
      p[0] = static_cast<double>(i);
      p[1] = static_cast<double>(j);
      p[2] = 10.0 * random.unit();
    }
  std::vector<double> knots = casteljau::clamped_uniform_knots(kDegree, kNet);
  BSplineSurface surface = BSplineSurface::from_trusted(
      kDegree, kDegree, knots, knots,
      casteljau::ControlNet::from_trusted(kNet, kNet, casteljau::PointArray::from_trusted(3, net)));
  std::vector<double> ts(kGrid);
  const casteljau::Interval domain = surface.domain_u();
  for (std::size_t a = 0; a < kGrid; ++a) ts[a] = domain.lerp(static_cast<double>(a) / static_cast<double>(kGrid - 1));
  std::vector<double> su(kGrid * kGrid), sv(kGrid * kGrid);
  for (std::size_t a = 0; a < kGrid; ++a)
    for (std::size_t b = 0; b < kGrid; ++b) {
      su[a * kGrid + b] = ts[a];
      sv[a * kGrid + b] = ts[b];
    }
  return Data{std::move(net), std::move(knots), std::move(surface), ts, ts, std::vector<double>(kGrid * kGrid * 3),
              std::move(su), std::move(sv)};
}

Data& data() {
  static Data d = make_data();
  return d;
}

using Implementation = void (*)(double* points);

// --- casteljau --------------------------------------------------------------------

void run_casteljau(double* points) {
  const Data& d = data();
  casteljau::grid_points_at(d.surface, d.us, d.vs, {points, kGrid * kGrid * 3});
}

/// The grid on every usable core: one contiguous block of u rows per thread,
/// each through grid_points_at.
void run_casteljau_all_cores(double* points) {
  const Data& d = data();
  static const int threads = casteljau::bench::usable_cpus();
  casteljau::bench::run_chunks(kGrid, 1, threads, [&](std::size_t begin, std::size_t end) {
    casteljau::grid_points_at(d.surface, std::span<const double>(d.us).subspan(begin, end - begin), d.vs,
                              {points + 3 * kGrid * begin, 3 * kGrid * (end - begin)});
  });
}

/// The scattered batch on the same 10^6 (u, v) pairs: what a caller without a grid pays.
void run_casteljau_scattered(double* points) {
  const Data& d = data();
  casteljau::points_at(d.surface, d.scattered_us, d.scattered_vs, {points, kGrid * kGrid * 3});
}

// --- OpenCASCADE 7.6 ------------------------------------------------------------------

#if defined(CASTELJAU_HAVE_OCCT)
struct Occt {
  Handle(Geom_BSplineSurface) surface;
  Occt() {
    const int n = static_cast<int>(kNet);
    TColgp_Array2OfPnt poles(1, n, 1, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double* q = data().net.data() + 3 * (i * n + j);
        poles.SetValue(i + 1, j + 1, gp_Pnt(q[0], q[1], q[2]));
      }
    const int distinct = n - kDegree + 1;
    TColStd_Array1OfReal knots(1, distinct);
    TColStd_Array1OfInteger mults(1, distinct);
    for (int i = 0; i < distinct; ++i) {
      knots.SetValue(i + 1, data().knots[static_cast<std::size_t>(kDegree + i)]);
      mults.SetValue(i + 1, (i == 0 || i == distinct - 1) ? kDegree + 1 : 1);
    }
    surface = new Geom_BSplineSurface(poles, knots, knots, mults, mults, kDegree, kDegree);
  }
};
Occt& occt() {
  static Occt o;
  return o;
}

/// GeomAdaptor_Surface::D0: OpenCASCADE's cached evaluation (a per-patch
/// polynomial cache rebuilt when (u, v) leaves the cached patch).
void run_occt_adaptor(double* points) {
  GeomAdaptor_Surface adaptor(occt().surface);
  const Data& d = data();
  gp_Pnt p;
  for (std::size_t a = 0; a < kGrid; ++a)
    for (std::size_t b = 0; b < kGrid; ++b) {
      adaptor.D0(d.us[a], d.vs[b], p);
      double* out = points + 3 * (a * kGrid + b);
      out[0] = p.X();
      out[1] = p.Y();
      out[2] = p.Z();
    }
}

/// Geom_BSplineSurface::D0 directly.
void run_occt_geom(double* points) {
  const Geom_BSplineSurface& surface = *occt().surface;
  const Data& d = data();
  gp_Pnt p;
  for (std::size_t a = 0; a < kGrid; ++a)
    for (std::size_t b = 0; b < kGrid; ++b) {
      surface.D0(d.us[a], d.vs[b], p);
      double* out = points + 3 * (a * kGrid + b);
      out[0] = p.X();
      out[1] = p.Y();
      out[2] = p.Z();
    }
}
#endif

// --- SISL 4.6 -----------------------------------------------------------------------------

#if defined(CASTELJAU_HAVE_SISL)
/// SISL's first direction runs fastest in both its coefficients and the
/// output of s1506, so casteljau's v is given as SISL's first direction:
/// then the coefficient array is casteljau's row-major net unchanged and
/// s1506 writes the grid with v fastest, as casteljau does.
SISLSurf* sisl_surface() {
  static SISLSurf* surface = [] {
    std::vector<double> knots = data().knots, knots2 = data().knots, net = data().net;
    return newSurf(static_cast<int>(kNet), static_cast<int>(kNet), kDegree + 1, kDegree + 1, knots.data(),
                   knots2.data(), net.data(), 1, 3, 1);
  }();
  return surface;
}

std::vector<double>& sisl_normals() {
  static std::vector<double> normals(kGrid * kGrid * 3);
  return normals;
}

/// s1506: the whole grid in one call (ider = 0: positions only; it also
/// fills a normal array, unused for ider = 0).
void run_sisl(double* points) {
  Data& d = data();
  int status = 0;
  s1506(sisl_surface(), 0, static_cast<int>(kGrid), d.vs.data(), static_cast<int>(kGrid), d.us.data(), points,
        sisl_normals().data(), &status);
  if (status < 0) std::fill(points, points + kGrid * kGrid * 3, NAN);
}
#endif

#if defined(CASTELJAU_HAVE_GMP)
using Exact = mpq_class;
#else
using Exact = double;
#endif

/// The reference coordinates at every kCheckStride-th grid point, computed once.
const std::vector<Exact>& reference() {
  static const std::vector<Exact> values = [] {
    const Data& d = data();
    std::vector<Exact> out;
    for (std::size_t k = 0; k < kGrid * kGrid; k += kCheckStride) {
      const double u = d.us[k / kGrid], v = d.vs[k % kGrid];
#if defined(CASTELJAU_HAVE_GMP)
      for (mpq_class& x : casteljau::test::exact_surface_point(d.surface, u, v)) out.push_back(std::move(x));
#else
      for (double x : casteljau::point_at(d.surface, u, v)) out.push_back(x);
#endif
    }
    return out;
  }();
  return values;
}

double check(const double* points) {
  const std::vector<Exact>& exact = reference();
  double error = 0.0;
  std::size_t sample = 0;
  for (std::size_t k = 0; k < kGrid * kGrid; k += kCheckStride, ++sample) {
    for (std::size_t j = 0; j < 3; ++j) {
      const double value = points[3 * k + j];
#if defined(CASTELJAU_HAVE_GMP)
      const double difference = casteljau::test::error_of(value, exact[3 * sample + j]);
#else
      const double difference = std::abs(value - exact[3 * sample + j]);
#endif
      error = std::max(error, std::isfinite(value) ? difference / kScale : INFINITY);
    }
  }
  return error;
}

void run_row(benchmark::State& state, Implementation implementation) {
  Data& d = data();
  std::fill(d.points.begin(), d.points.end(), NAN);
  for (auto _ : state) {
    implementation(d.points.data());
    benchmark::DoNotOptimize(d.points.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kGrid * kGrid));
  const double error = check(d.points.data());
  state.counters["max_error_rel"] = error;
  if (!(error <= kRelativeBound)) {
    state.SkipWithError(("relative error " + std::to_string(error) + " exceeds the bound").c_str());
  }
}

void register_rows() {
  auto add = [](const char* name, Implementation implementation) {
    benchmark::RegisterBenchmark((std::string("W5/grid/") + name).c_str(),
                                 [=](benchmark::State& state) { run_row(state, implementation); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  };
  add("casteljau", &run_casteljau);
  add("casteljau-points_at", &run_casteljau_scattered);
#if defined(CASTELJAU_HAVE_OCCT)
  add("occt-adaptor", &run_occt_adaptor);
  add("occt-geom-bspline-surface", &run_occt_geom);
#endif
#if defined(CASTELJAU_HAVE_SISL)
  add("sisl-s1506", &run_sisl);
#endif
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  if (casteljau::bench::all_cores_run()) {
    benchmark::RegisterBenchmark("W5/grid/casteljau-all-cores",
                                 [](benchmark::State& state) {
                                   run_row(state, &run_casteljau_all_cores);
                                   state.counters["threads"] = casteljau::bench::usable_cpus();
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  } else {
    register_rows();
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

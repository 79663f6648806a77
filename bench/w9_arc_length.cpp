// W9 (issue 16): the arc length of W1's curve (bench/w1_curve.hpp: a cubic
// B-spline in 3D, 1000 random control points, 997 spans) at 1e-9 relative
// accuracy. Rows: W9/arc-length/<impl>, one whole length per iteration
// (items = 1 curve), casteljau's including its setup (the Bézier pieces).
//
// Oracle: casteljau at 1e-13 of the curve's size, cross-checked once against
// OpenCASCADE's GCPnts_AbscissaPoint::Length at its tightest tolerance (an
// independent integrator on OpenCASCADE's own evaluation); their relative
// difference is reported as oracle_agreement on every row, and the oracle
// is refused if they disagree beyond 1e-12. Each row fails (SkipWithError)
// when its length is more than 1e-9 relative away from the oracle and
// reports its relative error as error_rel.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/ops/arc_length.hpp"
#include "w1_curve.hpp"

#if defined(CASTELJAU_HAVE_OCCT)
#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>
#endif

namespace {

using casteljau::BSplineCurve;

constexpr double kRelativeAccuracy = 1e-9;

const BSplineCurve& curve() {
  static const BSplineCurve c = casteljau::bench::w1_curve();
  return c;
}

double casteljau_length(double relative) {
  const double size = casteljau::size_of(curve());
  return casteljau::arc_length(curve(), casteljau::Tolerance{relative * size}).value();
}

#if defined(CASTELJAU_HAVE_OCCT)
/// GCPnts_AbscissaPoint::Length(curve, tolerance): OpenCASCADE's arc length
/// (Gauss integration per span, refined until the tolerance, relative to the
/// length, is met).
double occt_length(double relative) {
  GeomAdaptor_Curve adaptor(casteljau::bench::occt_w1().curve);
  return GCPnts_AbscissaPoint::Length(adaptor, relative);
}
#endif

#if defined(CASTELJAU_HAVE_SISL)
/// s1240: SISL's curve length to a given absolute accuracy.
double sisl_length(double relative) {
  SISLCurve* c = casteljau::bench::sisl_w1();
  double length = NAN;
  int status = 0;
  s1240(c, relative * casteljau::size_of(curve()), &length, &status);
  return status < 0 ? NAN : length;
}
#endif

struct Oracle {
  double length = NAN;
  double agreement = NAN;  // relative difference to OpenCASCADE's tightest, NaN without it
};

const Oracle& oracle() {
  static const Oracle o = [] {
    Oracle result{casteljau_length(1e-13), NAN};
#if defined(CASTELJAU_HAVE_OCCT)
    result.agreement = std::abs(occt_length(1e-13) - result.length) / result.length;
#endif
    return result;
  }();
  return o;
}

std::string relative_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

void run_row(benchmark::State& state, double (*length)(double)) {
  const Oracle& reference = oracle();
  double value = NAN;
  for (auto _ : state) {
    value = length(kRelativeAccuracy);
    benchmark::DoNotOptimize(value);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  const double error = std::abs(value - reference.length) / reference.length;
  state.counters["error_rel"] = error;
  state.counters["oracle_agreement"] = reference.agreement;
  if (!(reference.agreement <= 1e-12) && !std::isnan(reference.agreement)) {
    state.SkipWithError(("the oracle and OpenCASCADE disagree by " + relative_text(reference.agreement)).c_str());
  } else if (!(error <= kRelativeAccuracy)) {
    state.SkipWithError(("relative error " + relative_text(error) + " exceeds the requested 1e-9 (length " +
                         relative_text(value) + ", oracle " + relative_text(reference.length) + ")")
                            .c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  auto add = [](const char* name, double (*length)(double)) {
    benchmark::RegisterBenchmark((std::string("W9/arc-length/") + name).c_str(),
                                 [length](benchmark::State& state) { run_row(state, length); })
        ->Unit(benchmark::kMillisecond);
  };
  add("casteljau", &casteljau_length);
#if defined(CASTELJAU_HAVE_OCCT)
  add("occt-abscissa", &occt_length);
#endif
#if defined(CASTELJAU_HAVE_SISL)
  add("sisl-s1240", &sisl_length);
#endif
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

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
using casteljau::bench::kW1ControlPoints;
using casteljau::bench::kW1Degree;

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
const Handle(Geom_BSplineCurve) & occt_curve() {
  static const Handle(Geom_BSplineCurve) c = [] {
    const int n = static_cast<int>(kW1ControlPoints), distinct = n - kW1Degree + 1;
    TColgp_Array1OfPnt poles(1, n);
    const std::vector<double> control = casteljau::bench::w1_control_points();
    for (int i = 0; i < n; ++i) poles.SetValue(i + 1, gp_Pnt(control[3 * i], control[3 * i + 1], control[3 * i + 2]));
    TColStd_Array1OfReal knots(1, distinct);
    TColStd_Array1OfInteger mults(1, distinct);
    const auto all = curve().knots();
    for (int i = 0; i < distinct; ++i) {
      knots.SetValue(i + 1, all[static_cast<std::size_t>(kW1Degree + i)]);
      mults.SetValue(i + 1, (i == 0 || i == distinct - 1) ? kW1Degree + 1 : 1);
    }
    return Handle(Geom_BSplineCurve)(new Geom_BSplineCurve(poles, knots, mults, kW1Degree));
  }();
  return c;
}

/// GCPnts_AbscissaPoint::Length(curve, tolerance): OpenCASCADE's arc length
/// (Gauss integration per span, refined until the tolerance, relative to the
/// length, is met).
double occt_length(double relative) {
  GeomAdaptor_Curve adaptor(occt_curve());
  return GCPnts_AbscissaPoint::Length(adaptor, relative);
}
#endif

#if defined(CASTELJAU_HAVE_SISL)
/// s1240: SISL's curve length to a given absolute accuracy.
double sisl_length(double relative) {
  static SISLCurve* c = [] {
    std::vector<double> knots(curve().knots().begin(), curve().knots().end());
    std::vector<double> control = casteljau::bench::w1_control_points();
    return newCurve(static_cast<int>(kW1ControlPoints), kW1Degree + 1, knots.data(), control.data(), 1, 3, 1);
  }();
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

// W9 (issue 16): the arc length of W1's curve (bench/w1_curve.hpp: a cubic
// B-spline in 3D, 1000 random control points, 997 spans) at 1e-9 relative
// accuracy. Rows: W9/arc-length/<impl>, one whole length per iteration
// (items = 1 curve), casteljau's including its setup (the Bézier pieces);
// W9/arc-length-xy/<impl> the same curve projected on the xy plane, for the
// plane-only peer kurbo (its 997 cubic pieces, each to its share).
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
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#endif
#if defined(CASTELJAU_HAVE_RUST_PEERS)
#include "casteljau/bspline/bezier_pieces.hpp"
#include "rust_peers.h"
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

/// W1's curve on the xy plane (bench/w1_curve.hpp).
const BSplineCurve& plane() {
  static const BSplineCurve c = casteljau::bench::w1_plane_curve();
  return c;
}

double casteljau_plane_length(double relative) {
  return casteljau::arc_length(plane(), casteljau::Tolerance{relative * casteljau::size_of(plane())}).value();
}

#if defined(CASTELJAU_HAVE_OCCT)
/// The plane curve as OpenCASCADE's Geom2d_BSplineCurve, GCPnts_AbscissaPoint on it.
double occt_plane_length(double relative) {
  static const Handle(Geom2d_BSplineCurve) c = [] {
    const casteljau::bench::OcctW1& w1 = casteljau::bench::occt_w1();
    TColgp_Array1OfPnt2d poles(1, w1.poles.Length());
    for (int i = 1; i <= w1.poles.Length(); ++i) poles.SetValue(i, gp_Pnt2d(w1.poles(i).X(), w1.poles(i).Y()));
    return Handle(Geom2d_BSplineCurve)(new Geom2d_BSplineCurve(poles, w1.knots, w1.mults, casteljau::bench::kW1Degree));
  }();
  Geom2dAdaptor_Curve adaptor(c);
  return GCPnts_AbscissaPoint::Length(adaptor, relative);
}
#endif

#if defined(CASTELJAU_HAVE_RUST_PEERS)
/// kurbo's ParamCurveArclen on the plane curve's 997 cubic pieces, each to
/// its share of the accuracy (kurbo's accuracy is absolute per call).
double kurbo_plane_length(double relative) {
  static const std::vector<double> cubics = [] {
    std::vector<double> all;
    for (const casteljau::BezierCurve& piece : casteljau::to_bezier_pieces(plane()).pieces) {
      const auto c = piece.control_points().coordinates();
      all.insert(all.end(), c.begin(), c.end());
    }
    return all;
  }();
  const std::size_t count = cubics.size() / 8;
  return casteljau_kurbo_path_arclen(cubics.data(), count,
                                     relative * casteljau::size_of(plane()) / static_cast<double>(count));
}
#endif

struct Oracle {
  double length = NAN;
  double agreement = NAN;  // relative difference to OpenCASCADE's tightest, NaN without it
};

const Oracle& plane_oracle() {
  static const Oracle o = [] {
    Oracle result{casteljau_plane_length(1e-13), NAN};
#if defined(CASTELJAU_HAVE_OCCT)
    result.agreement = std::abs(occt_plane_length(1e-13) - result.length) / result.length;
#endif
    return result;
  }();
  return o;
}

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

void run_row(benchmark::State& state, double (*length)(double), const Oracle& reference) {
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
  auto add = [](const char* variant, const char* name, double (*length)(double), const Oracle& (*reference)()) {
    benchmark::RegisterBenchmark((std::string("W9/") + variant + "/" + name).c_str(),
                                 [length, reference](benchmark::State& state) { run_row(state, length, reference()); })
        ->Unit(benchmark::kMillisecond);
  };
  add("arc-length", "casteljau", &casteljau_length, &oracle);
#if defined(CASTELJAU_HAVE_OCCT)
  add("arc-length", "occt-abscissa", &occt_length, &oracle);
#endif
#if defined(CASTELJAU_HAVE_SISL)
  add("arc-length", "sisl-s1240", &sisl_length, &oracle);
#endif
  add("arc-length-xy", "casteljau", &casteljau_plane_length, &plane_oracle);
#if defined(CASTELJAU_HAVE_OCCT)
  add("arc-length-xy", "occt-abscissa", &occt_plane_length, &plane_oracle);
#endif
#if defined(CASTELJAU_HAVE_RUST_PEERS)
  add("arc-length-xy", "kurbo", &kurbo_plane_length, &plane_oracle);
#endif
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

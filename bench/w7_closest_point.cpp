// W7 (issue 16): the nearest point of random query points on a curve.
//   W7/cubic/<impl>:     a plane cubic Bézier with an inflection, 10^5 queries
//                        uniform in its box grown by half its size each side.
//   W7/bspline/<impl>:   W1's curve (bench/w1_curve.hpp: a cubic B-spline in
//                        3D, 997 spans), 10^5 queries uniform in [0, 100)^3.
//   W7/bspline-xy/<impl>: W1's curve projected on the xy plane (a plane
//                        B-spline, 997 cubic pieces), for the plane-only peers.
// Items are query points answered; a peer too slow for all of them answers
// the first kPeerQueries (its items say so), which keeps the row's
// throughput comparable.
//
// Oracle: tests/support/nearest_oracle.hpp, brute force (the exact nearest of
// dense samples, golden-section refined), computed once per variant. A row's
// answer misses when its distance exceeds the oracle's by more than 1e-9 of
// the curve's size; casteljau's rows fail (SkipWithError) on any miss, the
// peers report theirs as the `misses` counter. OpenCASCADE's
// GeomAPI_ProjectPointOnCurve returns orthogonal projections only, so its
// rows also compare the two end points, as any caller must.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "support/nearest_oracle.hpp"
#include "support/splitmix.hpp"
#include "w1_curve.hpp"

#if defined(CASTELJAU_HAVE_OCCT)
#include <Geom2dAPI_ProjectPointOnCurve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#endif

#if defined(CASTELJAU_HAVE_RUST_PEERS)
#include "rust_peers.h"
#endif

namespace {

using casteljau::BezierCurve;
using casteljau::BSplineCurve;
using casteljau::CurveView;

constexpr std::size_t kQueries = 100000;
constexpr std::size_t kPeerQueries = 2000;
constexpr double kMissRelative = 1e-9;

/// One workload: the curve, its queries, the oracle's distances.
struct Workload {
  std::vector<double> queries;    // row-major, n x d
  std::vector<double> reference;  // the oracle's distance per query
  double size = 0.0;
  int dimension = 0;
  std::size_t count() const { return reference.size(); }
};

Workload make_workload(CurveView curve, std::vector<double> lower, std::vector<double> upper, std::uint64_t seed,
                       int samples_per_piece) {
  Workload w;
  w.dimension = curve.dimension();
  w.size = casteljau::size_of(curve);
  casteljau::test::SplitMix random{seed};
  w.queries.resize(kQueries * static_cast<std::size_t>(w.dimension));
  for (std::size_t i = 0; i < kQueries; ++i)
    for (int j = 0; j < w.dimension; ++j)
      w.queries[i * w.dimension + j] = lower[j] + (upper[j] - lower[j]) * random.unit();
  const casteljau::test::NearestOracle oracle(curve, samples_per_piece);
  w.reference.resize(kQueries);
  for (std::size_t i = 0; i < kQueries; ++i) w.reference[i] = oracle.distance(&w.queries[i * w.dimension]);
  return w;
}

const BezierCurve& cubic() {
  static const BezierCurve c = BezierCurve::from_trusted(
      casteljau::PointArray::from_trusted(2, {0.0, 0.0, 1.0, 4.0, 3.0, -2.0, 4.0, 2.0}));
  return c;
}
const BSplineCurve& spatial() {
  static const BSplineCurve c = casteljau::bench::w1_curve();
  return c;
}
/// W1's curve on the xy plane (bench/w1_curve.hpp).
const BSplineCurve& plane() {
  static const BSplineCurve c = casteljau::bench::w1_plane_curve();
  return c;
}

const Workload& cubic_workload() {
  static const Workload w = make_workload(cubic(), {-2.0, -3.0}, {6.0, 5.0}, 7001, 8192);
  return w;
}
const Workload& spatial_workload() {
  static const Workload w = make_workload(spatial(), {0, 0, 0}, {100, 100, 100}, 7002, 64);
  return w;
}
const Workload& plane_workload() {
  static const Workload w = make_workload(plane(), {0, 0}, {100, 100}, 7003, 64);
  return w;
}

/// Counts the misses of `distances` (the first distances.size() queries) and reports them.
void check(benchmark::State& state, const Workload& w, const std::vector<double>& distances, bool ours) {
  std::size_t misses = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    const double excess = (distances[i] - w.reference[i]) / w.size;
    if (!(excess <= kMissRelative)) ++misses;
    if (std::isfinite(excess)) worst = std::max(worst, excess);
  }
  state.counters["misses"] = static_cast<double>(misses);
  state.counters["worst_excess_rel"] = worst;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * distances.size()));
  if (ours && misses > 0)
    state.SkipWithError((std::to_string(misses) + " queries farther than the oracle by more than 1e-9 of the size").c_str());
}

void casteljau_row(benchmark::State& state, CurveView curve, const Workload& w) {
  std::vector<double> parameters(w.count()), distances(w.count());
  for (auto _ : state) {
    if (!casteljau::closest_points(curve, w.queries, parameters, distances)) state.SkipWithError("refused");
    benchmark::DoNotOptimize(distances.data());
  }
  check(state, w, distances, true);
}

#if defined(CASTELJAU_HAVE_OCCT)
double end_distance(const double* q, const casteljau::Point& start, const casteljau::Point& end) {
  double s = 0.0, e = 0.0;
  for (std::size_t j = 0; j < start.size(); ++j) s += (q[j] - start[j]) * (q[j] - start[j]), e += (q[j] - end[j]) * (q[j] - end[j]);
  return std::sqrt(std::min(s, e));
}

/// Geom2dAPI_ProjectPointOnCurve on a plane curve, LowerDistance() and the ends.
void occt_plane_row(benchmark::State& state, const Handle(Geom2d_Curve)& curve, CurveView ours, const Workload& w,
                    std::size_t count) {
  const casteljau::Interval domain = ours.domain();
  const casteljau::Point start = casteljau::point_at(ours, domain.lower), end = casteljau::point_at(ours, domain.upper);
  std::vector<double> distances(count);
  for (auto _ : state) {
    Geom2dAPI_ProjectPointOnCurve projector;
    for (std::size_t i = 0; i < count; ++i) {
      const double* q = &w.queries[2 * i];
      projector.Init(gp_Pnt2d(q[0], q[1]), curve);
      const double ends = end_distance(q, start, end);
      distances[i] = projector.NbPoints() > 0 ? std::min(projector.LowerDistance(), ends) : ends;
    }
    benchmark::DoNotOptimize(distances.data());
  }
  check(state, w, distances, false);
}

Handle(Geom2d_Curve) occt_cubic() {
  TColgp_Array1OfPnt2d poles(1, 4);
  const auto& p = cubic().control_points();
  for (int i = 0; i < 4; ++i) poles.SetValue(i + 1, gp_Pnt2d(p[i][0], p[i][1]));
  return new Geom2d_BezierCurve(poles);
}

Handle(Geom2d_Curve) occt_plane() {
  const casteljau::bench::OcctW1& w1 = casteljau::bench::occt_w1();
  TColgp_Array1OfPnt2d poles(1, w1.poles.Length());
  for (int i = 1; i <= w1.poles.Length(); ++i) poles.SetValue(i, gp_Pnt2d(w1.poles(i).X(), w1.poles(i).Y()));
  return new Geom2d_BSplineCurve(poles, w1.knots, w1.mults, casteljau::bench::kW1Degree);
}

void occt_spatial_row(benchmark::State& state) {
  const Workload& w = spatial_workload();
  const casteljau::Interval domain = spatial().domain();
  const casteljau::Point start = casteljau::point_at(spatial(), domain.lower), end = casteljau::point_at(spatial(), domain.upper);
  std::vector<double> distances(kPeerQueries);
  for (auto _ : state) {
    GeomAPI_ProjectPointOnCurve projector;
    for (std::size_t i = 0; i < kPeerQueries; ++i) {
      const double* q = &w.queries[3 * i];
      projector.Init(gp_Pnt(q[0], q[1], q[2]), casteljau::bench::occt_w1().curve);
      const double ends = end_distance(q, start, end);
      distances[i] = projector.NbPoints() > 0 ? std::min(projector.LowerDistance(), ends) : ends;
    }
    benchmark::DoNotOptimize(distances.data());
  }
  check(state, w, distances, false);
}
#endif

#if defined(CASTELJAU_HAVE_RUST_PEERS)
/// kurbo's ParamCurveNearest on a CubicBez (accuracy 1e-9 of the size).
void kurbo_cubic_row(benchmark::State& state) {
  const Workload& w = cubic_workload();
  const std::vector<double> p(cubic().control_points().coordinates().begin(), cubic().control_points().coordinates().end());
  std::vector<double> ts(w.count()), squared(w.count()), distances(w.count());
  for (auto _ : state) {
    casteljau_kurbo_cubic_nearest(p.data(), w.queries.data(), w.count(), kMissRelative * w.size, ts.data(), squared.data());
    benchmark::DoNotOptimize(squared.data());
  }
  for (std::size_t i = 0; i < w.count(); ++i) distances[i] = std::sqrt(squared[i]);
  check(state, w, distances, false);
}

/// kurbo over the plane B-spline's cubic pieces: the nearest of every piece's nearest.
void kurbo_plane_row(benchmark::State& state) {
  const Workload& w = plane_workload();
  const casteljau::BezierPieces pieces = casteljau::to_bezier_pieces(plane());
  std::vector<double> cubics;
  for (const BezierCurve& piece : pieces.pieces) {
    const auto c = piece.control_points().coordinates();
    cubics.insert(cubics.end(), c.begin(), c.end());
  }
  std::vector<std::size_t> piece(kPeerQueries);
  std::vector<double> ts(kPeerQueries), squared(kPeerQueries), distances(kPeerQueries);
  for (auto _ : state) {
    casteljau_kurbo_path_nearest(cubics.data(), pieces.pieces.size(), w.queries.data(), kPeerQueries,
                                 kMissRelative * w.size, piece.data(), ts.data(), squared.data());
    benchmark::DoNotOptimize(squared.data());
  }
  for (std::size_t i = 0; i < kPeerQueries; ++i) distances[i] = std::sqrt(squared[i]);
  check(state, w, distances, false);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  auto add = [](const std::string& name, auto row) {
    benchmark::RegisterBenchmark(("W7/" + name).c_str(), row)->Unit(benchmark::kMillisecond);
  };
  add("cubic/casteljau", [](benchmark::State& s) { casteljau_row(s, cubic(), cubic_workload()); });
  add("bspline/casteljau", [](benchmark::State& s) { casteljau_row(s, spatial(), spatial_workload()); });
  add("bspline-xy/casteljau", [](benchmark::State& s) { casteljau_row(s, plane(), plane_workload()); });
#if defined(CASTELJAU_HAVE_OCCT)
  add("cubic/occt-project", [](benchmark::State& s) {
    occt_plane_row(s, occt_cubic(), cubic(), cubic_workload(), kQueries);
  });
  add("bspline/occt-project", [](benchmark::State& s) { occt_spatial_row(s); });
  add("bspline-xy/occt-project", [](benchmark::State& s) {
    occt_plane_row(s, occt_plane(), plane(), plane_workload(), kPeerQueries);
  });
#endif
#if defined(CASTELJAU_HAVE_RUST_PEERS)
  add("cubic/kurbo", [](benchmark::State& s) { kurbo_cubic_row(s); });
  add("bspline-xy/kurbo", [](benchmark::State& s) { kurbo_plane_row(s); });
#endif
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

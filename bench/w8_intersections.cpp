// W8 (issue 16): intersections of 10^4 pairs of plane cubic Béziers, every
// control point a dyadic rational (k / 2^20 in [0, 1]) so that the exact
// oracle sees the very curves the doubles hold:
//   80% random pairs; 10% tangent pairs (b built through a(s0) with the
//   tangent a'(s0) and another curvature: a contact of order 2); 10% near
//   tangent pairs (such a b moved by 2^-30 to 2^-29 along the normal at the
//   contact, either side: two crossings about 2^-15 apart, or none).
// Rows: W8/cubic-pairs/<impl>, all pairs per iteration (items = pairs).
//
// Oracle: tests/support/exact_intersections.hpp (resultants and exact root
// isolation in GMP), once per run. A pair is judged by its distinct
// intersection points (answers within 1e-6 in both parameters are one):
// `misses` counts the pairs where an implementation lost an exact point (a
// tangency, or two crossings closer than 1e-6, found as one point counts as
// found), `spurious` those where it reported a point the oracle does not
// have (beyond 1e-6 of every exact point). casteljau's row fails on either;
// the peers report theirs. casteljau runs at a tolerance of 1e-12 of the
// size: the near-tangent pairs' 2^-30 gap is 1e-9 of it, a contact at the
// default tolerance; the peers run at their defaults (OpenCASCADE's 1e-6).
// W8_DEBUG=1 in the environment prints every pair judged wrong, with the
// oracle's points and the row's.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "casteljau/ops/intersection.hpp"
#include "support/exact_intersections.hpp"
#include "support/splitmix.hpp"

#if defined(CASTELJAU_HAVE_OCCT)
#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#endif
#if defined(CASTELJAU_HAVE_2GEOM)
#include <2geom/bezier-curve.h>
#endif
#if defined(CASTELJAU_HAVE_RUST_PEERS)
#include "rust_peers.h"
#endif

namespace {

using casteljau::BezierCurve;
using casteljau::test::ExactBezier;
using Q = mpq_class;

constexpr int kPairs = 10000;
constexpr double kSame = 1e-6;

/// One pair: its control points (8 doubles each) and the oracle's points (a, b).
struct Pair {
  std::vector<double> a, b;
  std::vector<std::pair<double, double>> exact;
};

ExactBezier exact_of(const std::vector<double>& p) {
  ExactBezier e;
  for (int i = 0; i < 4; ++i) e.points.push_back({Q(p[2 * i]), Q(p[2 * i + 1])});
  return e;
}

double dyadic(casteljau::test::SplitMix& random) { return std::ldexp(static_cast<double>(random.next() >> 44), -20); }

/// b through a(s0) with the tangent a'(s0), built in power form about u = 1/2
/// and converted to Bernstein form; every coefficient stays dyadic because
/// the power coefficients are multiples of 3 (P1 = P0 + c1 / 3 ...).
std::vector<double> tangent_to(const std::vector<double>& a, double s0, casteljau::test::SplitMix& random) {
  const BezierCurve curve =
      BezierCurve::from_trusted(casteljau::PointArray::from_trusted(2, std::vector<double>(a.begin(), a.end())));
  const std::vector<casteljau::Point> d = casteljau::derivatives_up_to(curve, s0, 1);  // exact for dyadic s0 of few bits
  const double px = d[0][0], py = d[0][1], tx = d[1][0], ty = d[1][1];
  // b(u) = P + T h + c N h^2 + D h^3, h = u - 1/2, N = T rotated; c, D multiples of 3.
  const double c = 3.0 * (1.0 + std::ldexp(static_cast<double>(random.next() >> 60), -2));
  const double dx = 3.0 * (dyadic(random) - 0.5), dy = 3.0 * (dyadic(random) - 0.5);
  const double nx = -ty, ny = tx;
  // Power coefficients about u = 0: expand h = u - 1/2.
  const auto power = [&](double p0, double t, double n, double dd) {
    const double c0 = p0 - t / 2 + c * n / 4 - dd / 8;
    const double c1 = t - c * n + 3 * dd / 4;
    const double c2 = c * n - 3 * dd / 2;
    const double c3 = dd;
    return std::array<double, 4>{c0, c0 + c1 / 3, c0 + 2 * c1 / 3 + c2 / 3, c0 + c1 + c2 + c3};
  };
  const auto x = power(px, tx, nx, dx), y = power(py, ty, ny, dy);
  return {x[0], y[0], x[1], y[1], x[2], y[2], x[3], y[3]};
}

const std::vector<Pair>& pairs() {
  static const std::vector<Pair> all = [] {
    casteljau::test::SplitMix random{8008};
    std::vector<Pair> result;
    for (int k = 0; k < kPairs; ++k) {
      Pair pair;
      for (int i = 0; i < 8; ++i) pair.a.push_back(dyadic(random));
      const int kind = k % 10;
      if (kind < 8) {
        for (int i = 0; i < 8; ++i) pair.b.push_back(dyadic(random));
      } else {
        const double s0 = std::ldexp(static_cast<double>(1 + (random.next() >> 61)), -3);  // 1/8 .. 7/8
        pair.b = tangent_to(pair.a, s0, random);
        if (kind == 9) {
          // Moved along the normal N = (-T_y, T_x) at the contact, scaled by a
          // power of two (exact): between 2^-30 and 2^-29 away, either side.
          const BezierCurve b = BezierCurve::from_trusted(casteljau::PointArray::from_trusted(2, pair.b));
          const casteljau::Point t = casteljau::derivative_at(b, 0.5, 1);
          const double scale = std::ldexp(1.0, -30 - std::ilogb(std::hypot(t[0], t[1])));
          const double side = (random.next() & 1) ? scale : -scale;
          for (int i = 0; i < 4; ++i) pair.b[2 * i] += -t[1] * side, pair.b[2 * i + 1] += t[0] * side;
        }
      }
      for (const auto& x : casteljau::test::exact_intersections(exact_of(pair.a), exact_of(pair.b)))
        if (x.kind != casteljau::test::ExactIntersection::Kind::overlap)
          pair.exact.emplace_back(casteljau::test::exact_estimate(x.a_lower, x.a_upper),
                                  casteljau::test::exact_estimate(x.b_lower, x.b_upper));
      result.push_back(std::move(pair));
    }
    return result;
  }();
  return all;
}

/// Misses and spurious points of one pair's answers against the oracle.
void judge(const Pair& pair, const std::vector<std::pair<double, double>>& found, std::size_t& misses, std::size_t& spurious) {
  const auto near = [](const std::pair<double, double>& x, const std::pair<double, double>& y) {
    return std::abs(x.first - y.first) <= kSame && std::abs(x.second - y.second) <= kSame;
  };
  bool missed = false, extra = false;
  for (const auto& e : pair.exact)
    if (std::none_of(found.begin(), found.end(), [&](const auto& f) { return near(e, f); })) missed = true;
  for (const auto& f : found)
    if (std::none_of(pair.exact.begin(), pair.exact.end(), [&](const auto& e) { return near(e, f); })) extra = true;
  misses += missed;
  spurious += extra;
  if ((missed || extra) && std::getenv("W8_DEBUG")) {
    std::fprintf(stderr, "pair a=");
    for (double x : pair.a) std::fprintf(stderr, "%.17g,", x);
    std::fprintf(stderr, " b=");
    for (double x : pair.b) std::fprintf(stderr, "%.17g,", x);
    std::fprintf(stderr, "\n  exact:");
    for (const auto& e : pair.exact) std::fprintf(stderr, " (%.12g, %.12g)", e.first, e.second);
    std::fprintf(stderr, "\n  found:");
    for (const auto& f : found) std::fprintf(stderr, " (%.12g, %.12g)", f.first, f.second);
    std::fprintf(stderr, "\n");
  }
}

template <class Intersect>
void run_row(benchmark::State& state, Intersect&& intersect, bool ours) {
  const std::vector<Pair>& all = pairs();
  std::vector<std::vector<std::pair<double, double>>> found(all.size());
  for (auto _ : state) {
    for (std::size_t k = 0; k < all.size(); ++k) {
      found[k].clear();
      intersect(all[k], found[k]);
    }
    benchmark::DoNotOptimize(found.data());
  }
  std::size_t misses = 0, spurious = 0;
  for (std::size_t k = 0; k < all.size(); ++k) judge(all[k], found[k], misses, spurious);
  state.counters["misses"] = static_cast<double>(misses);
  state.counters["spurious"] = static_cast<double>(spurious);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * all.size()));
  if (ours && misses + spurious > 0)
    state.SkipWithError((std::to_string(misses) + " pairs missed and " + std::to_string(spurious) +
                         " had spurious points against the exact oracle")
                            .c_str());
}

BezierCurve cubic(const std::vector<double>& p) {
  return BezierCurve::from_trusted(casteljau::PointArray::from_trusted(2, std::vector<double>(p.begin(), p.end())));
}

void casteljau_pair(const Pair& pair, std::vector<std::pair<double, double>>& out) {
  const BezierCurve a = cubic(pair.a), b = cubic(pair.b);
  // 1e-12 of the size: the near-tangent pairs pass 2^-30 (about 1e-9 of
  // the size) apart, a contact within the default tolerance of 1e-9.
  const double size = std::max(casteljau::size_of(a), casteljau::size_of(b));
  const auto found = casteljau::intersections(a, b, casteljau::Tolerance{1e-12 * size});
  for (const casteljau::CurveIntersection& x : found.value())
    if (x.kind != casteljau::IntersectionKind::overlap) out.emplace_back(x.a.lower, x.b.lower);
}

#if defined(CASTELJAU_HAVE_OCCT)
Handle(Geom2d_BezierCurve) occt_cubic(const std::vector<double>& p) {
  TColgp_Array1OfPnt2d poles(1, 4);
  for (int i = 0; i < 4; ++i) poles.SetValue(i + 1, gp_Pnt2d(p[2 * i], p[2 * i + 1]));
  return new Geom2d_BezierCurve(poles);
}
/// Geom2dAPI_InterCurveCurve with OpenCASCADE's default tolerance (1e-6).
void occt_pair(const Pair& pair, std::vector<std::pair<double, double>>& out) {
  Geom2dAPI_InterCurveCurve inter(occt_cubic(pair.a), occt_cubic(pair.b), 1e-6);
  for (int i = 1; i <= inter.NbPoints(); ++i) {
    const IntRes2d_IntersectionPoint& p = inter.Intersector().Point(i);
    out.emplace_back(p.ParamOnFirst(), p.ParamOnSecond());
  }
}
#endif

#if defined(CASTELJAU_HAVE_2GEOM)
/// Geom::CubicBezier::intersect (lib2geom's Bézier clipping) at its default epsilon.
void lib2geom_pair(const Pair& pair, std::vector<std::pair<double, double>>& out) {
  const auto make = [](const std::vector<double>& p) {
    return Geom::CubicBezier(Geom::Point(p[0], p[1]), Geom::Point(p[2], p[3]), Geom::Point(p[4], p[5]),
                             Geom::Point(p[6], p[7]));
  };
  const Geom::CubicBezier a = make(pair.a), b = make(pair.b);
  for (const Geom::CurveIntersection& x : a.intersect(b)) out.emplace_back(x.first, x.second);
}
#endif

#if defined(CASTELJAU_HAVE_RUST_PEERS)
/// lyon_geom's CubicBezierSegment::cubic_intersections_t.
void lyon_pair(const Pair& pair, std::vector<std::pair<double, double>>& out) {
  double ta[9], tb[9];
  const std::size_t n = std::min<std::size_t>(9, casteljau_lyon_cubic_intersections(pair.a.data(), pair.b.data(), ta, tb, 9));
  for (std::size_t i = 0; i < n; ++i) out.emplace_back(ta[i], tb[i]);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const auto add = [](const std::string& name, auto intersect, bool ours) {
    benchmark::RegisterBenchmark(("W8/cubic-pairs/" + name).c_str(),
                                 [intersect, ours](benchmark::State& state) { run_row(state, intersect, ours); })
        ->Unit(benchmark::kMillisecond);
  };
  add("casteljau", &casteljau_pair, true);
#if defined(CASTELJAU_HAVE_OCCT)
  add("occt-intercurvecurve", &occt_pair, false);
#endif
#if defined(CASTELJAU_HAVE_2GEOM)
  add("lib2geom-intersect", &lib2geom_pair, false);
#endif
#if defined(CASTELJAU_HAVE_RUST_PEERS)
  add("lyon-cubic-intersections", &lyon_pair, false);
#endif
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

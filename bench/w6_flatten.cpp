// W6 (../../shared/docs/performance.md): flatten a cubic Bézier spanning 100
// units to a polyline within 0.01, three shapes, casteljau beside its peers.
// Rows W6/<shape>/<impl>. Every row carries counters measured outside the
// timed loop and independently of the method: segments, max_deviation (dense
// samples of the curve, evaluated by the Bernstein sum, against the produced
// polyline, refined near the worst samples), within_tolerance, and the optimum
// segment count with vertices on the curve (greedy furthest reach with a dense
// deviation check; greedy is optimal when the feasible pieces are nested).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/ops/flatten.hpp"

#ifdef CASTELJAU_HAVE_OCCT
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <GCPnts_UniformDeflection.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#endif

namespace {

constexpr double kTolerance = 0.01;
constexpr int kDenseSamples = 200000;

struct P2 {
  double x, y;
};
P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
P2 operator*(double s, P2 a) { return {s * a.x, s * a.y}; }
double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }
double cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
P2 lerp(P2 a, P2 b, double t) { return a + t * (b - a); }

using Cubic = std::array<P2, 4>;

struct Shape {
  const char* name;
  Cubic points;
};

const Shape kShapes[] = {
    {"gentle-arc", {{{0, 0}, {30, 40}, {70, 40}, {100, 0}}}},
    {"s-curve", {{{0, 0}, {100, 0}, {0, 100}, {100, 100}}}},
    {"near-cusp", {{{0, 0}, {100, 100}, {5, 100}, {100, 0}}}},
};

// ---- the independent reference: Bernstein sum and distance to segments -----

P2 bernstein_point(const Cubic& c, double t) {
  const double s = 1.0 - t;
  const double b0 = s * s * s, b1 = 3.0 * t * s * s, b2 = 3.0 * t * t * s, b3 = t * t * t;
  return {b0 * c[0].x + b1 * c[1].x + b2 * c[2].x + b3 * c[3].x, b0 * c[0].y + b1 * c[1].y + b2 * c[2].y + b3 * c[3].y};
}

double distance_to_segment(P2 p, P2 a, P2 b) {
  const P2 ab = b - a;
  const double l2 = dot(ab, ab);
  const double u = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  const P2 e = p - (a + u * ab);
  return std::sqrt(dot(e, e));
}

double distance_to_polyline(P2 p, const std::vector<P2>& line) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) best = std::min(best, distance_to_segment(p, line[i], line[i + 1]));
  return best;
}

/// Golden-section maximisation of f on [lo, hi] (f unimodal there), returning the max seen.
template <class F>
double golden_maximum(F f, double lo, double hi, double best) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 80 && hi - lo > 1e-15; ++i) {
    if (f1 > f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - r * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + r * (hi - lo), f2 = f(x2);
    }
  }
  return std::max({best, f1, f2});
}

/// Largest distance from the curve to the polyline (Hausdorff, curve to
/// polyline): dense samples, then golden-section refinement around the 32
/// largest local maxima of the sampled distance.
double measured_deviation(const Cubic& c, const std::vector<P2>& line) {
  std::vector<double> d(kDenseSamples + 1);
  for (int k = 0; k <= kDenseSamples; ++k) d[k] = distance_to_polyline(bernstein_point(c, double(k) / kDenseSamples), line);
  std::vector<int> peaks;
  for (int k = 0; k <= kDenseSamples; ++k)
    if ((k == 0 || d[k] >= d[k - 1]) && (k == kDenseSamples || d[k] >= d[k + 1])) peaks.push_back(k);
  std::sort(peaks.begin(), peaks.end(), [&](int a, int b) { return d[a] > d[b]; });
  double worst = *std::max_element(d.begin(), d.end());
  auto f = [&](double t) { return distance_to_polyline(bernstein_point(c, t), line); };
  for (std::size_t i = 0; i < std::min<std::size_t>(peaks.size(), 32); ++i) {
    const int k = peaks[i];
    worst = golden_maximum(f, std::max(0.0, double(k - 1) / kDenseSamples),
                           std::min(1.0, double(k + 1) / kDenseSamples), worst);
  }
  return worst;
}

/// Largest distance from C on [a, b] to the chord [C(a), C(b)], densely.
double dense_piece_deviation(const Cubic& c, double a, double b) {
  constexpr int kPieceSamples = 2000;
  const P2 pa = bernstein_point(c, a), pb = bernstein_point(c, b);
  auto f = [&](double t) { return distance_to_segment(bernstein_point(c, t), pa, pb); };
  double worst = 0.0;
  int worst_k = 0;
  for (int k = 1; k < kPieceSamples; ++k) {
    const double v = f(a + (b - a) * k / kPieceSamples);
    if (v > worst) worst = v, worst_k = k;
  }
  return golden_maximum(f, a + (b - a) * (worst_k - 1) / kPieceSamples, a + (b - a) * (worst_k + 1) / kPieceSamples,
                        worst);
}

/// The optimum number of segments with vertices on the curve: greedy furthest
/// reach, each reach found by bisection on the dense deviation.
int optimum_segments(const Cubic& c, double tolerance) {
  double a = 0.0;
  int segments = 0;
  while (a < 1.0) {
    ++segments;
    if (dense_piece_deviation(c, a, 1.0) <= tolerance) break;
    double lo = a, hi = 1.0;
    for (int i = 0; i < 50; ++i) {
      const double mid = 0.5 * (lo + hi);
      (dense_piece_deviation(c, a, mid) <= tolerance ? lo : hi) = mid;
    }
    a = lo;
  }
  return segments;
}

// ---- casteljau ---------------------------------------------------------------

casteljau::BezierCurve to_curve(const Cubic& c) {
  std::vector<double> xy;
  for (const P2& p : c) xy.insert(xy.end(), {p.x, p.y});
  return casteljau::BezierCurve::make(*casteljau::PointArray::make(2, xy)).value();
}

std::vector<P2> run_casteljau(const casteljau::BezierCurve& curve) {
  const auto line = casteljau::flatten(curve, casteljau::Tolerance{kTolerance});
  std::vector<P2> out;
  for (std::size_t i = 0; i < line->points.size(); ++i) out.push_back({line->points[i][0], line->points[i][1]});
  return out;
}

// ---- subdivision: recursive halving with the control-polygon test ------------

void subdivide_into(const Cubic& c, double tolerance, std::vector<P2>& out, int depth) {
  const double flatness = std::max(distance_to_segment(c[1], c[0], c[3]), distance_to_segment(c[2], c[0], c[3]));
  if (flatness <= tolerance || depth >= 40) {
    out.push_back(c[3]);
    return;
  }
  const P2 p01 = lerp(c[0], c[1], 0.5), p12 = lerp(c[1], c[2], 0.5), p23 = lerp(c[2], c[3], 0.5);
  const P2 p012 = lerp(p01, p12, 0.5), p123 = lerp(p12, p23, 0.5), mid = lerp(p012, p123, 0.5);
  subdivide_into({c[0], p01, p012, mid}, tolerance, out, depth + 1);
  subdivide_into({mid, p123, p23, c[3]}, tolerance, out, depth + 1);
}

void run_subdivision(const Cubic& c, std::vector<P2>& out) {
  out.clear();
  out.push_back(c[0]);
  subdivide_into(c, kTolerance, out, 0);
}

// ---- Levien's parabola method (kurbo's flatten), a peer without guarantee ----
// R. Levien, "Flattening quadratic Béziers" (2019): the cubic is cut into
// quadratics (error 0.1 x tolerance, the count from the cubic-to-quadratic
// bound |P3 - 3P2 + 3P1 - P0| sqrt(3)/36), each quadratic mapped to a piece of
// the parabola y = x^2, and vertices spread evenly in an approximation of
// the integral of the square root of curvature; vertices lie on the quadratics.

double approx_parabola_integral(double x) {
  constexpr double d = 0.67;
  return x / (1.0 - d + std::sqrt(std::sqrt(d * d * d * d + 0.25 * x * x)));
}
double approx_parabola_inv_integral(double x) {
  constexpr double b = 0.39;
  return x * (1.0 - b + std::sqrt(b * b + 0.25 * x * x));
}

struct Quad {
  P2 p0, p1, p2;
  double a0, a2, u0, uscale, val;
};

void estimate_subdivision(Quad& q, double sqrt_tolerance) {
  const P2 d01 = q.p1 - q.p0, d12 = q.p2 - q.p1, dd = d01 - d12;
  const double cr = cross(q.p2 - q.p0, dd);
  const double x0 = dot(d01, dd) / cr, x2 = dot(d12, dd) / cr;
  const double scale = std::abs(cr / (std::sqrt(dot(dd, dd)) * (x2 - x0)));
  q.a0 = approx_parabola_integral(x0);
  q.a2 = approx_parabola_integral(x2);
  q.val = 0.0;
  if (std::isfinite(scale)) {
    const double da = std::abs(q.a2 - q.a0), sqrt_scale = std::sqrt(scale);
    if (std::signbit(x0) == std::signbit(x2)) {
      q.val = da * sqrt_scale;
    } else {  // the piece holds the curvature maximum
      const double xmin = sqrt_tolerance / sqrt_scale;
      q.val = sqrt_tolerance * da / approx_parabola_integral(xmin);
    }
  }
  q.u0 = approx_parabola_inv_integral(q.a0);
  q.uscale = 1.0 / (approx_parabola_inv_integral(q.a2) - q.u0);
}

void run_levien(const Cubic& c, std::vector<P2>& out, std::vector<Quad>& quads) {
  constexpr double kToQuadShare = 0.1;
  out.clear();
  quads.clear();
  out.push_back(c[0]);
  const double q_accuracy = kTolerance * kToQuadShare;
  const P2 e = (c[3] - c[0]) + 3.0 * (c[1] - c[2]);
  const double err = dot(e, e), max_hypot2 = 432.0 * q_accuracy * q_accuracy;
  const int n_quads = std::max(1, int(std::ceil(std::pow(err / max_hypot2, 1.0 / 6.0))));
  const double sqrt_remain = std::sqrt(kTolerance * (1.0 - kToQuadShare));
  double sum = 0.0;
  for (int i = 0; i < n_quads; ++i) {
    const double t0 = double(i) / n_quads, t1 = double(i + 1) / n_quads;
    // the sub-cubic on [t0, t1] by the blossom, then its best quadratic
    auto blossom = [&](double u, double v, double w) {
      P2 a[4] = {c[0], c[1], c[2], c[3]};
      const double ts[3] = {u, v, w};
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3 - r; ++k) a[k] = lerp(a[k], a[k + 1], ts[r]);
      return a[0];
    };
    const P2 s0 = blossom(t0, t0, t0), s1 = blossom(t0, t0, t1), s2 = blossom(t0, t1, t1), s3 = blossom(t1, t1, t1);
    Quad q{s0, 0.25 * ((3.0 * s1 - s0) + (3.0 * s2 - s3)), s3, 0, 0, 0, 0, 0};
    estimate_subdivision(q, sqrt_remain);
    sum += q.val;
    quads.push_back(q);
  }
  const int n = std::max(1, int(std::ceil(0.5 * sum / sqrt_remain)));
  const double step = sum / n;
  int i = 1;
  double val_sum = 0.0;
  for (const Quad& q : quads) {
    double target = i * step;
    while (target < val_sum + q.val && i < n) {
      const double u = (target - val_sum) / q.val;
      const double a = q.a0 + (q.a2 - q.a0) * u;
      const double t = (approx_parabola_inv_integral(a) - q.u0) * q.uscale;
      const double s = 1.0 - t;
      out.push_back(s * s * q.p0 + 2.0 * s * t * q.p1 + t * t * q.p2);
      ++i;
      target = i * step;
    }
    val_sum += q.val;
  }
  out.push_back(c[3]);
}

// ---- OpenCASCADE -------------------------------------------------------------

#ifdef CASTELJAU_HAVE_OCCT
Geom2dAdaptor_Curve occt_curve(const Cubic& c) {
  TColgp_Array1OfPnt2d poles(1, 4);
  for (int i = 0; i < 4; ++i) poles.SetValue(i + 1, gp_Pnt2d(c[i].x, c[i].y));
  return Geom2dAdaptor_Curve(new Geom2d_BezierCurve(poles));
}

template <class Algorithm>
void run_occt(const Geom2dAdaptor_Curve& curve, std::vector<P2>& out) {
  out.clear();
  Algorithm algorithm(curve, kTolerance);
  if (!algorithm.IsDone()) return;
  for (int i = 1; i <= algorithm.NbPoints(); ++i) {
    const gp_Pnt2d p = curve.Value(algorithm.Parameter(i));
    out.push_back({p.X(), p.Y()});
  }
}
#endif

// ---- rows --------------------------------------------------------------------

/// Who answers for the tolerance: casteljau and the methods written here
/// (subdivision, Levien's) promise it, so exceeding it fails the row; a
/// peer's excess is its measured behaviour, reported (within_tolerance = 0,
/// and bench/report.py leaves it out of the best-peer ratio), not a failure.
enum class Promise { tolerance, reported };

void set_counters(benchmark::State& state, const Cubic& c, const std::vector<P2>& line, int optimum,
                  Promise promise = Promise::tolerance) {
  // A polyline must run from the curve's first point to its last.
  if (line.size() < 2 || line.front().x != c[0].x || line.front().y != c[0].y ||
      std::hypot(line.back().x - c[3].x, line.back().y - c[3].y) > 1e-12 * 100.0) {
    state.SkipWithError("the polyline does not join the curve's end points");
    return;
  }
  const double deviation = measured_deviation(c, line);
  state.counters["segments"] = double(line.size()) - 1.0;
  state.counters["max_deviation"] = deviation;
  state.counters["within_tolerance"] = deviation <= kTolerance ? 1.0 : 0.0;
  state.counters["optimum"] = optimum;
  state.counters["ratio_to_optimum"] = (double(line.size()) - 1.0) / optimum;
  if (promise == Promise::tolerance && !(deviation <= kTolerance)) {
    state.SkipWithError(("deviation " + std::to_string(deviation) + " exceeds the tolerance").c_str());
  }
}

void register_rows(const Shape& shape, int optimum) {
  const std::string prefix = std::string("W6/") + shape.name + "/";
  const Cubic c = shape.points;
  benchmark::RegisterBenchmark((prefix + "casteljau").c_str(), [c, optimum](benchmark::State& state) {
    const casteljau::BezierCurve curve = to_curve(c);
    for (auto _ : state) {
      auto line = casteljau::flatten(curve, casteljau::Tolerance{kTolerance});
      benchmark::DoNotOptimize(line);
    }
    set_counters(state, c, run_casteljau(curve), optimum);
  });
  benchmark::RegisterBenchmark((prefix + "subdivision").c_str(), [c, optimum](benchmark::State& state) {
    std::vector<P2> out;
    out.reserve(1024);
    for (auto _ : state) {
      run_subdivision(c, out);
      benchmark::DoNotOptimize(out.data());
    }
    set_counters(state, c, out, optimum);
  });
  benchmark::RegisterBenchmark((prefix + "levien-parabola").c_str(), [c, optimum](benchmark::State& state) {
    std::vector<P2> out;
    std::vector<Quad> quads;
    out.reserve(1024);
    quads.reserve(64);
    for (auto _ : state) {
      run_levien(c, out, quads);
      benchmark::DoNotOptimize(out.data());
    }
    set_counters(state, c, out, optimum);
  });
#ifdef CASTELJAU_HAVE_OCCT
  benchmark::RegisterBenchmark((prefix + "occt-uniform-deflection").c_str(), [c, optimum](benchmark::State& state) {
    const Geom2dAdaptor_Curve curve = occt_curve(c);
    std::vector<P2> out;
    out.reserve(1024);
    for (auto _ : state) {
      run_occt<GCPnts_UniformDeflection>(curve, out);
      benchmark::DoNotOptimize(out.data());
    }
    set_counters(state, c, out, optimum, Promise::reported);
  });
  benchmark::RegisterBenchmark((prefix + "occt-quasi-uniform-deflection").c_str(),
                               [c, optimum](benchmark::State& state) {
                                 const Geom2dAdaptor_Curve curve = occt_curve(c);
                                 std::vector<P2> out;
                                 out.reserve(1024);
                                 for (auto _ : state) {
                                   run_occt<GCPnts_QuasiUniformDeflection>(curve, out);
                                   benchmark::DoNotOptimize(out.data());
                                 }
                                 set_counters(state, c, out, optimum, Promise::reported);
                               });
#endif
}

}  // namespace

int main(int argc, char** argv) {
  for (const Shape& shape : kShapes) {
    const int optimum = optimum_segments(shape.points, kTolerance);
    std::printf("W6 optimum segments with vertices on the curve, %s at %g: %d\n", shape.name, kTolerance, optimum);
    register_rows(shape, optimum);
  }
  std::fflush(stdout);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

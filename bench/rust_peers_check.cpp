/* Hand check of the Rust peers' C ABI (rust_peers.h) against brute force.
 * Not part of any build. From the repository root, with Debian's cargo:
 *
 *   B=/tmp/rust_peers_check && rm -rf $B && mkdir -p $B/crate/src $B/crate/.cargo
 *   cp bench/rust_peers/Cargo.toml $B/crate/ && cp bench/rust_peers/src/lib.rs $B/crate/src/
 *   cp bench/rust_peers/.cargo/config.toml $B/crate/.cargo/
 *   cd $B/crate && RUSTC=/usr/bin/rustc /usr/bin/cargo generate-lockfile --offline &&
 *     CARGO_TARGET_DIR=$B/target RUSTC=/usr/bin/rustc RUSTFLAGS='-C target-cpu=native' \
 *     /usr/bin/cargo build --release --frozen && cd -
 *   g++ -std=c++20 -O2 -Wall -Wextra -Ibench bench/rust_peers_check.cpp \
 *     $B/target/release/libcasteljau_rust_peers.a -lpthread -ldl -lm -o $B/check && $B/check
 *
 * (or link build-bench/bench/rust_peers/release/libcasteljau_rust_peers.a once
 * rust_peers.cmake has built it). Exit status 0 iff every check passes; the
 * last check provokes a caught panic, whose message Rust prints on stderr. */
#include "rust_peers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

using Cubic = std::array<double, 8>;
struct P {
  double x, y;
};

P eval(const Cubic& c, double t) {
  double s = 1 - t;
  double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
  return {b0 * c[0] + b1 * c[2] + b2 * c[4] + b3 * c[6], b0 * c[1] + b1 * c[3] + b2 * c[5] + b3 * c[7]};
}

// Polyline length over [0, t1] with n segments.
double brute_arclen(const Cubic& c, double t1, int n) {
  double len = 0;
  P a = eval(c, 0);
  for (int i = 1; i <= n; ++i) {
    P b = eval(c, t1 * i / n);
    len += std::hypot(b.x - a.x, b.y - a.y);
    a = b;
  }
  return len;
}

// Least squared distance over n+1 samples, refined by golden-section search
// around the best sample.
std::pair<double, double> brute_nearest(const Cubic& c, P q, int n) {
  auto d2 = [&](double t) {
    P p = eval(c, t);
    return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
  };
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (d2(double(i) / n) < d2(double(best) / n)) best = i;
  double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(1.0, (best + 1.0) / n);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 100; ++k) {
    double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (d2(m1) < d2(m2))
      hi = m2;
    else
      lo = m1;
  }
  double t = 0.5 * (lo + hi);
  return {t, d2(t)};
}

// Crossings of two polylines (n segments each): the intersection points.
std::vector<P> brute_crossings(const Cubic& a, const Cubic& b, int n) {
  std::vector<P> pa(n + 1), pb(n + 1), out;
  for (int i = 0; i <= n; ++i) pa[i] = eval(a, double(i) / n), pb[i] = eval(b, double(i) / n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      P r{pa[i + 1].x - pa[i].x, pa[i + 1].y - pa[i].y}, s{pb[j + 1].x - pb[j].x, pb[j + 1].y - pb[j].y};
      double den = r.x * s.y - r.y * s.x;
      if (den == 0) continue;
      P w{pb[j].x - pa[i].x, pb[j].y - pa[i].y};
      double u = (w.x * s.y - w.y * s.x) / den, v = (w.x * r.y - w.y * r.x) / den;
      if (u >= 0 && u < 1 && v >= 0 && v < 1) out.push_back({pa[i].x + u * r.x, pa[i].y + u * r.y});
    }
  return out;
}

int passes = 0, failures = 0;
void check(bool ok, const char* what, double got, double want) {
  std::printf("%-4s %-44s got %.12g  want %.12g\n", ok ? "ok" : "FAIL", what, got, want);
  ++(ok ? passes : failures);
}

}  // namespace

int main() {
  const Cubic c{0, 0, 1, 2, 3, 2, 4, 0};
  const double acc = 1e-9;

  // Arc length, inverse arc length.
  double want = brute_arclen(c, 1, 1000000);
  double got = casteljau_kurbo_cubic_arclen(c.data(), acc);
  check(std::abs(got - want) < 1e-8, "kurbo arclen vs 1e6-segment polyline", got, want);
  double t_half = casteljau_kurbo_cubic_inv_arclen(c.data(), 0.5 * want, acc);
  double len_half = brute_arclen(c, t_half, 1000000);
  check(std::abs(len_half - 0.5 * want) < 1e-7, "arclen(0, inv_arclen(L/2)) vs L/2", len_half, 0.5 * want);

  // The same cubic as a two-piece path (split at t = 1/2).
  P m01{0.5, 1}, m23{3.5, 1}, m012{1.25, 1.5}, m123{2.75, 1.5};
  P mid = eval(c, 0.5);
  const double path[16] = {0, 0, m01.x, m01.y, m012.x, m012.y, mid.x, mid.y,
                           mid.x, mid.y, m123.x, m123.y, m23.x, m23.y, 4, 0};
  got = casteljau_kurbo_path_arclen(path, 2, acc);
  check(std::abs(got - want) < 1e-8, "kurbo path arclen (2 pieces) vs polyline", got, want);

  // Nearest point, single cubic and two-piece path.
  const double q[] = {2, 3, -1, -1, 2, 0.5, 5, 1, 0.3, 1.9};
  const size_t nq = sizeof q / sizeof q[0] / 2;
  double t[nq], d2[nq], pt[nq], pd2[nq];
  size_t piece[nq];
  casteljau_kurbo_cubic_nearest(c.data(), q, nq, acc, t, d2);
  casteljau_kurbo_path_nearest(path, 2, q, nq, acc, piece, pt, pd2);
  for (size_t i = 0; i < nq; ++i) {
    auto [bt, bd2] = brute_nearest(c, {q[2 * i], q[2 * i + 1]}, 100000);
    char what[96];
    std::snprintf(what, sizeof what, "nearest (%g,%g): distance", q[2 * i], q[2 * i + 1]);
    check(std::abs(std::sqrt(d2[i]) - std::sqrt(bd2)) < 1e-6, what, std::sqrt(d2[i]), std::sqrt(bd2));
    std::snprintf(what, sizeof what, "nearest (%g,%g): t", q[2 * i], q[2 * i + 1]);
    check(std::abs(t[i] - bt) < 1e-4, what, t[i], bt);
    double global_t = 0.5 * (double(piece[i]) + pt[i]);
    std::snprintf(what, sizeof what, "path nearest (%g,%g): distance", q[2 * i], q[2 * i + 1]);
    check(std::abs(std::sqrt(pd2[i]) - std::sqrt(bd2)) < 1e-6, what, std::sqrt(pd2[i]), std::sqrt(bd2));
    std::snprintf(what, sizeof what, "path nearest (%g,%g): piece + t", q[2 * i], q[2 * i + 1]);
    check(piece[i] < 2 && std::abs(global_t - bt) < 1e-4, what, global_t, bt);
  }

  // Cubic/cubic intersections (lyon): a wave crossing c three times.
  const Cubic w{0.2, 0.2, 1.2, 3.5, 2.8, -2.0, 3.8, 1.4};
  double ta[16], tb[16];
  size_t n = casteljau_lyon_cubic_intersections(c.data(), w.data(), ta, tb, 16);
  std::vector<P> bx = brute_crossings(c, w, 4000);
  check(n == bx.size(), "lyon cubic_intersections_t: count", double(n), double(bx.size()));
  for (size_t i = 0; i < std::min<size_t>(n, 16); ++i) {
    P pa = eval(c, ta[i]), pb = eval(w, tb[i]);
    double best = std::numeric_limits<double>::infinity();
    for (P b : bx) best = std::min(best, std::hypot(pa.x - b.x, pa.y - b.y));
    char what[96];
    std::snprintf(what, sizeof what, "lyon hit %zu (ta %.6f, tb %.6f): |a(ta)-b(tb)|", i, ta[i], tb[i]);
    check(std::hypot(pa.x - pb.x, pa.y - pb.y) < 1e-6, what, std::hypot(pa.x - pb.x, pa.y - pb.y), 0);
    std::snprintf(what, sizeof what, "lyon hit %zu: distance to a polyline crossing", i);
    check(best < 1e-5, what, best, 0);
  }
  for (P b : bx) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < std::min<size_t>(n, 16); ++i) {
      P pa = eval(c, ta[i]);
      best = std::min(best, std::hypot(pa.x - b.x, pa.y - b.y));
    }
    check(best < 1e-5, "polyline crossing matched by a lyon hit", best, 0);
  }
  size_t n1 = casteljau_lyon_cubic_intersections(c.data(), w.data(), ta, tb, 1);
  check(n1 == n, "lyon with capacity 1 still returns the count", double(n1), double(n));

  // Cubic/line-segment intersections (kurbo PathSeg::intersect_line).
  const double line[4] = {-1, 0.5, 5, 1.5};
  double tc[4], tl[4];
  size_t nl = casteljau_kurbo_cubic_line_intersections(c.data(), line, tc, tl, 4);
  size_t sign_changes = 0;
  auto side = [&](double tt) {
    P p = eval(c, tt);
    return (line[2] - line[0]) * (p.y - line[1]) - (line[3] - line[1]) * (p.x - line[0]);
  };
  for (int i = 0; i < 100000; ++i) sign_changes += (side(i / 1e5) > 0) != (side((i + 1) / 1e5) > 0);
  check(nl == sign_changes, "kurbo intersect_line: count", double(nl), double(sign_changes));
  for (size_t i = 0; i < std::min<size_t>(nl, 4); ++i) {
    P p = eval(c, tc[i]);
    P l{line[0] + tl[i] * (line[2] - line[0]), line[1] + tl[i] * (line[3] - line[1])};
    check(std::hypot(p.x - l.x, p.y - l.y) < 1e-9, "kurbo line hit: |c(t_curve)-line(t_line)|",
          std::hypot(p.x - l.x, p.y - l.y), 0);
  }

  // A NaN query makes kurbo 0.7's nearest panic (unwrap on no candidate):
  // the wrapper must catch it and report NaN.
  const double nanq[2] = {std::nan(""), std::nan("")};
  double nt = 0, nd = 0;
  casteljau_kurbo_cubic_nearest(c.data(), nanq, 1, acc, &nt, &nd);
  check(std::isnan(nt) && std::isnan(nd), "NaN query: no crash, NaN out", nd, std::nan(""));

  std::printf("%d passed, %d failed\n", passes, failures);
  return failures == 0 ? 0 : 1;
}

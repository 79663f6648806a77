// The exact intersection oracle (tests/support/exact_intersections.hpp) checked
// on its whole corpus (tests/support/intersection_corpus.hpp) independently of
// itself, before tests/ops/intersection_corpus_test.cpp trusts it:
//  - every point: both curves evaluated exactly at the interval ends agree
//    within the Lipschitz bound of the widths (exactly when the ends are exact);
//  - at rational points, multiplicity 1 iff the tangents' cross product is
//    not 0 (exact hodographs);
//  - overlaps: the ends and the midpoints of the two arcs are the same points;
//  - the answers known by construction (count, kind, multiplicity, rational
//    or closed-form parameters);
//  - for well-conditioned transversal cases, the count of a double-precision
//    subdivision search (bounding boxes of control polygons).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "support/exact_intersections.hpp"
#include "support/intersection_corpus.hpp"

using casteljau::test::ExactBezier;
using casteljau::test::ExactIntersection;
using Kind = ExactIntersection::Kind;
using Q = mpq_class;

namespace {

int failures = 0;
void expect(bool ok, const std::string& name, const std::string& what) {
  if (!ok) {
    ++failures;
    std::printf("  FAIL %s: %s\n", name.c_str(), what.c_str());
  }
}

// ---------------------------------------------------------------- expected
struct Val {  // an expected parameter: exact, approximate or unspecified
  std::optional<Q> exact;
  std::optional<double> approx;
};
Val ex(const Q& q) { return Val{q, std::nullopt}; }
Val ap(double d) { return Val{std::nullopt, d}; }
Val any() { return Val{}; }

struct ExpectedPoint {
  Kind kind;
  int multiplicity;
  Val a, b;
  Val a_hi = {}, b_hi = {};  // overlap: upper ends (a, b are the lower ends)
  bool reversed = false;
};
struct Expected {
  int count;
  std::vector<ExpectedPoint> points;  // empty: only the count; else all, sorted by a
  bool subdivision_check = false;     // compare the count with a double subdivision
};

ExpectedPoint tr(Val a, Val b) { return {Kind::transversal, 1, a, b}; }
ExpectedPoint tg(int m, Val a, Val b) { return {Kind::tangent, m, a, b}; }
ExpectedPoint ov(Q al, Q au, Q bl, Q bu, bool reversed) {
  return {Kind::overlap, ExactIntersection::kSharedComponent, ex(al), ex(bl), ex(au), ex(bu), reversed};
}

// Chebyshev graphs y = T_p(x) (a, x = 2s - 1) against x = T_q(y) (b, y = 2t - 1):
// x = T_q(T_p(x)) = T_pq(x), x = cos θ with cos(pq θ) = cos θ.
std::vector<ExpectedPoint> chebyshev_crossings(int p, int q) {
  std::vector<std::pair<double, double>> st;
  const double pi = std::numbers::pi;
  for (int d : {p * q - 1, p * q + 1})
    for (int k = 0; 2 * k <= d; ++k) {
      const double th = 2 * pi * k / d;
      st.emplace_back((1 + std::cos(th)) / 2, (1 + std::cos(p * th)) / 2);
    }
  std::sort(st.begin(), st.end());
  std::vector<ExpectedPoint> out;
  for (std::size_t i = 0; i < st.size(); ++i) {
    if (i > 0 && std::abs(st[i].first - st[i - 1].first) < 1e-12) continue;  // θ = 0 twice
    out.push_back(tr(ap(st[i].first), ap(st[i].second)));
  }
  return out;
}

std::map<std::string, Expected> expectations() {
  const double pi = std::numbers::pi;
  std::map<std::string, Expected> e;
  const Q h(1, 2), q(1, 4), tq(3, 4);
  e["lines_cross_at_halves"] = {1, {tr(ex(h), ex(h))}};
  e["lines_parallel_disjoint"] = {0, {}};
  e["lines_cross_outside_domain"] = {0, {}};
  e["line_cubic_three_crossings"] = {3, {}, true};
  e["vertical_line_cubic"] = {1, {}, true};
  // x = s on both: t = s = (1 ± sqrt(1/2)) / 2
  e["quadratic_horizontal_line"] = {2, {tr(ap((1 - std::sqrt(0.5)) / 2), ap((1 - std::sqrt(0.5)) / 2)),
                                        tr(ap((1 + std::sqrt(0.5)) / 2), ap((1 + std::sqrt(0.5)) / 2))}, true};
  {
    auto pts = chebyshev_crossings(2, 2);
    e["quadratic_quadratic_chebyshev_4"] = {4, pts, true};
  }
  e["cubic_cubic_chebyshev_9"] = {9, chebyshev_crossings(3, 3), true};
  e["cubic_cubic_shrunk_seven"] = {7, {}, true};
  {
    auto pts = chebyshev_crossings(3, 3);
    for (auto& p : pts) {
      p.a = ap((1.0 / 16 + *p.a.approx) / (9.0 / 8));
      p.b = ap((1.0 / 16 + *p.b.approx) / (9.0 / 8));
    }
    e["cubic_cubic_nine_interior"] = {9, pts, true};
  }
  e["quartic_cubic_chebyshev_12"] = {12, chebyshev_crossings(4, 3), true};
  e["quintic_quintic_chebyshev_25"] = {25, chebyshev_crossings(5, 5), true};
  e["sextic_sextic_chebyshev_36"] = {36, chebyshev_crossings(6, 6), true};
  {
    // T5(x) = T2(x): θ = 2πk/3, 2πk/7; s = t = (1 + cos θ)/2
    std::vector<double> s;
    for (int d : {3, 7})
      for (int k = 0; 2 * k <= d; ++k) s.push_back((1 + std::cos(2 * pi * k / d)) / 2);
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end(), [](double x, double y) { return std::abs(x - y) < 1e-12; }), s.end());
    std::vector<ExpectedPoint> pts;
    for (double v : s) pts.push_back(tr(ap(v), ap(v)));
    pts[1] = tr(ex(Q(1, 4)), ex(Q(1, 4)));  // x = -1/2
    pts.back() = tr(ex(1), ex(1));
    e["quintic_quadratic_chebyshev_5"] = {5, pts, true};
  }
  {
    // T6(x) = 1/4: 6θ = ±acos(1/4) + 2πk
    std::vector<double> s;
    const double c = std::acos(0.25);
    for (int k = -6; k <= 6; ++k)
      for (double th : {(c + 2 * pi * k) / 6, (-c + 2 * pi * k) / 6})
        if (th >= 0 && th <= pi) s.push_back((1 + std::cos(th)) / 2);
    std::sort(s.begin(), s.end());
    std::vector<ExpectedPoint> pts;
    for (double v : s) pts.push_back(tr(ap(v), ap(v)));
    e["sextic_line_six_crossings"] = {6, pts, true};
  }
  e["cubic_cubic_graphs_three"] = {3, {tr(any(), any()), tr(ex(h), ex(h)), tr(any(), any())}, true};
  e["cubic_cubic_graphs_contact_3"] = {1, {tg(3, ex(h), ex(h))}};
  e["collinear_folded_cubic_vs_line"] = {3, {}, true};
  const Q d21 = casteljau::test::corpus_detail::p2(-21);
  e["parabolas_crossing_at_pm_2^-20"] = {2, {tr(ex(h - d21), ex(h - d21)), tr(ex(h + d21), ex(h + d21))}};

  e["parabola_line_tangent_at_vertex"] = {1, {tg(2, ex(h), ex(h))}};
  e["parabola_line_tangent_reversed"] = {1, {tg(2, ex(h), ex(h))}};
  e["cubic_inflection_tangent_line"] = {1, {tg(3, ex(h), ex(h))}};
  e["quartic_flat_point_line"] = {1, {tg(4, ex(h), ex(h))}};
  e["parabola_cubic_osculating_3"] = {1, {tg(3, ex(h), ex(h))}};
  e["parabola_quartic_contact_4"] = {1, {tg(4, ex(h), ex(h))}};
  e["parabolas_tangent_opposite"] = {1, {tg(2, ex(h), ex(h))}};
  e["parabolas_tangent_same_side"] = {1, {tg(2, ex(h), ex(h))}};
  e["quartic_double_tangent_line"] = {2, {tg(2, ex(q), ex(q)), tg(2, ex(tq), ex(tq))}};
  e["cubic_tangent_and_crossing_line"] = {2, {tr(ex(Q(1, 6)), ex(Q(1, 6))), tg(2, ex(Q(2, 3)), ex(Q(2, 3)))}};
  e["tangent_at_start_parameter"] = {1, {tg(2, ex(0), ex(h))}};
  e["g1_join_end_to_start"] = {1, {tg(2, ex(1), ex(0))}};
  e["curvature_continuous_join"] = {1, {tg(3, ex(1), ex(0))}};
  e["cusp_tangent_line"] = {1, {tg(3, ex(h), ex(tq))}};
  e["cusp_transversal_line"] = {1, {tg(2, ex(h), ex(h))}};

  const double r265 = std::ldexp(1.0, -26) / std::sqrt(2.0), r275 = std::ldexp(1.0, -27) / std::sqrt(2.0);
  e["parabola_line_2^-52_below_miss"] = {0, {}};
  e["parabola_line_2^-52_above_two_hits"] = {2, {tr(ap(0.5 - r265), ap(0.5 - r265)), tr(ap(0.5 + r265), ap(0.5 + r265))}};
  e["arch_line_1ulp_above_miss"] = {0, {}};
  e["arch_line_1ulp_below_two_hits"] = {2, {tr(ap(0.5 - r275), ap(0.5 - r275)), tr(ap(0.5 + r275), ap(0.5 + r275))}};
  e["nearly_parallel_lines_cross_at_half"] = {1, {tr(ex(h), ex(h))}};
  e["nearly_parallel_lines_cross_at_quarter"] = {1, {tr(ex(q), ex(q))}};
  e["nearly_parallel_lines_miss"] = {0, {}};
  e["cubic_translated_up_2^-50_miss"] = {0, {}};
  e["cubic_translated_right_2^-50_one_crossing"] = {1, {tr(ap(0.5), ap(0.5))}};
  e["parabolas_nearly_tangent_miss"] = {0, {}};

  e["identical_cubics"] = {1, {ov(0, 1, 0, 1, false)}};
  e["identical_reversed"] = {1, {ov(0, 1, 0, 1, true)}};
  e["subsegment_same_direction"] = {1, {ov(q, tq, 0, 1, false)}};
  e["subsegment_reversed"] = {1, {ov(q, h, 0, 1, true)}};
  e["shared_middle_subarc"] = {1, {ov(Q(1, 3), 1, 0, Q(2, 3), false)}};
  e["shared_middle_subarc_reversed"] = {1, {ov(Q(1, 3), 1, Q(1, 3), 1, true)}};
  e["degree_elevated_copy"] = {1, {ov(0, 1, 0, 1, false)}};
  e["degree_elevated_twice_reversed"] = {1, {ov(0, 1, 0, 1, true)}};
  e["quadratic_elevated_to_cubic"] = {1, {ov(0, 1, 0, 1, false)}};
  e["coincident_lines_partial"] = {1, {ov(q, 1, 0, Q(3, 7), false)}};
  e["coincident_vertical_segments"] = {1, {ov(h, 1, 0, h, false)}};
  e["collinear_lines_touch_at_end"] = {1, {tg(ExactIntersection::kSharedComponent, ex(1), ex(0))}};
  e["collinear_lines_disjoint"] = {0, {}};
  e["curve_and_its_continuation"] = {1, {tg(ExactIntersection::kSharedComponent, ex(1), ex(0))}};
  e["same_curve_disjoint_arcs"] = {0, {}};
  e["overlap_and_crossing_at_double_point"] = {2, {tr(ex(Q(2, 5)), ex(Q(3, 5))), ov(Q(3, 5), 1, 0, Q(2, 5), false)}};

  e["corner_shared_start"] = {1, {tr(ex(0), ex(0))}};
  e["end_to_start_corner"] = {1, {tr(ex(1), ex(0))}};
  e["end_on_interior"] = {1, {tr(ex(1), ex(h))}};
  e["start_on_interior"] = {1, {tr(ex(0), ex(q))}};
  e["closed_by_two_arcs"] = {2, {tr(ex(0), ex(1)), tr(ex(1), ex(0))}};
  e["cubics_cross_at_halves"] = {2, {tr(ex(h), ex(h)), tr(ex(1), ex(1))}, true};  // both also end at (2, 0)
  e["line_through_double_point"] = {3, {tr(ex(q), ex(h)), tr(ex(h), ex(Q(2, 3))), tr(ex(tq), ex(h))}, true};
  e["two_loops_share_double_point"] = {5, {}, true};  // 4 at the double point, checked below

  const double r = std::sqrt(3.0 / 20.0);
  e["self_loop_rational"] = {1, {tr(ex(q), ex(tq))}};
  e["self_loop_irrational"] = {1, {tr(ap(0.5 - r), ap(0.5 + r))}};
  e["self_cusp_none"] = {0, {}};
  e["self_s_cubic_none"] = {0, {}};
  e["self_quadratic_none"] = {0, {}};
  e["self_line_none"] = {0, {}};
  e["self_closed_cubic"] = {1, {tr(ex(0), ex(1))}};
  e["self_end_on_itself"] = {1, {tr(ex(Q(1, 3)), ex(1))}};
  e["self_chebyshev_3_4"] = {3, {}};
  e["self_chebyshev_4_5"] = {6, {}};
  e["self_chebyshev_5_6"] = {10, {}};
  e["self_tacnode_quartic"] = {1, {tg(-1, ex(q), ex(tq))}};  // -1: any multiplicity >= 2
  return e;
}

// ------------------------------------------------------------ exact checks
Q max_speed(const ExactBezier& c) {  // bound on |c'|_inf: n max |ΔP|
  Q m = 0;
  const int n = static_cast<int>(c.points.size()) - 1;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) m = std::max(m, Q(abs(c.points[i + 1][k] - c.points[i][k])));
  return m * n;
}
std::array<Q, 2> exact_tangent(const ExactBezier& c, const Q& t) {
  ExactBezier h;
  const int n = static_cast<int>(c.points.size()) - 1;
  for (int i = 0; i < n; ++i) h.points.push_back({n * (c.points[i + 1][0] - c.points[i][0]), n * (c.points[i + 1][1] - c.points[i][1])});
  return casteljau::test::exact_bezier_point(h, t);
}
bool same_point(const std::array<Q, 2>& p, const std::array<Q, 2>& q) { return p[0] == q[0] && p[1] == q[1]; }

void check_point(const std::string& name, const ExactBezier& a, const ExactBezier& b, const ExactIntersection& x) {
  using casteljau::test::exact_bezier_point;
  expect(x.a_lower <= x.a_upper && x.b_lower <= x.b_upper, name, "interval ends out of order");
  expect(x.a_lower >= 0 && x.a_upper <= 1 && x.b_lower >= 0 && x.b_upper <= 1, name, "parameter outside [0,1]");
  const Q wa = x.a_upper - x.a_lower, wb = x.b_upper - x.b_lower;
  const Q limit(mpz_class(1), mpz_class(1) << 80);
  expect(wa <= limit && wb <= limit, name, "interval wider than 2^-80");
  const Q bound = max_speed(a) * wa + max_speed(b) * wb;
  for (const Q& s : {x.a_lower, x.a_upper})
    for (const Q& t : {x.b_lower, x.b_upper}) {
      const auto p = exact_bezier_point(a, s), q = exact_bezier_point(b, t);
      expect(abs(p[0] - q[0]) <= bound && abs(p[1] - q[1]) <= bound, name, "points at the interval ends do not agree");
    }
  if (wa == 0 && wb == 0 && x.multiplicity != ExactIntersection::kSharedComponent) {
    const auto da = exact_tangent(a, x.a_lower), db = exact_tangent(b, x.b_lower);
    const Q cross = da[0] * db[1] - da[1] * db[0];
    expect((cross != 0) == (x.multiplicity == 1), name, "multiplicity 1 disagrees with the tangents' cross product");
  }
  expect((x.kind == Kind::transversal) == (x.multiplicity == 1), name, "kind disagrees with the multiplicity");
}
void check_overlap(const std::string& name, const ExactBezier& a, const ExactBezier& b, const ExactIntersection& x) {
  using casteljau::test::exact_bezier_point;
  const Q b_first = x.reversed ? x.b_upper : x.b_lower, b_last = x.reversed ? x.b_lower : x.b_upper;
  expect(same_point(exact_bezier_point(a, x.a_lower), exact_bezier_point(b, b_first)), name, "overlap start differs");
  expect(same_point(exact_bezier_point(a, x.a_upper), exact_bezier_point(b, b_last)), name, "overlap end differs");
  expect(same_point(exact_bezier_point(a, Q((x.a_lower + x.a_upper) / 2)), exact_bezier_point(b, Q((x.b_lower + x.b_upper) / 2))),
         name, "overlap midpoints differ");
  expect(x.a_lower < x.a_upper && x.b_lower < x.b_upper, name, "degenerate overlap");
}
void check_value(const std::string& name, const Val& v, const Q& lo, const Q& hi, const char* which) {
  if (v.exact) {
    expect(lo == *v.exact && hi == *v.exact, name, std::string(which) + " not the exact rational " + v.exact->get_str());
  } else if (v.approx) {
    const double est = casteljau::test::exact_estimate(lo, hi);
    expect(std::abs(est - *v.approx) <= 1e-13, name,
           std::string(which) + " " + std::to_string(est) + " far from the closed form " + std::to_string(*v.approx));
  }
}

// ------------------------------------- independent double subdivision search
using P2 = std::array<double, 2>;
std::vector<P2> to_d(const ExactBezier& c) { return casteljau::test::control_points_as_doubles(c); }
void split(const std::vector<P2>& c, std::vector<P2>& l, std::vector<P2>& r) {
  std::vector<P2> w = c;
  const std::size_t n = c.size();
  l.resize(n);
  r.resize(n);
  l[0] = w[0];
  r[n - 1] = w[n - 1];
  for (std::size_t k = 1; k < n; ++k) {
    for (std::size_t i = 0; i + k < n; ++i)
      for (int j = 0; j < 2; ++j) w[i][j] = 0.5 * (w[i][j] + w[i + 1][j]);
    l[k] = w[0];
    r[n - 1 - k] = w[n - 1 - k];
  }
}
struct BoxD {
  double x0, x1, y0, y1;
};
BoxD box(const std::vector<P2>& c) {
  BoxD b{c[0][0], c[0][0], c[0][1], c[0][1]};
  for (const P2& p : c) {
    b.x0 = std::min(b.x0, p[0]);
    b.x1 = std::max(b.x1, p[0]);
    b.y0 = std::min(b.y0, p[1]);
    b.y1 = std::max(b.y1, p[1]);
  }
  return b;
}
void search(const std::vector<P2>& a, double s0, double s1, const std::vector<P2>& b, double t0, double t1, int depth,
            std::vector<P2>& hits) {
  const BoxD ba = box(a), bb = box(b);
  const double eps = 1e-12;
  if (ba.x1 < bb.x0 - eps || bb.x1 < ba.x0 - eps || ba.y1 < bb.y0 - eps || bb.y1 < ba.y0 - eps) return;
  if (depth >= 20) {
    hits.push_back({(s0 + s1) / 2, (t0 + t1) / 2});
    return;
  }
  std::vector<P2> al, ar, bl, br;
  split(a, al, ar);
  split(b, bl, br);
  const double sm = (s0 + s1) / 2, tm = (t0 + t1) / 2;
  search(al, s0, sm, bl, t0, tm, depth + 1, hits);
  search(al, s0, sm, br, tm, t1, depth + 1, hits);
  search(ar, sm, s1, bl, t0, tm, depth + 1, hits);
  search(ar, sm, s1, br, tm, t1, depth + 1, hits);
}
/// Clusters of leaf parameter pairs closer than 2^-16 (single linkage).
int subdivision_count(const ExactBezier& a, const ExactBezier& b) {
  std::vector<P2> hits;
  search(to_d(a), 0, 1, to_d(b), 0, 1, 0, hits);
  std::sort(hits.begin(), hits.end());
  const double gap = std::ldexp(1.0, -16);
  std::vector<int> parent(hits.size());
  for (std::size_t i = 0; i < hits.size(); ++i) parent[i] = static_cast<int>(i);
  std::function<int(int)> find = [&](int i) { return parent[i] == i ? i : parent[i] = find(parent[i]); };
  for (std::size_t i = 0; i < hits.size(); ++i)
    for (std::size_t j = i + 1; j < hits.size() && hits[j][0] - hits[i][0] < gap; ++j)
      if (std::abs(hits[i][1] - hits[j][1]) < gap) parent[find(static_cast<int>(i))] = find(static_cast<int>(j));
  int clusters = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) clusters += find(static_cast<int>(i)) == static_cast<int>(i);
  return clusters;
}

const char* kind_name(Kind k) {
  return k == Kind::transversal ? "transversal" : k == Kind::tangent ? "tangent" : "overlap";
}

void check_doubles() {
  using casteljau::test::nearest_double;
  using casteljau::test::ulps_from;
  const std::string n = "ulps_from";
  expect(nearest_double(Q(1, 3)) == 1.0 / 3.0, n, "nearest 1/3");
  expect(nearest_double(Q(-2, 3)) == -2.0 / 3.0, n, "nearest -2/3");
  const Q third(1, 3);
  expect(ulps_from(third, third, 1.0 / 3.0) == 0, n, "0 ulps at the nearest double");
  expect(ulps_from(third, third, std::nextafter(1.0 / 3.0, 1.0)) == 1, n, "1 ulp above");
  expect(ulps_from(third, third, std::nextafter(std::nextafter(1.0 / 3.0, 0.0), 0.0)) == 2, n, "2 ulps below");
  expect(ulps_from(Q(0), Q(0), -0.0) == 0 && ulps_from(Q(0), Q(0), 5e-324) == 1, n, "around zero");
  expect(ulps_from(Q(0), Q(0), -5e-324) == 1, n, "negative denormal");
  // a tie: 1 + 2^-53 lies halfway between 1 and 1 + 2^-52, rounds to even (1)
  const Q tie = Q(1) + casteljau::test::corpus_detail::p2(-53);
  expect(nearest_double(tie) == 1.0, n, "ties to even");
}

}  // namespace

/// Runs every check; the number of failures.
static int run_oracle_check() {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  check_doubles();
  const auto corpus = casteljau::test::intersection_corpus();
  const auto expected = expectations();
  int n_pairs = 0, n_self = 0, n_points = 0, n_overlaps = 0;
  for (const auto& c : corpus) {
    const auto t0 = clock::now();
    std::vector<ExactIntersection> got;
    try {
      got = c.b ? casteljau::test::exact_intersections(c.a, *c.b) : casteljau::test::exact_self_intersections(c.a);
    } catch (const std::exception& e) {
      expect(false, c.name, std::string("exception: ") + e.what());
      continue;
    }
    const double ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
    (c.b ? n_pairs : n_self)++;
    std::printf("%-44s deg %zu%s  %2zu found  %8.1f ms\n", c.name.c_str(), c.a.points.size() - 1,
                c.b ? (" x " + std::to_string(c.b->points.size() - 1)).c_str() : " self", got.size(), ms);
    const ExactBezier& b = c.b ? *c.b : c.a;
    for (const auto& x : got) {
      if (x.kind == Kind::overlap)
        std::printf("    overlap     a=[%s, %s] b=[%s, %s]%s\n", x.a_lower.get_str().c_str(), x.a_upper.get_str().c_str(),
                    x.b_lower.get_str().c_str(), x.b_upper.get_str().c_str(), x.reversed ? " reversed" : "");
      else
        std::printf("    %-11s m=%d a=%.17g%s b=%.17g%s\n", kind_name(x.kind), x.multiplicity,
                    casteljau::test::exact_estimate(x.a_lower, x.a_upper), x.a_lower == x.a_upper ? " (exact)" : "",
                    casteljau::test::exact_estimate(x.b_lower, x.b_upper), x.b_lower == x.b_upper ? " (exact)" : "");
      if (x.kind == Kind::overlap) {
        ++n_overlaps;
        check_overlap(c.name, c.a, b, x);
        // the oracle's overlap ends are the exact end parameters: report them
        expect(x.a_lower.get_den() < 1000 && x.b_lower.get_den() < 1000, c.name, "overlap ends not simple rationals");
      } else {
        ++n_points;
        check_point(c.name, c.a, b, x);
        if (!c.b) expect(x.a_upper < x.b_lower || (x.a_lower == x.a_upper && x.b_lower == x.b_upper && x.a_lower < x.b_lower),
                         c.name, "self-intersection with s >= t");
      }
    }
    const auto it = expected.find(c.name);
    if (it == expected.end()) {
      expect(false, c.name, "no expectation");
      continue;
    }
    const Expected& want = it->second;
    if (want.count >= 0) expect(static_cast<int>(got.size()) == want.count, c.name, "count " + std::to_string(got.size()) +
                                                                                        " instead of " + std::to_string(want.count));
    if (!want.points.empty() && got.size() == want.points.size()) {
      for (std::size_t i = 0; i < got.size(); ++i) {
        const auto& w = want.points[i];
        const auto& x = got[i];
        expect(x.kind == w.kind, c.name, "kind of #" + std::to_string(i));
        if (w.multiplicity >= 0) expect(x.multiplicity == w.multiplicity, c.name, "multiplicity of #" + std::to_string(i));
        else expect(x.multiplicity >= 2, c.name, "multiplicity >= 2 of #" + std::to_string(i));
        if (w.kind == Kind::overlap) {
          check_value(c.name, w.a, x.a_lower, x.a_lower, "overlap a start");
          check_value(c.name, w.a_hi, x.a_upper, x.a_upper, "overlap a end");
          check_value(c.name, w.b, x.b_lower, x.b_lower, "overlap b start");
          check_value(c.name, w.b_hi, x.b_upper, x.b_upper, "overlap b end");
          expect(x.reversed == w.reversed, c.name, "overlap direction");
        } else {
          check_value(c.name, w.a, x.a_lower, x.a_upper, "a");
          check_value(c.name, w.b, x.b_lower, x.b_upper, "b");
        }
      }
    }
    if (c.name == "cubics_cross_at_halves") {
      bool found = false;
      for (const auto& x : got) found |= x.a_lower == Q(1, 2) && x.a_upper == Q(1, 2) && x.b_lower == Q(1, 2);
      expect(found, c.name, "no crossing at (1/2, 1/2)");
    }
    if (c.name == "two_loops_share_double_point") {
      int at_double = 0;
      for (const auto& x : got)
        for (const Q& s : {Q(1, 4), Q(3, 4)})
          for (const Q& t : {Q(1, 4), Q(3, 4)}) at_double += x.a_lower == s && x.b_lower == t && x.a_upper == s;
      expect(at_double == 4, c.name, "not four crossings at the shared double point");
    }
    if (c.name.rfind("self_chebyshev", 0) == 0)
      for (const auto& x : got) expect(x.kind == Kind::transversal, c.name, "Chebyshev double point not transversal");
    if (want.subdivision_check && c.b) {
      const int n = subdivision_count(c.a, *c.b);
      std::printf("    double subdivision: %d clusters\n", n);
      expect(n == static_cast<int>(got.size()), c.name, "double subdivision finds " + std::to_string(n));
    }
  }
  const double seconds = std::chrono::duration<double>(clock::now() - start).count();
  std::printf("\n%zu cases (%d pairs, %d self), %d point intersections, %d overlaps, %d failures, %.2f s\n",
              corpus.size(), n_pairs, n_self, n_points, n_overlaps, failures, seconds);
  return failures;
}

TEST(ExactIntersectionOracle, AgreesWithWhatTheCorpusKnowsByConstruction) { EXPECT_EQ(run_oracle_check(), 0); }

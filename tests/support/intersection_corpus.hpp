#pragma once
// A torture corpus for curve-curve and self-intersection: plane polynomial
// Bézier curves whose control points are dyadic rationals exactly representable
// as doubles, so the double-precision code sees exactly the curves the exact
// oracle (exact_intersections.hpp) solves. Every case says what it tests;
// tests/support/exact_intersections_check.cpp holds the answers known by
// construction.

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "exact_intersections.hpp"

namespace casteljau::test {

struct IntersectionCase {
  std::string name;
  ExactBezier a;
  std::optional<ExactBezier> b;  // none: self-intersections of a
};

/// The control points as doubles (exact: every corpus point is a double).
inline std::vector<std::array<double, 2>> control_points_as_doubles(const ExactBezier& c) {
  std::vector<std::array<double, 2>> out;
  for (const auto& p : c.points) {
    const double x = p[0].get_d(), y = p[1].get_d();
    if (mpq_class(x) != p[0] || mpq_class(y) != p[1])
      throw std::logic_error("control point (" + p[0].get_str() + ", " + p[1].get_str() +
                             ") not exactly representable as a double");
    out.push_back({x, y});
  }
  return out;
}

namespace corpus_detail {

using Q = mpq_class;
using QPoly = std::vector<Q>;

/// Exact from doubles (every double is a dyadic rational).
inline ExactBezier curve(std::initializer_list<std::array<double, 2>> points) {
  ExactBezier c;
  for (const auto& p : points) c.points.push_back({Q(p[0]), Q(p[1])});
  return c;
}
/// The Bézier form of degree n of the power-basis curve (x(s), y(s)).
inline ExactBezier from_power(const QPoly& x, const QPoly& y, int n) {
  ExactBezier c;
  c.points.resize(n + 1);
  for (int k = 0; k < 2; ++k) {
    QPoly p = k == 0 ? x : y;
    p.resize(n + 1, Q(0));
    for (int i = 0; i <= n; ++i) {
      Q b = 0;
      for (int j = 0; j <= i; ++j) {
        mpz_class cij, cnj;
        mpz_bin_uiui(cij.get_mpz_t(), i, j);
        mpz_bin_uiui(cnj.get_mpz_t(), n, j);
        b += p[j] * exact_intersection_detail::ratio(cij, cnj);
      }
      b.canonicalize();
      c.points[i][k] = b;
    }
  }
  return c;
}
inline QPoly mul(const QPoly& a, const QPoly& b) {
  QPoly c(a.size() + b.size() - 1, Q(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}
inline QPoly add(QPoly a, const QPoly& b) {
  if (a.size() < b.size()) a.resize(b.size(), Q(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
  return a;
}
inline QPoly scaled(QPoly a, const Q& c) {
  for (Q& v : a) v *= c;
  return a;
}
/// f(alpha s + beta).
inline QPoly compose(const QPoly& f, const Q& alpha, const Q& beta) {
  QPoly out{Q(0)};
  for (int i = static_cast<int>(f.size()) - 1; i >= 0; --i) out = add(mul(out, QPoly{beta, alpha}), QPoly{f[i]});
  return out;
}
/// Power coefficients of the Chebyshev polynomial T_n.
inline QPoly chebyshev(int n) {
  QPoly a{Q(1)}, b{Q(0), Q(1)};
  if (n == 0) return a;
  for (int k = 2; k <= n; ++k) {
    QPoly c = add(mul(QPoly{Q(0), Q(2)}, b), scaled(a, Q(-1)));
    a = b;
    b = c;
  }
  return b;
}
/// Affine image p -> M p + v of a curve.
inline ExactBezier mapped(const ExactBezier& c, const Q& m00, const Q& m01, const Q& m10, const Q& m11, const Q& v0,
                          const Q& v1) {
  ExactBezier out = c;
  for (auto& p : out.points) p = {m00 * p[0] + m01 * p[1] + v0, m10 * p[0] + m11 * p[1] + v1};
  return out;
}
inline ExactBezier translated(const ExactBezier& c, const Q& dx, const Q& dy) { return mapped(c, 1, 0, 0, 1, dx, dy); }
/// Scales both curves by the lcm of the odd parts of their denominators, so
/// that every coordinate is dyadic (uniform scaling keeps every parameter).
inline void make_dyadic(ExactBezier& a, std::optional<ExactBezier>& b) {
  mpz_class l = 1;
  auto visit = [&](const ExactBezier& c) {
    for (const auto& p : c.points)
      for (const Q& v : p) {
        mpz_class d = v.get_den();
        while (mpz_even_p(d.get_mpz_t())) d /= 2;
        mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), d.get_mpz_t());
      }
  };
  visit(a);
  if (b) visit(*b);
  const Q s(l);
  a = mapped(a, s, 0, 0, s, 0, 0);
  if (b) *b = mapped(*b, s, 0, 0, s, 0, 0);
}
/// The graph y = T_n(x) for x = 2s - 1 in [-1, 1], degree n.
inline ExactBezier chebyshev_graph(int n) {
  return from_power(QPoly{Q(-1), Q(2)}, compose(chebyshev(n), Q(2), Q(-1)), n);
}
/// The mirrored graph x = T_n(y).
inline ExactBezier chebyshev_graph_mirrored(int n) {
  const ExactBezier g = chebyshev_graph(n);
  return mapped(g, 0, 1, 1, 0, 0, 0);
}
/// The Chebyshev curve (T_p(2s-1), T_q(2s-1)) (Koseleff & Pecker): (p-1)(q-1)/2
/// double points, all inside the parameter interval.
inline ExactBezier chebyshev_curve(int p, int q) {
  return from_power(compose(chebyshev(p), Q(2), Q(-1)), compose(chebyshev(q), Q(2), Q(-1)), std::max(p, q));
}
/// The graph y = f(x) for x = x0 + w s, as a Bézier curve of degree n.
inline ExactBezier graph(const QPoly& f, const Q& x0, const Q& w, int n) {
  return from_power(QPoly{x0, w}, compose(f, w, x0), n);
}
inline Q p2(int e) {  // 2^e
  Q q(1);
  if (e >= 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), e);
  else mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), -e);
  return q;
}

}  // namespace corpus_detail

/// The corpus (see each case's comment).
inline std::vector<IntersectionCase> intersection_corpus() {
  using namespace corpus_detail;
  std::vector<IntersectionCase> cases;
  auto add_pair = [&](std::string name, ExactBezier a, ExactBezier b) {
    std::optional<ExactBezier> ob = std::move(b);
    make_dyadic(a, ob);
    cases.push_back({std::move(name), std::move(a), std::move(ob)});
  };
  auto add_self = [&](std::string name, ExactBezier a) {
    std::optional<ExactBezier> none;
    make_dyadic(a, none);
    cases.push_back({std::move(name), std::move(a), std::nullopt});
  };
  const double e52 = std::ldexp(1.0, -52);

  // Reusable curves.
  const ExactBezier s_cubic = curve({{0, 0}, {1, 2}, {3, -1}, {4, 1}});  // an S-shaped cubic, no self-intersection
  const ExactBezier loop = curve({{0, 0}, {22, 12}, {-4, 12}, {18, 0}});  // loop: a(1/4) = a(3/4) = (9, 27/4)
  const ExactBezier cusp = curve({{0, 0}, {1, 1}, {0, 1}, {1, 0}});      // cusp at s = 1/2, point (1/2, 3/4)
  const ExactBezier wiggle = curve({{0, -1}, {0.25, 3}, {0.75, -3}, {1, 1}});  // crosses y = 0 three times
  const ExactBezier vertex0 = curve({{0, 0.5}, {0.5, -0.5}, {1, 0.5}});  // y = 2 (s - 1/2)^2, vertex (1/2, 0)
  const ExactBezier arch = curve({{0, 0}, {0.5, 1}, {1, 0}});            // y = 2 s (1 - s), vertex (1/2, 1/2)
  const ExactBezier bump = curve({{0, 0}, {0.25, 1}, {0.75, 1}, {1, 0}});  // symmetric cubic arch

  // ---- transversal crossings
  // Two segments crossing at both midpoints: exact rational 1/2, 1/2.
  add_pair("lines_cross_at_halves", curve({{0, 0}, {1, 1}}), curve({{0, 1}, {1, 0}}));
  // Parallel distinct segments: no intersection (the resultant is a nonzero constant).
  add_pair("lines_parallel_disjoint", curve({{0, 0}, {1, 1}}), curve({{0, 1}, {1, 2}}));
  // The supporting lines cross at s = 2: outside the domain, nothing reported.
  add_pair("lines_cross_outside_domain", curve({{0, 0}, {1, 0}}), curve({{2, -1}, {2, 1}}));
  // A cubic crossing a segment three times (irrational parameters).
  add_pair("line_cubic_three_crossings", wiggle, curve({{0, 0}, {1, 0}}));
  // A vertical segment: x_b is constant, the a-side resultant is free of t.
  add_pair("vertical_line_cubic", wiggle, curve({{0.5, -2}, {0.5, 2}}));
  // A parabola and a horizontal segment: two irrational crossings (1 ± 1/sqrt 2)/2.
  add_pair("quadratic_horizontal_line", curve({{0, 0}, {0.5, 2}, {1, 0}}), curve({{0, 0.5}, {1, 0.5}}));
  // Chebyshev graphs y = T2(x), x = T2(y): 4 crossings (Bezout's maximum), one at
  // both ends (1, 1) and one at the rational s = 1/4.
  add_pair("quadratic_quadratic_chebyshev_4", chebyshev_graph(2), chebyshev_graph_mirrored(2));
  // y = T3(x), x = T3(y): 9 crossings, at both starts, both ends and both midpoints.
  add_pair("cubic_cubic_chebyshev_9", chebyshev_graph(3), chebyshev_graph_mirrored(3));
  // The same with b shrunk by 15/16: the two crossings at the ends leave the
  // domain, 7 remain, none at an end.
  add_pair("cubic_cubic_shrunk_seven", chebyshev_graph(3),
           mapped(chebyshev_graph_mirrored(3), Q(15, 16), 0, 0, Q(15, 16), 0, 0));
  // Both Chebyshev cubics extended to [-1/16, 17/16] (exact reparametrization):
  // 9 crossings, all interior (s = (1/16 + (1 + cos θ)/2) / (9/8)).
  add_pair("cubic_cubic_nine_interior", exact_subcurve(chebyshev_graph(3), Q(-1, 16), Q(17, 16)),
           exact_subcurve(chebyshev_graph_mirrored(3), Q(-1, 16), Q(17, 16)));
  // y = T4(x) against x = T3(y): 12 crossings.
  add_pair("quartic_cubic_chebyshev_12", chebyshev_graph(4), chebyshev_graph_mirrored(3));
  // y = T5(x) against x = T5(y): 25 crossings.
  add_pair("quintic_quintic_chebyshev_25", chebyshev_graph(5), chebyshev_graph_mirrored(5));
  // y = T6(x) against x = T6(y): 36 crossings, all real: a degree-36 resultant
  // with 36 roots in [0,1].
  add_pair("sextic_sextic_chebyshev_36", chebyshev_graph(6), chebyshev_graph_mirrored(6));
  // y = T5(x) against y = T2(x): 5 crossings, at both ends (s = t = 1) and at x = -1/2 (s = t = 1/4).
  add_pair("quintic_quadratic_chebyshev_5", chebyshev_graph(5), chebyshev_graph(2));
  // y = T6(x) against the segment y = 1/4: 6 crossings of a line and a sextic.
  add_pair("sextic_line_six_crossings", chebyshev_graph(6), curve({{-1, 0.25}, {1, 0.25}}));
  // Two cubic graphs over the same x = 3s: their difference (Bernstein
  // coefficients -1, 2, -2, 1) has three roots, one at s = 1/2.
  add_pair("cubic_cubic_graphs_three", curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}}),
           curve({{0, -1}, {1, 4}, {2, -4}, {3, 1}}));
  // Two cubic graphs whose difference is (2s - 1)^3: contact of order 3
  // between two curved cubics, multiplicity 3 at s = t = 1/2.
  add_pair("cubic_cubic_graphs_contact_3", curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}}),
           curve({{0, -1}, {1, 3}, {2, -3}, {3, 1}}));
  // A cubic with collinear control points that folds back on its line
  // (improper: a point of it traced three times) against a crossing segment.
  add_pair("collinear_folded_cubic_vs_line", curve({{0, 0}, {3, 3}, {-1, -1}, {2, 2}}), curve({{0, 2}, {2, 0}}));
  // y = x^2 and y = 2 x^2 - 2^-40: two crossings at exactly x = ±2^-20
  // (s = t = 1/2 ± 2^-21), nearly tangent.
  add_pair("parabolas_crossing_at_pm_2^-20", curve({{-1, 1}, {0, -1}, {1, 1}}),
           translated(curve({{-1, 2}, {0, -2}, {1, 2}}), 0, -std::ldexp(1.0, -40)));

  // ---- tangencies
  // A parabola touching its vertex tangent: multiplicity 2 at s = t = 1/2.
  add_pair("parabola_line_tangent_at_vertex", vertex0, curve({{0, 0}, {1, 0}}));
  // The same with the line reversed (t runs backwards).
  add_pair("parabola_line_tangent_reversed", vertex0, curve({{1, 0}, {0, 0}}));
  // y = (x - 3/2)^3 / 27 against its inflection tangent y = 0: multiplicity 3.
  add_pair("cubic_inflection_tangent_line", curve({{0, -0.125}, {1, 0.125}, {2, -0.125}, {3, 0.125}}),
           curve({{0, 0}, {3, 0}}));
  // y = (s - 1/2)^4 against y = 0: a flat point, multiplicity 4.
  add_pair("quartic_flat_point_line",
           from_power(QPoly{Q(0), Q(4)}, QPoly{Q(1, 16), Q(-1, 2), Q(3, 2), Q(-2), Q(1)}, 4), curve({{0, 0}, {4, 0}}));
  // y = x^2 against y = x^2 + x^3 (same curvature): osculation, multiplicity 3.
  add_pair("parabola_cubic_osculating_3", graph(QPoly{0, 0, 1}, Q(-3, 2), Q(3), 2),
           graph(QPoly{0, 0, 1, 1}, Q(-3, 2), Q(3), 3));
  // y = x^2 against y = x^2 + x^4: contact of order 4, multiplicity 4.
  add_pair("parabola_quartic_contact_4", graph(QPoly{0, 0, 1}, Q(-3, 2), Q(3), 2),
           graph(QPoly{0, 0, 1, 0, 1}, Q(-3, 2), Q(3), 4));
  // y = x^2 against y = -x^2: tangent, opposite sides.
  add_pair("parabolas_tangent_opposite", curve({{-1, 1}, {0, -1}, {1, 1}}), curve({{-1, -1}, {0, 1}, {1, -1}}));
  // y = x^2 against y = 2 x^2 (on [-1/2, 1/2]): tangent, same side.
  add_pair("parabolas_tangent_same_side", curve({{-1, 1}, {0, -1}, {1, 1}}),
           curve({{-0.5, 0.5}, {0, -0.5}, {0.5, 0.5}}));
  // y = 4 (x^2 - 1/4)^2 against y = 0: two tangencies, at s = 1/4 and 3/4.
  add_pair("quartic_double_tangent_line", graph(QPoly{Q(1, 4), 0, Q(-2), 0, Q(4)}, Q(-1), Q(2), 4),
           curve({{-1, 0}, {1, 0}}));
  // y = x^3 - x and its tangent at x = 1/2: tangent at s = 2/3 (rational, not
  // dyadic), crossing at s = 1/6.
  add_pair("cubic_tangent_and_crossing_line", graph(QPoly{0, -1, 0, 1}, Q(-3, 2), Q(3), 3),
           curve({{-1.5, 0.125}, {1.5, -0.625}}));
  // A parabola whose start tangent is the segment: tangent at s = 0, t = 1/2.
  add_pair("tangent_at_start_parameter", curve({{0, 0}, {1, 0}, {1, 1}}), curve({{-1, 0}, {1, 0}}));
  // G1 join: a ends where b starts with the same tangent: multiplicity 2 at (1, 0).
  add_pair("g1_join_end_to_start", curve({{-1, 1}, {0, 0}, {1, 0}}), curve({{1, 0}, {2, 0}, {2, 2}}));
  // A join with equal curvature too: multiplicity 3 at (1, 0).
  add_pair("curvature_continuous_join", curve({{-1, 1}, {0, 0}, {1, 0}}), curve({{1, 0}, {2, 0}, {2, 1}}));
  // A vertical line through a cusp along its tangent: multiplicity 3.
  add_pair("cusp_tangent_line", cusp, curve({{0.5, 0}, {0.5, 1}}));
  // A horizontal line through a cusp, across its tangent: multiplicity 2 (kind
  // tangent: a cusp is singular), s = 1/2, t = 1/2.
  add_pair("cusp_transversal_line", cusp, curve({{0, 0.75}, {1, 0.75}}));

  // ---- near misses
  // Line 2^-52 below the vertex of y = 2 (s - 1/2)^2: no intersection.
  add_pair("parabola_line_2^-52_below_miss", vertex0, curve({{0, -e52}, {1, -e52}}));
  // Line 2^-52 above it: two transversal crossings at s = 1/2 ± 2^-26.5.
  add_pair("parabola_line_2^-52_above_two_hits", vertex0, curve({{0, e52}, {1, e52}}));
  // Line one ulp above the vertex 1/2 of y = 2 s (1 - s): no intersection.
  add_pair("arch_line_1ulp_above_miss", arch,
           curve({{0, std::nextafter(0.5, 1.0)}, {1, std::nextafter(0.5, 1.0)}}));
  // Line one ulp below it: two transversal crossings at s = 1/2 ± 2^-27.5.
  add_pair("arch_line_1ulp_below_two_hits", arch,
           curve({{0, std::nextafter(0.5, 0.0)}, {1, std::nextafter(0.5, 0.0)}}));
  // Segments with slopes 1/2 and 1/2 - 2^-40 crossing at s = t = 1/2.
  add_pair("nearly_parallel_lines_cross_at_half", curve({{0, 0}, {1, 0.5}}),
           curve({{0, std::ldexp(1.0, -41)}, {1, 0.5 - std::ldexp(1.0, -41)}}));
  // Slopes differing by 2^-40 crossing at s = t = 1/4.
  add_pair("nearly_parallel_lines_cross_at_quarter", curve({{0, 0}, {1, 0.5}}),
           curve({{0, std::ldexp(1.0, -42)}, {1, 0.5 - 3 * std::ldexp(1.0, -42)}}));
  // Slopes differing by 2^-42 whose lines cross at s = 2: no intersection.
  add_pair("nearly_parallel_lines_miss", curve({{0, 0}, {1, 0.5}}),
           curve({{0, std::ldexp(1.0, -41)}, {1, 0.5 + std::ldexp(1.0, -42)}}));
  // A cubic arch and its copy 2^-50 higher: no intersection.
  add_pair("cubic_translated_up_2^-50_miss", bump, translated(bump, 0, std::ldexp(1.0, -50)));
  // The arch and its copy 2^-50 to the right: one crossing near the top.
  add_pair("cubic_translated_right_2^-50_one_crossing", bump, translated(bump, std::ldexp(1.0, -50), 0));
  // y = x^2 and y = 2 x^2 + 2^-40: no intersection.
  add_pair("parabolas_nearly_tangent_miss", curve({{-1, 1}, {0, -1}, {1, 1}}),
           translated(curve({{-1, 2}, {0, -2}, {1, 2}}), 0, std::ldexp(1.0, -40)));

  // ---- overlaps
  // The same cubic twice: overlap a [0,1], b [0,1].
  add_pair("identical_cubics", s_cubic, s_cubic);
  // The cubic and its reverse: overlap a [0,1], b [0,1] reversed.
  add_pair("identical_reversed", s_cubic, exact_reversed(s_cubic));
  // A sub-arc split exactly at 1/4 and 3/4: a [1/4, 3/4], b [0, 1].
  add_pair("subsegment_same_direction", s_cubic, exact_subcurve(s_cubic, Q(1, 4), Q(3, 4)));
  // A reversed sub-arc [1/4, 1/2]: a [1/4, 1/2], b [0, 1] reversed.
  add_pair("subsegment_reversed", s_cubic, exact_reversed(exact_subcurve(s_cubic, Q(1, 4), Q(1, 2))));
  // C[0, 3/4] and C[1/4, 1] share C[1/4, 3/4]: a [1/3, 1], b [0, 2/3].
  add_pair("shared_middle_subarc", exact_subcurve(s_cubic, 0, Q(3, 4)), exact_subcurve(s_cubic, Q(1, 4), 1));
  // The same with b reversed: a [1/3, 1], b [1/3, 1] reversed.
  add_pair("shared_middle_subarc_reversed", exact_subcurve(s_cubic, 0, Q(3, 4)),
           exact_reversed(exact_subcurve(s_cubic, Q(1, 4), 1)));
  // The cubic and its degree-elevated copy (degree 4): overlap a [0,1], b [0,1].
  add_pair("degree_elevated_copy", s_cubic, exact_elevated(s_cubic));
  // Five times the cubic and its copy elevated to degree 5, reversed.
  add_pair("degree_elevated_twice_reversed", mapped(s_cubic, 5, 0, 0, 5, 0, 0),
           exact_reversed(exact_elevated(exact_elevated(mapped(s_cubic, 5, 0, 0, 5, 0, 0)))));
  // A quadratic against its cubic form (coordinates multiples of 3).
  add_pair("quadratic_elevated_to_cubic", curve({{0, 0}, {3, 6}, {6, 0}}), exact_elevated(curve({{0, 0}, {3, 6}, {6, 0}})));
  // Collinear segments overlapping: a [1/4, 1], b [0, 3/7] (rational, not dyadic).
  add_pair("coincident_lines_partial", curve({{0, 0}, {1, 1}}), curve({{0.25, 0.25}, {2, 2}}));
  // Collinear vertical segments (x constant in both: P is identically 0).
  add_pair("coincident_vertical_segments", curve({{1, 0}, {1, 2}}), curve({{1, 1}, {1, 3}}));
  // Collinear segments meeting end to start: one point, shared component.
  add_pair("collinear_lines_touch_at_end", curve({{0, 0}, {1, 1}}), curve({{1, 1}, {2, 2}}));
  // Collinear disjoint segments: the same line, no common point.
  add_pair("collinear_lines_disjoint", curve({{0, 0}, {1, 1}}), curve({{2, 2}, {3, 3}}));
  // C[0, 1/2] and C[1/2, 1]: one point (a = 1, b = 0), shared component.
  add_pair("curve_and_its_continuation", exact_subcurve(s_cubic, 0, Q(1, 2)), exact_subcurve(s_cubic, Q(1, 2), 1));
  // C[0, 1/4] and C[1/2, 1]: the same algebraic curve, disjoint arcs.
  add_pair("same_curve_disjoint_arcs", exact_subcurve(s_cubic, 0, Q(1, 4)), exact_subcurve(s_cubic, Q(1, 2), 1));
  // L[0, 5/8] and L[3/8, 1] of the loop: overlap a [3/5, 1], b [0, 2/5], and a
  // crossing at the double point, a = 2/5, b = 3/5.
  add_pair("overlap_and_crossing_at_double_point", exact_subcurve(loop, 0, Q(5, 8)), exact_subcurve(loop, Q(3, 8), 1));

  // ---- shared end points and knots
  // Both curves start at the origin, different tangents: transversal at 0, 0.
  add_pair("corner_shared_start", curve({{0, 0}, {1, 0}, {2, 1}}), curve({{0, 0}, {0, 1}, {1, 2}}));
  // a ends where b starts, a corner: transversal at a = 1, b = 0.
  add_pair("end_to_start_corner", curve({{0, 0}, {1, 1}, {2, 0}}), curve({{2, 0}, {2, -1}, {3, -1}}));
  // a's end on b's interior (T junction): a = 1, b = 1/2.
  add_pair("end_on_interior", curve({{1, 2}, {1, 0.5}}), curve({{0, 0}, {1, 1}, {2, 0}}));
  // a's start on a segment's interior: a = 0, b = 1/4.
  add_pair("start_on_interior", curve({{1, 0}, {1, 1}, {2, 1}, {3, 1}}), curve({{0, 0}, {4, 0}}));
  // Two arcs closing a loop: a(0) = b(1) and a(1) = b(0).
  add_pair("closed_by_two_arcs", curve({{0, 0}, {1, 1}, {2, 0}}), curve({{2, 0}, {1, -1}, {0, 0}}));
  // Two cubics crossing at both parameters 1/2 (a knot when split there); they
  // also share their end (2, 0).
  add_pair("cubics_cross_at_halves", curve({{0, 0}, {0, 2}, {2, 2}, {2, 0}}),
           curve({{0, 3}, {0.5, 1.5}, {1.5, 1.5}, {2, 0}}));
  // A vertical line through the loop's double point: two crossings at the same
  // point and b = 1/2 (the b side sees both), and one at the loop's top.
  add_pair("line_through_double_point", loop, curve({{9, 0}, {9, 13.5}}));
  // The loop and its copy turned by 90 degrees about the double point: four
  // crossings at that one point, each curve passing twice (neither the a side
  // nor the b side isolates them: sheared projections do), and one elsewhere.
  add_pair("two_loops_share_double_point", loop, mapped(loop, 0, -1, 1, 0, 9 + 6.75, 6.75 - 9));

  // ---- self-intersections
  // The loop: a(1/4) = a(3/4), transversal.
  add_self("self_loop_rational", loop);
  // (0,0),(2,1),(-1,1),(1,0): a loop at s, t = 1/2 ∓ sqrt(3/20).
  add_self("self_loop_irrational", curve({{0, 0}, {2, 1}, {-1, 1}, {1, 0}}));
  // (0,0),(1,1),(0,1),(1,0): a cusp at s = 1/2, not a self-intersection.
  add_self("self_cusp_none", cusp);
  // An S-shaped cubic without self-intersection.
  add_self("self_s_cubic_none", s_cubic);
  // A parabola and a segment: never.
  add_self("self_quadratic_none", arch);
  add_self("self_line_none", curve({{0, 0}, {1, 2}}));
  // A closed cubic, a(0) = a(1): its seam (0, 1) is no self-intersection.
  add_self("self_closed_cubic", curve({{0, 0}, {1, 2}, {-1, 2}, {0, 0}}));
  // The loop cut at 3/4: its end lies on itself, (1/3, 1).
  add_self("self_end_on_itself", exact_subcurve(loop, 0, Q(3, 4)));
  // Chebyshev curves (T3, T4), (T4, T5), (T5, T6): 3, 6 and 10 double points.
  add_self("self_chebyshev_3_4", chebyshev_curve(3, 4));
  add_self("self_chebyshev_4_5", chebyshev_curve(4, 5));
  add_self("self_chebyshev_5_6", chebyshev_curve(5, 6));
  // x = τ^4 - τ^2/2, y = τ^3 - τ/4, τ = 2s - 1: the curve touches itself
  // (a tacnode, both branches vertical) at s = 1/4, 3/4.
  add_self("self_tacnode_quartic", from_power(compose(QPoly{0, 0, Q(-1, 2), 0, 1}, Q(2), Q(-1)),
                                              compose(QPoly{0, Q(-1, 4), 0, 1}, Q(2), Q(-1)), 4));

  for (const IntersectionCase& c : cases) {
    control_points_as_doubles(c.a);
    if (c.b) control_points_as_doubles(*c.b);
  }
  return cases;
}

}  // namespace casteljau::test

"""Seed 001, section 1.2.3.1: the B-spline basis functions N_{i,k} of the Cox–de Boor recursion.

The seed counts by order k: N_{i,k} is piecewise of degree k - 1 (not k), C^(k-2) at a simple knot
(not C^(k-1)), and N_{i,1} is 1 on the half-open [t_i, t_{i+1}). Each repetition of a knot (not of
a control point, as printed) takes one degree of continuity away there. Here everything is cubic:
order 4, degree 3, so C^2 at a simple knot, C^1 at a double knot, C^0 (a corner) at a triple one.

casteljau calls: cj.uniform_knots and cj.clamped_uniform_knots build the knot vectors,
casteljau.plot.basis draws every N_{i,3} (by cj.basis_function), cj.basis_function sums them, and
cj.continuity_at_knots measures the continuity of a curve on the same knots.

In the figure: the black dashed line is sum_i N_{i,3}(u). It is 1 on the domain [t_3, t_{n+1}]
(shaded) and smaller outside it, where uniform knots leave some functions missing. Clamped knots
make the end functions Bézier-like (they reach 1 at the ends). Bottom row: the knot u = 2 doubled
(the functions are still C^1 there: no corner yet, only the second derivative jumps) and tripled
(a corner: one function reaches 1 at u = 2 and a curve on these knots passes through a control point).
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

p = 3  # degree 3 = order 4 in the seed's counting
cases = {
    "uniform knots (unclamped)": cj.uniform_knots(p, 7, (0.0, 4.0)),
    "clamped uniform knots": cj.clamped_uniform_knots(p, 7, (0.0, 4.0)),
    "u = 2 of multiplicity 2": np.array([0, 0, 0, 0, 1, 2, 2, 3, 4, 4, 4, 4], float),
    "u = 2 of multiplicity 3": np.array([0, 0, 0, 0, 1, 2, 2, 2, 3, 4, 4, 4, 4], float),
}

fig, axes = plt.subplots(2, 2, figsize=(12, 7.5), constrained_layout=True)
for ax, (title, knots) in zip(axes.flat, cases.items()):
    count = len(knots) - p - 1  # number of basis functions (= control points)
    plot.basis(ax, knots, p, linewidth=1.8)
    us = np.linspace(knots[0], knots[-1], 801)
    total = sum(cj.basis_function(knots, p, i, us) for i in range(count))
    ax.plot(us, total, "k--", linewidth=1, label="sum of all N_i,3")
    ax.axvspan(knots[p], knots[count], color="grey", alpha=0.12, label="domain")
    ax.plot(knots, np.zeros_like(knots), "k|", ms=12)  # the knots; repeated ones overlap
    # A curve on these knots (any control points will do) shows the continuity at each knot.
    zigzag = np.column_stack([np.arange(count), (-1.0) ** np.arange(count)])
    smoothness = [f"C^{k.measured.parametric} at {k.value:g}"
                  for k in cj.continuity_at_knots(cj.BSplineCurve(p, knots, zigzag))]
    print(f"{title}: {', '.join(smoothness)}")
    inside = (us >= knots[p]) & (us <= knots[count])
    print(f"   partition of unity on the domain: max |sum - 1| = {np.max(np.abs(total[inside] - 1)):.1e}")
    ax.set_title(f"{title}\nknots {' '.join(f'{t:g}' for t in knots)}", fontsize=9)
    ax.set_ylim(-0.08, 1.25)
    ax.legend(fontsize=7, loc="upper right", framealpha=1)
    ax.set_xlabel("u")
course.save(fig, "001_bspline_basis")

"""Seed 003, part II §2 (geometric construction of M(t), and the algorithm that computes the curve's points).

The exercise: build the point M(t) with ruler and compass only, by cutting each leg of the
control polygon in the ratio t, then each leg of the new polygon, until one point is left.
The seed derives it from M(t) = (1 - t) Q(t) + t R(t), where Q(t) is the point of the Bézier curve
of (P_0, P_1, P_2) and R(t) that of (P_1, P_2, P_3): the construction recurses on shorter polygons.
casteljau: `cj.casteljau_construction(curve, t)` returns every intermediate polygon,
`plot.de_casteljau` draws them; `cj.point_at` is the same algorithm.
Example: the seed's cubic A(-3,0) B(-3,4) C(3,4) D(3,0) (semicircle.csv), at t = 0.25, 0.5, 0.75.

In each panel: the dashed polygons with 4, 3, 2 points, the red point M(t) on the curve, and the
two grey quadratic curves that carry Q(t) and R(t) (the ends of the last segment).
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

TS = (0.25, 0.5, 0.75)

points = course.read_points("semicircle.csv")
curve = cj.BezierCurve(points)
first, last = cj.BezierCurve(points[:-1]), cj.BezierCurve(points[1:])  # Q(t) and R(t) live on these

fig, axes = plt.subplots(1, len(TS), figsize=(5 * len(TS), 3.8), sharey=True)
for ax, t in zip(axes, TS):
    levels = cj.casteljau_construction(curve, t)  # [polygon (4, 2), (3, 2), (2, 2) = [Q, R], (1, 2) = M]
    q, r = levels[-2]
    m = levels[-1][0]
    assert np.allclose(q, cj.point_at(first, t)) and np.allclose(r, cj.point_at(last, t))
    assert np.allclose(m, (1 - t) * q + t * r) and np.allclose(m, cj.point_at(curve, t))
    print(f"t = {t}: Q = {q}, R = {r}, M = {m}")
    plot.curve(ax, first, color="0.7", linewidth=1)
    plot.curve(ax, last, color="0.7", linewidth=1)
    plot.de_casteljau(ax, curve, t)
    for label, point in (("Q", q), ("R", r), ("M", m)):
        ax.annotate(f"{label}({t})", point, xytext=(4, -12), textcoords="offset points")
    for label, point in zip("ABCD", points):
        ax.annotate(label, point, xytext=(-12 if point[0] < 0 else 5, 3), textcoords="offset points")
    ax.set_title(f"t = {t}")
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
course.save(fig, "003_geometric_construction")

"""Seed 004, the spiral cycle(n) (cells [15]-[17], [22], [37]) and de Casteljau's construction (cells [26]-[30]).

The notebook's cycle(n) puts n + 1 control points on a spiral, P_k at angle
-pi/2 + 2 k pi / n and distance 1/(k+1) from the origin, and uses it as a
harder test curve than its 5-point polygon: cycle(10) in cell [17], cycle(8)
and cycle(20) later. In section 3.2 it draws the construction of C(t) by
repeated barycentres: on the polygon at t = 0.5 (cell [28]) and on cycle(5) at
t = 0.6 (cell [30]).

casteljau: course.read_points("spiral_<n>.csv") holds cycle(n);
plot.curve(c, polygon=True) draws curve and control polygon; plot.de_casteljau(c, t)
draws every level of cj.casteljau_construction(c, t) and the point C(t).

What to look at: figure 1, each curve starts along the first leg, swings wide
and curls inward to its end P_n, arriving along the last leg; it touches no
other control point and stays in their convex hull (section 2.1). A larger n
packs more points along the same single turn; the curve barely changes.
Figure 2: each dashed level has one point fewer; the last segment, on which
C(t) (red) lies, is tangent to the curve there; the polygon's C(0.5) is
(2.25, 1.5).
"""

import course
from course import cj, plt

from casteljau import plot

fig, axes = plt.subplots(1, 4, figsize=(16, 6))
for ax, n in zip(axes, (5, 8, 10, 20)):
    spiral = cj.BezierCurve(course.read_points(f"spiral_{n}.csv"))
    plot.curve(spiral, ax=ax, color="k", polygon=True)  # cell [17] for n = 10
    ax.set_title(f"cycle({n}): degree {spiral.degree}")
    ax.set_aspect("equal")
    ax.grid(True)
course.save(fig, "004_spirals")

polygon = cj.BezierCurve(course.read_points("notebook_polygon.csv"))
cycle5 = cj.BezierCurve(course.read_points("spiral_5.csv"))
fig, axes = plt.subplots(1, 2, figsize=(14, 6), gridspec_kw={"width_ratios": [1.6, 1]})
for ax, curve, t, cell in zip(axes, (polygon, cycle5), (0.5, 0.6), ("[28]", "[30]")):
    levels = cj.casteljau_construction(curve, t)  # level 0 = control points, ..., level n = [C(t)]
    print(f"cell {cell}: t = {t}, {len(levels)} levels, C(t) = {levels[-1][0]}")
    plot.de_casteljau(curve, t, ax=ax)
    ax.set_title(f"cell {cell}: de Casteljau at t = {t}")
    ax.set_aspect("equal")
    ax.grid(True)
course.save(fig, "004_casteljau_construction")

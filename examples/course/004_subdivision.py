"""Seed 004, notebook section 3.3: subdivision by de Casteljau (the proposition and cells [31]-[37]).

The notebook proves that the points of the de Casteljau triangle at t split
the curve: the left edge P_0^0, P_0^1, ..., P_0^n is the control polygon of
the part over [0, t], the right edge P_0^n, ..., P_n^0 that of [t, 1]. Doing
it again on both halves, r times at t = 1/2, gives 2^r + 1 points of the
curve (cell [32]: r = 10 gives 1025); cells [35] and [37] plot r = 9.

casteljau: cj.subdivide_recursive(c, r) returns the 2^r + 1 points;
cj.split_at(c, t) the two halves; plot.subdivision(c, r, polygons=True) draws
the points' polyline and the 2^r pieces' polygons; plot.de_casteljau the triangle.

What to look at: figure 1, the 513 points trace the whole curve (the red
dots are the control points). Figure 2, left: the blue and green polygons
(the halves) lie exactly on the outer edges of the dashed triangle; right:
after two rounds the four small polygons already hug the curve.
"""

import course
from course import cj, np, plt

from casteljau import plot

cell35 = cj.BezierCurve([(0, 0), (1, 2), (2, 3), (4, 1), (5, 3)])  # the control points of cells [32]-[35]
spiral = cj.BezierCurve(course.read_points("spiral_20.csv"))  # cycle(20), cell [37]
points = cj.subdivide_recursive(cell35, 10)
gap = max(np.linalg.norm(p - cj.point_at(cell35, i / 1024)) for i, p in enumerate(points))  # point i is C(i/2^r)
print(f"r = 10: {len(points)} points, at most {gap:.1e} from C(i/1024)")

fig, axes = plt.subplots(1, 2, figsize=(14, 6))
for ax, curve, title in zip(axes, (cell35, spiral), ("cell [35]: r = 9", "cell [37]: cycle(20), r = 9")):
    plot.subdivision(curve, 9, ax=ax)  # 2^9 + 1 = 513 points joined by segments
    plot.control_polygon(curve, ax=ax, color="r", linestyle="none")
    ax.set_title(title)
    ax.grid(True)
course.save(fig, "004_subdivision_r9")

fig, (left, right) = plt.subplots(1, 2, figsize=(14, 6))
plot.de_casteljau(cell35, 0.5, ax=left)  # the triangle: the polygons of levels 0..n-1, and C(1/2)
for half, color in zip(cj.split_at(cell35, 0.5), ("b", "g")):
    plot.control_polygon(half, ax=left, color=color, linestyle="-", linewidth=3, alpha=0.5)
left.set_title("one round: the halves' polygons are the triangle's edges")
plot.curve(cell35, ax=right, color="k")
plot.control_polygon(cell35, ax=right, color="0.6")
plot.subdivision(cell35, 2, ax=right, polygons=True, color="none")  # only the 4 pieces' polygons
right.set_title("two rounds: 4 pieces' polygons")
for ax in (left, right):
    ax.grid(True)
course.save(fig, "004_subdivision_polygons")

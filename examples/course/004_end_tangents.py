"""Seed 004, notebook section 2.2 and cells [18]-[22] (with the curves of cells [12]-[14]).

The notebook differentiates the Bernstein basis at 0 and 1 and finds that a
Bézier curve leaves P_0 along P_1 - P_0 and arrives at P_n along P_n - P_{n-1}:
C'(0) = n (P_1 - P_0), C'(1) = n (P_n - P_{n-1}). It then draws the curve, its
control points and the two end legs, on the 5-point polygon of cell [14]
(cell [20]) and on the spiral cycle(8) (cell [22]).

casteljau: plot.curve(c, polygon=True) draws the curve and its control points;
plot.tangents(c) the end tangents, each scaled by 1/n so that it is exactly the
first or last leg of the polygon; cj.derivative_at(c, t) gives C'(t) itself.

What to look at: each blue segment is the first (last) leg of the polygon, and
the curve leaves P_0 (reaches P_n) tangent to it. The curve passes through P_0
and P_n only; the other control points stay off it.
"""

import course
from course import cj, np, plt

from casteljau import plot

curves = {"cell [20]: the notebook polygon": cj.BezierCurve(course.read_points("notebook_polygon.csv")),
          "cell [22]: cycle(8)": cj.BezierCurve(course.read_points("spiral_8.csv"))}

fig, axes = plt.subplots(1, 2, figsize=(13, 5), gridspec_kw={"width_ratios": [2, 0.7]})  # the spiral is tall and narrow
for ax, (title, curve) in zip(axes, curves.items()):
    p, n = curve.control_points, curve.degree
    start, end = cj.derivative_at(curve, 0.0), cj.derivative_at(curve, 1.0)
    assert np.allclose(start, n * (p[1] - p[0])) and np.allclose(end, n * (p[n] - p[n - 1]))
    print(f"{title}: n = {n}, C'(0) = {start} = n (P1 - P0), C'(1) = {end} = n (Pn - Pn-1)")
    plot.curve(curve, ax=ax, color="k", polygon=True, polygon_kw={"linestyle": "none"})  # points only
    plot.tangents(curve, ax=ax, color="b", linewidth=2)  # the legs P0P1 and P(n-1)Pn
    ax.set_title(title)
    ax.set_aspect("equal")
    ax.grid(True)
course.save(fig, "004_end_tangents")

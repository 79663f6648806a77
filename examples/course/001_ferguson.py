"""Seed 001, section 1.2.1: Ferguson's cubic, from two end points and two end tangents.

Ferguson writes a cubic P(u) = a0 + a1 u + a2 u^2 + a3 u^3 on [0, 1] and fixes its four vector
coefficients by four conditions: the start point P(0), the end point P(1), the start tangent
P'(0) and the end tangent P'(1). Keeping the two points and the tangent directions but changing
the tangents' length changes the shape a lot: short tangents give an almost straight curve, long
ones a wide bulge and, longer still, a loop.

casteljau call: cj.ferguson_curve(start, start_tangent, end, end_tangent) returns the same cubic
as a Bézier curve, with control points P0, P0 + T0/3, P1 - T1/3, P1; cj.derivative_at checks the
end tangents; casteljau.plot draws the curves, control polygons and tangents.

In the figure: five Ferguson curves between the same two points with the same tangent directions
(up at the start, down at the end), the tangents of length 1, 4, 8, 12 and 16: the curve rises
higher and higher and finally loops. The dashed polygon is the Bézier control polygon of the longest
one, and the red arrows its end tangents T0/3 and T1/3 (a third of their length: the first arrow
ends on the inner control point P0 + T0/3).
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

start, end = np.array([0.0, 0.0]), np.array([4.0, 0.0])
start_direction = np.array([2.0, 1.0]) / np.sqrt(5.0)  # unit tangents: only the length varies
end_direction = np.array([2.0, -1.0]) / np.sqrt(5.0)

fig, ax = plt.subplots(figsize=(8, 6))
for length, colour in zip([1, 4, 8, 12, 16], plt.cm.viridis(np.linspace(0, 0.9, 5))):
    t0, t1 = length * start_direction, length * end_direction
    curve = cj.ferguson_curve(start, t0, end, t1)
    # The conditions Ferguson imposes, checked on the library's curve:
    assert np.allclose(cj.derivative_at(curve, 0.0), t0) and np.allclose(cj.derivative_at(curve, 1.0), t1)
    plot.curve(ax, curve, color=colour, lw=2, label=f"|T0| = |T1| = {length:g}")
    if length == 16:
        plot.control_polygon(ax, curve, color="grey", linestyle="--")
        plot.tangents(ax, curve, [0.0, 1.0], scale=1 / 3, color="tab:red")  # T0/3 and T1/3

ax.plot(*np.array([start, end]).T, "ko", ms=7)
ax.annotate("P(0)", start, textcoords="offset points", xytext=(-30, -12))
ax.annotate("P(1)", end, textcoords="offset points", xytext=(8, -12))
ax.set_aspect("equal")
ax.grid(alpha=0.3)
ax.legend(fontsize=8, loc="lower left")
ax.set_title("Ferguson cubics: same end points and tangent directions, longer tangents")
course.save(fig, "001_ferguson")

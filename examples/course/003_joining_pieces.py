"""Seed 003, part III §1 a) (fighting the global control of one Bézier curve by joining short pieces).

The exercise: join two cubic Bézier pieces so that the second polygon starts where the first ends
and its first leg lies on the line of the first polygon's last leg: the tangent is shared.
  - same direction and same length (with both pieces on parameter intervals of length 1): the
    derivatives agree, the join is C1;
  - same direction, another length: only the tangent line agrees, the join is G1 but not C1;
  - another direction: a corner (G0 only).
casteljau: `cj.join(first, second)` glues two B-splines (`cj.to_bspline` of each piece) into one
curve and reports `continuity.parametric` (the k of C^k) and `continuity.tangent` (G1 or not).

In each panel the arrows start at the joint: the two one-sided derivatives there, divided by 3
(blue: the first polygon's last leg carried forward; orange: the second polygon's first leg).
One on top of the other for C1, aligned with different lengths for G1, at an angle for a corner.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

FIRST = np.array([(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)])
REST = np.array([(7.0, -1.0), (8.0, 1.0)])  # the last two control points of the second piece
last_leg = FIRST[3] - FIRST[2]
JOINS = {  # the second control point of the second piece
    "C1: same leg continued": FIRST[3] + last_leg,
    "G1 only: collinear, twice as long": FIRST[3] + 2 * last_leg,
    "corner: another direction": FIRST[3] + np.array([1.0, 1.0]),
}

first = cj.BezierCurve(FIRST)
fig, axes = plt.subplots(1, len(JOINS), figsize=(5 * len(JOINS), 4), sharey=True)
for ax, (title, second_leg_end) in zip(axes, JOINS.items()):
    second = cj.BezierCurve(np.vstack([FIRST[3], second_leg_end, REST]))
    joined = cj.join(cj.to_bspline(first), cj.to_bspline(second))
    k, g1 = joined.continuity.parametric, joined.continuity.tangent
    print(f"{title:35s} -> C^{k}, tangent continuous (G1): {g1}, gap {joined.gap}")
    plot.curve(ax, first, polygon=True, color="k")
    plot.curve(ax, second, polygon=True, color="tab:purple", polygon_kw={"color": "tab:purple"})
    plot.tangents(ax, first, [1.0], scale=1 / 3, color="tab:blue", linewidth=4, label="first piece, t = 1")
    plot.tangents(ax, second, [0.0], scale=1 / 3, color="tab:orange", linewidth=1.5, label="second piece, t = 0")
    ax.set_title(f"{title}\njoin() reports C^{k}, G1 = {g1}")
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
axes[0].legend(loc="upper right")
course.save(fig, "003_joining_pieces")

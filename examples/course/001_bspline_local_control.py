"""Seed 001, sections 1.2.2 and 1.2.3: local control of a B-spline against global control of Bézier.

The seed lists as a drawback of Bézier curves that control is global (and the degree grows with the
number of points), and as an advantage of B-splines that control is local. Here both curves use
the same 11 control points: a cubic B-spline (examples/spline.json, 8 spans) and the Bézier curve
of degree 10. Then control point P_5 is moved up by 1.5 and we see what changes.

casteljau calls: cj.read_models (the JSON model), cj.BSplineCurve and cj.BezierCurve, cj.points_at
(the B-spline's support rule: N_{i,p} vanishes outside [t_i, t_{i+p+1}]); casteljau.plot draws.

In the figure: top, the B-spline before (solid) and after (dashed): only the part over the shaded
parameters u in [t_5, t_9] = [2, 6] (4 of the 8 spans) moves, the rest is exactly the same.
Middle, the Bézier curve: all of it moves. Bottom, how far each point moved, against the
parameter scaled to [0, 1]: zero outside [0.25, 0.75] for the B-spline, nonzero everywhere for Bézier.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

spline = cj.read_models(course.EXAMPLES / "spline.json")[0]
p, knots, points = spline.degree, spline.knots, spline.control_points
moved_index = 5
moved = points.copy()
moved[moved_index, 1] += 1.5
spline_after = cj.BSplineCurve(p, knots, moved)
bezier, bezier_after = cj.BezierCurve(points), cj.BezierCurve(moved)

fig, axes = plt.subplots(3, 1, figsize=(9, 10), constrained_layout=True)
# N_{5,3} is non-zero only on [t_5, t_9]: the spans whose points depend on P_5.
lower, upper = knots[moved_index], knots[moved_index + p + 1]
for ax, before, after, name in [(axes[0], spline, spline_after, "cubic B-spline"),
                                (axes[1], bezier, bezier_after, "Bézier curve of degree 10")]:
    plot.curve(ax, before, polygon=True, polygon_kw={"color": "tab:blue"},
               color="tab:blue", linewidth=2, label="before")
    plot.curve(ax, after, color="tab:red", linewidth=2, linestyle="--", label=f"P_{moved_index} moved up")
    plot.control_polygon(ax, moved, color="tab:red", linewidth=0.6)
    ax.set_title(name)
    ax.set_aspect("equal")
    ax.legend(fontsize=8, loc="upper left")
part = cj.points_at(spline, np.linspace(lower, upper, 200))  # the arc that changed
axes[0].plot(*part.T, color="gold", linewidth=8, alpha=0.4, zorder=0, label="u in [2, 6]")
axes[0].legend(fontsize=8, loc="upper left")

s = np.linspace(0.0, 1.0, 801)  # parameter scaled to [0, 1] for both curves
spline_shift = np.linalg.norm(cj.points_at(spline_after, 8 * s) - cj.points_at(spline, 8 * s), axis=1)
bezier_shift = np.linalg.norm(cj.points_at(bezier_after, s) - cj.points_at(bezier, s), axis=1)
axes[2].plot(s, spline_shift, color="tab:green", label="B-spline")
axes[2].plot(s, bezier_shift, color="tab:purple", label="Bézier")
axes[2].axvspan(lower / 8, upper / 8, color="gold", alpha=0.3, label="support of N_5,3")
axes[2].set_xlabel("parameter / length of the domain")
axes[2].set_ylabel("distance moved")
axes[2].legend(fontsize=8)
outside = (8 * s < lower) | (8 * s > upper)
print(f"outside u in [{lower:g}, {upper:g}]: B-spline points moved by at most "
      f"{spline_shift[outside].max():.1e}, Bézier points by up to {bezier_shift[outside].max():.2f}")
course.save(fig, "001_bspline_local_control")

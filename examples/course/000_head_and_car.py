"""Seed 000, section 2 (C1 interpolating curves of cubic Bézier pieces) and remark 1 (C1 versus C2).

The exercise: through the points P_0..P_m of the head (head.csv) and of the car (car.csv), join
cubic Bézier pieces P_i, Q_i, R_i, P_{i+1} whose tangents at the joints are (P_{i+1} - P_{i-1})/alpha.
`cj.interpolate_c1_bezier(points, alpha)` builds that PiecewiseBezierCurve (piece i on [i, i+1]).
The remark: with cubic pieces one can do better, a C2 curve (a cubic B-spline):
`cj.interpolate_cubic(points, u, "natural")` on the same parameters u_i = i.

Figure 000_head_and_car: one column per alpha; triangles are the Q_i, squares the R_i.
alpha small means long tangents (loops); alpha large short ones (the curve gets close to the polygon).
Figure 000_head_and_car_curvature: signed curvature (`cj.signed_curvature_at`) along u, piece by piece.
The C1 curve (alpha = 2, the tangents closest to the spline's) jumps at each joint (grey lines);
the C2 spline's curvature is continuous. `cj.continuity_at_knots` measures the same thing.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

ALPHAS = (1.0, 2.0, 3.0)  # the seed's alpha = 1, Catmull-Rom's 2, and a student's choice: change me
COMPARE = 2.0  # the alpha of the C1 curve in the curvature plot
SHAPES = ("head.csv", "car.csv")
ts = np.linspace(0, 1, 101)

fig, axes = plt.subplots(2, len(ALPHAS), figsize=(5 * len(ALPHAS), 9))
for row, name in zip(axes, SHAPES):
    points = course.read_points(name)
    for ax, alpha in zip(row, ALPHAS):
        c1 = cj.interpolate_c1_bezier(points, alpha)
        controls = np.array([piece.control_points for piece in c1.pieces])  # (m, 4, 2): P_i, Q_i, R_i, P_i+1
        plot.curve(ax, c1, color="k")
        plot.control_polygon(ax, c1, color="0.6", marker="none")
        ax.plot(*controls[:, 1].T, "^", color="tab:orange", markersize=4, label="Q_i")
        ax.plot(*controls[:, 2].T, "s", color="tab:green", markersize=4, label="R_i")
        ax.plot(*points.T, "o", color="tab:blue", markersize=5, label="P_i")
        ax.set_title(f"{name[:-4]}, alpha = {alpha:g}")
        ax.set_aspect("equal")
axes[0, 0].legend(loc="lower left")
course.save(fig, "000_head_and_car")

fig, axes = plt.subplots(len(SHAPES), 1, figsize=(11, 7.5), gridspec_kw={"hspace": 0.35})
for ax, name in zip(axes, SHAPES):
    points = course.read_points(name)
    m = len(points) - 1
    c1 = cj.interpolate_c1_bezier(points, COMPARE)
    c2 = cj.interpolate_cubic(points, np.arange(m + 1.0), "natural")
    for label, curve, pieces in ((f"C1, alpha = {COMPARE:g}", c1, c1.pieces),
                                 ("C2, natural cubic spline", c2, cj.to_bezier_pieces(c2).pieces)):
        kappa = np.array([[cj.signed_curvature_at(piece, t) for t in ts] for piece in pieces])  # (m, 101)
        jumps = np.abs(kappa[1:, 0] - kappa[:-1, -1])  # right limit minus left limit at u = 1..m-1
        orders = {k.measured.parametric for k in cj.continuity_at_knots(cj.to_bspline(curve))}
        print(f"{name} {label}: continuity C^{min(orders)} at the joints, largest curvature jump {jumps.max():.3g}")
        u = np.hstack([np.append(i + ts, np.nan) for i in range(m)])  # NaN: no line across a joint
        ax.plot(u, np.hstack([np.append(k, np.nan) for k in kappa]), label=label)
    ax.vlines(np.arange(1, m), 0, 1, transform=ax.get_xaxis_transform(), color="0.8", linewidth=0.8)
    ax.set_yscale("symlog", linthresh=1.0)  # spikes at tight turns, and small values near 0 both show
    ax.set_title(f"{name[:-4]}: signed curvature along u (joints at the integers)")
    ax.legend(loc="upper left")
course.save(fig, "000_head_and_car_curvature")

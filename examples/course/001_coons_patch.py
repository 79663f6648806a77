"""Seed 001, section 2.1: a Coons patch, a surface filled in from its four boundary curves.

Coons blends the four boundaries P(u, 0), P(u, 1), P(0, v), P(1, v) with two functions f_0, f_1
(f_0 + f_1 = 1, f_0(0) = 1, f_0(1) = 0) and subtracts the bilinear corner term, so that the patch
meets each boundary exactly. The seed names the fourth curve P(v, 1): it is P(1, v). Its cubic
blending is misprinted too: f_0(t) = 2t^3 - 3t^2 + 1 (not 2t^3 - 2t^2 + 1, whose value at t = 1 is
1), with f_1(t) = -2t^3 + 3t^2. The simplest blending is linear: f_0 = 1 - t, f_1 = t.

casteljau calls: cj.CoonsPatch(u0, u1, v0, v1, blending) with u0 = P(0, v), u1 = P(1, v),
v0 = P(u, 0), v1 = P(u, 1) (here cubic cj.BezierCurve boundaries), cj.point_at, cj.points_at
(on (u, v) pairs), cj.blending_functions; casteljau.plot.surface_wireframe draws in 3D.

In the figure: top, the patch with linear and with cubic blending, the boundaries in red; the
same boundaries, a different interior (the cubic one stays closer to each boundary's shape near
that boundary, since f_0' = f_1' = 0 at the ends). Bottom left, the blending functions (the dotted
curve is the misprinted f_0). Bottom right, the height of both patches along v = 0.25.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

v0 = cj.BezierCurve([[0, 0, 0], [1, 0, 2], [2, 0, 2], [3, 0, 0]])  # P(u, 0)
v1 = cj.BezierCurve([[0, 3, 0], [1, 3, -1], [2, 3, -1], [3, 3, 0]])  # P(u, 1)
u0 = cj.BezierCurve([[0, 0, 0], [0, 1, 1.5], [0, 2, 1.5], [0, 3, 0]])  # P(0, v)
u1 = cj.BezierCurve([[3, 0, 0], [3, 1, -1.5], [3, 2, 1], [3, 3, 0]])  # P(1, v)
patches = {name: cj.CoonsPatch(u0, u1, v0, v1, name) for name in ("linear", "cubic")}

fig = plt.figure(figsize=(12, 9), constrained_layout=True)
views = [fig.add_subplot(2, 2, k, projection="3d") for k in (1, 2)]
blend, cut = fig.add_subplot(2, 2, 3), fig.add_subplot(2, 2, 4)
t = np.linspace(0.0, 1.0, 101)
section = np.column_stack([t, np.full_like(t, 0.25)])  # the (u, v) pairs (u, 0.25)
for ax, (name, patch) in zip(views, patches.items()):
    plot.surface_wireframe(ax, patch, 13, color="tab:blue", linewidth=0.7)
    for boundary in (u0, u1, v0, v1):
        plot.curve(ax, boundary, color="tab:red", linewidth=2.5)
    ax.set_title(f"Coons patch, {name} blending")
    ax.view_init(elev=30, azim=-60)
    # The patch reproduces its boundaries: P(0, v) = u0(v), P(u, 1) = v1(u), and so on.
    gap = max(max(np.linalg.norm(cj.point_at(patch, 0.0, s) - cj.point_at(u0, s)),
                  np.linalg.norm(cj.point_at(patch, s, 1.0) - cj.point_at(v1, s))) for s in t)
    print(f"{name}: largest gap to the boundaries {gap:.1e}")
    cut.plot(t, cj.points_at(patch, section)[:, 2], label=f"{name} blending")
    f0, f1 = np.array([cj.blending_functions(name, s) for s in t]).T
    style = "--" if name == "linear" else "-"
    blend.plot(t, f0, style, color="tab:blue", label=f"f_0, {name}")
    blend.plot(t, f1, style, color="tab:orange", label=f"f_1, {name}")
blend.plot(t, 2 * t**3 - 2 * t**2 + 1, ":", color="grey", label="printed f_0 = 2t³−2t²+1")
blend.set_title("blending functions f_0(t), f_1(t)")
cut.set_title("height z of P(u, 0.25)")
for ax in (blend, cut):
    ax.set_xlabel("u" if ax is cut else "t")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
difference = cj.points_at(patches["linear"], section) - cj.points_at(patches["cubic"], section)
print(f"along v = 0.25 the two patches differ by up to {np.max(np.abs(difference)):.3f}")
course.save(fig, "001_coons_patch")

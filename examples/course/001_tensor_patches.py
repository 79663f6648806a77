"""Seed 001, sections 2.2, 2.2.1: tensor-product Bézier and B-spline surfaces from one control net.

A tensor-product surface sweeps a curve (the generatrix) whose control points themselves move
along curves (the directrices): P(u, v) = sum_i sum_j M_i(u) M_j(v) P_ij over a grid of control
points P_ij. With Bernstein polynomials as M the degrees are fixed by the size of the net (here
6 x 7 points: degrees 5 and 6) and each point pulls on the whole patch; with B-spline basis
functions the degrees are chosen freely (here bicubic) and each point acts only locally. (The
seed writes B_j(u) P_ij B_i(v), i along v; casteljau puts row i along u: the same surface with the
parameters renamed.)

casteljau calls: cj.BezierSurface(net), cj.BSplineSurface(3, 3, knots_u, knots_v, net) on
cj.clamped_uniform_knots, cj.point_at; casteljau.plot.surface_wireframe(..., net=True) draws the
surface and its control net.

In the figure: the same control net (red) under both surfaces. The Bézier patch (left) is a
smoothed-out average of the net; the bicubic B-spline (right) follows the net's hills and valleys
much more closely. Both pass through the four corner points only (clamped knots for the B-spline).
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

rows, columns = 6, 7
i, j = np.meshgrid(np.arange(rows), np.arange(columns), indexing="ij")  # row i runs along u
heights = np.sin(1.3 * i) * np.cos(1.1 * j) + 0.15 * i  # a deterministic, bumpy net
net = np.stack([i, j, heights], axis=-1).astype(float)  # (rows, columns, 3)

bezier = cj.BezierSurface(net)
bspline = cj.BSplineSurface(3, 3, cj.clamped_uniform_knots(3, rows), cj.clamped_uniform_knots(3, columns), net)

fig = plt.figure(figsize=(13, 5.5), constrained_layout=True)
for k, (surface, name) in enumerate([(bezier, f"Bézier, degrees ({bezier.degree_u}, {bezier.degree_v})"),
                                     (bspline, f"B-spline, degrees ({bspline.degree_u}, {bspline.degree_v})")]):
    ax = fig.add_subplot(1, 2, k + 1, projection="3d")
    plot.surface_wireframe(ax, surface, 16, net=True, color="tab:blue", linewidth=0.7,
                           net_kw={"color": "tab:red", "linewidth": 0.8})
    ax.set_title(name)
    ax.view_init(elev=35, azim=-55)
    ax.set_zlim(-1.2, 1.8)
    corners = [(0, 0), (0, 1), (1, 0), (1, 1)]
    corner_gap = max(np.linalg.norm(cj.point_at(surface, u, v) - net[-u, -v]) for u, v in corners)
    print(f"{name}: passes through the corners (gap {corner_gap:.1e})")
course.save(fig, "001_tensor_patches")

"""Seed 003, part III §3 (extension to surfaces): a bicubic Bézier patch from a 4 x 4 control net.

The exercise: let a generating curve move and deform: each of its control points travels along
its own Bézier curve. The result is the tensor-product patch
    M(u, v) = sum_i sum_j B_{n,i}(u) B_{m,j}(v) A_ij,   (u, v) in [0, 1]^2,
here with n = m = 3 and the net A_ij of examples/patch.json (`cj.read_models` gives a BezierSurface).
casteljau: `cj.point_at(surface, u, v)`, `cj.grid_points_at`, `cj.iso_curve` (the generating
curve at a fixed u or v), and `plot.surface_wireframe(..., net=True)` to draw it.

In the figure: the iso-curves of the patch (blue), its control net (red, dashed); the patch
passes through the four corner points of the net only, and its four edges are the Bézier curves
of the net's border rows and columns (checked below), like the edges of the control polyhedron.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

surface = cj.read_models(course.EXAMPLES / "patch.json")[0]
net = surface.control_net  # (4, 4, 3): rows along u
print(f"{type(surface).__name__} of degree ({surface.degree_u}, {surface.degree_v}), net {net.shape}")

# The corners are control points; an edge (u = 0) is the Bézier curve of the first row of the net.
for u, v in ((0, 0), (0, 1), (1, 0), (1, 1)):
    assert np.allclose(cj.point_at(surface, u, v), net[-u, -v])
edge = cj.iso_curve(surface, "u", 0.0)
vs = np.linspace(0, 1, 11)
row0 = cj.BezierCurve(net[0])
print("edge u = 0 is the Bézier curve of row 0:", np.allclose(cj.points_at(edge, vs), cj.points_at(row0, vs)))
print("M(0.5, 0.5) =", cj.point_at(surface, 0.5, 0.5), " normal there:", cj.normal_at(surface, 0.5, 0.5))

fig = plt.figure(figsize=(8, 6.5))
ax = fig.add_subplot(projection="3d")
plot.surface_wireframe(ax, surface, count=12, net=True, color="tab:blue", linewidth=0.8)
plot.curve(ax, edge, color="k", linewidth=2.5, label="edge u = 0 (row 0 of the net)")
for i, j in ((0, 0), (0, 3), (3, 0), (3, 3)):  # name the corners, to find one's way in 3D
    ax.text(*net[i, j], f"  A{i}{j}", color="tab:red")
ax.set_xlabel("x")
ax.set_ylabel("y")
ax.set_zlabel("z")
ax.view_init(elev=30, azim=-125)
ax.legend(loc="upper left")
ax.set_title("bicubic Bézier patch and its 4 x 4 control net")
course.save(fig, "003_bezier_patch")

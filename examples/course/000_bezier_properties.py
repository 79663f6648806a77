"""Seed 000, section 1 (properties of Bézier curves): show them, and check them in numbers, on one
example, the degree-4 polygon notebook_polygon.csv.
  (a) the curve starts at c_0, ends at c_n, and leaves/arrives along the first/last legs:
      gamma'(0) = n (c_1 - c_0), gamma'(1) = n (c_n - c_{n-1})   (`cj.derivative_at`, `plot.tangents`);
  (b) it stays inside the convex hull of its control points;
  (c) affine invariance: mapping the control points (`cj.transformed`) gives the mapped curve
      (`cj.AffineMap`, `cj.transformed_point` point by point);
  (d) global control: moving one control point moves every point with 0 < t < 1, by B_{n,k}(t) times the move.
Look at: the blue end tangents on the legs; the curve inside the grey hull; the red curve through
the black dots; in (d) the two curves differ everywhere except at the two ends.
"""

import numpy as np
from scipy.spatial import ConvexHull

import course
from course import cj, plt
from casteljau import plot

points = course.read_points("notebook_polygon.csv")
curve = cj.BezierCurve(points)
n, ts = curve.degree, np.linspace(0, 1, 201)
samples = cj.points_at(curve, ts)
fig, axes = plt.subplots(2, 2, figsize=(10, 8))
(a, b), (c, d) = axes

# (a) end points and end tangents
print("gamma(0), gamma(1):", cj.point_at(curve, 0), cj.point_at(curve, 1))
print("gamma'(0) =", cj.derivative_at(curve, 0), " n(c1 - c0) =", n * (points[1] - points[0]))
print("gamma'(1) =", cj.derivative_at(curve, 1), " n(cn - cn-1) =", n * (points[-1] - points[-2]))
plot.curve(a, curve, polygon=True, color="k")
plot.tangents(a, curve, linewidth=3)
a.set_title("(a) through c_0 and c_n, tangent to the end legs")

# (b) convex hull: every sample satisfies every half-plane inequality of the hull
hull = ConvexHull(points)
inside = np.all(samples @ hull.equations[:, :2].T + hull.equations[:, 2] <= 1e-12)
print("all samples inside the convex hull:", inside)
b.fill(*points[hull.vertices].T, color="0.85", label="convex hull")
plot.curve(b, curve, polygon=True, color="k")
b.set_title("(b) inside the convex hull of the control points")

# (c) affine invariance: rotate by 120 degrees, then shear and translate
affine = cj.AffineMap([[1.0, 0.5], [0.0, 1.0]], [7.0, 1.0]).after(cj.AffineMap.rotate_2d(np.radians(120)))
image = cj.transformed(curve, affine)
mapped = np.array([cj.transformed_point(affine, p) for p in samples[::10]])
print("max |image curve - mapped points| =", np.abs(cj.points_at(image, ts[::10]) - mapped).max())
plot.curve(c, curve, polygon=True, color="k")
plot.curve(c, image, polygon=True, color="tab:red", polygon_kw={"color": "tab:orange"})
c.plot(*mapped.T, "ko", markerfacecolor="none", markersize=6)
c.set_title("(c) map the control points = map the curve")

# (d) global control: move c_2 up; the difference is B_{n,2}(t) * move, nonzero on (0, 1)
K, MOVE = 2, np.array([0.0, 1.5])
moved = cj.BezierCurve(points + np.outer(np.arange(n + 1) == K, MOVE))
shift = np.linalg.norm(cj.points_at(moved, ts) - samples, axis=1)
print("displacement at t = 0.1, 0.5, 0.9:", shift[[20, 100, 180]],
      f"= B_{{{n},{K}}}(t) |move|:", cj.bernstein(n, K, [0.1, 0.5, 0.9]) * np.linalg.norm(MOVE))
plot.curve(d, curve, polygon=True, color="k")
plot.curve(d, moved, polygon=True, color="tab:green", polygon_kw={"color": "tab:green"})
d.set_title(f"(d) moving c_{K} moves the whole curve")
for ax in axes.flat:
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
course.save(fig, "000_bezier_properties")

"""Seed 000, section 1 (de Casteljau's algorithm, theorem 1): draw a Bézier curve from its control points.

The exercise: from the control points c_0..c_n, compute the curve point by
point with de Casteljau's repeated linear interpolation, and draw it.
casteljau does it with `cj.point_at` / `cj.points_at` (de Casteljau inside);
`cj.casteljau_construction` returns every level of the triangle at one t,
and `plot.de_casteljau` draws them. We check the known value B(0.5) = (2.25, 1.5)
of the degree-4 polygon notebook_polygon.csv, and compare with the direct
Bernstein sum `cj.point_at_bernstein_sum` (definition 1 of the seed).

In the figure: left, the curve and its control polygon; right, the
construction at t = 0.5: each dashed polygon has one point fewer than the one
before, and the last level is the single red point B(0.5), on the curve.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

T = 0.5  # the parameter of the construction (try 0.3)

points = course.read_points("notebook_polygon.csv")
curve = cj.BezierCurve(points)  # degree n = 4

# de Casteljau: level r holds the n + 1 - r points c_j^(r); the last level is gamma(t).
levels = cj.casteljau_construction(curve, T)
for r, level in enumerate(levels):
    print(f"level {r}: {np.round(level, 4).tolist()}")

point = cj.point_at(curve, T)
print(f"B({T}) by de Casteljau  = {point}")
print(f"B({T}) by Bernstein sum = {cj.point_at_bernstein_sum(curve, T)}")
assert np.allclose(cj.point_at(curve, 0.5), (2.25, 1.5)), "the seed's known value"

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True)
plot.curve(left, curve, polygon=True, color="k")
left.set_title(f"Bézier curve of degree {curve.degree} and its control polygon")
plot.de_casteljau(right, curve, T)
right.annotate(f"B({T}) = ({point[0]:.2f}, {point[1]:.2f})", point, xytext=(-45, -35), textcoords="offset points")
right.set_title(f"de Casteljau's construction at t = {T}")
for ax in (left, right):
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
course.save(fig, "000_de_casteljau")

"""Seed 003, part II §1 (Bézier's "pantin vectoriel", the vector form) and §2 (the control-point form).

The exercise: Bézier first wrote a curve as a chain of vectors laid head to tail,
    P(u) = sum_i f_i(u) V_i,   V_0 = P_0 (from the origin O), V_i = P_i - P_{i-1},
with f_0 = 1 and f_i = sum_{k >= i} B_{n,k}; the same curve is the usual sum_k B_{n,k}(u) P_k.
casteljau: `cj.to_vector_form` / `cj.from_vector_form` convert between the two,
`cj.point_at_vector_form` evaluates the vector form, `cj.bezier_basis_polynomial` gives f_i.
Example: a skew cubic (POLYGON below), so that the vectors point in different directions.

Left: the reference chain (black: V_0 from O, then V_1, V_2, V_3) and, for a few u, the chain of
the scaled vectors f_i(u) V_i: each one ends on the curve, at P(u). Right: the four f_i for n = 3,
f_1 = 3u - 3u^2 + u^3, f_2 = 3u^2 - 2u^3, f_3 = u^3 (the seed's formulas, checked below).
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

POLYGON = [(1.0, 1.0), (2.0, 4.0), (6.0, 5.0), (7.0, 2.0)]  # P_0..P_3 (try semicircle.csv's A, B, C, D)
points = np.array(POLYGON)
curve = cj.BezierCurve(points)
vectors = cj.to_vector_form(points)  # row 0 = V_0 = P_0, row i = P_i - P_{i-1}
n, us = curve.degree, np.linspace(0, 1, 201)
print("V_i =", vectors.tolist(), " back to P_i:", np.array_equal(cj.from_vector_form(vectors), points))

# The two forms give the same points.
gap = max(np.linalg.norm(cj.point_at_vector_form(vectors, u) - cj.point_at(curve, u)) for u in us)
print(f"max |vector form - control-point form| over {us.size} parameters = {gap:.2e}")
f = np.array([cj.bezier_basis_polynomial(n, i, us) for i in range(n + 1)])  # (n + 1, 201)
seed = np.array([np.ones_like(us), 3 * us - 3 * us**2 + us**3, 3 * us**2 - 2 * us**3, us**3])
print(f"max |f_i - seed's formulas| = {np.abs(f - seed).max():.2e}")


def chain(ax, scaled, **style):
    """The vectors of `scaled` (rows) head to tail from the origin, as arrows."""
    tails = np.vstack([np.zeros(2), np.cumsum(scaled, axis=0)[:-1]])
    ax.quiver(*tails.T, *scaled.T, angles="xy", scale_units="xy", scale=1, width=0.006, **style)


fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8), gridspec_kw={"width_ratios": [1.4, 1]})
plot.curve(left, curve, color="k", linewidth=2)
chain(left, vectors, color="k")
for u, color in zip((0.25, 0.5, 0.75), ("tab:blue", "tab:orange", "tab:green")):
    scaled = np.array([cj.bezier_basis_polynomial(n, i, u) for i in range(n + 1)])[:, None] * vectors
    chain(left, scaled, color=color, alpha=0.8)
    left.plot(*cj.point_at_vector_form(vectors, u), "o", color=color, label=f"P({u}) = sum f_i({u}) V_i")
left.plot(0, 0, "ks")
left.annotate("O", (0, 0), xytext=(6, -4), textcoords="offset points")
left.set_title("vector chains f_i(u) V_i, head to tail from O")
left.set_aspect("equal")
left.legend(loc="lower right")
for i in range(n + 1):
    right.plot(us, f[i], label=f"$f_{i}$")
right.set_title(rf"Bézier's basis $f_i(u) = \sum_{{k \geq i}} B_{{{n},k}}(u)$")
right.set_xlabel("u")
right.legend()
for ax in (left, right):
    ax.grid(True, alpha=0.3)
course.save(fig, "003_vector_form")

"""Seed 001, section 1.1, problem P2: natural splines of order q through the same points.

Among all functions through (x_i, y_i), take the one whose q-th derivative has the smallest
integral of its square. Between two nodes it is a polynomial of degree 2q - 1, and at the nodes its
derivatives up to order 2q - 2 are continuous (the seed's theorem (iii) says 2q - 1: that is a
misprint; the (2q - 1)-th derivative jumps at each x_i, as the seed's own remark says). The seed's
side conditions read sum_i d_i x_i^k = 0 for k = 0 .. q - 1 (the "= 0" is missing there).
q = 1 gives the broken line, q = 2 the natural cubic spline, q = 3 the natural quintic.

casteljau call: cj.interpolate_natural(points, parameters, order=q), a B-spline of degree 2q - 1
(solved in a stable basis, not the seed's truncated powers); cj.derivatives_at for s' and s'';
cj.continuity_at_knots for the continuity measured at each node.

In the figure: top, the three splines through 11 of the Runge points (all pass through the dots,
none oscillates like the polynomial of 001_runge); middle, s' (q = 1 jumps at every node); bottom,
s'' (q = 1 has none, q = 2 is a broken line, q = 3 is smooth).
"""

import numpy as np

import course
from course import cj, plt

points = course.read_points("runge.csv")[::2]  # 11 points: x = -1, -0.8, ..., 1
x = cj.function_parameters(points)  # the parameter of each point is its x: s is a graph y = s(x)
xs = np.linspace(x[0], x[-1], 1001)

fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
for q, colour in [(1, "tab:green"), (2, "tab:blue"), (3, "tab:red")]:
    s = cj.interpolate_natural(points, x, q)
    label = f"q = {q} (degree {s.degree})"
    axes[0].plot(xs, cj.points_at(s, xs)[:, 1], color=colour, label=label)
    # Column 1 of the derivative curve is d^k y / dx^k, since the parameter is x.
    for order in (1, 2):
        if order <= s.degree:
            axes[order].plot(xs, cj.derivatives_at(s, xs, order)[:, 1], color=colour, label=label)
    residual = np.max(np.abs(cj.points_at(s, x) - points))
    smoothness = min(node.measured.parametric for node in cj.continuity_at_knots(s))
    print(f"q = {q}: max |s(x_i) - y_i| = {residual:.1e}, "
          f"C^{smoothness} at every node (theory: 2q - 2 = {2 * q - 2})")

axes[0].plot(points[:, 0], points[:, 1], "ko", ms=5, label="data")
for ax, name in zip(axes, ["s(x)", "s'(x)", "s''(x)"]):
    ax.set_ylabel(name)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
axes[0].set_title("natural splines of order q through the same 11 points")
axes[2].set_xlabel("x")
course.save(fig, "001_natural_splines")

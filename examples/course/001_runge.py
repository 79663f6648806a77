"""Seed 001, section 1.1, problem P1: one polynomial through all the points, and why it wiggles.

Given n + 1 points (x_i, y_i) with distinct x_i there is exactly one polynomial of degree <= n
that passes through all of them. The seed warns that this polynomial can oscillate badly; the
classic demonstration is Runge's function y = 1 / (1 + 25 x^2) on [-1, 1].

casteljau call: cj.interpolate_lagrange(points, parameters) builds that polynomial (in the stable
barycentric form) and cj.points_at evaluates it; cj.chebyshev_parameters(count, (a, b)) gives
Chebyshev nodes, which crowd towards the ends of the interval.

In the figure: on the left, uniform nodes (taken from examples/runge.csv) for n = 5, 10, 20: the
curves swing further and further away from the function near x = +-1 as n grows (the n = 20
curve leaves the frame). On the right, Chebyshev nodes for the same n: the error shrinks as n
grows. The legend gives the largest error max |p(x) - y(x)| on [-1, 1].
"""

import numpy as np

import course
from course import cj, plt


def runge(x):
    return 1.0 / (1.0 + 25.0 * x * x)


data = course.read_points("runge.csv")  # 21 uniform nodes x = -1, -0.9, ..., 1 (n = 20)
xs = np.linspace(-1.0, 1.0, 801)  # where we look at the polynomials

fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
for ax, title in zip(axes, ["uniform nodes", "Chebyshev nodes"]):
    ax.plot(xs, runge(xs), "k", lw=2.5, label="1 / (1 + 25 x²)")
    ax.set_title(f"polynomial interpolation, {title}")
    ax.set_xlabel("x")

for n, colour in [(5, "tab:blue"), (10, "tab:orange"), (20, "tab:red")]:
    uniform = data[:: 20 // n]  # every (20/n)-th point of runge.csv: n + 1 uniform nodes
    x_cheb = cj.chebyshev_parameters(n + 1, (-1.0, 1.0))
    chebyshev = np.column_stack([x_cheb, runge(x_cheb)])
    for ax, points in zip(axes, [uniform, chebyshev]):
        # The points are (x, y) and the parameter is x itself, so the interpolant is the
        # graph curve x -> (x, p(x)): column 1 of points_at is p(x).
        p = cj.interpolate_lagrange(points, points[:, 0])
        values = cj.points_at(p, xs)[:, 1]
        error = np.max(np.abs(values - runge(xs)))
        ax.plot(xs, values, color=colour, label=f"n = {p.degree}, max error {error:.3g}")
        ax.plot(points[:, 0], points[:, 1], "o", color=colour, ms=4)

for ax in axes:
    ax.set_ylim(-0.6, 1.6)
    ax.legend(loc="upper center", fontsize=8)
    ax.grid(alpha=0.3)
course.save(fig, "001_runge")

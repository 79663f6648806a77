"""Seed 001, section 1.2.4: rational curves (NURBS): weights, and exact circles.

Each control point P_i gets a weight beta_i > 0; the curve is computed in homogeneous coordinates
(beta_i P_i, beta_i) and projected back by dividing by the last coordinate. The seed prints
sigma(u) = (1 / sum beta_i) sum beta_i P_i M_i(u); the correct formula divides by a function of u:
sigma(u) = sum beta_i P_i M_i(u) / sum beta_i M_i(u). A larger weight pulls the curve toward its
point, a smaller one pushes it away; and well-chosen weights give conics exactly, which no
polynomial curve can do.

casteljau calls: cj.BSplineCurve(degree, knots, points, weights), cj.clamped_uniform_knots,
cj.basis_function (to check the corrected formula), cj.make_circle (the exact circle: nine
control points, weights 1, sqrt(1/2), 1, ...), cj.interpolate_cubic (a polynomial approximation).

In the figure: left, a quadratic B-spline whose middle weight is 0.25, 1 or 4: the curve moves
toward P_2 as the weight grows. Middle, the unit circle by make_circle, the same nine control points
with every weight 1 (a polynomial: clearly not a circle) and a periodic cubic spline through 8
points of the circle (looks right). Right, their radial error |C(u)| - 1 on a log scale: about
1e-16 for the NURBS (rounding only), 1e-3 for the cubic spline.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

points = np.array([[0, 0], [1, 1], [2.5, 3], [4, 1], [5, 0]], float)
knots = cj.clamped_uniform_knots(2, len(points))
us = np.linspace(0.0, 1.0, 401)
fig, axes = plt.subplots(1, 3, figsize=(16, 4.8), constrained_layout=True)
for weight, colour in [(0.25, "tab:blue"), (1.0, "tab:green"), (4.0, "tab:red")]:
    weights = np.array([1, 1, weight, 1, 1], float)
    curve = cj.BSplineCurve(2, knots, points, weights)
    plot.curve(axes[0], curve, color=colour, linewidth=2, label=f"beta_2 = {weight:g}")
    # The corrected formula: the weighted sum divided by sum_i beta_i N_i(u), which varies with u.
    basis = np.array([cj.basis_function(knots, 2, i, us) for i in range(len(points))])  # (5, k)
    sigma = (weights[:, None] * basis).T @ points / (weights @ basis)[:, None]
    assert np.allclose(sigma, cj.points_at(curve, us))
plot.control_polygon(axes[0], points, color="grey")
axes[0].annotate("P_2", points[2], textcoords="offset points", xytext=(5, 5))
axes[0].set_title("one weight varied")
axes[0].legend(fontsize=8, loc="lower center")

circle = cj.make_circle((0.0, 0.0), 1.0)
polynomial = cj.BSplineCurve(circle.degree, circle.knots, circle.control_points)  # weights dropped
angles = np.linspace(0.0, 2 * np.pi, 9)
spline = cj.interpolate_cubic(np.column_stack([np.cos(angles), np.sin(angles)])[:-1],
                              angles / (2 * np.pi), "periodic")  # 8 points + the closing parameter
for curve, colour, name in [(circle, "k", "NURBS make_circle"),
                            (polynomial, "tab:orange", "same points, weights 1"),
                            (spline, "tab:purple", "periodic cubic spline, 8 points")]:
    plot.curve(axes[1], curve, color=colour, linewidth=4 if colour == "k" else 1.5, label=name)
    radius = np.linalg.norm(cj.points_at(curve, us), axis=1)
    axes[2].semilogy(us, np.abs(radius - 1.0) + 1e-17, color=colour, label=name)
    print(f"{name}: max radial error {np.max(np.abs(radius - 1.0)):.1e}")
plot.control_polygon(axes[1], circle, color="grey")
axes[1].set_title("the unit circle")
axes[2].set_title("radial error | |C(u)| - 1 |")
axes[2].set_xlabel("u")
for ax in axes[:2]:
    ax.set_aspect("equal")
for ax in axes[1:]:
    ax.legend(fontsize=8)
course.save(fig, "001_nurbs_weights")

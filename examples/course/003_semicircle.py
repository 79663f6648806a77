"""Seed 003, part III §2 (use for numerical control): how well does a cubic reproduce a semicircle?

The exercise: a machine driven by Bézier curves must also cut ordinary shapes such as circular
arcs. The seed proposes the cubic with polygon A(-3,0) B(-3,4) C(3,4) D(3,0) (semicircle.csv,
also `cj.seed_semicircle_cubic()`) for the upper half of the circle of radius 3 centred at O,
and says it is good to about 1/100. We measure the radial error |C(t)| - 3: its largest value is
about 0.055 (1.8 % of the radius), five times the claim (docs/seeds.md lists the correction).
A polynomial curve cannot be exactly a circle; a rational one can: the quadratic NURBS of
semicircle.json (`cj.read_models`), the same as `cj.seed_semicircle()` = `cj.make_arc(...)`,
has a radial error at rounding level (about 1e-15).

Left: the cubic (black), its polygon, the NURBS and its polygon (green), the true circle (dotted).
Middle: the cubic's radial error against the polar angle, always >= 0 (the cubic lies outside),
zero at both ends and at the top. Right: the NURBS's radial error, in units of machine epsilon.
"""

import numpy as np

import course
from course import cj, plt
from casteljau import plot

RADIUS = 3.0
cubic = cj.BezierCurve(course.read_points("semicircle.csv"))
assert cubic == cj.seed_semicircle_cubic()
nurbs = cj.read_models(course.EXAMPLES / "semicircle.json")[0]
assert nurbs == cj.seed_semicircle() == cj.make_arc((0, 0), RADIUS, np.pi, -np.pi)

ts = np.linspace(0, 1, 20001)
fig, (shape, error, exact) = plt.subplots(1, 3, figsize=(16, 4.2))
for name, curve, ax in (("cubic Bézier", cubic, error), ("NURBS", nurbs, exact)):
    points = cj.points_at(curve, ts)
    radial = np.hypot(points[:, 0], points[:, 1]) - RADIUS  # distance to the circle, signed
    angle = np.degrees(np.arctan2(points[:, 1], points[:, 0]))
    worst = np.abs(radial).argmax()
    print(f"{name}: largest radial error {abs(radial[worst]):.3g} ({100 * abs(radial[worst]) / RADIUS:.2g} % "
          f"of the radius) at t = {ts[worst]:.4f}, angle {angle[worst]:.1f} degrees")
    if curve is cubic:
        ax.plot(angle, radial, "k")
        ax.axhline(0.01, color="tab:red", linestyle="--", label="the seed's claim, 1/100")
        ax.axhline(radial[worst], color="0.5", linestyle=":", label=f"largest error {radial[worst]:.4f}")
        ax.set_title("cubic: radial error |C(t)| - 3")
        ax.legend()
    else:
        ax.plot(angle[::20], radial[::20] / np.finfo(float).eps, ".", color="tab:green", markersize=3)
        ax.set_ylabel("in units of machine epsilon, 2.2e-16")
        ax.set_title("NURBS: radial error (exact up to rounding)")
    ax.set_xlabel("polar angle (degrees)")
    ax.invert_xaxis()  # left to right as the curves go, from A (180 degrees) to D (0)
theta = np.linspace(0, np.pi, 181)
shape.plot(RADIUS * np.cos(theta), RADIUS * np.sin(theta), "k:", linewidth=2, label="true semicircle")
plot.curve(shape, cubic, polygon=True, color="k", label="cubic")
plot.curve(shape, nurbs, polygon=True, color="tab:green", polygon_kw={"color": "tab:green"}, label="NURBS")
shape.set_aspect("equal")
shape.set_title("semicircle of radius 3: cubic and NURBS")
shape.legend(loc="lower center")
for ax in (shape, error, exact):
    ax.grid(True, alpha=0.3)
course.save(fig, "003_semicircle")

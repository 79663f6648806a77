"""Seed 004, notebook sections 1.2-1.4 (cells [10]-[11], [15]) against section 3.2 (cells [23]-[25]).

The notebook first sums the Bernstein terms (its bezier0), warns in section 1.4
that for a large degree (try cycle(200)) the sum goes wrong, and in section 3
replaces it by de Casteljau's two-point barycentres, which need no binomial.
casteljau: cj.point_at_bernstein_sum(c, t) is that sum (with the notebook's
binomial product); cj.point_at and cj.points_at run de Casteljau.

What to look at: left, at n = 200 both curves coincide; nothing vanishes, the
control points |P_k| = 1/(k+1) just crowd near the origin. Middle: they differ
by about 1e-16. Right: the sum agrees up to n = 1020, then its binomials
overflow (the notebook's running product C(n,i) (n-i)/(i+1) passes 1.8e308 a
little before C(n, n/2) itself does, near n = 1030) and it returns inf/NaN.
"""

import course
from course import cj, np, plt

from casteljau import plot


def cycle(n):
    """The notebook's cycle(n) (cell [15]): P_k = (cos a_k, sin a_k) / (k + 1), a_k = -pi/2 + 2 k pi / n."""
    k = np.arange(n + 1)
    angle = -np.pi / 2 + 2 * np.pi * k / n
    return np.column_stack([np.cos(angle), np.sin(angle)]) / (k + 1)[:, None]


assert np.allclose(cycle(20), course.read_points("spiral_20.csv"))  # the same points as the CSV file
polygon = cj.BezierCurve(course.read_points("notebook_polygon.csv"))
print("B(0.5): sum", cj.point_at_bernstein_sum(polygon, 0.5), "de Casteljau", cj.point_at(polygon, 0.5))

curve = cj.BezierCurve(cycle(200))
ts = np.linspace(0.0, 1.0, 501)
exact = cj.points_at(curve, ts)
naive = np.array([cj.point_at_bernstein_sum(curve, t) for t in ts])  # one call per t, like the notebook
gap = np.linalg.norm(naive - exact, axis=1)
print(f"n = 200: largest |sum - de Casteljau| = {gap.max():.1e}")

degrees = np.r_[100:1000:25, 1000:1061, 1100:1301:50]  # every n near the breakdown
gaps = np.array([np.linalg.norm(cj.point_at_bernstein_sum(c, 0.5) - cj.point_at(c, 0.5))
                 for c in (cj.BezierCurve(cycle(int(n))) for n in degrees)])
ok = np.isfinite(gaps)  # False where the sum gave inf or NaN
first = degrees[~ok][0]
print("the sum first fails at n =", first)

fig, (left, middle, right) = plt.subplots(1, 3, figsize=(16, 5))
plot.control_polygon(curve, ax=left, color="0.7", marker="none")
plot.curve(curve, ax=left, color="k", linewidth=3, label="de Casteljau")
left.plot(naive[:, 0], naive[:, 1], "y--", label="Bernstein sum")
left.legend()
left.set_title("cycle(200): both evaluators")
middle.semilogy(ts, np.maximum(gap, 1e-18), "k")
middle.set_title("|sum - de Casteljau| along t, n = 200")
right.semilogy(degrees[ok], np.maximum(gaps[ok], 1e-18), "k.-", label="finite")
right.semilogy(degrees[~ok], np.ones((~ok).sum()), "rx", label="inf or NaN")
right.axvline(first, color="r", linestyle=":", label=f"first failure: n = {first}")
right.set_title("|sum - de Casteljau| at t = 1/2, against n")
right.legend()
for ax in (left, middle, right):
    ax.grid(True)
course.save(fig, "004_naive_vs_casteljau")

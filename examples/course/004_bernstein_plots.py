"""Seed 004, notebook section 1.1, cells [6]-[9]: the Bernstein basis of degree 20.

The notebook defines B_{n,k}(t) = C(n,k) t^k (1-t)^(n-k), proves that the
n + 1 polynomials of degree n add up to 1 and form a basis of the polynomials
of degree <= n, then plots the 21 of degree 20 (cell [8]) and the same plot
without the two end ones, B_0 and B_20 (cell [9]).

casteljau: plot.bernstein_basis(n, ks) draws B_{n,k} for k in ks; the values
come from cj.bernstein_all(n, ts), one row per t, one column per k.

What to look at: on the left, B_0 and B_20 start at 1 at their end and fall
fast; the dashed red line is the sum of all 21 curves, flat at 1 (partition of
unity). On the right, without the ends, the interior B_k are bumps of height
well below 1, B_k peaking at t = k/20: they are small, and they overlap.
"""

import course
from course import cj, np, plt

from casteljau import plot

N = 20
ts = np.linspace(0.0, 1.0, 501)
values = cj.bernstein_all(N, ts)  # shape (501, 21): values[i, k] = B_{20,k}(ts[i])
total = values.sum(axis=1)
print(f"max |sum_k B_20,k(t) - 1| over [0, 1]: {np.max(np.abs(total - 1)):.1e}")
print(f"interior peaks: B_1(1/20) = {cj.bernstein(N, 1, 1 / N):.3f} (the tallest),",
      f"B_10(1/2) = {cj.bernstein(N, 10, 0.5):.3f}")

fig, (left, right) = plt.subplots(1, 2, figsize=(14, 6), sharey=True)
plot.bernstein_basis(N, ax=left)  # cell [8]: every k = 0..20
left.plot(ts, total, "r--", linewidth=2, label="sum of the 21 polynomials")
left.set_title("B_20,k for k = 0..20 (cell [8])")
left.legend(loc="center")

plot.bernstein_basis(N, range(1, N), ax=right)  # cell [9]: k = 1..19, the ends left out
right.set_title("without B_20,0 and B_20,20 (cell [9])")

for ax in (left, right):
    ax.set_xlabel("t")
    ax.grid(True)
course.save(fig, "004_bernstein_20")

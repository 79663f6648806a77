"""Seed 001, sections 1.2.2.1 and 1.2.2.2: Bézier's polynomials f_i and the Bernstein basis.

Bézier first wrote his curves as P(u) = sum_i f_i(u) a_i with vectors a_0 = P_0, a_i = P_i - P_{i-1}
and f_i(u) = sum_{k >= i} B_{n,k}(u); summing by parts gives the Bernstein (control point) form
P(u) = sum_i B_{n,i}(u) P_i, because f_i - f_{i+1} = B_{n,i}. Two printed formulas are wrong:
for n = 3, f_1 = u^3 - 3u^2 + 3u (= 1 - (1 - u)^3), not u^3 - 3u^2 + u; for n = 4,
B_3 = 4u^3(1 - u) = -4u^4 + 4u^3, not -3u^4 + 4u^3 (that one is f_3). The coefficient rule is
also off by a sign: the u^k coefficient of f_i is (-1)^(k-i) C(k-1, i-1) C(n, k), not (-1)^(k-1).

casteljau calls: cj.bernstein(n, k, u), cj.bezier_basis_polynomial(n, i, u) and casteljau.plot's
bernstein_basis; the script checks the seed's polynomials (corrected) against them.

In the figure: left, the four Bernstein polynomials of degree 3 (they add up to 1); middle, Bézier's
f_0 = 1 > f_1 > f_2 > f_3 on (0, 1), each rising from 0 to 1 except f_0; right, the Bernstein basis
of degree 4. The dotted curves are the misprinted f_1 and B_3: clearly not members of the family.
"""

from math import comb

import numpy as np

import course
from course import cj, plt
from casteljau import plot

u = np.linspace(0.0, 1.0, 201)
n = 3
# The seed's n = 3 polynomials, with f_1 corrected.
seed_f = [np.ones_like(u), u**3 - 3 * u**2 + 3 * u, -2 * u**3 + 3 * u**2, u**3]
library_f = [cj.bezier_basis_polynomial(n, i, u) for i in range(n + 1)]
for i in range(n + 1):
    assert np.allclose(seed_f[i], library_f[i]), f"f_{i}"
    # The coefficient rule (sign corrected): f_i = sum_{k>=i} (-1)^(k-i) C(k-1, i-1) C(n, k) u^k.
    if i > 0:
        rule = sum((-1) ** (k - i) * comb(k - 1, i - 1) * comb(n, k) * u**k for k in range(i, n + 1))
        assert np.allclose(library_f[i], rule), f"coefficient rule for f_{i}"
    next_f = library_f[i + 1] if i < n else 0.0
    assert np.allclose(library_f[i] - next_f, cj.bernstein(n, i, u)), f"f_{i} - f_{i+1} = B_{i}"
# The corrected B_3 of degree 4, and the printed one for comparison.
print("n = 4: max |B_3 - 4u^3(1-u)|   =", np.max(np.abs(cj.bernstein(4, 3, u) - 4 * u**3 * (1 - u))))
print("n = 4: max |B_3 - (-3u^4+4u^3)| =", np.max(np.abs(cj.bernstein(4, 3, u) - (-3 * u**4 + 4 * u**3))),
      "(the misprint)")
print("n = 3: f_0..f_3 and f_i - f_(i+1) = B_i agree with the library")

fig, (left, middle, right) = plt.subplots(1, 3, figsize=(15, 4.2), sharey=True)
for k in range(n + 1):
    plot.bernstein_basis(left, n, [k], color=f"C{k}", linewidth=2, label=f"B_{k}")
    middle.plot(u, library_f[k], color=f"C{k}", lw=2, label=f"f_{k}")
left.plot(u, sum(cj.bernstein(n, k, u) for k in range(n + 1)), "k--", lw=1, label="sum = 1")
middle.plot(u, seed_f[1] - 2 * u, ":", color="C1", label="printed f_1 = u³−3u²+u")
for k in range(5):
    plot.bernstein_basis(right, 4, [k], color=f"C{k}", linewidth=2, label=f"B_{k}")
right.plot(u, -3 * u**4 + 4 * u**3, ":", color="C3", label="printed B_3 = −3u⁴+4u³")
titles = ["Bernstein basis, n = 3", "Bézier's polynomials f_i, n = 3", "Bernstein basis, n = 4"]
for ax, title in zip((left, middle, right), titles):
    ax.set_title(title)
    ax.set_xlabel("u")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
course.save(fig, "001_bezier_polynomials")

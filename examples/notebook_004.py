"""Seed 004's Python notebook (Bernstein polynomials, Bézier curves, de Casteljau), redone with casteljau.

    PYTHONPATH=build/python /usr/bin/python3 examples/notebook_004.py [OUTDIR]

writes one PNG per figure of the notebook into OUTDIR (default
out/notebook_004). Each figure is a few calls to casteljau.plot; the comment
above it names the notebook cell it redoes. The notebook's points are the
CSV files next to this script (notebook_polygon.csv, spiral_<n>.csv = cycle(n)).
"""

from __future__ import annotations

import math
import os
import pathlib
import sys

import matplotlib

if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
    matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import casteljau as cj  # noqa: E402
from casteljau import plot  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parent


def read_points(name: str) -> np.ndarray:
    """An examples/ CSV point set: '#' comment lines, an 'x,y' header, one point per line."""
    lines = [line for line in (EXAMPLES / name).read_text().splitlines() if line.strip() and not line.startswith("#")]
    return np.array([[float(value) for value in line.split(",")] for line in lines[1:]])


def cycle(n: int) -> np.ndarray:
    """The notebook's cycle(n) (cell [15]): n + 1 points on a spiral, P_k = (cos t_k, sin t_k) / (k + 1)."""
    k = np.arange(n + 1)
    t = -math.pi / 2 + 2 * k * math.pi / n
    return np.column_stack([np.cos(t), np.sin(t)]) / (k + 1)[:, None]


def figure(size):
    fig, ax = plt.subplots(figsize=size)
    ax.grid(True)
    return fig, ax


def save(fig, outdir: pathlib.Path, name: str) -> pathlib.Path:
    path = outdir / f"{name}.png"
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return path


def main(outdir: pathlib.Path) -> list[pathlib.Path]:
    outdir.mkdir(parents=True, exist_ok=True)
    written = []
    polygon = cj.BezierCurve(read_points("notebook_polygon.csv"))  # Ps = [(0, 0), (1, 2), (2, 2), (4, 1), (4, 0)]
    spiral = {n: cj.BezierCurve(read_points(f"spiral_{n}.csv")) for n in (5, 8, 10, 20)}
    print("B(0.5) =", cj.point_at(polygon, 0.5), "(the notebook prints (2.25, 1.5))")

    # Cell [8]: plot_bernstein(20), the 21 Bernstein polynomials of degree 20.
    fig, ax = figure((8, 8))
    plot.bernstein_basis(20, ax=ax)
    written.append(save(fig, outdir, "01_bernstein_20"))

    # Cell [9]: plot_bernstein(20, range(1, 20)), the same without B_0 and B_20.
    fig, ax = figure((8, 8))
    plot.bernstein_basis(20, range(1, 20), ax=ax)
    written.append(save(fig, outdir, "02_bernstein_20_without_ends"))

    # Cell [14]: plot_bezier1(Ps), the curve and its control points.
    fig, ax = figure((10, 5))
    plot.curve(polygon, ax=ax, color="k", polygon=True)
    written.append(save(fig, outdir, "03_bezier_polygon"))

    # Cell [17]: plot_bezier1(cycle(10)), a spiral's control polygon and curve.
    fig, ax = figure((8, 8))
    plot.curve(spiral[10], ax=ax, color="k", polygon=True)
    written.append(save(fig, outdir, "04_bezier_cycle_10"))

    # Section 1.4, first remark ("take n = 200: the curve has vanished"): the notebook's bezier0
    # (the direct Bernstein sum, point_at_bernstein_sum) against de Casteljau for cycle(200). Both
    # agree to rounding at n = 200 (the degree-200 curve is just small); the sum breaks down only
    # when its binomials overflow, near n = 1030 (right panel, at t = 1/2).
    curve200 = cj.BezierCurve(cycle(200))
    ts = np.linspace(0.0, 1.0, 501)
    casteljau_points = cj.points_at(curve200, ts)
    naive_points = np.array([cj.point_at_bernstein_sum(curve200, t) for t in ts])  # the notebook's loop over t
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(15, 5))
    plot.control_polygon(curve200, ax=left, color="0.7", marker="none")
    plot.curve(curve200, ax=left, color="k", linewidth=3, label="de Casteljau")
    left.plot(naive_points[:, 0], naive_points[:, 1], "y--", label="Bernstein sum (bezier0)")
    left.set_title("cycle(200): both evaluators")
    left.legend()
    difference = np.linalg.norm(naive_points - casteljau_points, axis=1)
    middle.semilogy(ts, np.maximum(difference, 1e-18), "k")
    middle.set_title("|bezier0 - de Casteljau|, n = 200")
    degrees = np.arange(100, 1301, 50)
    gaps = []
    for n in degrees:  # one evaluation per degree
        c = cj.BezierCurve(cycle(int(n)))
        gaps.append(np.linalg.norm(cj.point_at_bernstein_sum(c, 0.5) - cj.point_at(c, 0.5)))
    gaps = np.array(gaps)
    finite = np.isfinite(gaps)
    right.semilogy(degrees[finite], np.maximum(gaps[finite], 1e-18), "ko-", label="finite")
    right.semilogy(degrees[~finite], np.full((~finite).sum(), 1.0), "rx", markersize=10, label="inf or NaN")
    right.set_title("|bezier0 - de Casteljau| at t = 1/2 against n")
    right.legend()
    for ax in (left, middle, right):
        ax.grid(True)
    written.append(save(fig, outdir, "05_bernstein_sum_vs_casteljau_n200"))

    # Cell [20]: plot_bezier2(Ps), the end tangents along P0P1 and P(n-1)Pn.
    fig, ax = figure((10, 5))
    plot.curve(polygon, ax=ax, color="k", polygon=True, polygon_kw={"linestyle": "none"})
    plot.tangents(polygon, ax=ax, color="b")
    written.append(save(fig, outdir, "06_tangents_polygon"))

    # Cell [22]: plot_bezier2(cycle(8)).
    fig, ax = figure((8, 8))
    plot.curve(spiral[8], ax=ax, color="k", polygon=True, polygon_kw={"linestyle": "none"})
    plot.tangents(spiral[8], ax=ax, color="b")
    written.append(save(fig, outdir, "07_tangents_cycle_8"))

    # Cell [28]: demo_casteljau(Ps, 0.5), the construction of B(1/2) = (2.25, 1.5).
    fig, ax = figure((10, 5))
    plot.de_casteljau(polygon, 0.5, ax=ax)
    written.append(save(fig, outdir, "08_casteljau_polygon_t05"))

    # Cell [30]: demo_casteljau(cycle(5), 0.6).
    fig, ax = figure((8, 8))
    plot.de_casteljau(spiral[5], 0.6, ax=ax)
    written.append(save(fig, outdir, "09_casteljau_cycle_5_t06"))

    # Cell [35]: plot_bezier(Ps, 9) with the cell's Ps = [(0, 0), (1, 2), (2, 3), (4, 1), (5, 3)]:
    # the 2^9 + 1 points of recursive subdivision, and the control points.
    cell35 = cj.BezierCurve([(0, 0), (1, 2), (2, 3), (4, 1), (5, 3)])
    fig, ax = figure((10, 7))
    plot.subdivision(cell35, 9, ax=ax)
    plot.control_polygon(cell35, ax=ax, color="r", linestyle="none")
    written.append(save(fig, outdir, "10_subdivision_r9"))

    # Cell [37]: plot_bezier(cycle(20), 9).
    fig, ax = figure((8, 8))
    plot.subdivision(spiral[20], 9, ax=ax)
    plot.control_polygon(spiral[20], ax=ax, color="r", linestyle="none")
    written.append(save(fig, outdir, "11_subdivision_cycle_20_r9"))

    # Section 3.3, the proposition before cell [31]: the sides of the de Casteljau triangle are the
    # halves' control polygons; two rounds of subdivision give the 4 pieces' polygons, hugging the curve.
    fig, ax = figure((10, 7))
    plot.curve(cell35, ax=ax, color="k")
    plot.control_polygon(cell35, ax=ax, color="0.6")
    plot.subdivision(cell35, 2, ax=ax, polygons=True, color="none")
    written.append(save(fig, outdir, "12_subdivision_polygons_r2"))
    return written


if __name__ == "__main__":
    target = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path("out/notebook_004")
    for path in main(target):
        print(path)

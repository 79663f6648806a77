"""What the course examples share: the seeds' data, headless plotting, where figures go.

Every example in this folder is run the same way, from the repository root:

    PYTHONPATH=build/python /usr/bin/python3 examples/course/000_head_and_car.py [OUTDIR]

and writes its figure(s) as PNG into OUTDIR (default out/course), printing each path.
docs/course.md says which seed section each example answers.
"""

from __future__ import annotations

import os
import pathlib
import sys

import matplotlib

if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
    matplotlib.use("Agg")  # no screen (CI, ssh): draw into files only

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import casteljau as cj  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent


def read_points(name: str) -> np.ndarray:
    """A point set of examples/ (head.csv, car.csv, semicircle.csv, ...) as an (n, 2) array."""
    return cj.read_points_csv(EXAMPLES / name)


def output_dir() -> pathlib.Path:
    """The folder named on the command line, else out/course; created if missing."""
    folder = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path("out/course")
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def save(fig, name: str) -> pathlib.Path:
    """Writes the figure as OUTDIR/<name>.png, closes it, prints and returns the path."""
    path = output_dir() / f"{name}.png"
    fig.savefig(path, dpi=80, bbox_inches="tight")
    plt.close(fig)
    print(path)
    return path

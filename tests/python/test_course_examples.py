"""The course companion (examples/course/, docs/course.md): every example runs
headless, exits 0, and writes the figures it prints, each a PNG that is not
blank; docs/course.md names every example and every example file is in it.
The run time of each example is printed (pytest -s) for the closing notes."""

from __future__ import annotations

import os
import pathlib
import re
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")

import matplotlib.image  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import casteljau as cj  # noqa: E402

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
COURSE = REPOSITORY / "examples" / "course"
EXAMPLES = sorted(path for path in COURSE.glob("*.py") if path.name != "course.py")


def test_there_is_an_example_for_each_seed():
    seeds = {path.name[:3] for path in EXAMPLES}
    assert seeds == {"000", "001", "003", "004"}


@pytest.mark.parametrize("example", EXAMPLES, ids=[path.stem for path in EXAMPLES])
def test_example_writes_its_figures(example, tmp_path):
    package = pathlib.Path(os.path.abspath(cj.__file__)).parent.parent
    env = {key: value for key, value in os.environ.items() if key not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env["PYTHONPATH"] = str(package)
    started = time.monotonic()
    result = subprocess.run([sys.executable, str(example), str(tmp_path)], capture_output=True, text=True, env=env,
                            timeout=120, cwd=tmp_path)
    seconds = time.monotonic() - started
    assert result.returncode == 0, result.stderr
    printed = [pathlib.Path(line) for line in result.stdout.splitlines() if line.endswith(".png")]
    written = sorted(tmp_path.glob("*.png"))
    assert written, f"{example.name} wrote no figure"
    assert sorted(path.resolve() for path in printed) == [path.resolve() for path in written]
    for path in written:
        image = matplotlib.image.imread(path)
        assert image.shape[0] > 100 and image.shape[1] > 100
        background = image[0, 0]
        assert np.mean(np.any(np.abs(image - background) > 0.1, axis=-1)) > 0.01, f"{path.name} looks blank"
    print(f"{example.name}: {len(written)} figure(s) in {seconds:.2f} s")


def test_the_course_page_names_every_example():
    page = (REPOSITORY / "docs" / "course.md").read_text()
    named = set(re.findall(r"examples/course/(?:cpp/)?([\w.]+\.(?:py|cpp))", page))
    files = {path.name for path in EXAMPLES} | {path.name for path in (COURSE / "cpp").glob("*.cpp")}
    assert files - named == set(), "examples docs/course.md does not name"
    assert named - files == set(), "docs/course.md names examples that do not exist"

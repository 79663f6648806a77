"""`cmake --install` puts a working package into a prefix the user names.

Installs the python component of the build that the tests import (the folder
above build/python) into a temporary prefix, then imports it in a fresh
interpreter run from another folder with only the prefix on PYTHONPATH, and
evaluates a curve there: the extension, the pure-Python files and the stubs
must all be installed."""

import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import casteljau


def test_install_into_a_prefix_gives_an_importable_package(tmp_path):
    cmake = shutil.which("cmake")
    if cmake is None:
        pytest.fail("cmake is not on PATH")
    package = pathlib.Path(casteljau.__file__).parent
    build_dir = package.parents[1]
    assert (build_dir / "CMakeCache.txt").exists(), f"{build_dir} is not a CMake build folder"
    prefix = tmp_path / "prefix"
    subprocess.run([cmake, "--install", str(build_dir), "--component", "python", "--prefix", str(prefix)],
                   check=True, capture_output=True, text=True)
    site = prefix / "lib" / f"python{sys.version_info.major}.{sys.version_info.minor}" / "site-packages"
    installed = site / "casteljau"
    names = {p.name for p in installed.iterdir()}
    assert "__init__.py" in names and "__init__.pyi" in names and "py.typed" in names, names
    assert any(n.startswith("_casteljau.") and n.endswith(".so") for n in names), names
    assert not any(p.is_symlink() for p in installed.iterdir()), "installed files must be copies"

    script = (
        "import casteljau, numpy\n"
        "c = casteljau.BSplineCurve(1, [0, 0, 1, 1], [[0.0, 0.0], [2.0, 4.0]])\n"
        "print(casteljau.__file__)\n"
        "print(casteljau.points_at(c, numpy.array([0.25]))[0].tolist())\n"
    )
    environment = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "CASTELJAU_PYTHONPATH")}
    environment["PYTHONPATH"] = str(site)
    result = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, env=environment,
                            check=True, capture_output=True, text=True)
    where, value = result.stdout.splitlines()
    assert pathlib.Path(where).resolve().is_relative_to(prefix.resolve())
    assert value == "[0.5, 1.0]"

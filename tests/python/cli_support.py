"""What the pytest files share: where the repository is and which casteljau
executable they run (CASTELJAU_CLI, which ctest and `make test` set, else
build/casteljau). pytest puts this folder on sys.path (rootdir-relative
"prepend" import mode), so the tests import it by name."""

import os
import pathlib

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def casteljau_cli():
    path = os.environ.get("CASTELJAU_CLI") or str(REPOSITORY / "build" / "casteljau")
    if not os.access(path, os.X_OK):
        pytest.fail(f"no casteljau executable at {path!r}: set CASTELJAU_CLI")
    return path

"""Makes `import casteljau` find the module under test: the folder in
CASTELJAU_PYTHONPATH (`make test` and ctest set it to build/python), else an
already importable casteljau (PYTHONPATH), else the repository's build/python.
The module tests must test the build of this checkout, never an installed copy
found by accident, so an explicit folder comes first on sys.path."""

import os
import pathlib
import sys

_REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
_folder = os.environ.get("CASTELJAU_PYTHONPATH")
if _folder:
    sys.path.insert(0, _folder)
elif not any((pathlib.Path(p) / "casteljau" / "__init__.py").exists() for p in sys.path if p):
    sys.path.insert(0, str(_REPOSITORY / "build" / "python"))

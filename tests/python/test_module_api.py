"""The module's surface: every public name has a type stub and a docstring.

Reads the stubs (casteljau/__init__.pyi, scipy_like.pyi, plot.pyi) with `ast`
and compares them with what the compiled module and the Python files define,
so a binding added without its stub or its documentation fails here."""

import ast
import inspect
import pathlib
import re

import pytest

import casteljau
import casteljau._casteljau as compiled

PACKAGE = pathlib.Path(casteljau.__file__).parent


def stub_names(path):
    """Top-level names a .pyi defines (functions, classes, assignments, imports)."""
    tree = ast.parse(path.read_text(), str(path))
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
        elif isinstance(node, ast.ImportFrom):
            names.update(alias.asname or alias.name for alias in node.names)
    return names


def stub_members(path):
    """{class name: names of its methods and properties} in a .pyi."""
    tree = ast.parse(path.read_text(), str(path))
    members = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            members[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)} | {
                n.target.id for n in node.body if isinstance(n, ast.AnnAssign) and isinstance(n.target, ast.Name)}
    return members


def public(module):
    return sorted(n for n in dir(module) if not n.startswith("_"))


def overload_texts(doc):
    """The text of each overload of a pybind11 docstring, signatures removed."""
    if "Overloaded function." in doc:
        parts = re.split(r"^\d+\. ", doc.split("Overloaded function.", 1)[1], flags=re.M)[1:]
    else:
        parts = [doc]
    return [part.split("\n", 1)[1].strip() if "\n" in part else "" for part in parts]


def test_every_compiled_name_has_a_stub():
    stubbed = stub_names(PACKAGE / "__init__.pyi")
    missing = [name for name in public(compiled) if name not in stubbed]
    assert not missing, f"names of casteljau._casteljau without a stub in __init__.pyi: {missing}"


def test_every_compiled_function_and_overload_is_documented():
    undocumented = []
    for name in public(compiled):
        item = getattr(compiled, name)
        if inspect.ismodule(item):
            continue
        doc = getattr(item, "__doc__", None) or ""
        if callable(item) and not inspect.isclass(item):
            if not all(len(text) > 20 for text in overload_texts(doc)):
                undocumented.append(name)
        elif inspect.isclass(item) and len(doc.strip()) < 20:
            undocumented.append(name)
    assert not undocumented, f"functions or overloads without a docstring: {undocumented}"


def test_every_class_member_is_documented_and_stubbed():
    members = stub_members(PACKAGE / "__init__.pyi")
    problems = []
    for name in public(compiled):
        cls = getattr(compiled, name)
        if not inspect.isclass(cls) or issubclass(cls, BaseException):
            continue
        for member, value in vars(cls).items():
            if member.startswith("_") or member in ("name", "value"):  # pybind11 enum internals
                continue
            doc = getattr(value, "__doc__", None) or ""
            if len(doc.strip()) < 3:
                problems.append(f"{name}.{member}: no docstring")
            if member not in members.get(name, set()):
                problems.append(f"{name}.{member}: no stub")
    assert not problems, problems


@pytest.mark.parametrize("module_name", ["scipy_like", "plot"])
def test_python_modules_have_stubs_and_docstrings(module_name):
    module = __import__(f"casteljau.{module_name}", fromlist=["*"])
    stubbed = stub_names(PACKAGE / f"{module_name}.pyi")
    own = [n for n in public(module)
           if getattr(getattr(module, n), "__module__", None) == module.__name__]
    assert own, f"casteljau.{module_name} defines nothing public"
    assert not [n for n in own if n not in stubbed], "names without a stub"
    assert not [n for n in own if len((getattr(module, n).__doc__ or "").strip()) < 20], "names without a docstring"


def test_the_scipy_like_names_are_exported_by_the_package():
    for name in ("BSpline", "make_interp_spline", "CubicSpline", "make_lsq_spline", "make_smoothing_spline"):
        assert getattr(casteljau, name).__module__ == "casteljau.scipy_like"

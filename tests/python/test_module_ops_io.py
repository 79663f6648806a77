"""casteljau's ops and io layers in Python (python/src/ops.cpp, python/src/io.cpp).

References: the sphere's equation for the tessellation of make_sphere (its
vertices within the tolerance of |S - c| = r, The NURBS Book §8.5), meshio (Debian
python3-meshio, written by other people) reading back the OBJ, STL and PLY
files written from Python, the seed worked example (control points (0,0),
(1,2), (2,2), (4,1), (4,0) give B(0.5) = (2.25, 1.5)) for flattening, and the
objects themselves for the model JSON and CSV round trips (exact: the
numbers are written in shortest round-trip form).
"""

import json
import os
import pathlib
import pickle

import meshio
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import casteljau as c

SEEDED = settings(derandomize=True, max_examples=20, deadline=None)
SEED_POINTS = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [4.0, 1.0], [4.0, 0.0]])


# --- flattening ---------------------------------------------------------------------------


def distance_to_polyline(points, polyline):
    """The distance from each point to the polyline (segments), vectorized."""
    a, b = polyline[:-1], polyline[1:]
    ab = b - a
    length2 = np.maximum((ab ** 2).sum(axis=1), 1e-300)
    t = np.clip(((points[:, None, :] - a[None]) * ab[None]).sum(axis=2) / length2, 0, 1)
    nearest = a[None] + t[..., None] * ab[None]
    return np.sqrt(((points[:, None, :] - nearest) ** 2).sum(axis=2)).min(axis=1)


def test_flatten_the_seed_curve_within_the_tolerance():
    curve = c.BezierCurve(SEED_POINTS)
    np.testing.assert_array_equal(c.point_at(curve, 0.5), [2.25, 1.5])
    for tolerance in (0.1, 1e-3, 1e-6):
        points, parameters = c.flatten(curve, tolerance)
        assert points.shape == (len(parameters), 2)
        assert parameters[0] == 0 and parameters[-1] == 1 and np.all(np.diff(parameters) > 0)
        np.testing.assert_array_equal(points, c.points_at(curve, parameters))
        dense = c.points_at(curve, np.linspace(0, 1, 4001))
        assert distance_to_polyline(dense, points).max() <= tolerance
        assert c.flatten_segment_count(curve, tolerance) == len(parameters) - 1
    assert c.control_polygon_flatness(curve) >= c.chord_deviation_bound(curve, 0.0, 1.0) - 1e-15
    assert 0 <= c.chord_deviation_bound(curve, 0.25, 0.5) <= c.chord_deviation_bound(curve, 0.0, 1.0)


@SEEDED
@given(st.integers(0, 2**32 - 1))
def test_flatten_any_curve_within_the_tolerance(seed):
    rng = np.random.default_rng(seed)
    n, d = int(rng.integers(1, 7)), int(rng.integers(1, 4))
    weights = rng.uniform(0.5, 2, n + 1) if rng.integers(0, 2) else None
    curve = c.BezierCurve(rng.uniform(-1, 1, (n + 1, d)), weights)
    tolerance = float(10 ** rng.uniform(-4, -1))
    points, parameters = c.flatten(curve, tolerance)
    dense = c.points_at(curve, np.linspace(0, 1, 2001))
    assert distance_to_polyline(dense, points).max() <= tolerance


def test_flatten_errors():
    curve = c.BezierCurve(SEED_POINTS)
    for tolerance in (0.0, -1.0, np.nan, np.inf):
        with pytest.raises(ValueError, match="tolerance"):
            c.flatten(curve, tolerance)
        with pytest.raises(ValueError, match="tolerance"):
            c.flatten_segment_count(curve, tolerance)
    with pytest.raises(ValueError):
        c.flatten(curve, 1e-30)  # below what double precision certifies
    with pytest.raises(ValueError, match="more than 2"):
        c.flatten(curve, 1e-6, max_segments=2)
    for cap in (0, -5, 2**40):
        with pytest.raises(ValueError, match="max_segments"):
            c.flatten(curve, 1e-3, max_segments=cap)
    for t0, t1 in ((0.5, 0.5), (0.7, 0.2), (-0.1, 0.5), (0.5, 1.5), (np.nan, 1.0)):
        with pytest.raises(ValueError):
            c.chord_deviation_bound(curve, t0, t1)
    with pytest.raises(TypeError):
        c.flatten(SEED_POINTS, 1e-3)


# --- tessellation and meshes ------------------------------------------------------------------


@pytest.mark.parametrize("tolerance", [1e-2, 1e-3])
def test_tessellated_sphere_is_watertight_and_within_the_tolerance(tolerance):
    center, radius = np.array([1.0, -2.0, 0.5]), 2.0
    sphere = c.make_sphere(center, radius)
    mesh = c.tessellate(sphere, tolerance)
    topology = c.mesh_topology(mesh)
    assert topology.watertight, topology
    assert (topology.boundary_edges, topology.non_manifold_edges, topology.inconsistently_oriented_edges,
            topology.degenerate_triangles) == (0, 0, 0, 0)
    vertices, normals, triangles = mesh.vertices, mesh.normals, mesh.triangles
    assert vertices.shape[1] == 3 and normals.shape == vertices.shape
    assert triangles.dtype == np.int64 and triangles.shape[1] == 3
    assert triangles.min() >= 0 and triangles.max() < len(vertices)
    # Euler characteristic of a sphere: V - E + F = 2, with E = 3F/2.
    assert len(vertices) - 3 * len(triangles) // 2 + len(triangles) == 2
    assert np.abs(np.linalg.norm(vertices - center, axis=1) - radius).max() <= 1e-13 * radius
    # Every point of a triangle within the tolerance: centroids and edge midpoints.
    corners = vertices[triangles]
    for sample in (corners.mean(axis=1), (corners[:, 0] + corners[:, 1]) / 2):
        assert (radius - np.linalg.norm(sample - center, axis=1)).max() <= tolerance
    np.testing.assert_allclose(normals, (vertices - center) / radius, atol=1e-9)
    # Counter-clockwise seen from outside: face normals point outwards.
    face = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    assert np.all((face * (corners.mean(axis=1) - center)).sum(axis=1) > 0)


def test_tessellate_several_kinds_and_errors():
    patch = c.BezierSurface(np.array([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0.0]]]))
    square = [c.BezierCurve([[0, 0, 1], [0, 1, 1]]), c.BezierCurve([[1, 0, 1], [1, 1, 1.5]]),
              c.BezierCurve([[0, 0, 1], [1, 0, 1]]), c.BezierCurve([[0, 1, 1], [1, 1, 1.5]])]
    coons = c.CoonsPatch(*square)
    torus = c.make_torus([0, 0, 5], [0, 0, 1], 2, 0.5)
    mesh = c.tessellate([patch, coons, torus], 1e-2)
    alone = [c.tessellate(s, 1e-2) for s in (patch, coons, torus)]
    assert len(mesh.vertices) == sum(len(m.vertices) for m in alone)
    assert c.mesh_topology(alone[2]).watertight
    assert c.mesh_topology(alone[0]).boundary_edges > 0
    assert c.tessellate((s for s in [patch]), 1e-2) == alone[0]  # any iterable
    with pytest.raises(ValueError, match="no surface"):
        c.tessellate([], 1e-2)
    with pytest.raises(TypeError, match=r"surfaces\[1\]"):
        c.tessellate([patch, square[0]], 1e-2)
    with pytest.raises(TypeError):
        c.tessellate("sphere", 1e-2)
    with pytest.raises(ValueError, match="R\\^2"):
        c.tessellate(c.BezierSurface(np.zeros((2, 2, 2))), 1e-2)
    for tolerance in (0.0, -1.0, np.nan):
        with pytest.raises(ValueError, match="tolerance"):
            c.tessellate(patch, tolerance)
    with pytest.raises(ValueError):
        c.tessellate(torus, 1e-300)


def tetrahedron():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    normals = vertices - vertices.mean(axis=0)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    triangles = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return c.TriangleMesh(vertices, normals, triangles)


def test_triangle_mesh_class_and_topology():
    mesh = tetrahedron()
    assert repr(mesh) == "TriangleMesh(4 vertices, 4 triangles)"
    assert c.mesh_topology(mesh).watertight
    assert pickle.loads(pickle.dumps(mesh)) == mesh
    assert c.TriangleMesh(mesh.vertices, mesh.normals, mesh.triangles.astype(np.uint16)) == mesh
    flipped = c.TriangleMesh(mesh.vertices, mesh.normals, mesh.triangles[:, ::-1] * [1, 1, 1])
    assert flipped != mesh
    opened = c.TriangleMesh(mesh.vertices, mesh.normals, mesh.triangles[:3])
    topology = c.mesh_topology(opened)
    assert topology.boundary_edges == 3 and not topology.watertight
    mixed = c.TriangleMesh(mesh.vertices, mesh.normals, np.vstack([mesh.triangles[:3], mesh.triangles[3, ::-1]]))
    assert c.mesh_topology(mixed).inconsistently_oriented_edges == 3
    degenerate = c.TriangleMesh(mesh.vertices, mesh.normals, [[0, 0, 1]])
    assert c.mesh_topology(degenerate).degenerate_triangles == 1
    empty = c.TriangleMesh(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros((0, 3), dtype=int))
    assert not c.mesh_topology(empty).watertight  # no triangles: encloses nothing (issue 15)


def test_triangle_mesh_errors():
    mesh = tetrahedron()
    v, n, t = mesh.vertices, mesh.normals, mesh.triangles
    with pytest.raises(ValueError, match=r"triangles\[1, 2\] is 4"):
        c.TriangleMesh(v, n, np.array([[0, 1, 2], [0, 1, 4]]))
    with pytest.raises(ValueError, match="outside"):
        c.TriangleMesh(v, n, np.array([[0, 1, -1]]))
    with pytest.raises(ValueError, match="outside"):
        c.TriangleMesh(v, n, np.array([[0, 1, 2**63 + 5]], dtype=np.uint64))
    with pytest.raises(TypeError, match="integers"):
        c.TriangleMesh(v, n, t.astype(float))
    with pytest.raises(ValueError, match=r"\(m, 3\)"):
        c.TriangleMesh(v, n, t[:, :2])
    with pytest.raises(ValueError, match="one normal per vertex"):
        c.TriangleMesh(v, n[:3], t)
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        c.TriangleMesh(v[:, :2], n, t)
    bad = v.copy()
    bad[2, 1] = np.nan
    with pytest.raises(ValueError, match=r"vertices\[2, 1\] is NaN"):
        c.TriangleMesh(bad, n, t)
    with pytest.raises(TypeError):
        c.TriangleMesh(v.astype(complex), n, t)


# --- mesh files ------------------------------------------------------------------------------


@pytest.mark.parametrize("extension", ["obj", "stl", "ply"])
def test_mesh_files_read_back_with_meshio(tmp_path, extension):
    mesh = c.tessellate(c.make_sphere([0, 0, 0], 1.0), 5e-2)
    path = tmp_path / f"sphere.{extension}"
    getattr(c, f"write_{extension}")(mesh, path)  # os.PathLike
    read = meshio.read(path)
    triangles = read.cells_dict["triangle"]
    assert len(triangles) == len(mesh.triangles)
    if extension == "stl":
        # STL stores each triangle's three corners; meshio merges equal ones.
        assert len(np.unique(read.points, axis=0)) == len(mesh.vertices)
        np.testing.assert_allclose(read.points[triangles], mesh.vertices[mesh.triangles], rtol=0, atol=1e-7)
    else:
        assert len(read.points) == len(mesh.vertices)
        np.testing.assert_array_equal(read.points, mesh.vertices)
        np.testing.assert_array_equal(triangles, mesh.triangles)
    # The same bytes as to_obj / to_stl / to_ply, written by str path too.
    again = tmp_path / f"again.{extension}"
    getattr(c, f"write_{extension}")(mesh, str(again))
    contents = getattr(c, f"to_{extension}")(mesh)
    assert again.read_bytes() == (contents.encode() if isinstance(contents, str) else contents)


def test_mesh_bytes_and_write_errors(tmp_path):
    mesh = tetrahedron()
    assert len(c.to_stl(mesh)) == 84 + 50 * 4
    assert isinstance(c.to_ply(mesh), bytes) and c.to_ply(mesh).startswith(b"ply\n")
    assert c.to_obj(mesh).count("\nf ") + c.to_obj(mesh).startswith("f ") == 4
    missing = tmp_path / "no such folder" / "mesh.obj"
    with pytest.raises(ValueError, match="no such folder"):
        c.write_obj(mesh, missing)
    assert not missing.parent.exists()
    with pytest.raises(TypeError):
        c.write_stl(mesh, 42)


# --- model JSON --------------------------------------------------------------------------------


def every_model_kind():
    rng = np.random.default_rng(2)
    bezier = c.BezierCurve(SEED_POINTS)
    rational = c.BezierCurve(rng.uniform(-1, 1, (4, 3)), rng.uniform(0.5, 2, 4))
    piecewise = c.PiecewiseBezierCurve([bezier, c.BezierCurve([[4.0, 0.0], [5.0, -1.0], [6.0, 0.1]])])
    bspline = c.BSplineCurve(3, [0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1], rng.uniform(-1, 1, (6, 2)))
    nurbs = c.BSplineCurve(2, [0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1.0]], [1, 2 ** -0.5, 1])
    surface = c.BSplineSurface(2, 1, [0, 0, 0, 0.5, 1, 1, 1], [0, 0, 1, 1], rng.uniform(-1, 1, (4, 2, 3)))
    sphere = c.make_sphere([0.1, 0.2, 0.3], 1 / 3)
    patch = c.BezierSurface(rng.uniform(-1, 1, (3, 2, 3)), rng.uniform(0.5, 2, (3, 2)))
    coons = c.CoonsPatch(c.BezierCurve([[0, 0, 0], [0, 1, 0.3]]), c.BezierCurve([[1, 0, 0], [1, 1, 0]]),
                         c.BezierCurve([[0, 0, 0], [0.5, 0.1, 0], [1, 0, 0]]),
                         c.BSplineCurve(1, [0, 0, 1, 1], [[0, 1, 0.3], [1, 1, 0]]), "cubic")
    return [bezier, rational, piecewise, bspline, nurbs, surface, sphere, patch, coons]


def test_model_json_round_trip_through_a_string_and_a_file(tmp_path):
    models = every_model_kind()
    for model in models:
        text = c.to_json(model)
        assert "\n" not in text and json.loads(text)["type"] == c.type_name(model)
        (back,) = c.parse_models_json(text)
        assert type(back) is type(model) and back == model
    text = c.models_to_json(models)
    assert c.parse_models_json(text) == models
    path = tmp_path / "models.json"
    c.write_models_json(models, path)
    assert path.read_text() == text
    assert c.read_models_json(path) == models
    assert c.read_models_json(str(path)) == models
    assert c.read_models(path) == models
    single = tmp_path / "one.json"
    c.write_models_json(models[-1:], os.fspath(single))
    assert c.read_models_json(single) == models[-1:]
    # A CSV point set is the control polygon of one Bézier curve.
    csv = tmp_path / "points.csv"
    c.write_points_csv(SEED_POINTS, csv)
    assert c.read_models(csv) == [c.BezierCurve(SEED_POINTS)]


def test_read_models_reads_svg_drawings(tmp_path):
    # One piecewise curve per subpath, the group's transform applied, turned
    # upright (y up from the page's bottom, here y = 0: the file's y negated):
    # the square's corners worked by hand.
    drawing = tmp_path / "d.svg"
    drawing.write_text('<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(1 2)">'
                       '<path d="M0 0 h4 v4 h-4 z M10 10 L11 11"/></g><circle r="1"/></svg>')
    models = c.read_models(drawing)
    assert len(models) == 3 and all(type(m) is c.PiecewiseBezierCurve for m in models)
    np.testing.assert_array_equal(c.points_at(models[0], np.array([0.0, 1.0, 2.0, 3.0, 4.0])),
                                  [[1, -2], [5, -2], [5, -6], [1, -6], [1, -2]])
    # read_file_models: the same models with where they came from (casteljau info).
    file = c.read_file_models(drawing)
    assert file["format"] == "SVG drawing" and file["page_bottom"] == 0.0 and file["skipped"] == []
    assert [o["element"] for o in file["origins"]] == ["path", "path", "circle"]
    assert file["insunits"] == 0 and file["unit"] == "" and file["millimetres_per_unit"] is None
    assert [c.to_json(m) for m in file["models"]] == [c.to_json(m) for m in models]
    dxf = tmp_path / "d.dxf"
    dxf.write_text("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n1\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
                   "0\nLINE\n5\n2A\n8\nwalls\n10\n0\n20\n0\n11\n3\n21\n4\n0\nTEXT\n8\n0\n1\nhi\n0\nENDSEC\n0\nEOF\n")
    file = c.read_file_models(dxf)
    assert file["unit"] == "inches" and file["millimetres_per_unit"] == 25.4 and file["insunits"] == 1
    assert file["origins"] == [{"element": "LINE", "id": "2A", "layer": "walls", "line": 15}]
    assert file["skipped"] == ["line 29: TEXT"]
    assert c.read_file_models(dxf, "mm")["insunits"] == 4
    with pytest.raises(ValueError, match="units 'cm' is not user or mm"):
        c.read_file_models(dxf, "cm")
    broken = tmp_path / "broken.svg"
    broken.write_text('<svg>\n<path id="p" d="M0 0 L1 x"/></svg>')
    with pytest.raises(ValueError, match=r"broken.svg, line 2, <path id='p'>: path data, character 9 \('x'\)"):
        c.read_models(broken)


def test_model_helpers():
    bezier, _, piecewise, bspline, _, surface, sphere, patch, coons = every_model_kind()
    assert [c.is_surface(m) for m in (bezier, piecewise, surface, coons)] == [False, False, True, True]
    assert c.dimension_of(bezier) == 2 and c.dimension_of(sphere) == 3
    assert c.control_point_count(piecewise) == 8 and c.control_point_count(sphere) == 45
    assert c.domain_of(piecewise) == (0.0, 2.0) and c.domain_of(bspline) == (0.0, 1.0)
    with pytest.raises(ValueError, match="surface"):
        c.domain_of(surface)
    converted = c.to_bspline(bezier)
    assert isinstance(converted, c.BSplineCurve)
    np.testing.assert_allclose(c.point_at(converted, 0.5), [2.25, 1.5], rtol=0, atol=1e-15)
    assert isinstance(c.to_bspline(patch), c.BSplineSurface)
    assert isinstance(c.to_bspline(coons), c.BSplineSurface)
    with pytest.raises(TypeError, match="model"):
        c.to_json(SEED_POINTS)
    with pytest.raises(TypeError, match=r"models\[1\]"):
        c.models_to_json([bezier, "bezier"])
    with pytest.raises(ValueError, match="at least one model"):
        c.models_to_json([])
    with pytest.raises(TypeError):
        c.models_to_json(bezier)


def test_malformed_json_names_where():
    with pytest.raises(ValueError, match=r"m\.json, line 2, column \d+"):
        c.parse_models_json('{"type": "bezier",\n "control_points": [[0, 0], [1, }', "m.json")
    with pytest.raises(ValueError, match=r"<string>.*control_points\[1\]\[0\]"):
        c.parse_models_json('{"type": "bezier", "control_points": [[0, 0], ["a", 1]]}')
    with pytest.raises(ValueError, match="unknown field 'colour'"):
        c.parse_models_json('{"type": "bezier", "control_points": [[0, 0]], "colour": 1}')
    with pytest.raises(ValueError, match="weight"):
        c.parse_models_json('{"type": "bezier", "control_points": [[0, 0], [1, 1]], "weights": [1, -1]}')
    with pytest.raises(ValueError, match=r"control_points\[1\]"):
        c.parse_models_json('{"type": "bezier_surface", "control_points": [[[0, 0], [1, 0]], [[0, 1]]]}')
    with pytest.raises(TypeError):
        c.parse_models_json(42)
    assert c.parse_models_json(b'{"type": "bezier", "control_points": [[0, 0]]}') == [c.BezierCurve([[0.0, 0.0]])]


def test_file_errors_name_the_path(tmp_path):
    missing = tmp_path / "missing.json"
    for read in (c.read_models_json, c.read_models, c.read_points_csv, c.read_numbers_csv, c.read_text_file):
        with pytest.raises(ValueError, match="missing.json"):
            read(missing)
    with pytest.raises(ValueError, match="directory"):
        c.read_models_json(tmp_path)
    broken = tmp_path / "broken.json"
    broken.write_text("{\n  nope\n}")
    with pytest.raises(ValueError, match=r"broken\.json, line 2"):
        c.read_models_json(broken)
    with pytest.raises(TypeError):
        c.read_models_json(3.5)
    # Writing into a missing folder: an error naming it, nothing written.
    target = tmp_path / "absent" / "models.json"
    with pytest.raises(ValueError, match="absent"):
        c.write_models_json(every_model_kind()[:1], target)
    assert not target.parent.exists()
    # An existing file stays whole when a later write fails before renaming.
    kept = tmp_path / "kept.json"
    c.write_models_json(every_model_kind()[:1], kept)
    before = kept.read_bytes()
    with pytest.raises(TypeError):
        c.write_models_json([object()], kept)
    assert kept.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["broken.json", "kept.json"]  # no temporary file left


# --- CSV and files -----------------------------------------------------------------------------


@SEEDED
@given(st.integers(0, 2**32 - 1))
def test_points_csv_round_trip_is_exact(seed):
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(int(rng.integers(1, 20)), int(rng.integers(1, 5)))) * 10.0 ** rng.integers(-20, 20)
    text = c.format_points_csv(points)
    np.testing.assert_array_equal(c.parse_points_csv(text), points)


def test_csv_parsing_files_and_errors(tmp_path):
    points = c.parse_points_csv("# a comment\nx,y\n0,0\n1, 2\n+2.25,1.5\n")
    np.testing.assert_array_equal(points, [[0, 0], [1, 2], [2.25, 1.5]])
    with pytest.raises(ValueError, match=r"head\.csv, line 3, field 2: 'abc' is not a number"):
        c.parse_points_csv("0,0\n1,1\n2,abc\n", "head.csv")
    with pytest.raises(ValueError):
        c.parse_points_csv("0,0\n1\n")
    with pytest.raises(ValueError):
        c.parse_points_csv("# nothing\n")
    path = pathlib.Path(tmp_path) / "p.csv"
    c.write_points_csv(SEED_POINTS, path)
    np.testing.assert_array_equal(c.read_points_csv(path), SEED_POINTS)
    assert c.read_text_file(path) == c.format_points_csv(SEED_POINTS)
    assert c.parse_number("+2.5e-3") == 2.5e-3
    for text, message in (("abc", "not a number"), ("nan", "NaN"), ("1e999", "overflows")):
        with pytest.raises(ValueError, match=message):
            c.parse_number(text)
    values, lines = c.parse_numbers_csv("t\n0.5\n# skip\n0.25\n")
    np.testing.assert_array_equal(values, [0.5, 0.25])
    np.testing.assert_array_equal(lines, [2, 4])
    with pytest.raises(ValueError):
        c.parse_numbers_csv("1\n2\n3\n", max_values=2)
    numbers = tmp_path / "t.csv"
    c.write_file_atomically(numbers, b"0\n0.5\n1\n")
    np.testing.assert_array_equal(c.read_numbers_csv(numbers), [0, 0.5, 1])
    c.write_file_atomically(str(numbers), "é\n")
    assert numbers.read_text(encoding="utf-8") == "é\n"
    assert c.display_name("a\nb") == "a\\x0ab"
    for bad in (np.array([[np.nan, 0]]), np.zeros((0, 2)), np.zeros(3)):
        with pytest.raises(ValueError):
            c.format_points_csv(bad)
    with pytest.raises(TypeError):
        c.format_points_csv(np.zeros((2, 2), dtype=complex))

"""casteljau's mesh files read by an independent reader: meshio (Debian's
python3-meshio, written by other people) reads the OBJ, binary STL and binary
PLY that ``casteljau tessellate`` writes for a unit NURBS sphere, and must get
the same mesh from each:

- OBJ and PLY (both full double precision: shortest round-trip text, binary
  doubles) give identical points, triangles and per-vertex normals;
- STL (float32) gives, triangle by triangle, the same vertices rounded to
  float32, and its facet normals (read with numpy from the 50-byte records)
  are the unit normals of those triangles;
- the geometry is right: every vertex is on the unit sphere, its normal is the
  radial direction, and every triangle winds counter-clockwise seen from its
  vertices' normals (outwards).
Run with /usr/bin/python3 -m pytest; the CLI comes from CASTELJAU_CLI.
"""

import json
import math
import subprocess

import meshio
import numpy as np
import pytest

from cli_support import casteljau_cli

HALF_ROOT2 = math.sqrt(0.5)


def unit_sphere_model():
    """The NURBS Book's 9-point circle (weights 1, sqrt(1/2)) revolved around
    the meridian semicircle from the south to the north pole: degree (2, 2)."""
    circle = [(1, 0, 1), (1, 1, HALF_ROOT2), (0, 1, 1), (-1, 1, HALF_ROOT2), (-1, 0, 1),
              (-1, -1, HALF_ROOT2), (0, -1, 1), (1, -1, HALF_ROOT2), (1, 0, 1)]
    meridian = [(0, -1, 1), (1, -1, HALF_ROOT2), (1, 0, 1), (1, 1, HALF_ROOT2), (0, 1, 1)]
    points = [[[m[0] * c[0], m[0] * c[1], m[1]] for m in meridian] for c in circle]
    weights = [[c[2] * m[2] for m in meridian] for c in circle]
    return {"type": "bspline_surface", "degree": [2, 2],
            "knots": [[0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1], [0, 0, 0, 0.5, 0.5, 1, 1, 1]],
            "control_points": points, "weights": weights}


@pytest.fixture(scope="module")
def meshes(tmp_path_factory):
    folder = tmp_path_factory.mktemp("meshes")
    model = folder / "sphere.json"
    model.write_text(json.dumps(unit_sphere_model()))
    files = {}
    for extension in ("obj", "stl", "ply"):
        path = folder / f"sphere.{extension}"
        run = subprocess.run([casteljau_cli(), "tessellate", str(model), "--tolerance", "0.005", "-o", str(path)],
                             capture_output=True, text=True, check=False)
        assert run.returncode == 0, run.stderr
        assert run.stdout.endswith("watertight\n") and "not watertight" not in run.stdout, run.stdout
        files[extension] = path
    return files


def triangles_of(mesh):
    assert [block.type for block in mesh.cells] == ["triangle"]
    return mesh.cells[0].data


def test_obj_and_ply_agree_exactly(meshes):
    obj = meshio.read(meshes["obj"])
    ply = meshio.read(meshes["ply"])
    np.testing.assert_array_equal(obj.points, ply.points)
    np.testing.assert_array_equal(triangles_of(obj), triangles_of(ply))
    ply_normals = np.column_stack([ply.point_data[name] for name in ("nx", "ny", "nz")])
    np.testing.assert_array_equal(obj.point_data["obj:vn"], ply_normals)


def test_geometry_unit_sphere_radial_normals_outward_winding(meshes):
    ply = meshio.read(meshes["ply"])
    points = ply.points
    normals = np.column_stack([ply.point_data[name] for name in ("nx", "ny", "nz")])
    triangles = triangles_of(ply)
    assert np.max(np.abs(np.linalg.norm(points, axis=1) - 1.0)) <= 1e-13
    assert np.max(np.abs(normals - points)) <= 1e-12
    a, b, c = (points[triangles[:, k]] for k in range(3))
    faces = np.cross(b - a, c - a)
    for k in range(3):
        assert np.all(np.einsum("ij,ij->i", faces, normals[triangles[:, k]]) > 0.0)


def test_stl_has_the_same_triangles_in_float32_and_their_normals(meshes):
    stl = meshio.read(meshes["stl"])
    ply = meshio.read(meshes["ply"])
    ply_triangles = triangles_of(ply)
    stl_corners = stl.points[triangles_of(stl)]
    expected = ply.points[ply_triangles].astype(np.float32).astype(np.float64)
    np.testing.assert_array_equal(stl_corners, expected)
    # The facet records: normal, three vertices (float32), a uint16 attribute.
    record = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])
    raw = meshes["stl"].read_bytes()
    count = int(np.frombuffer(raw, dtype="<u4", count=1, offset=80)[0])
    assert count == len(ply_triangles) and len(raw) == 84 + 50 * count
    facets = np.frombuffer(raw, dtype=record, count=count, offset=84)
    a, b, c = (ply.points[ply_triangles[:, k]] for k in range(3))
    faces = np.cross(b - a, c - a)
    faces /= np.linalg.norm(faces, axis=1)[:, None]
    assert np.max(np.abs(facets["normal"] - faces)) <= 1e-6
    assert np.all(facets["attribute"] == 0)

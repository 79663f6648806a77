"""casteljau.gcode (python/src/io.cpp): the G-code program of plane curves.

References: the exact NURBS half circle of radius 3 (examples/semicircle.json)
is one G2 whose centre I J = (3, 0) is worked by hand; the command line
(`casteljau gcode`, the same writer reached another way) writes the same
program for the same curves; the motion is checked by LinuxCNC's and cncjs's
interpreters in tests/gcode/, through the command line.
"""

import re
import subprocess

import numpy as np
import pytest

import casteljau as c
from cli_support import REPOSITORY, casteljau_cli

SEMICIRCLE = REPOSITORY / "examples" / "semicircle.json"


def motion_lines(program):
    return [line for line in program.splitlines() if not line.startswith("(")]


def test_the_half_circle_is_one_clockwise_arc():
    program = c.gcode(c.read_models(SEMICIRCLE), 0.01)
    assert motion_lines(program) == [
        "G21 G90 G17 G94",
        "G0 Z5.0000",
        "G0 X-3.0000 Y0.0000",
        "G1 Z-1.0000 F200.0000",
        "G2 X3.0000 Y0.0000 I3.0000 J0.0000 F600.0000",
        "G0 Z5.0000",
        "M2",
    ]
    assert "(source: Python)" in program


def test_the_same_program_as_the_command_line(tmp_path):
    head = tmp_path / "head.json"
    subprocess.run([casteljau_cli(), "interpolate", str(REPOSITORY / "examples" / "head.csv"), "--method",
                    "c1-bezier", "-o", str(head)], check=True, capture_output=True)
    out = tmp_path / "head.nc"
    subprocess.run([casteljau_cli(), "gcode", str(head), "--tolerance", "0.001", "--units", "in", "--step-down",
                    "0.02", "--dialect", "linuxcnc", "-o", str(out)], check=True, capture_output=True)
    program = c.gcode(c.read_models(head), 0.001, units="in", step_down=0.02, dialect="linuxcnc")
    assert motion_lines(program) == motion_lines(out.read_text())
    assert re.search(r"^G3 .* I-?\d+\.\d{5} J", program, re.MULTILINE)  # inches: 5 decimals


def test_lines_only_and_the_options():
    models = c.read_models(SEMICIRCLE)
    program = c.gcode(models, 0.01, lines=True, depth=2, step_down=1, safe_z=10, feed=1000, plunge_feed=100)
    assert not re.search(r"^G[23] ", program, re.MULTILINE)
    assert "G0 Z10.0000" in program
    assert "G1 Z-1.0000 F100.0000" in program and "G1 Z-2.0000" in program
    assert "F1000.0000" in program
    # The tolerance chooses the decimals: 0.0001 mm needs 6.
    assert "G2 X3.000000 Y0.000000 I3.000000 J0.000000" in c.gcode(models, 0.0001)
    # The box -3..3 x 0..3 moved to start at X0 Y0.
    assert "G2 X6.0000 Y0.0000 I3.0000 J0.0000" in c.gcode(models, 0.01, origin="lower-left")


@pytest.mark.parametrize("call, message", [
    (lambda m, s, p: c.gcode(m, 0.0), "tolerance 0 is not a distance > 0"),
    (lambda m, s, p: c.gcode(m, float("nan")), "tolerance nan is not a distance > 0"),
    (lambda m, s, p: c.gcode(m, 0.0005, decimals=4), "is not above what rounding to 4 decimals"),
    (lambda m, s, p: c.gcode(m, 0.01, depth=-1), "depth -1 is not a length > 0"),
    (lambda m, s, p: c.gcode(m, 0.01, feed=0), "feed 0 is not a length > 0"),
    (lambda m, s, p: c.gcode(m, 0.01, units="cm"), "units 'cm' is not mm or in"),
    (lambda m, s, p: c.gcode(m, 0.01, dialect="marlin"), "dialect 'marlin' is not grbl or linuxcnc"),
    (lambda m, s, p: c.gcode(m, 0.01, origin="middle"), "origin 'middle' is not drawing, lower-left or centre"),
    (lambda m, s, p: c.gcode(m + s, 0.01), "models[1]: G-code cuts plane curves, this one lives in R^3"),
    (lambda m, s, p: c.gcode(p, 0.01), "models[0]: gcode cuts plane curves, this is a surface"),
    (lambda m, s, p: c.gcode([], 0.01), "models is empty"),
])
def test_bad_input_is_a_value_error(call, message):
    models = c.read_models(SEMICIRCLE)
    space = [c.BezierCurve(np.array([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]))]
    patch = c.read_models(REPOSITORY / "examples" / "patch.json")
    with pytest.raises(ValueError, match=re.escape(message)):
        call(models, space, patch)

#!/usr/bin/python3
"""How LinuxCNC's interpreter reads a G-code program: rs274_motion.py IN.nc OUT.json

Runs LinuxCNC's standalone interpreter (Debian's linuxcnc-uspace:
/usr/bin/rs274 -g IN.nc < /dev/null), which prints the canonical machine
calls the program makes, one a line ("   12 N..... STRAIGHT_FEED(10.0000,
0.0000, -1.0000, ...)"), and writes the motion in the JSON that
gcode_check.cpp reads (the same as interpret.mjs writes for cncjs):
{"units": "G21", "moves": [{"motion": "G2", "from": [x, y, z], "to": [...],
"centre": [...]}, ...], "unhandled": [], "errors": [...]}, lengths in mm
(an inch program's numbers times 25.4, as cncjs gives them).

STRAIGHT_TRAVERSE is a G0, STRAIGHT_FEED a G1; ARC_FEED(end1, end2, centre1,
centre2, rotation, end_z, ...) in the XY plane (G17) turns counterclockwise
(G3) when rotation > 0, clockwise (G2) when < 0, and |rotation| - 1 whole
turns more: any such extra turn is an error here (casteljau never writes
one). rs274 reports a refused block as text among its output and still
exits 0; every line that is not a canonical call (or its "executing"
banner) is kept as an error, as is a program that does not reach
PROGRAM_END. The interpreter prints 4 decimals: gcode_check.cpp is told
the resolution that leaves (run.sh).
"""
import json
import re
import subprocess
import sys

CALL = re.compile(r'^\s*\d+\s+N\.+\s+([A-Z_0-9]+)\((.*)\)\s*$')


def numbers(arguments):
    return [float(a) for a in arguments.split(',')]


def main():
    if len(sys.argv) != 3:
        print('usage: rs274_motion.py IN.nc OUT.json', file=sys.stderr)
        return 2
    source, target = sys.argv[1:]
    run = subprocess.run(['rs274', '-g', source], stdin=subprocess.DEVNULL, capture_output=True, text=True,
                         timeout=120, check=False)
    scale = 1.0
    units = 'G21'
    position = [0.0, 0.0, 0.0]
    moves, errors = [], []
    ended = False
    for line in (run.stdout + run.stderr).splitlines():
        if not line.strip() or line.strip() == 'executing':
            continue
        call = CALL.match(line)
        if not call:
            errors.append(line.strip())
            continue
        name, arguments = call.groups()
        if name == 'USE_LENGTH_UNITS':
            inches = 'INCHES' in arguments
            units, scale = ('G20', 25.4) if inches else ('G21', 1.0)
        elif name in ('STRAIGHT_TRAVERSE', 'STRAIGHT_FEED'):
            x, y, z = (v * scale for v in numbers(arguments)[:3])
            moves.append({'motion': 'G0' if name == 'STRAIGHT_TRAVERSE' else 'G1', 'from': position, 'to': [x, y, z]})
            position = [x, y, z]
        elif name == 'ARC_FEED':
            values = numbers(arguments)
            end1, end2, centre1, centre2 = (v * scale for v in values[:4])
            rotation, end_z = int(values[4]), values[5] * scale
            if abs(rotation) != 1:
                errors.append(f'ARC_FEED turning {rotation} times (whole circles): {line.strip()}')
            moves.append({'motion': 'G3' if rotation > 0 else 'G2', 'from': position, 'to': [end1, end2, end_z],
                          'centre': [centre1, centre2, position[2]]})
            position = [end1, end2, end_z]
        elif name == 'PROGRAM_END':
            ended = True
    if run.returncode != 0:
        errors.append(f'rs274 exited with status {run.returncode}')
    if not ended:
        errors.append('the interpreter stopped before the end of the program (no PROGRAM_END)')
    with open(target, 'w', encoding='utf-8') as out:
        json.dump({'units': units, 'moves': moves, 'unhandled': [], 'errors': errors}, out)
    return 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/python3
"""Coverage per layer from gcovr's JSON (make coverage; docs/coverage.md).

usage: report.py COVERAGE.json [--uncovered FILE]

Prints, for each layer of ARCHITECTURE.md (its src/<layer>/ and
include/casteljau/<layer>/ files; cli/ and python/ as their own), the lines
and branches run by the suites, then the whole as `lines: N%` and
`branches: N%`. With --uncovered, writes every line no suite ran, by file,
for the list docs/coverage.md keeps of what stays uncovered and why.
Exit status 0: the report is information, not a gate (the targets are in
docs/coverage.md).
"""
import json
import sys
from collections import defaultdict

LAYERS = ["core", "bezier", "bspline", "nurbs", "curves", "interpolation", "surfaces", "ops", "io",
          "render"]


def layer_of(path):
    parts = path.split("/")
    if parts[0] == "src" and len(parts) > 2:
        return parts[1]
    if parts[:2] == ["include", "casteljau"] and len(parts) > 3:
        return parts[2]
    if parts[0] in ("cli", "python"):
        return parts[0]
    return None


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        report = json.load(f)
    totals = defaultdict(lambda: [0, 0, 0, 0])  # lines run, lines, branches taken, branches
    uncovered = defaultdict(list)
    for entry in report["files"]:
        layer = layer_of(entry["file"])
        if layer is None:
            continue
        count = totals[layer]
        for line in entry["lines"]:
            if line.get("gcovr/noncode"):
                continue
            count[1] += 1
            if line["count"] > 0:
                count[0] += 1
            else:
                uncovered[entry["file"]].append(line["line_number"])
            for branch in line.get("branches", []):
                count[3] += 1
                if branch["count"] > 0:
                    count[2] += 1

    def percent(part, whole):
        return 100.0 * part / whole if whole else 100.0

    print(f"{'layer':<14} {'lines':>16} {'':>7} {'branches':>16} {'':>7}")
    order = [layer for layer in LAYERS + ["cli", "python"] if layer in totals]
    whole = [0, 0, 0, 0]
    for layer in order:
        c = totals[layer]
        whole = [a + b for a, b in zip(whole, c)]
        print(f"{layer:<14} {c[0]:>7} / {c[1]:<6} {percent(c[0], c[1]):6.1f}% {c[2]:>7} / {c[3]:<6} "
              f"{percent(c[2], c[3]):6.1f}%")
    print(f"lines: {percent(whole[0], whole[1]):.1f}%")
    print(f"branches: {percent(whole[2], whole[3]):.1f}%")
    if len(argv) > 3 and argv[2] == "--uncovered":
        with open(argv[3], "w") as out:
            for path in sorted(uncovered, key=lambda p: (layer_of(p) or "", p)):
                lines = uncovered[path]
                # Runs of consecutive lines as a-b.
                runs, start = [], lines[0]
                for previous, current in zip(lines, lines[1:] + [None]):
                    if current != previous + 1:
                        runs.append(f"{start}" if start == previous else f"{start}-{previous}")
                        start = current
                out.write(f"{path}: {len(lines)} lines: {', '.join(runs)}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

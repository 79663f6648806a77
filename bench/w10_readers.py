"""W10 peers: python3-svgelements and ezdxf read the 10 MB SVG and DXF files
that bench/w10_drawing_readers.cpp wrote (into --data, default out/bench/w10),
in the same run. One timed read = the file parsed into the library's objects:
svgelements' SVG.parse (which parses every path's d into segments) and the
segments of its paths listed; ezdxf.readfile and the entities of the model
space listed. Throughput in MB of file per second (items = bytes), so the rows
compare with casteljau's read_svg_drawing and read_dxf_drawing.

Checks: svgelements finds as many drawing segments as the file has (Move
excluded, every Arc one segment; casteljau's row checks its own count), ezdxf
as many entities; else the row fails. Run with /usr/bin/python3.
"""
import argparse
import os
import re
import time

from benchmark_json import timed_rows, write_benchmark_json


def svg_rows(path, repetitions, family):
    import svgelements

    size = os.path.getsize(path)
    text = open(path).read()
    expected = len(re.findall(r"[LlHVCcSQqTA]", text.split('d="')[1].split('"')[0]))
    times, found = [], 0
    for _ in range(repetitions):
        started = time.perf_counter()
        document = svgelements.SVG.parse(path)
        found = sum(1 for element in document.elements() if isinstance(element, svgelements.Path)
                    for segment in element if not isinstance(segment, svgelements.Move))
        times.append(time.perf_counter() - started)
    error = 0.0 if found >= expected else 1.0
    return timed_rows("W10/svg-10MB/svgelements-SVG.parse", times, size, error, 0.0, family, counter="count_error")


def dxf_rows(path, repetitions, family):
    import ezdxf

    size = os.path.getsize(path)
    expected = sum(1 for line in open(path) if line.rstrip() in ("LINE", "ARC", "LWPOLYLINE", "SPLINE"))
    times, found = [], 0
    for _ in range(repetitions):
        started = time.perf_counter()
        document = ezdxf.readfile(path)
        found = sum(1 for _ in document.modelspace())
        times.append(time.perf_counter() - started)
    error = 0.0 if found == expected else 1.0
    return timed_rows("W10/dxf-10MB/ezdxf-readfile", times, size, error, 0.0, family, counter="count_error")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--out", default="-")
    parser.add_argument("--filter", default="")
    parser.add_argument("--data", default=os.environ.get("CASTELJAU_BENCH_DATA", "out/bench/w10"))
    arguments = parser.parse_args()
    rows = []
    pattern = re.compile(arguments.filter or ".")
    if pattern.search("W10/svg-10MB/svgelements-SVG.parse"):
        rows += svg_rows(os.path.join(arguments.data, "w10_path.svg"), arguments.repetitions, 0)
    if pattern.search("W10/dxf-10MB/ezdxf-readfile"):
        rows += dxf_rows(os.path.join(arguments.data, "w10_drawing.dxf"), arguments.repetitions, 1)
    write_benchmark_json(rows, arguments.out, library="svgelements, ezdxf")


if __name__ == "__main__":
    main()

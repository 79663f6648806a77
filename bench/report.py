"""One `make bench` run's results in two files, and the README's table from them.

    report.py collect --dir out/bench [--seconds S] [--build build-bench] [--cpu 0] [--load "1.2 1.3 1.4"]
        Reads every Google Benchmark JSON file of the run in --dir (the C++
        binaries' and the Python scripts', all in the same shape), writes
        --dir/results.json (their rows in one Google Benchmark document, each
        row tagged with the file it came from, and the run's context) and
        --dir/RESULTS.md: per workload the median and min-max of every row,
        casteljau's ratio to the best peer, the fraction of the hardware limit
        measured by the probe rows (HW/...) of the same run, and the machine,
        compiler and package versions. Exits 1 if a row failed its check.

    report.py readme --results docs/RESULTS.md --readme README.md [--check]
        Copies the summary table of a committed RESULTS.md, with its date and
        machine, between README's `<!-- bench:begin -->` and `<!-- bench:end -->`
        lines. --check changes nothing and exits 1 if README differs.

Row names are W<k>/<variant>/<implementation> (shared/docs/performance.md);
an implementation is casteljau's when its name starts with "casteljau", a
peer's when it starts with one of PEERS, and otherwise a baseline written in
bench/ from a textbook or paper (shown, never counted as a peer).

Run with /usr/bin/python3.
"""
import argparse
import datetime
import json
import os
import platform
import re
import shlex
import statistics
import subprocess
import sys
from collections import OrderedDict
from pathlib import Path

PEERS = ("occt", "sisl", "eigen", "scipy", "lib2geom", "gsl", "kurbo", "lyon", "svgelements", "ezdxf")
KIND_ORDER = {"casteljau": 0, "peer": 1, "baseline": 2}

# The Debian packages whose versions a run reports (the peers, the harness, the compiler).
PACKAGES = ("g++", "libbenchmark-dev", "libeigen3-dev", "libocct-foundation-dev", "libsisl-dev", "lib2geom-dev",
            "libgsl-dev", "python3-numpy", "python3-scipy", "python3-pybind11")

# Work per point of each workload, for the hardware limit (see LIMITS_TEXT).
W1_FMAS, W1_BYTES = 42, 24
W2_FMAS, W2_BYTES = 48, 48
W5_FMAS, W5_BYTES = 13, 24
W4_FMAS, W4_BYTES = 15, 24

LIMITS_TEXT = """\
The limit of a workload is the lower of two rates measured by the probe rows
above on the same core in the same run: the FMA rate divided by the
floating-point operations a point needs (each multiplication, FMA, addition
or division counted as one FMA slot), and the store rate (the faster of
streaming and ordinary stores into 24 MB) divided by the bytes a point
writes. It bounds the algorithm's arithmetic and its output traffic, not
loads: random-order rows (W1/W2 random) also wait on memory, so their
fractions are lower by nature.

| workload | operations per point | bytes stored per point | where the count comes from |
|---|---|---|---|
| W1 | 42 | 24 | cubic de Boor in 3D: 6 affine steps × 3 coordinates × 2 operations, and 6 divisions for the α |
| W2 | 48 | 48 | W1 and the derivative's last level: 3 coordinates × 2 more |
| W3 degree n, dimension d | n(n+1)·d | 8·d | de Casteljau: n(n+1)/2 steps per coordinate, one multiplication and one FMA each |
| W4 (per fit of n points) | 15 per point | 24 per point | the tridiagonal sweep and back substitution for 3 coordinates; the limit is a time, max(FMA time, store time) |
| W5 (grid) | 13 | 24 | the tensor product separates on a grid: 4 × 3 FMAs per point, the row stage (1.2 per point) shared by the 1000 points of a row |
| W6 | | | the optimum segment count with vertices on the curve: fraction = optimum ÷ segments |
| W7 | | | no hardware limit is stated: the work per query depends on how many pieces lie near it; rows report misses against the brute-force oracle |
| W8 | | | no hardware limit is stated: the work per pair depends on how the curves meet; rows report misses and spurious points against the exact oracle |
| W9 | | | no hardware limit is stated: the quadrature's node count depends on the curve; rows report error_rel against the oracle |
| W10 | | | no hardware limit is stated: rows are MB of file read per second; each checks the count of segments or entities it read |
| W11 | | | no hardware limit is stated: rows are one whole run (MB of SVG per second, or contours ordered per second); each checks that every contour is cut once and the ordered rapid moves are shorter, the greedy rows that the k-d tree's order is as long as the plain search's |
"""


# ---------------------------------------------------------------------------- reading


class Row:
    """One benchmark row: its repetitions, median, error, counters, source file."""

    def __init__(self, name, source):
        self.name = name
        self.source = source
        self.reps = []
        self.median = None
        self.error = None
        parts = name.split("/")
        self.workload = parts[0]
        self.variant = parts[1] if len(parts) > 2 else ""
        self.implementation = parts[-1]
        self.order = (0, 0, 0)

    @property
    def kind(self):
        if self.implementation.startswith("casteljau"):
            return "casteljau"
        if self.implementation.split("-")[0] in PEERS:
            return "peer"
        return "baseline"

    def _entry(self):
        return self.median or (self.reps[0] if self.reps else None)

    @property
    def ok(self):
        return self.error is None and self._entry() is not None

    def counter(self, key, default=None):
        entry = self._entry()
        return entry.get(key, default) if entry else default

    # Rates (per second, higher is better) or times (seconds, lower is better).
    def is_rate(self):
        entry = self._entry()
        return entry is not None and ("items_per_second" in entry or "bytes_per_second" in entry)

    def _value(self, entry):
        if "items_per_second" in entry:
            return entry["items_per_second"]
        if "bytes_per_second" in entry:
            return entry["bytes_per_second"]
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[entry.get("time_unit", "ns")]
        return entry["real_time"] * scale

    @property
    def value(self):
        """The median: a rate per second, or a time in seconds."""
        return self._value(self._entry())

    @property
    def spread(self):
        values = [self._value(r) for r in self.reps] or [self.value]
        return min(values), max(values)

    def better_than(self, other):
        return self.value > other.value if self.is_rate() else self.value < other.value


def read_rows(directory):
    """The rows of every *.json in directory (but results.json), and the raw
    entries tagged with their source. Rows come in registration order (files
    in name order, then Google Benchmark's family index), grouped by workload
    and then by variant in the order the variants first appear."""
    rows, entries, contexts = OrderedDict(), [], {}
    documents = []
    for path in sorted(Path(directory).glob("*.json")):
        if path.name == "results.json":
            continue
        try:
            documents.append((path, json.loads(path.read_text(encoding="utf-8"))))
        except json.JSONDecodeError as error:
            raise SystemExit(f"report.py: {path} is not JSON ({error}); did its benchmark crash?")
    # The binaries' files (their context names the caches) before the Python scripts'.
    documents.sort(key=lambda item: ("caches" not in item[1].get("context", {}), item[0].name))
    for file_rank, (path, document) in enumerate(documents):
        contexts[path.stem] = document.get("context", {})
        for entry in document.get("benchmarks", []):
            entries.append(dict(entry, source=path.stem))
            name = entry.get("run_name", entry["name"]).removesuffix("/real_time")
            row = rows.get(name)
            if row is None:
                row = rows[name] = Row(name, path.stem)
                row.order = (file_rank, entry.get("family_index", 0), entry.get("per_family_instance_index", 0))
            if entry.get("error_occurred"):
                row.error = entry.get("error_message", "error")
            elif entry.get("run_type") == "aggregate":
                if entry.get("aggregate_name") == "median":
                    row.median = entry
            else:
                row.reps.append(entry)
    registered = sorted(rows.values(), key=lambda r: r.order)
    variant_rank = {}
    for rank, row in enumerate(registered):
        variant_rank.setdefault((row.workload, row.variant), rank)

    def workload_number(row):
        match = re.fullmatch(r"W(\d+)", row.workload)
        return int(match.group(1)) if match else -1  # the probe rows (HW) first

    ordered = sorted(registered, key=lambda r: (workload_number(r), variant_rank[(r.workload, r.variant)],
                                                KIND_ORDER[r.kind], not is_headline(r), r.order))
    return OrderedDict((r.name, r) for r in ordered), entries, contexts


# ---------------------------------------------------------------------------- the run's context


def command_output(arguments):
    try:
        return subprocess.run(arguments, capture_output=True, text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


def package_versions():
    versions = OrderedDict()
    for package in PACKAGES:
        version = command_output(["dpkg-query", "-W", "-f=${Version}", package])
        versions[package] = version or "not installed"
    return versions


def compiler_of(build):
    """The C++ compiler's version line and the flags the bench sources were compiled with."""
    cache = Path(build) / "CMakeCache.txt"
    compiler, flags = "", ""
    if cache.exists():
        match = re.search(r"^CMAKE_CXX_COMPILER:\w+=(.*)$", cache.read_text(encoding="utf-8"), re.M)
        if match:
            compiler = command_output([match.group(1), "--version"]).partition("\n")[0]
    commands = Path(build) / "compile_commands.json"
    if commands.exists():
        for command in json.loads(commands.read_text(encoding="utf-8")):
            if command["file"].endswith("w1_w2_bspline.cpp"):
                words = shlex.split(command["command"])
                flags = " ".join(w for w in words if re.match(r"-(O\d|march=|mtune=|ffast-math|DNDEBUG)", w))
    return compiler, flags


def cpu_model():
    try:
        for line in Path("/proc/cpuinfo").read_text(encoding="utf-8").splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def cpu_features():
    try:
        text = Path("/proc/cpuinfo").read_text(encoding="utf-8")
    except OSError:
        return []
    flags = set(re.search(r"^flags\s*:(.*)$", text, re.M).group(1).split()) if "flags" in text else set()
    return [name for flag, name in (("avx512f", "AVX-512"), ("avx2", "AVX2"), ("fma", "FMA")) if flag in flags]


def memory_gib():
    try:
        kib = int(re.search(r"MemTotal:\s+(\d+)", Path("/proc/meminfo").read_text(encoding="utf-8")).group(1))
        return kib / 2**20
    except (OSError, AttributeError):
        return 0.0


def binary_size(size):
    return f"{size // 2**20} MiB" if size >= 2**20 else f"{size // 1024} KiB"


def run_context(args, contexts):
    """Everything RESULTS.md says about the machine and the run."""
    benchmark_context = next((c for c in contexts.values() if "caches" in c), {})
    caches = ", ".join(f"L{c['level']}{'d' if c['type'] == 'Data' else ''} {binary_size(c['size'])}"
                       for c in benchmark_context.get("caches", []) if c.get("type") != "Instruction")
    hypervisor = re.search(r"Hypervisor vendor:\s*(\S+)", command_output(["lscpu"]))
    compiler, flags = compiler_of(args.build)
    return OrderedDict(
        date=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        cpu=cpu_model(),
        features=cpu_features(),
        cores=os.cpu_count(),
        virtualization=hypervisor.group(1) if hypervisor else "",
        caches=caches,
        memory_gib=round(memory_gib(), 1),
        kernel=platform.release(),
        load_at_start=args.load,
        pinned_cpu=args.cpu,
        seconds=args.seconds,
        build_seconds=int(args.build_seconds) if args.build_seconds else None,
        compiler=compiler,
        flags=flags,
        python=platform.python_version(),
        packages=package_versions(),
    )


def machine_line(context):
    features = "/".join(context["features"])
    guest = f"{context['virtualization']} guest, " if context["virtualization"] else ""
    return (f"{guest}{context['cores']} cores of an {context['cpu']}"
            + (f" with {features}" if features else "")
            + (f", {context['caches']}" if context["caches"] else "")
            + f", {context['memory_gib']:g} GiB")


# ---------------------------------------------------------------------------- limits


class Probe:
    """The hardware rates measured by the HW/ rows of this run."""

    def __init__(self, rows):
        fma = [r for r in rows.values() if r.workload == "HW" and r.variant == "fma" and r.ok]
        stores = [r for r in rows.values() if r.workload == "HW" and r.variant.startswith("store") and r.ok]
        self.fma_row = fma[0] if fma else None
        self.store_row = max(stores, key=lambda r: r.value) if stores else None
        self.fma = self.fma_row.value if self.fma_row else None
        self.store = self.store_row.value if self.store_row else None

    def rate_limit(self, operations, stored_bytes):
        """(points per second, what binds it) or (None, "") without a probe."""
        if not self.fma or not self.store:
            return None, ""
        by_fma, by_store = self.fma / operations, self.store / stored_bytes
        return (by_fma, "FMA") if by_fma < by_store else (by_store, "stores")


def point_cost(workload, variant):
    """(operations, bytes stored) per point, or None when the workload has no per-point limit."""
    if workload == "W1":
        return W1_FMAS, W1_BYTES
    if workload == "W2":
        return W2_FMAS, W2_BYTES
    if workload == "W5":
        return W5_FMAS, W5_BYTES
    match = re.fullmatch(r"deg(\d+)-(\d)d", variant) if workload == "W3" else None
    if match:
        degree, dimension = int(match.group(1)), int(match.group(2))
        return degree * (degree + 1) * dimension, 8 * dimension
    return None


def fraction_of_limit(row, probe):
    """(fraction, limit text) for a row, or (None, "")."""
    if not row.ok:
        return None, ""
    if row.workload == "W6":
        optimum, segments = row.counter("optimum"), row.counter("segments")
        if optimum and segments and row.counter("within_tolerance") == 1:
            return optimum / segments, f"optimum {optimum:.0f} segments"
        return None, ""
    if row.workload == "W4":
        match = re.fullmatch(r"n(\d+)", row.variant)
        if not match or not probe.fma or not probe.store or row.is_rate():
            return None, ""
        n = int(match.group(1))
        limit = max(W4_FMAS * n / probe.fma, W4_BYTES * n / probe.store)
        return limit / row.value, f"{format_time(limit)} per fit"
    cost = point_cost(row.workload, row.variant)
    if cost is None or not row.is_rate() or row.implementation.endswith("all-cores"):
        return None, ""
    limit, bound = probe.rate_limit(*cost)
    if limit is None:
        return None, ""
    return row.value / limit, f"{limit / 1e6:,.0f} M/s ({bound})"


# ---------------------------------------------------------------------------- formatting


def significant(x, digits=3):
    """x with about `digits` significant digits, no exponent for ordinary sizes."""
    if x == 0 or not (abs(x) < float("inf")):
        return f"{x:g}"
    decimals = max(0, digits - 1 - int(f"{abs(x):e}".split("e")[1]))
    return f"{x:,.{decimals}f}"


def format_time(seconds):
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
        if seconds >= scale or unit == "ns":
            return f"{significant(seconds / scale)} {unit}"
    return f"{seconds:g} s"


def format_value(row, value):
    if row.workload == "HW":
        if row.variant == "fma":
            return f"{significant(value / 1e9)} G FMA/s"
        return f"{significant(value / 1e9)} GB/s"
    if row.is_rate():
        return f"{significant(value / 1e6)} M/s"
    return format_time(value)


def format_median(row):
    low, high = row.spread
    return f"{format_value(row, row.value)}", f"{format_value(row, low)} – {format_value(row, high)}"


def ratio_text(ratio):
    return f"{significant(ratio)}×"


def percent(fraction):
    return f"{significant(100 * fraction, 2)} %"


# ---------------------------------------------------------------------------- comparisons


W4_CONDITIONS = ("natural", "clamped", "not-a-knot", "periodic")


def condition_of(row):
    """W4 rows end with their end condition (casteljau-natural, gsl-cspline-not-a-knot)."""
    if row.workload != "W4":
        return ""
    return next((c for c in W4_CONDITIONS if row.implementation.endswith("-" + c)), "")


def is_headline(row):
    """Whether the row is casteljau's row of its variant: `casteljau`, or `casteljau-<condition>` in W4."""
    if row.workload == "W4":
        return row.implementation in ["casteljau-" + c for c in W4_CONDITIONS]
    return row.workload.startswith("W") and row.implementation == "casteljau"


def headline_rows(rows):
    return (row for row in rows.values() if is_headline(row))


def admissible_peer(row):
    """A peer row that may be the best peer: its check passed and, in W6, it kept the tolerance."""
    if row.kind != "peer" or not row.ok:
        return False
    return row.workload != "W6" or row.counter("within_tolerance", 0) == 1


def best_peer(rows, headline):
    candidates = [r for r in rows.values()
                  if r.workload == headline.workload and r.variant == headline.variant and admissible_peer(r)
                  and condition_of(r) == condition_of(headline)]
    best = None
    for row in candidates:
        if best is None or row.better_than(best):
            best = row
    return best


def speedup(ours, other):
    """How many times faster `ours` is than `other` (rates or times)."""
    return ours.value / other.value if ours.is_rate() else other.value / ours.value


# ---------------------------------------------------------------------------- RESULTS.md


def summary_table(rows, probe):
    lines = ["| workload | casteljau | best peer | casteljau ÷ best peer | of the hardware limit |",
             "|---|---|---|---|---|"]
    for ours in headline_rows(rows):
        label = f"{ours.workload} {ours.variant}" + (f" {condition_of(ours)}" if ours.workload == "W4" else "")
        if not ours.ok:
            lines.append(f"| {label} | FAILED: {ours.error} | | | |")
            continue
        peer = best_peer(rows, ours)
        fraction, limit = fraction_of_limit(ours, probe)
        if ours.workload == "W6":
            mine = (f"{ours.counter('segments'):.0f} segments, {format_time(ours.value)}")
            theirs = (f"{peer.implementation}: {peer.counter('segments'):.0f} segments, {format_time(peer.value)}"
                      if peer else "none within the tolerance")
        else:
            mine = format_value(ours, ours.value)
            theirs = f"{peer.implementation}: {format_value(peer, peer.value)}" if peer else "—"
        if peer is None and ours.workload == "W4":
            continue  # an end condition no peer offers: shown in the W4 table only
        ratio = ratio_text(speedup(ours, peer)) if peer else "—"
        share = f"{percent(fraction)} of {limit}" if fraction is not None else "—"
        lines.append(f"| {label} | **{mine}** | {theirs} | {ratio} | {share} |")
    return lines


def all_core_table(rows):
    lines = ["| row | threads | all cores | one core | speedup |", "|---|---|---|---|---|"]
    found = False
    for row in rows.values():
        if not row.implementation.endswith("-all-cores"):
            continue
        found = True
        single = rows.get(f"{row.workload}/{row.variant}/casteljau")
        if not row.ok:
            lines.append(f"| {row.name} | | FAILED: {row.error} | | |")
            continue
        one = format_value(single, single.value) if single and single.ok else "—"
        gain = ratio_text(row.value / single.value) if single and single.ok else "—"
        lines.append(f"| {row.name} | {row.counter('threads', 0):.0f} | {format_value(row, row.value)} | {one} | {gain} |")
    return lines if found else []


CHECK_COUNTERS = ("max_error_rel", "data_error_rel", "mid_error_rel", "end_error_rel")


def check_text(row):
    if not row.ok:
        return f"**FAILED**: {row.error}"
    if row.counter("spurious") is not None:  # W8: pairs judged against the exact oracle
        return f"pairs with a miss {row.counter('misses'):.0f}, with a spurious point {row.counter('spurious'):.0f}"
    if row.counter("misses") is not None:  # W7: answers farther than the brute-force oracle
        return f"misses {row.counter('misses'):.0f}, worst excess {row.counter('worst_excess_rel'):.1e} of the size"
    values = [f"{key.removesuffix('_rel').replace('_', ' ')} {row.counter(key):.1e}".replace(" 0.0e+00", " 0")
              for key in CHECK_COUNTERS if row.counter(key) is not None]
    return ", ".join(values) + (" of the scale" if values else "")


def workload_table(rows, probe, workload):
    members = [r for r in rows.values() if r.workload == workload]
    if workload == "W6":
        lines = ["| shape | implementation | kind | segments | optimum | max deviation | within 0.01 | time per curve (median) | min – max | of the optimum |",
                 "|---|---|---|---|---|---|---|---|---|---|"]
        for row in members:
            if not row.ok:
                lines.append(f"| {row.variant} | {row.implementation} | {row.kind} | **FAILED**: {row.error} | | | | | | |")
                continue
            median, spread = format_median(row)
            fraction, _ = fraction_of_limit(row, probe)
            within = "yes" if row.counter("within_tolerance") == 1 else "**no**"
            lines.append(f"| {row.variant} | {row.implementation} | {row.kind} | {row.counter('segments'):.0f} | "
                         f"{row.counter('optimum'):.0f} | {row.counter('max_deviation'):.4g} | {within} | {median} | "
                         f"{spread} | {percent(fraction) if fraction else '—'} |")
        return lines
    lines = ["| variant | implementation | kind | median | min – max | casteljau ÷ this | of the hardware limit | check |",
             "|---|---|---|---|---|---|---|---|"]
    headlines = {(r.variant, condition_of(r)): r for r in headline_rows(rows) if r.workload == workload}
    for row in members:
        if not row.ok:
            lines.append(f"| {row.variant} | {row.implementation} | {row.kind} | | | | | {check_text(row)} |")
            continue
        median, spread = format_median(row)
        ours = headlines.get((row.variant, condition_of(row)))
        compared = ours and ours.ok and ours is not row and not row.implementation.endswith("-all-cores")
        ratio = ratio_text(speedup(ours, row)) if compared else "—"
        fraction, _ = fraction_of_limit(row, probe)
        lines.append(f"| {row.variant} | {row.implementation} | {row.kind} | {median} | {spread} | {ratio} | "
                     f"{percent(fraction) if fraction is not None else '—'} | {check_text(row)} |")
    return lines


WORKLOAD_TITLES = OrderedDict(
    W1="W1: cubic B-spline curve in 3D, 10⁶ points (sorted or random parameters)",
    W2="W2: as W1, point and first derivative",
    W3="W3: one Bézier curve of degree 3, 7, 15 in 2D and 3D, 10⁶ random parameters",
    W4="W4: C² cubic interpolation of n 3D points, time per fit",
    W5="W5: bicubic B-spline surface (100 × 100 net) on a 1000 × 1000 grid",
    W6="W6: flattening a cubic Bézier spanning 100 units within 0.01",
    W7="W7: closest point of random queries on a plane cubic Bézier and on W1's curve (in 3D and on the xy plane), time per query",
    W8="W8: intersections of 10⁴ pairs of plane cubic Béziers (10% tangent, 10% near-tangent), time per pair",
    W9="W9: arc length of W1's curve (997 cubic spans in 3D) within 1e-9 relative, time per length",
    W10="W10: reading a 10 MB SVG path and a 10 MB DXF drawing (generated, seeded) into curves, MB of file per second",
    W11="W11: G-code of a 10 MB SVG drawing (generated, seeded; 0.01 mm), arcs or lines, and its cutting order",
)


def results_markdown(rows, probe, context):
    failed = [r for r in rows.values() if not r.ok]
    out = [f"# casteljau benchmarks: the run of {context['date']}", ""]
    build = (f" after {context['build_seconds']} s of building build-bench/"
             if context.get("build_seconds") is not None else "")
    out += [f"Run by `make bench` (bench/run.sh, then bench/report.py): {context['seconds']} s of benchmarks{build}. "
            f"Per-core rows pinned to CPU {context['pinned_cpu']} (`taskset`), all-core rows unpinned; "
            "Google Benchmark, 3 repetitions in random interleaving, median and min – max; "
            "every row's output checked against a reference (the check column), so a fast wrong answer fails the run. "
            "Workloads and peers: `shared/docs/performance.md`; method: [benchmarks.md](benchmarks.md).", ""]
    out += ["## Machine", "",
            f"- machine: {machine_line(context)}; Linux {context['kernel']}",
            f"- load average at the start: {context['load_at_start'] or 'not recorded'}",
            f"- compiler: {context['compiler'] or 'unknown'}, `{context['flags']}`",
            f"- Python {context['python']} (`/usr/bin/python3`)",
            "- packages: " + ", ".join(f"{name} {version}" for name, version in context["packages"].items()), ""]
    cores = all_core_table(rows)
    out += ["## Summary", "", "<!-- summary:begin -->"] + summary_table(rows, probe)
    if cores:
        out += ["", "All cores (the same batch cut into one chunk per core, unpinned):", ""] + cores
    out += ["<!-- summary:end -->", ""]
    out += ["“casteljau ÷ best peer” is how many times faster casteljau's row is than the fastest peer "
            "(OpenCASCADE, SISL, Eigen, scipy, lib2geom, GSL, kurbo, lyon_geom, svgelements, ezdxf) on the same work in this run; in W6 only peers "
            "within the tolerance count, and the segment counts are compared with the optimum.", ""]
    out += ["## Hardware limits of this run", ""]
    probe_rows = [r for r in rows.values() if r.workload == "HW"]
    if probe_rows:
        out += ["| probe | median | min – max |", "|---|---|---|"]
        for row in probe_rows:
            if row.ok:
                median, spread = format_median(row)
                out.append(f"| {row.name} | {median} | {spread} |")
            else:
                out.append(f"| {row.name} | **FAILED**: {row.error} | |")
        out.append("")
    else:
        out += ["No probe rows: fractions of the limit are not given.", ""]
    out += [LIMITS_TEXT]
    for workload, title in WORKLOAD_TITLES.items():
        if any(r.workload == workload for r in rows.values()):
            out += [f"## {title}", ""] + workload_table(rows, probe, workload) + [""]
    if failed:
        out += ["## Failed rows", ""] + [f"- `{r.name}`: {r.error or 'no result'}" for r in failed] + [""]
    return "\n".join(out)


def collect(args):
    rows, entries, contexts = read_rows(args.dir)
    if not rows:
        raise SystemExit(f"report.py: no benchmark rows in {args.dir}")
    probe = Probe(rows)
    context = run_context(args, contexts)
    document = {"context": dict(next(iter(contexts.values()), {}), casteljau_run=context), "benchmarks": entries}
    (Path(args.dir) / "results.json").write_text(json.dumps(document, indent=1) + "\n", encoding="utf-8")
    (Path(args.dir) / "RESULTS.md").write_text(results_markdown(rows, probe, context), encoding="utf-8")
    failed = [r.name for r in rows.values() if not r.ok]
    print(f"report.py: {len(rows)} rows, {len(failed)} failed -> {args.dir}/results.json, {args.dir}/RESULTS.md")
    for name in failed:
        print(f"   failed: {name}")
    return 1 if failed else 0


# ---------------------------------------------------------------------------- README


BEGIN, END = "<!-- bench:begin -->", "<!-- bench:end -->"


def readme_block(results_text):
    """The README's table: RESULTS.md's summary with its date and machine line."""
    date = re.search(r"^# casteljau benchmarks: the run of (.+)$", results_text, re.M)
    machine = re.search(r"^- machine: (.+)$", results_text, re.M)
    summary = re.search(r"<!-- summary:begin -->\n(.*?)<!-- summary:end -->", results_text, re.S)
    if not (date and machine and summary):
        raise SystemExit("report.py: the results file has no date, machine line or summary table")
    return "\n".join([BEGIN,
                      f"Generated from [docs/RESULTS.md](docs/RESULTS.md) by `make bench-publish`: one `make bench` run "
                      f"of {date.group(1)}, {machine.group(1)}.", "",
                      summary.group(1).rstrip("\n"), END])


def readme(args):
    results_text = Path(args.results).read_text(encoding="utf-8")
    readme_path = Path(args.readme)
    text = readme_path.read_text(encoding="utf-8")
    if text.count(BEGIN) != 1 or text.count(END) != 1:
        raise SystemExit(f"report.py: {readme_path} needs one {BEGIN} line and one {END} line")
    start, stop = text.index(BEGIN), text.index(END) + len(END)
    updated = text[:start] + readme_block(results_text) + text[stop:]
    if args.check:
        if updated != text:
            print(f"report.py: {readme_path}'s table differs from {args.results}; run `make bench-publish` "
                  f"or `{sys.argv[0]} readme`", file=sys.stderr)
            return 1
        return 0
    readme_path.write_text(updated, encoding="utf-8")
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    c = commands.add_parser("collect", help="merge a run's JSON files; write results.json and RESULTS.md")
    c.add_argument("--dir", default="out/bench")
    c.add_argument("--seconds", type=int, default=0, help="how long the run took")
    c.add_argument("--build", default="build-bench", help="the bench build (compiler and flags)")
    c.add_argument("--cpu", default="0", help="the CPU per-core rows were pinned to")
    c.add_argument("--load", default="", help="the load average at the start")
    c.add_argument("--build-seconds", default="", help="how long make bench spent building build-bench")
    r = commands.add_parser("readme", help="copy RESULTS.md's summary into README")
    r.add_argument("--results", default="docs/RESULTS.md")
    r.add_argument("--readme", default="README.md")
    r.add_argument("--check", action="store_true", help="exit 1 if README differs, change nothing")
    args = parser.parse_args(argv)
    return collect(args) if args.command == "collect" else readme(args)


if __name__ == "__main__":
    sys.exit(main())

"""bench/report.py: the ratios, limits and failures it writes into RESULTS.md,
on synthetic rows whose answers are worked out by hand, and the README's
benchmark table, which must equal docs/RESULTS.md's summary."""

import importlib.util
import json
import pathlib

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("bench_report", REPOSITORY / "bench" / "report.py")
report = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(report)


def rate_rows(name, per_second, key="items_per_second", **counters):
    """Google Benchmark's entries for one row: 3 repetitions and their median."""
    base = {"run_name": name + "/real_time", "run_type": "iteration", "time_unit": "ms", "real_time": 1.0, **counters}
    spread = (0.9 * per_second, per_second, 1.1 * per_second)
    entries = [dict(base, name=name + "/real_time", repetition_index=i, **{key: v}) for i, v in enumerate(spread)]
    entries.append(dict(base, name=name + "/real_time_median", run_type="aggregate", aggregate_name="median",
                        **{key: per_second}))
    return entries


def time_rows(name, value, unit, **counters):
    base = {"run_name": name + "/real_time", "run_type": "iteration", "time_unit": unit, **counters}
    entries = [dict(base, name=name + "/real_time", repetition_index=i, real_time=v)
               for i, v in enumerate((value, 0.8 * value, 1.3 * value))]
    entries.append(dict(base, name=name + "/real_time_median", run_type="aggregate", aggregate_name="median",
                        real_time=value))
    return entries


def failed_row(name, message):
    return [{"name": name + "/real_time", "run_name": name + "/real_time", "run_type": "iteration",
             "error_occurred": True, "error_message": message}]


def write(directory, stem, entries):
    context = {"num_cpus": 2, "caches": [{"type": "Data", "level": 1, "size": 49152, "num_sharing": 1}]}
    (directory / f"{stem}.json").write_text(json.dumps({"context": context, "benchmarks": entries}), encoding="utf-8")


@pytest.fixture
def run(tmp_path):
    """A run whose figures give round answers:
    FMA 84e9/s and stores 24e9 B/s -> W1 limit min(84e9/42, 24e9/24) = 1e9 points/s, bound by stores."""
    write(tmp_path, "w0_hardware_probe",
          rate_rows("HW/fma/avx512", 84e9) + rate_rows("HW/store-24MB/streaming", 24e9, key="bytes_per_second")
          + rate_rows("HW/store-24MB/ordinary", 12e9, key="bytes_per_second"))
    write(tmp_path, "w1_w2_bspline",
          rate_rows("W1/sorted/casteljau", 500e6, max_error_rel=0.0)
          + rate_rows("W1/sorted/textbook-A3.1", 100e6, max_error_rel=4e-16)  # a baseline, never the best peer
          + rate_rows("W1/sorted/occt-adaptor", 25e6, max_error_rel=9e-16)
          + rate_rows("W3/deg3-2d/casteljau", 800e6, max_error_rel=3e-16)
          + failed_row("W3/deg3-2d/occt", "relative error 0.5 exceeds the bound"))
    write(tmp_path, "w1_w2_bspline-all-cores", rate_rows("W1/sorted/casteljau-all-cores", 900e6, threads=2))
    write(tmp_path, "w1_scipy", rate_rows("W1/sorted/scipy-BSpline", 50e6, max_error_rel=1e-16))
    write(tmp_path, "w4_interpolation",
          time_rows("W4/n1000000/casteljau-natural", 40.0, "ms", data_error_rel=1e-16)
          + time_rows("W4/n1000000/gsl-cspline-natural", 160.0, "ms", data_error_rel=1e-16)
          + time_rows("W4/n1000000/casteljau-not-a-knot", 40.0, "ms")
          + time_rows("W4/n1000000/sisl-s1357-periodic", 1.0, "ms"))  # another condition: not a natural peer
    write(tmp_path, "w6_flatten",
          time_rows("W6/s-curve/casteljau", 4000.0, "ns", segments=78, optimum=78, within_tolerance=1,
                    max_deviation=0.00999)
          + time_rows("W6/s-curve/occt-quasi-uniform-deflection", 700.0, "ns", segments=1, optimum=78,
                      within_tolerance=0, max_deviation=20.4)
          + time_rows("W6/s-curve/occt-uniform-deflection", 26000.0, "ns", segments=82, optimum=78,
                      within_tolerance=1, max_deviation=0.01))
    return tmp_path


def collect(directory):
    return report.main(["collect", "--dir", str(directory), "--seconds", "321", "--build", str(directory),
                        "--cpu", "1", "--load", "0.5 0.4 0.3"])


def summary_lines(directory):
    text = (directory / "RESULTS.md").read_text(encoding="utf-8")
    block = text.split("<!-- summary:begin -->\n")[1].split("<!-- summary:end -->")[0]
    return {line.split(" | ")[0].lstrip("| "): line for line in block.splitlines()[2:]}


def test_ratio_to_the_best_peer_and_fraction_of_the_limit(run):
    collect(run)
    line = summary_lines(run)["W1 sorted"]
    # scipy's 50 M/s is the fastest peer (the textbook's 100 is ours, not a peer): 500 / 50 = 10x;
    # the limit is 1e9 points/s by the stores, so 500 M/s is 50 %.
    assert "**500 M/s**" in line
    assert "scipy-BSpline: 50.0 M/s" in line
    assert "| 10.0× |" in line
    assert "50 % of 1,000 M/s (stores)" in line


def test_times_compare_the_same_end_condition(run):
    collect(run)
    lines = summary_lines(run)
    # 160 ms / 40 ms; the 1 ms periodic SISL row is another problem and must not count.
    assert "gsl-cspline-natural: 160 ms" in lines["W4 n1000000 natural"]
    assert "| 4.00× |" in lines["W4 n1000000 natural"]
    # not-a-knot has no peer in this run: it stays out of the summary.
    assert "W4 n1000000 not-a-knot" not in lines
    # The W4 limit: max(15 n / 84e9, 24 n / 24e9) = 1 ms per fit for n = 1e6; 1 / 40 = 2.5 %.
    assert "2.5 % of 1.00 ms per fit" in lines["W4 n1000000 natural"]


def test_flattening_peers_over_the_tolerance_are_not_the_best(run):
    collect(run)
    line = summary_lines(run)["W6 s-curve"]
    # The quasi-uniform row is faster but 2000 times over the tolerance; the
    # uniform one keeps it: 26 us / 4 us = 6.5x, and 78 of an optimum 78 is 100 %.
    assert "occt-uniform-deflection: 82 segments, 26.0 µs" in line
    assert "| 6.50× |" in line
    assert "100 % of optimum 78 segments" in line
    table = (run / "RESULTS.md").read_text(encoding="utf-8")
    assert "| s-curve | occt-quasi-uniform-deflection | peer | 1 | 78 | 20.4 | **no** |" in table


def test_all_core_rows_are_compared_with_the_one_core_row(run):
    collect(run)
    table = (run / "RESULTS.md").read_text(encoding="utf-8")
    assert "| W1/sorted/casteljau-all-cores | 2 | 900 M/s | 500 M/s | 1.80× |" in table


def test_a_failed_row_fails_the_report_and_is_listed(run):
    assert collect(run) == 1
    text = (run / "RESULTS.md").read_text(encoding="utf-8")
    assert "- `W3/deg3-2d/occt`: relative error 0.5 exceeds the bound" in text
    # Without a peer that passed its check, W3 has no ratio.
    assert "| W3 deg3-2d | **800 M/s** | — | — |" in text


def test_a_clean_run_passes(run):
    path = run / "w1_w2_bspline.json"
    document = json.loads(path.read_text(encoding="utf-8"))
    document["benchmarks"] = [e for e in document["benchmarks"] if not e.get("error_occurred")]
    path.write_text(json.dumps(document), encoding="utf-8")
    assert collect(run) == 0


def test_results_json_holds_every_entry_with_its_source(run):
    collect(run)
    document = json.loads((run / "results.json").read_text(encoding="utf-8"))
    sources = {entry["source"] for entry in document["benchmarks"]}
    assert sources == {"w0_hardware_probe", "w1_w2_bspline", "w1_w2_bspline-all-cores", "w1_scipy",
                       "w4_interpolation", "w6_flatten"}
    assert len(document["benchmarks"]) == 4 * 16 + 1
    run_context = document["context"]["casteljau_run"]
    assert run_context["seconds"] == 321 and run_context["load_at_start"] == "0.5 0.4 0.3"
    assert "libbenchmark-dev" in run_context["packages"]


def test_a_crashed_benchmark_file_is_reported(run):
    (run / "w5_surface.json").write_text('{"context": {}, "benchmarks": [', encoding="utf-8")
    with pytest.raises(SystemExit, match="w5_surface.json is not JSON"):
        collect(run)


def test_readme_block_is_replaced_and_checked(run, tmp_path):
    collect(run)
    readme = tmp_path / "README.md"
    readme.write_text("# x\n\nbefore\n<!-- bench:begin -->\nstale\n<!-- bench:end -->\nafter\n", encoding="utf-8")
    arguments = ["readme", "--results", str(run / "RESULTS.md"), "--readme", str(readme)]
    assert report.main(arguments + ["--check"]) == 1
    assert report.main(arguments) == 0
    text = readme.read_text(encoding="utf-8")
    assert text.startswith("# x\n\nbefore\n<!-- bench:begin -->\nGenerated from")
    assert text.endswith("<!-- bench:end -->\nafter\n")
    assert "| W1 sorted | **500 M/s** |" in text
    assert report.main(arguments + ["--check"]) == 0


def test_the_committed_readme_table_is_the_committed_results_summary():
    assert report.main(["readme", "--results", str(REPOSITORY / "docs" / "RESULTS.md"),
                        "--readme", str(REPOSITORY / "README.md"), "--check"]) == 0

"""What a cut costs through Python beyond the same cut in C++ (at most 2 us, without
building report.changes; the cost of building it beside). pytest-benchmark, on the README sweep
(the liver, 8 mm tool, 36 cuts); not part of ctest (a measurement, not a test):

    PYTHONPATH=build/release/python/module /usr/bin/python3 -m pytest python/bench -q -p no:cacheprovider

How the overhead is told apart from the cut: the binding times the engine call itself
(report.wall_us, steady_clock around Cutter::cut with the ChangeLog, as a C++ caller calls it),
and the Python loop times the whole cutter.cut(centre) call with perf_counter_ns; the difference,
cut by cut on the same cut, is what Python adds (argument conversion, the mesh's lock, releasing
and taking back the GIL, the report object). The sweeps themselves (Python loop vs the C++ loop
of cutter.sweep) are benchmarked too, for the absolute figures.
"""
import pathlib
import statistics
import time

import numpy  # noqa: F401  imported up front: the first report.changes would otherwise pay numpy's import (~0.1 s)

import tetcut

LIVER = str(pathlib.Path(__file__).resolve().parents[2] / "corpus" / "meshes" / "liver.msh")
START, END, STEP = (95.0, 40.0, 100.0), (95.0, 180.0, 100.0), 4.0
CENTRES = [(95.0, 40.0 + 4.0 * k, 100.0) for k in range(36)]
ROUNDS = 7


def fresh_cutter():
    return (tetcut.Cutter(tetcut.read(LIVER), tool_diameter=8.0),), {}


def summary(values):
    values = sorted(values)
    return {"median": statistics.median(values), "p90": values[int(0.9 * (len(values) - 1))], "max": values[-1],
            "mean": statistics.fmean(values), "n": len(values)}


overheads, changes_costs = [], []


def python_loop(cutter, build_changes=False):
    clock = time.perf_counter_ns
    for centre in CENTRES:
        t0 = clock()
        report = cutter.cut(centre)
        t1 = clock()
        overheads.append((t1 - t0) / 1000.0 - report.wall_us)
        if build_changes:
            report.changes
            changes_costs.append((clock() - t1) / 1000.0)


def test_sweep_through_python_cut_by_cut(benchmark):
    overheads.clear()
    benchmark.pedantic(python_loop, setup=fresh_cutter, rounds=ROUNDS, iterations=1)
    s = summary(overheads)
    benchmark.extra_info["overhead_per_cut_us"] = s
    print(f"\nPython overhead per cut (us), {s['n']} cuts: median {s['median']:.2f}, p90 {s['p90']:.2f}, "
          f"max {s['max']:.2f} (goal: at most 2)")
    assert s["n"] == ROUNDS * len(CENTRES)


def test_sweep_through_the_cpp_loop(benchmark):
    def sweep(cutter):
        assert len(cutter.sweep(START, END, STEP)) == len(CENTRES)
    benchmark.pedantic(sweep, setup=fresh_cutter, rounds=ROUNDS, iterations=1)


def test_building_report_changes(benchmark):
    changes_costs.clear()
    benchmark.pedantic(lambda cutter: python_loop(cutter, build_changes=True), setup=fresh_cutter,
                       rounds=ROUNDS, iterations=1)
    s = summary(changes_costs)
    benchmark.extra_info["changes_per_cut_us"] = s
    print(f"\nbuilding report.changes per cut (us): median {s['median']:.2f}, p90 {s['p90']:.2f}, max {s['max']:.2f}")

#!/usr/bin/env python3
"""ctest ci.calibrate: bench/calibrate_budgets.py tightens wall-time bounds and never loosens
them, except for a figure named with --redefined (its benchmark now measures something else).

Six synthetic runs, each spread about 1 %, so that the bound is 1.5 x the slowest run rounded
up to two digits (the 99.9 % prediction bound is lower): "steady" at 10-10.2 us under a bound
of 100 is tightened to 16 (1.5 x 10.2 = 15.3); "slow" at 49.8-50 us under a bound of 20 would
need 75 and keeps 20; "first cut" at 30-30.9 us under a bound of 20, named as redefined, is
raised to 47 (1.5 x 30.9 = 46.35) and its calibration says "measurement redefined"; the count
figure is left alone; and a --redefined naming no figure is refused. Runs that started on a busy
machine (Google Benchmark's load average) are refused unless --busy says so.

`instructions` pins every callgrind figure at once (instructions and cache: baseline, +3 % bound,
toolchain), records the commit given as the paired comparison's reference, and refuses results
that lack one of the figures.

    calibrate_test.py SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

from checks import check, verdict  # noqa: E402 (this folder is on sys.path: the script's own)


def figure(name, field, bound, kind="time"):
    return {"name": name, "benchmark": "BM_X", "field": field, "max": bound, "kind": kind}


def run_file(folder, i, steady, slow, first):
    path = os.path.join(folder, f"run-{i}.json")
    bench = {"name": "BM_X_median", "run_name": "BM_X", "run_type": "aggregate", "aggregate_name": "median",
             "steady_us": steady, "slow_us": slow, "first_us": first, "allocations": 0}
    with open(path, "w", encoding="utf-8") as f:
        json.dump({"benchmarks": [bench]}, f)
    return path


def main(src):
    script = os.path.join(src, "bench", "calibrate_budgets.py")
    with tempfile.TemporaryDirectory() as folder:
        budgets_path = os.path.join(folder, "budgets.json")
        budgets = {"comment": "test", "figures": [
            figure("steady (us)", "steady_us", 100), figure("slow (us)", "slow_us", 20),
            figure("first cut (us)", "first_us", 20), figure("allocations", "allocations", 0, "count")]}
        with open(budgets_path, "w", encoding="utf-8") as f:
            json.dump(budgets, f)
        runs = [run_file(folder, i, 10 + 0.1 * (i % 3), 50 - 0.2 * (i % 2), 30 + 0.3 * (i % 4)) for i in range(6)]

        done = subprocess.run([sys.executable, script, "times", budgets_path, "--redefined", "first cut", *runs],
                              capture_output=True, text=True)
        print(done.stdout, done.stderr)
        check(done.returncode == 0, f"calibrate_budgets.py exited {done.returncode}")
        with open(budgets_path, encoding="utf-8") as f:
            after = {g["name"]: g for g in json.load(f)["figures"]}
        check(after["steady (us)"]["max"] == 16, f"steady: {after['steady (us)']['max']}, expected 16 (1.5 x 10.2)")
        check(after["slow (us)"]["max"] == 20, f"slow: {after['slow (us)']['max']}, expected 20 kept (never loosened)")
        first = after["first cut (us)"]
        check(first["max"] == 47, f"first cut: {first['max']}, expected 47 (redefined: 1.5 x 30.9)")
        check(first.get("calibration", "").startswith("measurement redefined; "),
              "the redefined figure's calibration does not say so: " + first.get("calibration", ""))
        check(after["allocations"]["max"] == 0 and "calibration" not in after["allocations"], "a count was calibrated")

        refused = subprocess.run([sys.executable, script, "times", budgets_path, "--redefined", "no such", *runs],
                                 capture_output=True, text=True)
        check(refused.returncode != 0 and "names no figure" in refused.stderr,
              f"a --redefined naming no figure was not refused: {refused.returncode} {refused.stderr}")
        # The same runs, one of them started at a load of 6 on this machine's cores.
        with open(runs[2], encoding="utf-8") as f:
            busy = json.load(f)
        busy["context"] = {"load_avg": [6.0 * (os.cpu_count() or 1), 5.0, 4.0]}
        with open(runs[2], "w", encoding="utf-8") as f:
            json.dump(busy, f)
        refused = subprocess.run([sys.executable, script, "times", budgets_path, *runs], capture_output=True, text=True)
        check(refused.returncode != 0 and "idle machine" in refused.stderr,
              f"runs taken on a busy machine were not refused: {refused.returncode} {refused.stderr}")
        taken = subprocess.run([sys.executable, script, "times", budgets_path, "--busy", *runs],
                               capture_output=True, text=True)
        check(taken.returncode == 0, f"--busy did not take the runs: {taken.returncode} {taken.stderr}")

        check_instructions(script, folder)
    return verdict("calibration tightens, loosens only a redefined figure, refuses a busy machine's runs, "
                   "and pins every callgrind figure with the reference commit")


def check_instructions(script, folder):
    budgets_path = os.path.join(folder, "callgrind-budgets.json")
    budgets = {"comment": "test", "figures": [
        {"name": "instructions per cut", "benchmark": "instructions_per_cut", "field": "instructions_per_cut",
         "kind": "instructions", "baseline": 1, "max": 1},
        {"name": "instructions in locate", "benchmark": "instructions_per_cut/locate", "field": "per_cut",
         "kind": "instructions", "baseline": 1, "max": 1},
        {"name": "cache misses", "benchmark": "ll_misses_per_cut", "field": "ll_misses_per_cut", "kind": "cache",
         "baseline": 1, "max": 1},
        figure("steady (us)", "steady_us", 100)]}
    with open(budgets_path, "w", encoding="utf-8") as f:
        json.dump(budgets, f)

    def entry(name, **fields):
        return {"name": name, "run_name": name, "run_type": "iteration", "toolchain": "GNU 1", **fields}

    results = {"benchmarks": [entry("instructions_per_cut", instructions_per_cut=200000),
                              entry("instructions_per_cut/locate", per_cut=30000),
                              entry("ll_misses_per_cut", ll_misses_per_cut=400)]}
    results_path = os.path.join(folder, "callgrind.json")
    with open(results_path, "w", encoding="utf-8") as f:
        json.dump(results, f)
    done = subprocess.run([sys.executable, script, "instructions", budgets_path, results_path, "--commit", "abc123"],
                          capture_output=True, text=True)
    check(done.returncode == 0, f"calibrate_budgets.py instructions exited {done.returncode}: {done.stderr}")
    with open(budgets_path, encoding="utf-8") as f:
        after = json.load(f)
    got = {g["name"]: (g["baseline"], g["max"], g.get("toolchain")) for g in after["figures"] if "baseline" in g}
    check(got == {"instructions per cut": (200000, 206000, "GNU 1"), "instructions in locate": (30000, 30900, "GNU 1"),
                  "cache misses": (400, 412, "GNU 1")}, f"the callgrind figures were pinned as {got}")
    check(after.get("reference", {}).get("commit") == "abc123", f"the reference is {after.get('reference')}")

    del results["benchmarks"][1]
    with open(results_path, "w", encoding="utf-8") as f:
        json.dump(results, f)
    refused = subprocess.run([sys.executable, script, "instructions", budgets_path, results_path],
                             capture_output=True, text=True)
    check(refused.returncode != 0 and "instructions in locate" in refused.stderr,
          f"results lacking a callgrind figure were not refused: {refused.returncode} {refused.stderr}")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

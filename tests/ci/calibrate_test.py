#!/usr/bin/env python3
"""ctest ci.calibrate: bench/calibrate_budgets.py tightens wall-time bounds and never loosens
them, except for a figure named with --redefined (its benchmark now measures something else).

Six synthetic runs, each spread about 1 %, so that the bound is 1.5 x the slowest run rounded
up to two digits (the 99.9 % prediction bound is lower): "steady" at 10-10.2 us under a bound
of 100 is tightened to 16 (1.5 x 10.2 = 15.3); "slow" at 49.8-50 us under a bound of 20 would
need 75 and keeps 20; "first cut" at 30-30.9 us under a bound of 20, named as redefined, is
raised to 47 (1.5 x 30.9 = 46.35) and its calibration says "measurement redefined"; the count
figure is left alone; and a --redefined naming no figure is refused.

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
    return verdict("calibration tightens, and loosens only a redefined figure")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

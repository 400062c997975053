#!/usr/bin/env python3
"""ctest ci.pr_table: bench/pr_table.py's Markdown for two results files with known changes
(bench/testdata/pr_base.json, pr_head.json, pr_budgets.json) and compare.py's comparison of them,
made here as `ci/bench --compare` makes it (bench/compare_results.sh); and bench/trend_points.py's
points.

In the test data the instruction count grows by 10 % past its budget, the cut p50 moves from
80 to 100 us over 5 repetitions each with the sweep's time (Mann-Whitney: significant), and the
16k build moves by 1 % inside its noise over 3 repetitions. The table takes its p-values from
compare.py's result: a comparison edited to say otherwise changes the table.

    pr_table_test.py SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

from checks import check, verdict  # noqa: E402 (this folder is on sys.path: the script's own)


def pr_table(bench, *args):
    return subprocess.run([sys.executable, os.path.join(bench, "pr_table.py"), *args], capture_output=True, text=True)


def main(src):
    with tempfile.TemporaryDirectory() as tmp:
        return run_checks(src, tmp)


def run_checks(src, tmp):
    bench = os.path.join(src, "bench")
    data = [os.path.join(bench, "testdata", n) for n in ("pr_base.json", "pr_head.json", "pr_budgets.json")]
    comparison = os.path.join(tmp, "head.compare.json")
    made = subprocess.run([os.path.join(bench, "compare_results.sh"), data[0], data[1], comparison],
                          capture_output=True, text=True)
    check(made.returncode == 0, f"compare_results.sh exited {made.returncode}: {made.stderr}")
    run = pr_table(bench, *data, comparison)
    print(run.stdout, run.stderr)
    check(run.returncode == 0, f"pr_table.py exited {run.returncode}")
    lines = run.stdout.splitlines()
    rows = [line for line in lines if line.startswith("| ") and not line.startswith("| figure")]
    check(lines and lines[0] == "<!-- tetcut-benchmark-delta -->", "the first line is not the comment marker")
    check("| figure | base | head | change | significance | budget |" in lines, "the header is not the issue's")
    check(len(rows) == 3, f"{len(rows)} rows, expected one per figure (3)")
    if len(rows) == 3:
        check(rows[0] == "| instructions per cut (callgrind) | 300,000 | 330,000 | +10.0 % | exact | <= 320,000 **OVER** |",
              "the instruction count is not the first row, or its cells are wrong: " + rows[0])
        by_name = {r.split(" | ")[0][2:]: r for r in rows}
        p50 = by_name.get("cut p50, 16k liver (us)", "")
        check("| 80 | 100 | +25.0 % | significant (p=0.01 for the benchmark's time, n=5+5) | <= 250 ok |" in p50,
              "cut p50 row: " + p50)
        build = by_name.get("build 16k tets (ms)", "")
        check("| 10.5 | 10.4 | -1.0 % | noise (p=1.00, n=3+3) | <= 40 ok |" in build, "build row: " + build)
    check("3 figures: 1 over budget at the head, 0 not measured at the head." in lines, "the summary line")

    # The p-value is compare.py's, read and not recomputed: say the sweep's times did not differ.
    edited = json.load(open(comparison)) if os.path.exists(comparison) else []
    for entry in edited:
        if entry.get("name") == "BM_CutSweep/0/iterations:1" and entry.get("utest"):
            entry["utest"]["time_pvalue"] = 0.5
    edited_path = os.path.join(tmp, "edited.compare.json")
    json.dump(edited, open(edited_path, "w"))
    run = pr_table(bench, *data, edited_path)
    check("| 80 | 100 | +25.0 % | noise (p=0.50 for the benchmark's time, n=5+5) | <= 250 ok |" in run.stdout,
          "the cut p50 row does not follow compare.py's p-value: " + run.stdout)

    bad = pr_table(bench, data[0], "/nonexistent.json", data[2], comparison)
    check(bad.returncode == 2 and "cannot read results /nonexistent.json" in bad.stderr,
          f"an unreadable file: exit {bad.returncode}, {bad.stderr.strip()}")
    usage = pr_table(bench, *data)
    check(usage.returncode == 2, f"without compare.py's result: exit {usage.returncode}, expected 2 (usage)")

    out = os.path.join(tmp, "points.json")
    run = subprocess.run([sys.executable, os.path.join(bench, "trend_points.py"), data[1], data[2], out],
                         capture_output=True, text=True)
    check(run.returncode == 0, f"trend_points.py exited {run.returncode}: {run.stderr}")
    points = json.load(open(out)) if os.path.exists(out) else []
    values = {p["name"]: (p["value"], p["unit"]) for p in points}
    check(values == {"build 16k tets (ms)": (10.4, "ms"), "cut p50, 16k liver (us)": (100.0, "us"),
                     "instructions per cut (callgrind)": (330000.0, "instructions")},
          f"trend points: {values}")
    return verdict("pr_table.py and trend_points.py: as specified")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

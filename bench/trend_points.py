#!/usr/bin/env python3
"""The gated figures of one `ci/bench` run as points of a trend, for the history on main.

    trend_points.py RESULTS.json BUDGETS.json OUT.json

Writes github-action-benchmark's `customSmallerIsBetter` input: one point per figure of
bench/budgets.json with an upper bound (all of them today), named as the budget names it, with
its unit and the budget as `extra`. The trend so follows the figures the gate judges (the
instruction count, the cut percentiles), not every raw benchmark and aggregate of the Google
Benchmark file, whose names change when a suite's arguments do. A figure with a lower bound
(bigger is better) would need its own series and is left out, with a note on stderr. A figure
missing from RESULTS (the instruction count when ci/bench ran without --instructions) is left
out too.

Exit 0, 2 on unreadable input or bad usage.
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from budget_gate import load, measured_value  # noqa: E402


def unit_of(figure):
    """"cut p50, 16k liver (us)" -> "us"; an instruction count -> "instructions"; a simulated cache
    miss count -> "misses"; a paired ratio -> "ratio"; else the field."""
    if figure.get("kind") == "cache":
        return "misses"
    if figure.get("kind") == "paired":
        return "ratio"
    if figure.get("kind") == "instructions" or "instructions" in figure["field"]:
        return "instructions"
    m = re.search(r"\(([^()]*)\)\s*$", figure["name"])
    return m.group(1) if m else figure["field"]


def points(results, budgets):
    out = []
    for figure in budgets.get("figures", []):
        if "max" not in figure:
            print(f"trend_points: '{figure['name']}' has a lower bound: not in the smaller-is-better trend",
                  file=sys.stderr)
            continue
        value = measured_value(results, figure)
        if value is None:
            continue
        out.append({"name": figure["name"], "unit": unit_of(figure), "value": value,
                    "extra": f"budget <= {figure['max']:g}; {figure['benchmark']} {figure['field']}"})
    return out


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    data = points(load(argv[1], "results"), load(argv[2], "budgets"))
    tmp = argv[3] + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(data, f, indent=1)
    os.replace(tmp, argv[3])
    print(f"trend_points: {len(data)} figures written to {argv[3]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/python3
"""The pull-request delta: one Markdown row per gated figure of bench/budgets.json.

    pr_table.py BASE.json HEAD.json BUDGETS.json COMPARE.json [--alpha A]

BASE and HEAD are results files of `ci/bench` (Google Benchmark JSON, merged across suites),
run on the same machine; COMPARE is what Google Benchmark's compare.py made of them
(`ci/bench --compare BASE.json` writes it beside HEAD as HEAD.compare.json, through
bench/compare_results.sh). Columns: figure, base, head, change, significance, budget (the head's
value against it). The callgrind figures (instruction counts and simulated cache misses, `ci/bench
--instructions`) come first: they do not depend on the runner's load, so any change is real for
one toolchain ("exact"). Wall-time
figures follow with compare.py's two-sided Mann-Whitney U test over the repetitions of their
benchmark, read from COMPARE and not computed again: "significant" when p < alpha (0.05) and the
medians are more than 1 % apart. compare.py tests a benchmark's own time (real_time, or
cpu_time for a cpu_time figure); a figure read from a counter (a per-cut percentile of a sweep)
gets the p-value of its benchmark's time, and its cell says so.

Prints the Markdown (the workflow adds it to the job summary and to a pull-request comment).
Exit 0 (information, not a gate: ci/gate is the gate), 2 on unreadable input or bad usage.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from budget_gate import is_callgrind, load, measured_value  # noqa: E402

# Marks the comment the workflow updates instead of adding a new one on every push.
MARKER = "<!-- tetcut-benchmark-delta -->"
NOISE_FLOOR_PERCENT = 1.0


def u_tests(comparison):
    """compare.py's U test of each benchmark, by name (its repetitions, not its aggregates)."""
    return {entry["name"]: entry["utest"] for entry in comparison
            if isinstance(entry, dict) and entry.get("run_type") == "iteration" and entry.get("utest")}


def number(value):
    if value is None:
        return "-"
    if value == int(value) and abs(value) >= 1000:
        return f"{int(value):,}"
    return f"{value:.4g}"


def significance(figure, vb, vh, tests, alpha):
    if vb is None or vh is None:
        return ""
    if is_callgrind(figure):
        return "exact"
    test = tests.get(figure["benchmark"])
    if test is None:
        return "not tested (fewer than 2 repetitions each)"
    p = float(test["cpu_pvalue"] if figure["field"] == "cpu_time" else test["time_pvalue"])
    apart = vb != 0 and abs(vh - vb) / abs(vb) * 100 > NOISE_FLOOR_PERCENT
    of = "" if figure["field"] in ("real_time", "cpu_time") else " for the benchmark's time"
    n = f"n={test['nr_of_repetitions']}+{test['nr_of_repetitions_other']}"
    return f"{'significant' if p < alpha and apart else 'noise'} (p={p:.2f}{of}, {n})"


def budget_cell(figure, head_value):
    if "max" in figure:
        bound, ok, sign = float(figure["max"]), (lambda v, b: v <= b), "<="
    else:
        bound, ok, sign = float(figure["min"]), (lambda v, b: v >= b), ">="
    if head_value is None:
        return f"{sign} {number(bound)}", None
    within = ok(head_value, bound)
    return f"{sign} {number(bound)} {'ok' if within else '**OVER**'}", within


def change_cell(base_value, head_value):
    if base_value is None or head_value is None:
        return "-"
    if base_value == 0:
        return "same" if head_value == 0 else "new"
    return f"{(head_value - base_value) / abs(base_value) * 100:+.1f} %"


def table(base, head, budgets, comparison, alpha):
    tests = u_tests(comparison)
    figures = budgets.get("figures", [])
    ordered = [f for f in figures if is_callgrind(f)] + [f for f in figures if not is_callgrind(f)]
    rows, over, missing = [], 0, 0
    for figure in ordered:
        vb, vh = measured_value(base, figure), measured_value(head, figure)
        budget, within = budget_cell(figure, vh)
        over += within is False
        missing += vh is None
        rows.append((figure["name"], number(vb), number(vh), change_cell(vb, vh),
                     significance(figure, vb, vh, tests, alpha), budget))
    lines = [MARKER, "### Benchmarks: this pull request against its base", "",
             "Instruction counts (callgrind) first: exact for one toolchain, so any change is real. "
             "Wall times are medians over repetitions on a shared runner, with the Mann-Whitney U test "
             "of Google Benchmark's compare.py over their benchmark's repetitions "
             f"(significant: p < {alpha:g} and more than {NOISE_FLOOR_PERCENT:g} % apart). "
             "The budget column judges the head.", "",
             "| figure | base | head | change | significance | budget |", "|---|---|---|---|---|---|"]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    lines += ["", f"{len(rows)} figures: {over} over budget at the head, {missing} not measured at the head."]
    return "\n".join(lines) + "\n"


def main(argv):
    args = list(argv[1:])
    alpha = 0.05
    if "--alpha" in args:
        i = args.index("--alpha")
        try:
            alpha = float(args[i + 1])
        except (IndexError, ValueError):
            print("pr_table: --alpha needs a number", file=sys.stderr)
            return 2
        del args[i:i + 2]
    if len(args) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    base, head, budgets = load(args[0], "results"), load(args[1], "results"), load(args[2], "budgets")
    comparison = load(args[3], "compare.py result")
    sys.stdout.write(table(base, head, budgets, comparison, alpha))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

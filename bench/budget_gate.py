#!/usr/bin/env python3
"""The budget gate: compares Google Benchmark JSON results with bench/budgets.json.

Prints one row per gated figure (figure, measured, budget, margin) and exits
0 when every figure is within budget, 1 when any exceeds it, 2 when a figure is
missing from the results or a file cannot be read.

A figure reads the `median` aggregate of its benchmark when the run had
repetitions (robust to a noisy neighbour on a 2-core machine), else the single
run's value.
"""
import json
import sys


def load(path, what):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        print(f"budget_gate: cannot read {what} {path}: {e}", file=sys.stderr)
        sys.exit(2)


def measured_value(results, figure):
    runs = [b for b in results.get("benchmarks", []) if b.get("run_name", b.get("name")) == figure["benchmark"]]
    medians = [b for b in runs if b.get("aggregate_name") == "median"]
    plain = [b for b in runs if b.get("run_type", "iteration") == "iteration"]
    chosen = medians[0] if medians else (plain[0] if plain else None)
    if chosen is None or figure["field"] not in chosen:
        return None
    return float(chosen[figure["field"]])


def main(argv):
    skip = set()
    if "--skip-missing" in argv:
        i = argv.index("--skip-missing")
        skip = set(argv[i + 1].split(","))
        argv = argv[:i] + argv[i + 2:]
    if len(argv) != 3:
        print("usage: budget_gate.py RESULTS.json BUDGETS.json [--skip-missing BENCH,...]", file=sys.stderr)
        return 2
    results = load(argv[1], "results")
    budgets = load(argv[2], "budgets")
    rows, failed, missing = [], 0, 0
    for figure in budgets.get("figures", []):
        value = measured_value(results, figure)
        if "max" in figure:
            bound, ok_cmp, sign = float(figure["max"]), (lambda v, b: v <= b), "<="
        else:
            bound, ok_cmp, sign = float(figure["min"]), (lambda v, b: v >= b), ">="
        if value is None and figure["benchmark"] in skip:
            rows.append((figure["name"], "not run", f"{sign} {bound:g}", "", "skipped"))
            continue
        if value is None:
            missing += 1
            rows.append((figure["name"], "missing", f"{sign} {bound:g}", "", "MISSING"))
            continue
        ok = ok_cmp(value, bound)
        failed += not ok
        if bound == 0:
            margin_text = "exact"
        else:
            margin = (bound - value) / bound * 100 if "max" in figure else (value - bound) / bound * 100
            margin_text = f"{margin:+.0f}%"
        rows.append((figure["name"], f"{value:.4g}", f"{sign} {bound:g}", margin_text, "ok" if ok else "OVER BUDGET"))

    header = ("figure", "measured", "budget", "margin", "status")
    widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(5)]
    for r in [header] + rows:
        print("  ".join(str(c).ljust(w) for c, w in zip(r, widths)))
    skipped = sum(1 for r in rows if r[4] == "skipped")
    print(f"budget gate: {len(rows) - failed - missing - skipped} within budget, {failed} over, {missing} missing, {skipped} skipped")
    if missing:
        return 2
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/python3
"""The pull-request delta: one Markdown row per gated figure of bench/budgets.json.

    pr_table.py BASE.json HEAD.json BUDGETS.json [--alpha A]

BASE and HEAD are results files of `ci/bench` (Google Benchmark JSON, merged across suites),
run on the same machine. Columns: figure, base, head, change, significance, budget (the head's
value against it). Instruction counts (callgrind, `ci/bench --instructions`) come first: they do
not depend on the runner's load, so any change is real for one toolchain ("exact"). Wall-time
figures follow, with a two-sided Mann-Whitney U test over their repetitions (scipy's, the one
Google Benchmark's compare.py uses; Debian's python3-scipy, so run it with /usr/bin/python3):
"significant" when p < alpha (0.05) and the medians are more than 1 % apart.

Prints the Markdown (the workflow adds it to the job summary and to a pull-request comment).
Exit 0 (information, not a gate: ci/gate is the gate), 2 on unreadable input or bad usage.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from budget_gate import load, measured_value  # noqa: E402

# Marks the comment the workflow updates instead of adding a new one on every push.
MARKER = "<!-- tetcut-benchmark-delta -->"
NOISE_FLOOR_PERCENT = 1.0


def is_instruction_count(figure):
    return "instructions" in figure["field"]


def repetition_samples(results, figure):
    """The figure's field in every repetition of its benchmark (not the aggregates)."""
    return [float(b[figure["field"]]) for b in results.get("benchmarks", [])
            if b.get("run_name", b.get("name")) == figure["benchmark"]
            and b.get("run_type", "iteration") == "iteration" and figure["field"] in b]


def number(value):
    if value is None:
        return "-"
    if value == int(value) and abs(value) >= 1000:
        return f"{int(value):,}"
    return f"{value:.4g}"


def significance(figure, base, head, alpha):
    if base is None or head is None:
        return ""
    if is_instruction_count(figure):
        return "exact"
    xb, xh = repetition_samples(base, figure), repetition_samples(head, figure)
    if len(xb) < 2 or len(xh) < 2:
        return "one run each: no test"
    from scipy.stats import mannwhitneyu  # python3-scipy (ci/packages.txt)

    p = float(mannwhitneyu(xb, xh, alternative="two-sided").pvalue)
    vb, vh = measured_value(base, figure), measured_value(head, figure)
    apart = vb != 0 and abs(vh - vb) / abs(vb) * 100 > NOISE_FLOOR_PERCENT
    return f"{'significant' if p < alpha and apart else 'noise'} (p={p:.2f}, n={len(xb)}+{len(xh)})"


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


def table(base, head, budgets, alpha):
    figures = budgets.get("figures", [])
    ordered = [f for f in figures if is_instruction_count(f)] + [f for f in figures if not is_instruction_count(f)]
    rows, over, missing = [], 0, 0
    for figure in ordered:
        vb, vh = measured_value(base, figure), measured_value(head, figure)
        budget, within = budget_cell(figure, vh)
        over += within is False
        missing += vh is None
        rows.append((figure["name"], number(vb), number(vh), change_cell(vb, vh),
                     significance(figure, base, head, alpha), budget))
    lines = [MARKER, "### Benchmarks: this pull request against its base", "",
             "Instruction counts (callgrind) first: exact for one toolchain, so any change is real. "
             "Wall times are medians over repetitions on a shared runner, tested with Mann-Whitney "
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
    if len(args) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    base, head, budgets = load(args[0], "results"), load(args[1], "results"), load(args[2], "budgets")
    sys.stdout.write(table(base, head, budgets, alpha))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""The budget gate: compares Google Benchmark JSON results with bench/budgets.json.

Prints one row per gated figure (figure, measured, budget, margin) and exits
0 when every figure is within budget, 1 when any exceeds it, 2 when a figure is
missing from the results, was measured with another toolchain than the one its
budget records (the instruction count), or a file cannot be read.

A figure reads the `median` aggregate of its benchmark when the run had
repetitions (robust to a noisy neighbour on a 2-core machine), else the single
run's value.

--markdown FILE also writes the table as Markdown (ci/gate's report, uploaded by
CI), with the `ci/bisect --budget` command that finds the commit that pushed each
figure over budget.

--confirm MORE.json (repeatable) adds re-runs of some benchmarks: a wall-time figure
(kind "time") is then the best of its medians over all the files. The machine's load
only ever makes a run slower, so the fastest of several runs is the estimate of what
the code costs; a real slowdown is slow in every run and still fails. Counts and
instruction figures are exact and read from RESULTS.json only.

--over-time FILE writes the benchmarks of the wall-time figures over budget, one a
line, when those are the only figures over budget (else an empty file): what ci/bench
re-runs before it fails a change on wall time.

--skip-missing BENCH,... and --skip-kinds KIND,... report the figures of those benchmarks,
or of those kinds, as skipped rather than missing when the results lack them (ci/bench
without --instructions has no callgrind figures, without --paired no paired ratios).

The kinds of figure: "time" (a wall time, or a ratio of two measured in one process),
"count" (exact: allocations, bytes), "instructions" and "cache" (callgrind's count and its
simulated cache misses: exact for the toolchain the figure records, refused with another),
"paired" (a bound on the lower end of the interval of a paired head / reference ratio,
bench/paired_gate.py).
"""
import json
import os
import sys

# Figures counted under callgrind: exact for one toolchain, whatever the machine's load.
CALLGRIND_KINDS = ("instructions", "cache")


def is_callgrind(figure):
    """An instruction count or a simulated cache-miss count (older budget files: by the field)."""
    return figure.get("kind") in CALLGRIND_KINDS or "instructions" in figure.get("field", "")


def load(path, what):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        print(f"budget_gate: cannot read {what} {path}: {e}", file=sys.stderr)
        sys.exit(2)


def measured_entry(results, figure):
    runs = [b for b in results.get("benchmarks", []) if b.get("run_name", b.get("name")) == figure["benchmark"]]
    medians = [b for b in runs if b.get("aggregate_name") == "median"]
    plain = [b for b in runs if b.get("run_type", "iteration") == "iteration"]
    return medians[0] if medians else (plain[0] if plain else None)


def measured_value(results, figure):
    chosen = measured_entry(results, figure)
    if chosen is None or figure["field"] not in chosen:
        return None
    return float(chosen[figure["field"]])


def best_value(results, confirmations, figure):
    """The figure's value: for a wall time, the fastest of the first run and its re-runs
    (returns the value and how many runs it was taken over); otherwise the first run's."""
    value = measured_value(results, figure)
    if figure.get("kind") != "time" or value is None:
        return value, 1
    values = [value] + [v for v in (measured_value(c, figure) for c in confirmations) if v is not None]
    return (min(values) if "max" in figure else max(values)), len(values)


def toolchain_mismatch(results, figure):
    """A figure calibrated with a recorded toolchain (the instruction count: deterministic for
    one compiler, flags and libraries, meaningless across them) is only compared with results
    taken with the same one. Returns the results' toolchain when it differs, else None."""
    if "toolchain" not in figure:
        return None
    entry = measured_entry(results, figure) or {}
    measured = entry.get("toolchain", "unknown")
    return None if measured == figure["toolchain"] else measured


def take_option(argv, name):
    """Removes `name VALUE` from argv; returns (argv, VALUE or None)."""
    if name not in argv:
        return argv, None
    i = argv.index(name)
    if i + 1 >= len(argv):
        return argv, None
    return argv[:i] + argv[i + 2:], argv[i + 1]


def take_repeated_option(argv, name):
    """Removes every `name VALUE` from argv; returns (argv, [VALUE...])."""
    values = []
    while True:
        argv, value = take_option(argv, name)
        if value is None:
            return argv, values
        values.append(value)


def write_lines(path, lines):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("".join(line + "\n" for line in lines))
    os.replace(tmp, path)


def markdown_table(rows):
    """The gate's rows as the lines of a Markdown table (ci/gate's report, docs/results.md)."""
    lines = ["| figure | measured | budget | margin | status |", "|---|---|---|---|---|"]
    return lines + ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]


def write_markdown(path, rows, summary):
    lines = markdown_table(rows) + ["", summary]
    over = [r[0] for r in rows if r[4] == "OVER BUDGET"]
    if over:
        lines += ["", "To find the commit that pushed a figure over budget (instruction counts, so"
                  " the machine's noise does not matter; see docs/bisect.md):", ""]
        # The unit in parentheses is left out: ci/bisect matches a figure by the start of its name.
        lines += [f"    ci/bisect --budget \"{name.split(' (')[0]}\" --good LAST_GOOD_COMMIT" for name in over]
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)


class Gate:
    """The gate's verdict on every figure: `rows` (figure, measured, budget, margin, status), the
    figures over budget, how many are missing, and the (figure, toolchain) pairs measured with
    another toolchain than their budget records."""

    def __init__(self, results, budgets, confirmations=(), skip=(), skip_kinds=()):
        self.rows, self.over_figures, self.missing, self.mismatched = gate_rows(results, budgets, confirmations, skip,
                                                                                skip_kinds)
        self.failed = len(self.over_figures)
        skipped = sum(1 for r in self.rows if r[4] == "skipped")
        within = len(self.rows) - self.failed - self.missing - skipped - len(self.mismatched)
        self.summary = (f"budget gate: {within} within budget, {self.failed} over, {self.missing} missing, "
                        f"{skipped} skipped, {len(self.mismatched)} on another toolchain")


def shown_value(value):
    """4 significant digits, but a large count in full (178,594, not 1.786e+05: a 3 % bound on it
    must be readable)."""
    return f"{int(value):,}" if value == int(value) and abs(value) >= 1e4 else f"{value:.4g}"


def gate_rows(results, budgets, confirmations, skip, skip_kinds=()):
    rows, missing, mismatched, over_figures = [], 0, [], []
    for figure in budgets.get("figures", []):
        value, runs = best_value(results, confirmations, figure)
        if "max" in figure:
            bound, ok_cmp, sign = float(figure["max"]), (lambda v, b: v <= b), "<="
        else:
            bound, ok_cmp, sign = float(figure["min"]), (lambda v, b: v >= b), ">="
        if value is None and (figure["benchmark"] in skip or figure.get("kind") in skip_kinds):
            rows.append((figure["name"], "not run", f"{sign} {bound:g}", "", "skipped"))
            continue
        if value is None:
            missing += 1
            rows.append((figure["name"], "missing", f"{sign} {bound:g}", "", "MISSING"))
            continue
        other = toolchain_mismatch(results, figure)
        if other is not None:
            # Not a pass: the count was taken with another toolchain and says nothing about
            # this change. Recalibrate on the new toolchain instead (docs/ci.md, "Recalibrating").
            mismatched.append((figure["name"], other))
            rows.append((figure["name"], shown_value(value), f"{sign} {bound:g}", "", "OTHER TOOLCHAIN"))
            continue
        ok = ok_cmp(value, bound)
        if not ok:
            over_figures.append(figure)
        if bound == 0:
            margin_text = "exact"
        else:
            margin = (bound - value) / bound * 100 if "max" in figure else (value - bound) / bound * 100
            margin_text = f"{margin:+.0f}%"
        shown = shown_value(value) + (f" (best of {runs})" if runs > 1 else "")
        rows.append((figure["name"], shown, f"{sign} {bound:g}", margin_text, "ok" if ok else "OVER BUDGET"))
    return rows, over_figures, missing, mismatched


def main(argv):
    argv, skip_arg = take_option(argv, "--skip-missing")
    skip = set(skip_arg.split(",")) if skip_arg else set()
    argv, kinds_arg = take_option(argv, "--skip-kinds")
    skip_kinds = set(kinds_arg.split(",")) if kinds_arg else set()
    argv, markdown = take_option(argv, "--markdown")
    argv, over_time_path = take_option(argv, "--over-time")
    argv, confirm_paths = take_repeated_option(argv, "--confirm")
    if len(argv) != 3:
        print("usage: budget_gate.py RESULTS.json BUDGETS.json [--skip-missing BENCH,...] [--skip-kinds KIND,...]"
              " [--markdown FILE]"
              " [--confirm MORE.json]... [--over-time FILE]", file=sys.stderr)
        return 2
    results = load(argv[1], "results")
    budgets = load(argv[2], "budgets")
    confirmations = [load(p, "re-run results") for p in confirm_paths]
    gate = Gate(results, budgets, confirmations, skip, skip_kinds)
    rows, over_figures, missing, mismatched = gate.rows, gate.over_figures, gate.missing, gate.mismatched

    header = ("figure", "measured", "budget", "margin", "status")
    widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(5)]
    for r in [header] + rows:
        print("  ".join(str(c).ljust(w) for c, w in zip(r, widths)))
    print(gate.summary)
    for name, other in mismatched:
        figure = next(f for f in budgets["figures"] if f["name"] == name)
        print(f"budget_gate: '{name}' was calibrated with\n  {figure['toolchain']}\nbut this build is\n  {other}\n"
              "the counts cannot be compared: recalibrate with `ci/bench --instructions --recalibrate-instructions`"
              " on an idle machine and commit bench/budgets.json", file=sys.stderr)
    if markdown:
        write_markdown(markdown, rows, gate.summary)
    if over_time_path:
        only_time = over_figures and all(f.get("kind") == "time" for f in over_figures)
        write_lines(over_time_path, sorted({f["benchmark"] for f in over_figures}) if only_time else [])
    if missing or mismatched:
        return 2
    return 1 if gate.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/python3
"""Calibrates bench/budgets.json from measurements (docs/ci.md, "Recalibrating budgets").

  calibrate_budgets.py instructions BUDGETS.json RESULTS.json
      The instruction figure (kind "instructions"): its baseline becomes the count in RESULTS,
      its bound the baseline plus the figure's tolerance (3 % unless it says otherwise), and it
      records the toolchain the count was taken with; the gate refuses to compare across
      toolchains. The count is deterministic for one toolchain, so one run is enough.

  calibrate_budgets.py times BUDGETS.json [--redefined NAME ...] [--busy] RESULTS1.json RESULTS2.json ...
      Every wall-time figure (kind "time") from N >= 5 runs of `ci/bench --quick` on the CI
      machine, idle: its bound becomes the one-sided 99.9 % prediction bound for one more run,
      under a log-normal model of the run-to-run spread (exp(m + t(0.999, N-1) s sqrt(1 + 1/N))
      over the logs of the N medians). A figure that is steady gets a tight bound, a noisy one a
      wide bound; a flat multiple of the median gave both the same. The bound is never below
      1.5 times the slowest of the N runs: runs taken in one sitting do not see the drift
      between sittings, nor a CI run's 25 minutes of compiling just before (1.25 was too close:
      the p50 of a CI run on 2026-11-24 came out 1.29 x the slowest idle run); and it never rises above the bound in the file (calibration tightens,
      an issue's goal stays a ceiling), except for a figure named with --redefined (the start of
      its name): one whose benchmark now measures something else, so that the bound in the file
      bounds another quantity; its commit says what changed. Figures of kind "count"
      (exact: allocations, bytes per tet, unresolved) and "paired" (limits on a ratio, set by
      hand) are left alone. Refused (exit 2) when a run started with a 1-minute load average
      above MAX_LOAD per core (Google Benchmark records it): a bound calibrated on a busy day
      gives every later slowdown that much room; --busy takes such runs anyway, and the figure's
      calibration note says so.

Writes BUDGETS.json in place (through a temporary file) and prints what changed. Needs scipy
(Debian's python3-scipy, installed by ci/deps): run it with /usr/bin/python3.
"""
import datetime
import json
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from budget_gate import CALLGRIND_KINDS, measured_entry, measured_value  # noqa: E402  (one reading of a result)


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def save(path, budgets):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(format_budgets(budgets))
    os.replace(tmp, path)


def format_budgets(budgets):
    """One figure a line, as the file has always been written (diffs stay readable)."""
    lines = ["{", f'  "comment": {json.dumps(budgets["comment"])},']
    if "reference" in budgets:
        lines.append(f'  "reference": {json.dumps(budgets["reference"])},')
    lines.append('  "figures": [')
    figures = [json.dumps(f) for f in budgets["figures"]]
    lines += ["    " + f + ("," if i + 1 < len(figures) else "") for i, f in enumerate(figures)]
    lines += ["  ]", "}"]
    return "\n".join(lines) + "\n"


def round_up(x, digits=2):
    if x <= 0:
        return x
    unit = 10 ** (math.floor(math.log10(x)) - digits + 1)
    # Rounded again: 82 * 0.01 is 0.8200000000000001 in binary, and the file is read by people.
    return round(math.ceil(x / unit) * unit, 12)


def today():
    return datetime.date.today().isoformat()


def calibrate_instructions(budgets, results, commit=None):
    figures = [f for f in budgets["figures"] if f.get("kind") in CALLGRIND_KINDS]
    if not figures:
        sys.exit("calibrate_budgets: no figure of kind 'instructions' or 'cache' in the budgets")
    absent = [f["name"] for f in figures if measured_value(results, f) is None
              or "toolchain" not in (measured_entry(results, f) or {})]
    if absent:
        sys.exit("calibrate_budgets: the results hold no count with its toolchain for: " + "; ".join(absent)
                 + " (ci/bench --instructions measures them all)")
    for figure in figures:
        value = measured_value(results, figure)
        toolchain = measured_entry(results, figure)["toolchain"]
        tolerance = float(figure.get("tolerance_pct", 3))
        old = figure.get("baseline")
        figure["baseline"] = int(value)
        figure["tolerance_pct"] = tolerance
        figure["max"] = math.ceil(value * (1 + tolerance / 100))
        figure["toolchain"] = toolchain
        figure["note"] = f"{WHAT[figure['kind']]}, calibrated {today()}" + (f" at {commit[:12]}" if commit else "") + \
            f"; gated at +{tolerance:g} %"
        print(f"{figure['name']}: baseline {old} -> {figure['baseline']}, bound {figure['max']}")
    print(f"  toolchain: {figures[0]['toolchain']}")
    if commit:
        budgets["reference"] = {"commit": commit, "date": today(),
                                "note": "the commit the callgrind baselines were taken at: `ci/bench --paired` builds "
                                        "its engine and compares wall times with it, pair by pair"}
        print(f"reference of the paired comparison: {commit}")


# What a callgrind figure counts, for its note.
WHAT = {"instructions": "callgrind count of bench/cut_instructions (every cut of the fixed liver sweep)",
        "cache": "callgrind's simulated last-level misses (fixed sizes) of the same sweep through 64 copies of the "
                 "liver, ids shuffled (bench/cut_instructions --shuffled-copies)"}


# The least margin over the slowest calibration run (see calibrate_times).
DRIFT = 1.5
# The most 1-minute load average per core a calibration run may start with: an idle machine.
MAX_LOAD = 0.5


def busy_runs(runs):
    """The runs that started on a busy machine: (index, load average), from Google Benchmark's context."""
    cores = os.cpu_count() or 1
    out = []
    for i, r in enumerate(runs):
        load_avg = r.get("context", {}).get("load_avg") or [0]
        if load_avg[0] / cores > MAX_LOAD:
            out.append((i, load_avg[0]))
    return out


def names(prefixes, figure):
    """Whether one of the prefixes (--redefined) starts the figure's name."""
    return any(figure["name"].startswith(p) for p in prefixes)


def calibrate_times(budgets, runs, redefined=(), busy=False):
    from scipy import stats  # python3-scipy

    n = len(runs)
    if n < 5:
        sys.exit(f"calibrate_budgets: {n} runs; a prediction bound wants at least 5")
    loaded = busy_runs(runs)
    if loaded and not busy:
        sys.exit("calibrate_budgets: runs " + ", ".join(f"{i + 1} (load {a:.1f})" for i, a in loaded)
                 + f" started above a load of {MAX_LOAD:g} per core: calibrate on the idle machine, or pass --busy")
    t = stats.t.ppf(0.999, n - 1)
    for figure in budgets["figures"]:
        if figure.get("kind") != "time":
            continue
        values = [measured_value(r, figure) for r in runs]
        if any(v is None or v <= 0 for v in values):
            print(f"{figure['name']}: missing or non-positive in some run, left alone")
            continue
        logs = [math.log(v) for v in values]
        m, s = statistics.fmean(logs), statistics.stdev(logs)
        predicted = math.exp(m + t * s * math.sqrt(1 + 1 / n))
        # Runs taken in one sitting miss the drift between sittings (another boot, another
        # neighbour on the host): never closer than DRIFT to the slowest run seen.
        bound = round_up(max(predicted, DRIFT * max(values)))
        old = figure["max"]
        is_redefined = names(redefined, figure)
        if bound > old and not is_redefined:
            # Calibration tightens, never loosens: a bound above the one in the file (an issue's
            # goal, or an earlier sitting's) would let the slowdown it was set against through.
            print(f"{figure['name']}: {old} kept (the runs give {bound}; median {statistics.median(values):.4g})")
            continue
        figure["max"] = bound
        figure["calibration"] = (("measurement redefined; " if is_redefined else "") + ("on a busy machine; " if loaded else "")
                                 + f"{today()}: {n} runs, median {statistics.median(values):.4g}, "
                                 f"min {min(values):.4g}, max {max(values):.4g}; bound = 99.9 % prediction (log-normal) "
                                 f"{predicted:.4g}, at least {DRIFT:g} x the slowest run")
        print(f"{figure['name']}: {old} -> {bound} (median {statistics.median(values):.4g}, spread {math.exp(s):.3f}x)")


def main(argv):
    if len(argv) < 4 or argv[1] not in ("instructions", "times"):
        print(__doc__, file=sys.stderr)
        return 2
    budgets_path = argv[2]
    budgets = load(budgets_path)
    if argv[1] == "instructions":
        commit = None
        if len(argv) == 6 and argv[4] == "--commit":
            commit = argv[5]
        elif len(argv) != 4:
            print(__doc__, file=sys.stderr)
            return 2
        calibrate_instructions(budgets, load(argv[3]), commit)
    else:
        args, redefined, busy = argv[3:], [], False
        while args and args[0] in ("--redefined", "--busy"):
            if args[0] == "--busy":
                busy, args = True, args[1:]
                continue
            if len(args) < 2:
                break
            redefined.append(args[1])
            args = args[2:]
        unknown = [r for r in redefined if not any(names([r], f) for f in budgets["figures"])]
        if unknown:
            sys.exit(f"calibrate_budgets: --redefined names no figure: {', '.join(unknown)}")
        calibrate_times(budgets, [load(p) for p in args], redefined, busy)
    save(budgets_path, budgets)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

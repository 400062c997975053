#!/usr/bin/env python3
"""The paired wall-time comparison: head against a reference, in turns, on one core.

  paired_gate.py --head BIN --reference BIN --meshes DIR --out OUT.json
                 [--pairs N] [--core C] [--small-only] [--seed S]

BIN is bench/paired_sweep built at each side (`ci/bench --paired` builds the reference's in a tree
of its own, bench/paired/CMakeLists.txt). Both are started afresh for each pair, pinned to core C
(taskset; the last core by default), and take turns: pair i runs one round of each, head first in
even pairs and the reference first in odd ones, so that neither side always runs into the other's
caches or a burst of load, nor keeps one process's address layout for every pair. A round is the gated sweep on the 1M-tet refined liver, then five on the liver
(pooled, after one untimed; --small-only: the liver alone), every cut timed and every stage
(CutTimings).

For each figure (the p50 and p99 of the cut and of each stage, per mesh), the pair's ratio is
head / reference; the estimate is the median of the N ratios, and its 95 % interval comes from a
bootstrap over the pairs (10,000 resamples, seeded). The machine's load moves both rounds of a
pair alike, so the ratio sees the code where a lone wall time sees the load. A figure fails when
the interval's lower bound is above its limit (bench/budgets.json, figures of kind "paired"): then
even the most favourable reading of the runs has the head slower than the limit allows.

OUT.json is shaped as Google Benchmark's, one entry per figure ("paired/16k cut p50", fields ratio,
ratio_low, ratio_high, head_us, reference_us), for bench/budget_gate.py, where bench/budgets.json
holds the limits. Prints the table. Exit 0 when it ran (the gate judges), 2 when a side failed.
"""
import argparse
import json
import os
import random
import shutil
import statistics
import subprocess
import sys

def limits(budgets_path):
    """The limit of each gated figure, from bench/budgets.json: its figures of kind "paired" bound
    the field ratio_low of the entry "paired/FIGURE"."""
    if not budgets_path:
        return {}
    with open(budgets_path, encoding="utf-8") as f:
        figures = json.load(f).get("figures", [])
    return {f["benchmark"][len("paired/"):]: float(f["max"]) for f in figures
            if f.get("kind") == "paired" and f.get("field") == "ratio_low"}


class Side:
    def __init__(self, name, binary, meshes, core, small_only):
        command = [binary, meshes] + (["--small-only"] if small_only else [])
        if core is not None and shutil.which("taskset"):
            command = ["taskset", "-c", str(core)] + command
        self.name = name
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        if self.process.stdout.readline().strip() != "ready":
            sys.exit(f"paired_gate: the {name} side ({binary}) did not start")

    def round(self):
        self.process.stdin.write("run\n")
        self.process.stdin.flush()
        line = self.process.stdout.readline()
        if not line:
            sys.exit(f"paired_gate: the {self.name} side stopped (exit {self.process.wait()})")
        return json.loads(line)

    def close(self):
        self.process.stdin.close()
        self.process.wait()


def bootstrap_interval(ratios, rng, resamples=10000):
    """The 2.5th and 97.5th percentiles of the median of `ratios` resampled with replacement."""
    n = len(ratios)
    medians = sorted(statistics.median(rng.choices(ratios, k=n)) for _ in range(resamples))
    return medians[int(0.025 * resamples)], medians[int(0.975 * resamples) - 1]


def compare(rounds_head, rounds_ref, seed):
    """Per figure: (head median, reference median, paired median ratio, low, high)."""
    rng = random.Random(seed)
    out = {}
    for figure in rounds_head[0]:
        heads = [r[figure] for r in rounds_head]
        refs = [r[figure] for r in rounds_ref]
        ratios = [h / r for h, r in zip(heads, refs) if r > 0]
        if len(ratios) < len(heads):
            continue  # a stage that took no time in some round: no ratio to take
        low, high = bootstrap_interval(ratios, rng)
        out[figure] = (statistics.median(heads), statistics.median(refs), statistics.median(ratios), low, high)
    return out


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--head", required=True)
    parser.add_argument("--reference", required=True)
    parser.add_argument("--meshes", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--pairs", type=int, default=10)
    parser.add_argument("--core", type=int, default=(os.cpu_count() or 1) - 1)
    parser.add_argument("--small-only", action="store_true")
    parser.add_argument("--seed", type=int, default=43)
    parser.add_argument("--budgets", help="bench/budgets.json: the limits, for the table's last column")
    args = parser.parse_args(argv[1:])
    if args.pairs < 10:
        print("paired_gate: fewer than 10 pairs give the bootstrap too few ratios to resample", file=sys.stderr)
        return 2

    rounds_head, rounds_ref = [], []
    for i in range(args.pairs):
        # Each pair starts both sides afresh: a process's address layout (ASLR's bases, where the
        # heap lands against the caches' sets) makes a stage a few percent faster or slower for
        # its whole life, the same binary against itself included (6.6 % on `finish`, interval
        # [1.061, 1.076], seen in CI). Over fresh processes that bias is one more draw per pair,
        # and the interval holds it.
        head = Side("head", args.head, args.meshes, args.core, args.small_only)
        ref = Side("reference", args.reference, args.meshes, args.core, args.small_only)
        first, second = (head, ref) if i % 2 == 0 else (ref, head)
        a, b = first.round(), second.round()
        rounds_head.append(a if first is head else b)
        rounds_ref.append(b if first is head else a)
        head.close()
        ref.close()

    results = compare(rounds_head, rounds_ref, args.seed)
    bounds = limits(args.budgets)
    benchmarks, rows = [], []
    for figure, (h, r, ratio, low, high) in results.items():
        entry = {"name": f"paired/{figure}", "run_name": f"paired/{figure}", "run_type": "iteration",
                 "head_us": h, "reference_us": r, "ratio": ratio, "ratio_low": low, "ratio_high": high,
                 "pairs": args.pairs}
        benchmarks.append(entry)
        bound = bounds.get(figure)
        status = "" if bound is None else ("SLOWER" if low > bound else "ok")
        rows.append((figure, f"{h:.2f}", f"{r:.2f}", f"{ratio:.3f}", f"[{low:.3f}, {high:.3f}]",
                     "" if bound is None else f"{bound:.2f}", status))
    header = ("figure (us)", "head", "reference", "ratio", "95 % interval", "limit", "")
    widths = [max(len(str(x[i])) for x in rows + [header]) for i in range(len(header))]
    print(f"paired: {args.pairs} pairs, head {args.head} against reference {args.reference}, core {args.core}")
    for row in [header] + rows:
        print("  ".join(str(c).ljust(w) for c, w in zip(row, widths)))
    with open(args.out + ".tmp", "w", encoding="utf-8") as f:
        json.dump({"context": {"source": "paired_gate", "pairs": args.pairs}, "benchmarks": benchmarks}, f, indent=1)
    os.replace(args.out + ".tmp", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

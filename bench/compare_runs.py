#!/usr/bin/env python3
"""Compares two Google Benchmark JSON runs (with repetitions) and prints the changes.

For every benchmark present in both, the per-repetition real times are compared with a
two-sided Mann-Whitney U test (normal approximation with tie correction), which does not
assume the noise of a shared 2-core machine is Gaussian. A change is reported as significant
when p < alpha (default 0.05) and the medians differ by more than the noise floor (1 %).

usage: compare_runs.py BASE.json NEW.json [--alpha A]
exit: 0 (the comparison is information, not a gate), 2 on unreadable input.
"""
import json
import math
import statistics
import sys


def samples(path):
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        print(f"compare_runs: cannot read {path}: {e}", file=sys.stderr)
        sys.exit(2)
    out = {}
    for b in data.get("benchmarks", []):
        if b.get("run_type", "iteration") != "iteration":
            continue
        out.setdefault(b.get("run_name", b["name"]), []).append((float(b["real_time"]), b.get("time_unit", "ns")))
    return out


def mann_whitney_p(x, y):
    n1, n2 = len(x), len(y)
    if n1 < 2 or n2 < 2:
        return 1.0
    ranked = sorted([(v, 0) for v in x] + [(v, 1) for v in y])
    ranks = [0.0] * len(ranked)
    tie_term = 0.0
    i = 0
    while i < len(ranked):
        j = i
        while j + 1 < len(ranked) and ranked[j + 1][0] == ranked[i][0]:
            j += 1
        for k in range(i, j + 1):
            ranks[k] = (i + j) / 2 + 1
        t = j - i + 1
        tie_term += t ** 3 - t
        i = j + 1
    r1 = sum(r for r, (_, g) in zip(ranks, ranked) if g == 0)
    u1 = r1 - n1 * (n1 + 1) / 2
    mu = n1 * n2 / 2
    n = n1 + n2
    sigma = math.sqrt(n1 * n2 / 12 * ((n + 1) - tie_term / (n * (n - 1))))
    if sigma == 0:
        return 1.0
    z = (abs(u1 - mu) - 0.5) / sigma
    return math.erfc(max(z, 0.0) / math.sqrt(2))


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    alpha = 0.05
    if "--alpha" in argv:
        alpha = float(argv[argv.index("--alpha") + 1])
        args = [a for a in args if a != argv[argv.index("--alpha") + 1]]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    base, new = samples(args[0]), samples(args[1])
    rows = [("benchmark", "base median", "new median", "change", "p", "verdict")]
    for name in sorted(set(base) & set(new)):
        xb = [v for v, _ in base[name]]
        xn = [v for v, _ in new[name]]
        unit = base[name][0][1]
        mb, mn = statistics.median(xb), statistics.median(xn)
        change = (mn - mb) / mb * 100 if mb else 0.0
        p = mann_whitney_p(xb, xn)
        verdict = "same"
        if p < alpha and abs(change) > 1.0:
            verdict = "SLOWER" if change > 0 else "faster"
        rows.append((name, f"{mb:.4g} {unit}", f"{mn:.4g} {unit}", f"{change:+.1f}%", f"{p:.3f}", verdict))
    for name in sorted(set(base) ^ set(new)):
        rows.append((name, "-" if name not in base else "present", "-" if name not in new else "present", "", "", "only in one run"))
    widths = [max(len(r[i]) for r in rows) for i in range(6)]
    for r in rows:
        print("  ".join(c.ljust(w) for c, w in zip(r, widths)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

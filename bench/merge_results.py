#!/usr/bin/env python3
"""Merges Google Benchmark JSON files (one per suite) into one: [--timed-only] OUT IN...

The context of the first file is kept; benchmarks are concatenated in the order given.
--timed-only keeps only the entries that have a time (`real_time`): what compare.py can read
(the callgrind count of `ci/bench --instructions` is an entry without one).
"""
import json
import os
import sys


def main(argv):
    args = argv[1:]
    timed_only = "--timed-only" in args
    if timed_only:
        args.remove("--timed-only")
    if len(args) < 2:
        print("usage: merge_results.py [--timed-only] OUT IN...", file=sys.stderr)
        return 2
    merged = None
    for path in args[1:]:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        if merged is None:
            merged = data
            merged["benchmarks"] = list(data.get("benchmarks", []))
        else:
            merged["benchmarks"].extend(data.get("benchmarks", []))
    if timed_only:
        merged["benchmarks"] = [b for b in merged["benchmarks"] if "real_time" in b]
    tmp = args[0] + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(merged, f, indent=1)
    os.replace(tmp, args[0])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

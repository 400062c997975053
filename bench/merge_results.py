#!/usr/bin/env python3
"""Merges Google Benchmark JSON files (one per suite) into one: OUT IN...

The context of the first file is kept; benchmarks are concatenated in the order given.
"""
import json
import sys


def main(argv):
    if len(argv) < 3:
        print("usage: merge_results.py OUT IN...", file=sys.stderr)
        return 2
    merged = None
    for path in argv[2:]:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        if merged is None:
            merged = data
        else:
            merged["benchmarks"].extend(data.get("benchmarks", []))
    tmp = argv[1] + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(merged, f, indent=1)
    import os
    os.replace(tmp, argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

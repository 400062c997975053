#!/usr/bin/env python3
"""ctest ci.peers_gate: the gate bounds tetcut's time over each peer's, and it can fail.

Every figure of bench/budgets.json on a BM_Peers run names a counter that
bench/peers/peers_bench.cpp reports; ci/bench runs peers_bench and prints the peers table. Then
budget_gate.py, given the real budget file and a synthetic BM_Peers run (plus the other figures'
benchmarks left out with --skip-missing), passes ratios within their bounds and fails one that
loses ground to a peer by a third over its bound; a singular vertex left by tetcut fails too.

    peers_gate_test.py SOURCE_DIR
"""
import json
import os
import re
import subprocess
import sys
import tempfile

from checks import check, verdict  # noqa: E402 (this folder is on sys.path: the script's own)


def main(src):
    with open(os.path.join(src, "bench/budgets.json"), encoding="utf-8") as f:
        budgets = json.load(f)
    peers = [g for g in budgets["figures"] if g["benchmark"].startswith("BM_Peers/")]
    with open(os.path.join(src, "bench/peers/peers_bench.cpp"), encoding="utf-8") as f:
        source = f.read()
    reported = set(re.findall(r'counters\["([a-z0-9_]+)"\]', source))
    reported |= {f"{a}_{field}" for a in ("tetcut", "blind", "cgal", "tetgen")
                 for field in re.findall(r'counters\[name \+ "_([a-z0-9_]+)"\]', source)}
    ratios = [g for g in peers if g["field"].startswith("p50_ratio_tetcut_over_")]
    check({g["field"] for g in ratios} >= {"p50_ratio_tetcut_over_blind", "p50_ratio_tetcut_over_cgal",
                                           "p50_ratio_tetcut_over_tetgen"},
          "bench/budgets.json does not bound tetcut's p50 over each peer's")
    for g in peers:
        check(g["field"] in reported, f"budget '{g['name']}' reads {g['field']}, which peers_bench does not report")
    with open(os.path.join(src, "ci/bench"), encoding="utf-8") as f:
        bench = f.read()
    check("peers_bench" in bench and "peers_table.py" in bench, "ci/bench does not run peers_bench and print the table")

    others = sorted({g["benchmark"] for g in budgets["figures"]} - {g["benchmark"] for g in peers})
    bench = open(os.path.join(src, "ci/bench"), encoding="utf-8").read()

    def gate(values):
        run = {"name": peers[0]["benchmark"], "run_name": peers[0]["benchmark"], "run_type": "iteration", **values}
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "results.json")
            with open(path, "w", encoding="utf-8") as f:
                json.dump({"benchmarks": [run]}, f)
            done = subprocess.run([sys.executable, os.path.join(src, "bench/budget_gate.py"), path,
                                   os.path.join(src, "bench/budgets.json"), "--skip-missing", ",".join(others)],
                                  capture_output=True, text=True)
        print(done.stdout, done.stderr)
        return done.returncode

    within = {g["field"]: (0.5 * g["max"] if g["max"] else 0) for g in peers}
    check(gate(within) == 0, "the gate fails peers figures within their bounds")
    for g in ratios:
        over = dict(within, **{g["field"]: 1.34 * g["max"]})
        check(gate(over) == 1, f"the gate passes {g['field']} at 1.34 x its bound")
    counts = [g for g in peers if g.get("kind") == "count"]
    check(bool(counts), "no count figure holds tetcut to no singularity on the peers' sweep")
    for g in counts:
        check(gate(dict(within, **{g["field"]: g["max"] + 1})) == 1, f"the gate passes {g['field']} over {g['max']}")
    # The engine adapters' figures (bench/peers/engines_compare.cpp --gate, runs engines/<adapter>):
    # each field one engines_compare reports, ci/bench running it, and tetcut held to no broken cut.
    engines = [g for g in budgets["figures"] if g["benchmark"].startswith("engines/")]
    with open(os.path.join(src, "bench/peers/engines_compare.cpp"), encoding="utf-8") as f:
        compare = f.read()
    engine_fields = set(re.findall(r'\{"([a-z0-9_]+)", ', compare)) | {"ratio_per_cut", "ratio_per_volume"}
    check(any(g["benchmark"] == "engines/tetcut" and g["field"] == "cuts_objected" and g["max"] == 0 for g in engines),
          "bench/budgets.json does not hold tetcut to no broken cut through its adapter")
    check(any(g["field"] == "ratio_per_volume" for g in engines), "no engines figure bounds a ratio per mm3 removed")
    for g in engines:
        check(g["field"] in engine_fields, f"budget '{g['name']}' reads {g['field']}, which engines_compare does not report")
    check("engines_compare --gate" in bench, "ci/bench does not run engines_compare --gate")
    return verdict("the gate bounds tetcut's ratio to each peer, and fails a change that loses ground")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

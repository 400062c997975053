#!/usr/bin/env python3
"""The peers table: reads the Google Benchmark JSON of bench/peers/peers_bench (alone or
merged into ci/bench's results) and prints, per sweep, each approach's per-cut figures, what the
checker said after its cuts, and tetcut's ratio to each peer.

    peers_table.py RESULTS.json [--markdown FILE] [--check]

--markdown FILE  also writes the tables as Markdown (for the README and docs/).
--check          exit 1 unless tetcut left no singularity, no flat tet and no unresolved request,
                 CGAL's classification left none either (our checker agrees with face_status),
                 and blind removal left some on the gated sweep (the harness sees what it
                 exists to see). ctest peers.bench_smoke runs it.

A figure reads the `median` aggregate when the run had repetitions, else the single run.
Exit 2 when the file cannot be read or holds no BM_Peers run.
"""
import json
import os
import sys

APPROACHES = [("tetcut", "tetcut (combined, defaults)"), ("blind", "blind removal (centroid in tool)"),
              ("cgal", "CGAL remove then classify"), ("tetgen", "TetGen -r, volume bound in tool")]
PEERS = [a for a in APPROACHES if a[0] != "tetcut"]


def runs(results):
    """The BM_Peers entries, one per sweep (the median aggregate when there is one), in sweep order."""
    chosen = {}
    for b in results.get("benchmarks", []):
        name = b.get("run_name", b.get("name", ""))
        if not name.startswith("BM_Peers/"):
            continue
        if b.get("aggregate_name") == "median" or (name not in chosen and b.get("run_type", "iteration") == "iteration"):
            chosen[name] = b
    return [chosen[k] for k in sorted(chosen, key=lambda n: int(n.split("/")[1]))]


def fmt(value, digits=3):
    if value is None:
        return "-"
    if value == 0:
        return "0"
    return f"{value:.{digits}g}"


def ratio(a, b):
    return None if not b else a / b


def ordinal(n):
    return f"{n}{'th' if 10 <= n % 100 <= 20 else {1: 'st', 2: 'nd', 3: 'rd'}.get(n % 10, 'th')}"


def approach_row(run, key, label):
    g = lambda field: run.get(f"{key}_{field}")  # noqa: E731
    extra = {"tetcut": f"{fmt(run.get('tetcut_unresolved'))} unresolved",
             "cgal": f"{fmt(run.get('cgal_refused'))} refused",
             "tetgen": f"{fmt(run.get('tetgen_failed'))} failed"}.get(key, "")
    first, removing = g("first_singular_cut"), g("first_singular_removing_cut")
    offset = run.get("tetgen_first_cut", 1) - 1 if key == "tetgen" else 0  # TetGen runs a window of the sweep
    return [label, fmt(g("cuts")), fmt(g("p50_us")), fmt(g("p99_us")), fmt(g("removed_per_cut")),
            fmt(g("created_per_cut")), f"{fmt(g('nonmanifold_vertices'))} / {fmt(g('nonmanifold_edges'))}",
            fmt(g("flat_tets")), f"{fmt(g('final_nonmanifold_vertices'))} / {fmt(g('final_nonmanifold_edges'))}",
            "never" if not first else f"cut {int(first + offset)}, the {ordinal(int(removing))} to remove tets", extra]


HEADER = ["approach", "cuts", "p50 us", "p99 us", "removed/cut", "created/cut",
          "singular v / e after cuts", "flat", "singular v / e at end", "first singularity", ""]
RATIO_HEADER = ["tetcut / peer", "p50 time", "p99 time", "removed/cut", "created/cut"]


def ratio_rows(run):
    rows = []
    for key, label in PEERS:
        ours_p50 = run.get("tetcut_first_cuts_p50_us") if key == "tetgen" else run.get("tetcut_p50_us")
        # The p50 ratio as the gate reads it (the median of the runs' ratios), when the run has it.
        p50 = run.get(f"p50_ratio_tetcut_over_{key}", ratio(ours_p50, run.get(f"{key}_p50_us")))
        p99 = None if key == "tetgen" else ratio(run.get("tetcut_p99_us"), run.get(f"{key}_p99_us"))
        rows.append([label, fmt(p50), fmt(p99),
                     fmt(ratio(run.get("tetcut_removed_per_cut"), run.get(f"{key}_removed_per_cut"))),
                     fmt(ratio(run.get("tetcut_created_per_cut"), run.get(f"{key}_created_per_cut")))])
    return rows


def text_table(header, rows):
    widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(len(header))]
    return ["  ".join(str(c).ljust(w) for c, w in zip(r, widths)).rstrip() for r in [header] + rows]


def md_table(header, rows):
    return ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] + \
           ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]


def tables(runs_, table):
    lines = []
    for run in runs_:
        title = f"{run.get('label', run.get('run_name'))}: {fmt(run.get('tets'), 6)} tets, tool {fmt(run.get('tool_diameter'))}"
        lines += [title if table is text_table else f"**{title}**", ""]
        lines += table(HEADER, [approach_row(run, k, label) for k, label in APPROACHES]) + [""]
        lines += table(RATIO_HEADER, ratio_rows(run)) + [""]
    return lines


def check(runs_):
    problems = []
    for run in runs_:
        name = run.get("label", run.get("run_name"))
        for field in ("tetcut_nonmanifold_vertices", "tetcut_nonmanifold_edges", "tetcut_flat_tets",
                      "tetcut_final_nonmanifold_vertices", "tetcut_final_nonmanifold_edges", "tetcut_unresolved",
                      "cgal_nonmanifold_vertices", "cgal_nonmanifold_edges", "cgal_final_nonmanifold_vertices",
                      "cgal_final_nonmanifold_edges"):
            if run.get(field, None) != 0:
                problems.append(f"{name}: {field} = {run.get(field)}, expected 0")
        for key, _ in APPROACHES:
            if not run.get(f"{key}_cuts"):
                problems.append(f"{name}: {key} made no cut")
        if run.get("run_name", "").startswith("BM_Peers/0") and not run.get("blind_final_nonmanifold_vertices"):
            problems.append(f"{name}: blind removal left no singular vertex: the harness would not see one")
    return problems


def main(argv):
    args = argv[1:]
    markdown = None
    if "--markdown" in args:
        i = args.index("--markdown")
        markdown = args[i + 1] if i + 1 < len(args) else None
        args = args[:i] + args[i + 2:]
    do_check = "--check" in args
    args = [a for a in args if a != "--check"]
    if len(args) != 1 or (markdown is None and "--markdown" in argv):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        with open(args[0], encoding="utf-8") as f:
            results = json.load(f)
    except (OSError, ValueError) as e:
        print(f"peers_table: cannot read {args[0]}: {e}", file=sys.stderr)
        return 2
    found = runs(results)
    if not found:
        print(f"peers_table: no BM_Peers run in {args[0]}", file=sys.stderr)
        return 2
    print("\n".join(tables(found, text_table)))
    if markdown:
        tmp = markdown + ".tmp"
        with open(tmp, "w", encoding="utf-8") as f:
            f.write("\n".join(tables(found, md_table)))
        os.replace(tmp, markdown)
    if do_check:
        problems = check(found)
        for p in problems:
            print("peers_table --check: " + p, file=sys.stderr)
        return 1 if problems else 0
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

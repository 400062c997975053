"""docs/paper.md's figures, read from `tetcut stats --json`: every figure the page quotes.

    paper_figures_test.py TETCUT SOURCE WORK [STATS_JSON]

Runs `tetcut stats --check end --json WORK/stats.json` (the page's command: 10 seeded sweeps, no
improvement pass), unless STATS_JSON names one already made by that command (ci/results makes it),
then formats each figure docs/paper.md quotes from the JSON as the page writes it and fails naming
every one the page does not contain verbatim. A figure is written in one of the forms below, so a
change of the engine that moves it fails here until the page says the new figure:

    cell     "6.7 [6.5, 7.0], 2711/40199"       a rate: ours, its 95 % interval, events/trials
    p        "p = 0.00064"                       Fisher's exact test against the paper's counts
    mean     "2.92 [2.68, 3.19]"                 a mean set size and its bootstrap interval
    span     "6.7-8.6"                           a figure's least and greatest over some meshes
"""
import json
import os
import subprocess
import sys

LIVERS = ("liver-coarse", "liver-refined", "liver-local")
ROUND = ("cylinder",) + LIVERS  # the meshes without the sheet


def row(stats, table, mesh):
    for r in stats[table]:
        if r["mesh"] == mesh:
            return r
    raise KeyError(f"{table} has no row {mesh}")


def cell(stats, table, mesh, key):
    r = row(stats, table, mesh)
    lo, hi = r["ci95"][key]
    k, n = r["count"][key]
    return f"{r[key]:.1f} [{lo:.1f}, {hi:.1f}], {k}/{n}"


def p(stats, table, mesh, key):
    return f"p = {row(stats, table, mesh)['fisher_p'][key]:.2g}"


def mean(stats, table, mesh, key):
    r = row(stats, table, mesh)
    lo, hi = r["ci95"][key]
    return f"{r[key]:.2f} [{lo:.2f}, {hi:.2f}]"


def span(stats, table, key, meshes, decimals=1):
    values = [row(stats, table, m)[key] for m in meshes]
    return f"{min(values):.{decimals}f}-{max(values):.{decimals}f}"


# (what, the figure as formatted from the JSON): every figure docs/paper.md quotes from `tetcut stats`.
def claims(s):
    out = []
    orders = (("direct-first", "table1", "table2"), ("surface-first-by-id", "table1_paper_order", "table2_paper_order"),
              ("revisit", "table1_revisit", "table2_revisit"), ("3.5 first set", "table1_first_set", "table2_first_set"))
    for name, t1, t2 in orders:
        out += [(f"{name}: % vertex, cylinder and livers", span(s, t1, "vertex_pct", ROUND)),
                (f"{name}: % removable, cylinder and livers", span(s, t1, "removable_pct", ROUND)),
                (f"{name}: % edge, cylinder and livers", span(s, t1, "edge_pct", ROUND)),
                (f"{name}: vertex unresolved, all meshes", span(s, t2, "vertex_unresolved_pct", [r["mesh"] for r in s[t2]])),
                (f"{name}: vertex set size, livers", span(s, t2, "vertex_cardinality", LIVERS, 2)),
                (f"{name}: edge set size, cylinder and livers", span(s, t2, "edge_cardinality", ROUND, 2)),
                (f"{name}: edge unresolved, cylinder and livers", span(s, t2, "edge_unresolved_pct", ROUND)),
                (f"{name}: card./op., cylinder and livers", span(s, t2, "global_cardinality_per_operation", ROUND, 2))]
        for mesh in ("cylinder", "sheet") + LIVERS:
            out += [(f"{name}: {mesh} % vertex", cell(s, t1, mesh, "vertex_pct")),
                    (f"{name}: {mesh} % vertex, p", p(s, t1, mesh, "vertex_pct")),
                    (f"{name}: {mesh} % removable", cell(s, t1, mesh, "removable_pct")),
                    (f"{name}: {mesh} % removable, p", p(s, t1, mesh, "removable_pct"))]
            if mesh != "sheet":
                out += [(f"{name}: {mesh} % edge", cell(s, t1, mesh, "edge_pct")),
                        (f"{name}: {mesh} % edge, p", p(s, t1, mesh, "edge_pct")),
                        (f"{name}: {mesh} edge unresolved", cell(s, t2, mesh, "edge_unresolved_pct")),
                        (f"{name}: {mesh} edge unresolved, p", p(s, t2, mesh, "edge_unresolved_pct")),
                        (f"{name}: {mesh} vertex unresolved", cell(s, t2, mesh, "vertex_unresolved_pct")),
                        (f"{name}: {mesh} vertex unresolved, p", p(s, t2, mesh, "vertex_unresolved_pct")),
                        (f"{name}: {mesh} edge set size", mean(s, t2, mesh, "edge_cardinality")),
                        (f"{name}: {mesh} vertex set size", mean(s, t2, mesh, "vertex_cardinality"))]
    return out


def main(argv):
    tetcut, source, work = argv[1:4]
    if len(argv) > 4:
        path = argv[4]
    else:
        os.makedirs(work, exist_ok=True)
        path = os.path.join(work, "stats.json")
        subprocess.run([tetcut, "stats", "--check", "end", "--json", path], check=True, stdout=subprocess.DEVNULL)
    with open(path) as f:
        stats = json.load(f)
    with open(os.path.join(source, "docs", "paper.md")) as f:
        page = " ".join(f.read().split())  # a figure may break across lines
    quoted = [(what, figure) for what, figure in claims(stats) if figure in page]
    if "--print" in os.environ.get("PAPER_FIGURES", ""):
        for what, figure in claims(stats):
            print(f"{'   ' if figure in page else 'NOT'} {what}: {figure}")
    # Every figure the page is meant to quote (MUST_QUOTE) must be there as the JSON gives it.
    missing = [(what, figure) for what, figure in claims(stats) if what in MUST_QUOTE and figure not in page]
    for what, figure in missing:
        print(f"docs/paper.md does not say {what} as `tetcut stats` gives it: {figure}")
    unknown = sorted(set(MUST_QUOTE) - {what for what, _ in claims(stats)})
    for what in unknown:
        print(f"paper_figures_test.py: no figure named {what}")
    print(f"{len(quoted)} of {len(claims(stats))} figures quoted; {len(missing)} missing of {len(MUST_QUOTE)} required")
    return 1 if missing or unknown else 0


# The figures docs/paper.md quotes (each in `claims`): the list grows with the page.
MUST_QUOTE = [
    "direct-first: % vertex, cylinder and livers",
    "direct-first: % removable, cylinder and livers",
    "direct-first: % edge, cylinder and livers",
    "direct-first: vertex unresolved, all meshes",
    "direct-first: vertex set size, livers",
    "direct-first: edge set size, cylinder and livers",
    "direct-first: edge unresolved, cylinder and livers",
    "direct-first: card./op., cylinder and livers",
    "direct-first: cylinder % vertex",
    "direct-first: cylinder % vertex, p",
    "direct-first: cylinder % edge",
    "direct-first: cylinder % edge, p",
    "direct-first: cylinder edge unresolved",
    "direct-first: cylinder edge unresolved, p",
    "direct-first: cylinder vertex unresolved",
    "direct-first: cylinder vertex unresolved, p",
    "direct-first: sheet % removable",
    "direct-first: sheet % removable, p",
    "direct-first: liver-coarse % edge",
    "direct-first: liver-coarse % edge, p",
    "direct-first: liver-coarse edge unresolved",
    "direct-first: liver-coarse edge unresolved, p",
    "direct-first: liver-coarse vertex unresolved",
    "direct-first: liver-coarse vertex unresolved, p",
    "direct-first: liver-refined % vertex",
    "direct-first: liver-refined % vertex, p",
    "direct-first: liver-refined % edge",
    "direct-first: liver-refined % edge, p",
    "direct-first: liver-refined edge unresolved",
    "direct-first: liver-refined edge unresolved, p",
    "direct-first: liver-refined vertex unresolved",
    "direct-first: liver-refined vertex unresolved, p",
    "direct-first: liver-refined edge set size",
    "direct-first: liver-local % edge",
    "direct-first: liver-local % edge, p",
    "direct-first: liver-local edge unresolved",
    "direct-first: liver-local edge unresolved, p",
    "direct-first: liver-local vertex unresolved",
    "direct-first: liver-local vertex unresolved, p",
    "surface-first-by-id: % vertex, cylinder and livers",
    "surface-first-by-id: % removable, cylinder and livers",
    "surface-first-by-id: % edge, cylinder and livers",
    "surface-first-by-id: vertex unresolved, all meshes",
    "surface-first-by-id: vertex set size, livers",
    "surface-first-by-id: edge set size, cylinder and livers",
    "surface-first-by-id: edge unresolved, cylinder and livers",
    "surface-first-by-id: card./op., cylinder and livers",
    "surface-first-by-id: sheet % vertex",
    "surface-first-by-id: sheet % vertex, p",
    "surface-first-by-id: sheet % removable",
    "surface-first-by-id: sheet % removable, p",
    "surface-first-by-id: liver-refined % vertex",
    "surface-first-by-id: liver-refined % vertex, p",
    "surface-first-by-id: liver-refined % removable",
    "surface-first-by-id: liver-refined % removable, p",
    "surface-first-by-id: liver-refined edge unresolved",
    "surface-first-by-id: liver-refined edge unresolved, p",
    "revisit: % vertex, cylinder and livers",
    "revisit: % removable, cylinder and livers",
    "revisit: vertex unresolved, all meshes",
    "revisit: edge set size, cylinder and livers",
    "revisit: edge unresolved, cylinder and livers",
    "revisit: card./op., cylinder and livers",
    "revisit: liver-refined edge unresolved, p",
    "3.5 first set: vertex unresolved, all meshes",
    "3.5 first set: vertex set size, livers",
    "3.5 first set: edge set size, cylinder and livers",
    "3.5 first set: card./op., cylinder and livers",
    "3.5 first set: liver-refined vertex set size",
    "3.5 first set: liver-refined edge unresolved",
    "3.5 first set: liver-refined edge unresolved, p",
]

if __name__ == "__main__":
    sys.exit(main(sys.argv))

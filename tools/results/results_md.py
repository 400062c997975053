#!/usr/bin/python3
"""Writes docs/results.md: every measured figure of tetcut, from the outputs of the tools that
measure them, never copied by hand. `ci/results` runs it on the CI machine; run that again and
commit the page whenever the figures move.

    results_md.py --bench RESULTS.json [--confirm RERUN.json]... --budgets BUDGETS.json
                  --stats STATS.json [--peer PEER.json] [--peer-without-improvement PEER.json]
                  [--sweeps SWEEPS.json]
                  [--build-dir DIR] [--how TEXT] [--out FILE]

RESULTS.json is ci/bench's Google Benchmark JSON (merged across suites, the callgrind figures
included with --instructions, the paired comparison with --paired, the session's memory), RERUN.json the re-runs ci/bench made of wall times over budget
(the gate keeps the fastest run, and so does the page), BUDGETS.json bench/budgets.json,
STATS.json `tetcut stats --json`'s output, PEER.json `tetcut_quality_peer --json`'s (with the
improvement pass, and with --improve off), SWEEPS.json `tetcut_quality_sweeps --json`'s. --build-dir is the build the figures came from (its compiler and flags are
named in the header), --how says how the benchmarks were run. Without --out the page goes to
stdout.

The page is a list of sections (SECTIONS at the end): each is one function from the inputs to
its Markdown lines, or to None when its inputs are absent (then it is left out). To add figures,
write one such function and add it to the list.
"""
import argparse
import json
import os
import platform
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench"))
from budget_gate import Gate, markdown_table, measured_entry  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench", "peers"))
import peers_table  # noqa: E402

# The Debian packages whose code is built into, or runs inside, what is measured.
LIBRARIES = ["libc6", "libstdc++6", "libtet1.5-dev", "libcgal-dev", "zlib1g-dev", "liblzma-dev",
             "nlohmann-json3-dev", "libcli11-dev", "libbenchmark-dev", "valgrind"]


class Inputs:
    def __init__(self, bench, confirmations, budgets, stats, build_dir, how, peer_on=None, peer_off=None,
                 sweeps=None, mechanics=None, haptic=None, engines=None):
        self.bench, self.confirmations, self.budgets, self.stats = bench, confirmations, budgets, stats
        self.mechanics = mechanics  # bench/mechanics_bench's Google Benchmark JSON
        self.haptic = haptic  # bench/haptic_stress --json
        self.engines = engines  # bench/peers/engines_compare --json
        self.build_dir, self.how = build_dir, how
        self.peer_on, self.peer_off = peer_on, peer_off  # tetcut_quality_peer --json, pass on and off
        self.sweeps = sweeps  # tetcut_quality_sweeps --json

    def median(self, benchmark):
        """The entry the gate reads for a benchmark: its median over the repetitions, else its run."""
        return measured_entry(self.bench, {"benchmark": benchmark}) if self.bench else None

    def benchmarks(self, prefix):
        """The names of the benchmarks that start with `prefix`, in the order they ran."""
        names = []
        for b in (self.bench or {}).get("benchmarks", []):
            name = b.get("run_name", b.get("name"))
            if name.startswith(prefix) and name not in names:
                names.append(name)
        return names


# ---- formatting --------------------------------------------------------------------------------

def fmt(value, decimals=1):
    """A figure for a table: thousands separated, `decimals` after the point; "-" when absent."""
    if value is None or (isinstance(value, float) and value != value):
        return "-"
    if decimals == 0:
        return f"{round(value):,}"
    return f"{value:,.{decimals}f}"


def short(value):
    """A figure whose size is not known in advance: 4 significant digits, or scientific when tiny."""
    if value is None:
        return "-"
    if value != 0 and abs(value) < 1e-3:
        return f"{value:.2g}"
    return f"{value:,.4g}" if abs(value) < 1e4 else fmt(value, 0)


def pair(ours, theirs, decimals=1):
    return f"{fmt(ours, decimals)} / {fmt(theirs, decimals)}"


def beside_paper(ours, paper, decimals=1):
    """Ours / the paper's, the paper's figure with no more digits than the paper printed."""
    if isinstance(paper, float):
        printed = len(repr(paper).split(".")[1]) if "." in repr(paper) else 0
        return f"{fmt(ours, decimals)} / {fmt(paper, max(1, min(decimals, printed)))}"
    return pair(ours, paper, decimals)


def with_interval(row, key, decimals=1):
    """Ours, its 95 % interval and, for a rate, its events of trials (`tetcut stats` over its seeded
    sweeps), then the paper's figure and, for a rate, Fisher's exact p of ours against the paper's
    rebuilt counts (`fisher_p`), starred below 0.05: "92.4 [92.1, 92.6] 40767/44120 / 84.1 (p 3e-40) *"."""
    ours, paper = row.get(key), row["paper"].get(key)
    ci, count = row.get("ci95", {}).get(key), row.get("count", {}).get(key)
    text = fmt(ours, decimals)
    if ci and ci[0] is not None:
        text += f" [{fmt(ci[0], decimals)}, {fmt(ci[1], decimals)}]"
    if count and key.endswith("_pct"):
        text += f" {count[0]}/{count[1]}"
    text += " / " + beside_paper(0, paper, decimals).split(" / ")[1]
    p = row.get("fisher_p", {}).get(key)
    if p is not None:
        text += f" (p {p:.2g})" + (" *" if p < 0.05 else "")
    return text


def table(header, rows, right_from=1):
    """A Markdown table; the columns from `right_from` on are numbers, aligned right."""
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---" if i < right_from else "---:" for i in range(len(header))) + "|"]
    return lines + ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]


def command_output(args):
    try:
        return subprocess.run(args, capture_output=True, text=True, check=False).stdout.strip()
    except OSError:
        return ""


# ---- sections ----------------------------------------------------------------------------------

def machine(inputs):
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            cpu = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), cpu)
    except OSError:
        pass
    context = (inputs.bench or {}).get("context", {})
    cores = f"{os.cpu_count()}"
    if context.get("num_cpus"):
        cores += f" (Google Benchmark saw {context['num_cpus']}"
        cores += f" at {context['mhz_per_cpu']} MHz)" if context.get("mhz_per_cpu") else ")"
    caches = ", ".join(f"L{c['level']} {c['type'].lower()} {c['size'] // 1024} KiB"
                       + (f" per {c['num_sharing']} CPUs" if c.get("num_sharing", 1) > 1 else "")
                       for c in context.get("caches", []))
    cache = {}
    build = inputs.build_dir
    if build and os.path.exists(os.path.join(build, "CMakeCache.txt")):
        with open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8") as f:
            for line in f:
                m = re.match(r"^([A-Za-z_]+):[A-Z]+=(.*)$", line.strip())
                if m:
                    cache[m.group(1)] = m.group(2)
    compiler = cache.get("CMAKE_CXX_COMPILER", "c++")
    build_type = cache.get("CMAKE_BUILD_TYPE", "")
    flags = " ".join(f for f in (cache.get("CMAKE_CXX_FLAGS", ""), cache.get(f"CMAKE_CXX_FLAGS_{build_type.upper()}", ""))
                     if f)
    cmake = command_output([cache.get("CMAKE_COMMAND", "cmake"), "--version"]).splitlines()
    packages = command_output(["dpkg-query", "-W", "-f", "${Package} ${Version}\\n"] + LIBRARIES).splitlines()
    rows = [("CPU", cpu), ("cores", cores)]
    if caches:
        rows.append(("caches", caches))
    if context.get("load_avg"):
        rows.append(("load average", ", ".join(f"{x:.2f}" for x in context["load_avg"])
                     + " (1, 5 and 15 minutes, as the first benchmark started)"))
    version = command_output([compiler, "--version"]).splitlines()
    rows += [("system", f"{platform.system()} {platform.release()}, {platform.machine()}"),
             ("compiler", version[0] if version else compiler),
             ("build", f"{build_type} {flags}".strip() + " (the project adds -ffp-contract=off)"),
             ("CMake", cmake[0] if cmake else "unknown"),
             ("libraries", ", ".join(packages) if packages else "unknown"),
             ("benchmarks", benchmark_runs(inputs))]
    return ["## Machine and toolchain", ""] + table(("", ""), rows, right_from=2)


def benchmark_runs(inputs):
    """How the benchmarks ran: the command, and the repetitions their medians are taken over."""
    repetitions = max((b.get("repetitions", 1) for b in (inputs.bench or {}).get("benchmarks", [])), default=0)
    how = f"`{inputs.how}`" if inputs.how else "ci/bench"
    return f"{how}, medians over {repetitions} repetitions" if repetitions > 1 else how


def budget_gate(inputs):
    if not inputs.bench:
        return None
    gate = Gate(inputs.bench, inputs.budgets, inputs.confirmations, skip_kinds={"instructions", "cache", "paired"})
    return ["## The budget gate", "",
            "Every figure of `bench/budgets.json`, as `ci/bench` gates it: the median over the repetitions, its "
            "budget, and how far below the budget it is. A wall time over budget is run again, up to twice, and the "
            "fastest run is kept (\"best of 3\"): load only slows a run down ([ci.md](ci.md)).", ""] + markdown_table(
        gate.rows) + ["", gate.summary]


def cut_sweeps(inputs):
    names = inputs.benchmarks("BM_CutSweep/") + inputs.benchmarks("BM_CutSweepCorpus/")
    if not names:
        return None
    rows = []
    for name in names:
        e = inputs.median(name)
        level = re.match(r"BM_CutSweep/(\d+)", name)
        times = {"0": "", "1": ", refined once", "2": ", refined twice"}
        mesh = (f"bundled liver{times.get(level.group(1), ', refined ' + level.group(1) + ' times')}" if level
                else e.get("label", name))
        rows.append((f"{mesh} ({fmt(e.get('tets'), 0)} tets)" if e.get("tets") else mesh, fmt(e.get("cuts"), 0),
                     fmt(e.get("p50_us")), fmt(e.get("p90_us")), fmt(e.get("p99_us")), fmt(e.get("max_us")),
                     fmt(e.get("first_us")), fmt(e.get("tets_removed_per_cut")), fmt(e.get("tets_created_per_cut")),
                     fmt(e.get("allocations"), 0), fmt(e.get("unresolved"), 0)))
    same_work = {order: inputs.median(f"BM_CutScalingSameWork/order:{i}/iterations:1")
                 for i, order in enumerate(("copies in order", "ids shuffled", "ids shuffled, then compact()"))}
    lines = ["## Per-cut latency", "",
             "Cautery sweeps with every cut timed (`bench/cut_bench.cpp`: the gated sweep through the bundled liver "
             "and the same paths through the refined livers; `bench/stages_bench.cpp`: a sweep along each bundled "
             "mesh). Percentiles are nearest-rank over every cut, the first included, in microseconds; `first` is "
             "the first cut with the caches emptied before it; allocations are counted over the whole sweep.", ""]
    lines += table(("sweep", "cuts", "p50", "p90", "p99", "max", "first", "removed / cut", "created / cut",
                    "allocations", "unresolved"), rows)
    rows = [(order, fmt(e.get("p50_us_16k")), fmt(e.get("p50_us_1M")), fmt(e["p50_ratio_1M_over_16k"], 2),
             fmt(e.get("p99_ratio_1M_over_16k"), 2)) for order, e in same_work.items() if e and "p50_ratio_1M_over_16k" in e]
    if rows:
        tets = next(e.get("tets_large") for e in same_work.values() if e)
        lines += ["", f"The same work on 64 copies of the liver ({fmt(tets, 0)} tets) against the lone liver, the sweep on "
                      "copy 0, both in one process (`BM_CutScalingSameWork`): with the copies' ids in order copy 0 keeps "
                      "the lone liver's memory layout; shuffled (a fixed seed) its tets lie scattered through the whole "
                      "mesh's memory, as a large mesh's do; compacted (`TetMesh::compact()`: the ids along a Morton "
                      "curve) they are near their neighbours again. Per-cut p50 in microseconds.", ""]
        lines += table(("ids of the 64 copies", "p50, liver", "p50, 64 copies", "p50 ratio", "p99 ratio"), rows)
    return lines


def swept_tool(inputs):
    ball = inputs.median("BM_CutSweep/0/iterations:1")
    capsule = inputs.median("BM_CapsuleSweep/iterations:1")
    strokes = inputs.median("BM_StrokeSampling/iterations:1")
    if not ball and not capsule and not strokes:
        return None
    lines = ["## The swept tool and the pieces a cut detaches", ""]
    rows = []
    for name, e in (("balls (`BM_CutSweep/0`)", ball), ("capsules (`BM_CapsuleSweep`)", capsule)):
        if e:
            rows.append((name, fmt(e.get("cuts"), 0), fmt(e.get("p50_us")), fmt(e.get("p99_us")), fmt(e.get("max_us")),
                         fmt(e.get("tets_removed_per_cut")), fmt(e.get("pieces_p50_us")), fmt(e.get("pieces_p99_us")),
                         fmt(e.get("fragments"), 0), fmt(e.get("allocations"), 0)))
    if rows:
        lines += ["The gated passes through the bundled liver cut by balls at their centres and by capsules joining "
                  "each pass's consecutive centres (`Cutter::cut_segment`, 4 mm long, the same 8 mm tool). Per-cut "
                  "times in microseconds over every cut; `search` is the search for the pieces each cut detached "
                  "(`CutTimings::pieces_us`), part of every cut; `pieces` is how many the sweep detached.", ""]
        lines += table(("sweep", "cuts", "p50", "p99", "max", "removed / cut", "search p50", "search p99", "pieces",
                        "allocations"), rows)
    p = inputs.median("instructions_per_cut/pieces")
    if p:
        lines += ["", f"The search's instructions per cut on the gated sweep (callgrind, the `pieces` stage): "
                      f"{fmt(p['per_cut'], 0)} mean, {fmt(p.get('p50_cut'), 0)} at the p50 cut, "
                      f"{fmt(p.get('p90_cut'), 0)} at the p90 cut."]
    if strokes:
        rows = []
        for pieces in (1, 2, 5, 10, 20):
            rows.append((str(pieces), fmt(strokes.get(f"capsules_{pieces}_volume"), 0), str(pieces + 1),
                         fmt(strokes.get(f"balls_{pieces + 1}_volume"), 0)))
        lines += ["", "One stroke across the liver (x = 95, z = 105 mm, y = 40 to 180 mm, the 8 mm tool) cut as capsules "
                      "and as balls at the same samples (`BM_StrokeSampling`): the volume removed, mm^3. The capsules' "
                      "does not depend on the sampling beyond the refinement's resolution; the balls' does.", ""]
        lines += table(("capsules", "volume removed", "balls", "volume removed"), rows)
    return lines


def removal_requests(inputs):
    names = inputs.benchmarks("BM_RemovalByStrategy/")
    if not names:
        return None
    rows = []
    for name in names:
        e = inputs.median(name)
        rows.append((e.get("label", name), fmt(e.get("p50_us"), 2), fmt(e.get("p99_us")), fmt(e.get("max_us")),
                     fmt(e.get("mean_cardinality"), 2), fmt(e.get("refinements"), 0), fmt(e.get("fallbacks"), 0),
                     fmt(e.get("attempts_undone"), 0), fmt(e.get("unresolved"), 0)))
    return ["## Removal requests by strategy", "",
            "2,000 requests for a tet on the current surface, one at a time as a cautery meets them "
            "(`BM_RemovalByStrategy`), each timed, in microseconds; the refinements and fallbacks are "
            "the requests in the tail.", ""] + table(
        ("strategy and mesh", "p50", "p99", "max", "mean cardinality", "refinements", "fallbacks", "attempts undone",
         "unresolved"), rows)


def instructions(inputs):
    e = inputs.median("instructions_per_cut")
    if not e:
        return None
    figures = {(f["benchmark"], f["field"]): f for f in inputs.budgets.get("figures", [])
               if f.get("kind") in ("instructions", "cache")}

    def baseline(benchmark, field):
        f = figures.get((benchmark, field))
        return fmt(f.get("baseline"), 0) + f" (<= {fmt(f.get('max'), 0)})" if f and f.get("baseline") else "-"

    lines = ["## Instructions per cut", "",
             f"callgrind over every cut of the fixed liver sweep (`bench/cut_instructions.cpp`, `ci/bench "
             f"--instructions`): {fmt(e['instructions_per_cut'], 0)} instructions per cut ({fmt(e.get('instructions'), 0)} "
             f"in {fmt(e.get('cuts'), 0)} cuts). Deterministic for one toolchain, whatever the machine's load. One profile "
             "part per cut gives the percentiles (nearest rank over the cuts); a stage is the inclusive cost of its "
             "`Cutter::Pipeline` member functions, what its `CutTimings` field times (finish: the tissue audit and the "
             "commit); `other` is the cut's own work around them. Each gated row's baseline and bound (+3 %) are "
             "`bench/budgets.json`'s.", ""]
    rows = [("whole cut", fmt(e["instructions_per_cut"], 0), fmt(e.get("p50_cut"), 0), fmt(e.get("p90_cut"), 0),
             fmt(e.get("p99_cut"), 0), baseline("instructions_per_cut", "instructions_per_cut") + "; p50 "
             + baseline("instructions_per_cut", "p50_cut") + "; p90 " + baseline("instructions_per_cut", "p90_cut"))]
    for stage in ("locate", "refine", "select", "remove", "improve", "finish", "pieces", "other"):
        s = inputs.median(f"instructions_per_cut/{stage}")
        if s:
            rows.append((stage, fmt(s["per_cut"], 0), fmt(s.get("p50_cut"), 0), fmt(s.get("p90_cut"), 0), "-",
                         baseline(f"instructions_per_cut/{stage}", "per_cut")))
    lines += table(("", "mean", "p50 cut", "p90 cut", "p99 cut", "baseline (bound) of the mean"), rows)
    c = inputs.median("ll_misses_per_cut")
    if c:
        lines += ["", f"Last-level cache misses on the same sweep through 64 copies of the liver whose ids are shuffled "
                      f"({fmt(c.get('cuts'), 0)} cuts, `cut_instructions --shuffled-copies`), in callgrind's simulated "
                      f"caches (32 KiB L1s, an 8 MiB 16-way last level; empty at the first cut): "
                      f"{fmt(c['ll_misses_per_cut'], 0)} per cut, {fmt(c.get('d1_misses_per_cut'), 0)} L1 data misses, "
                      f"{fmt(c.get('instructions_per_cut'), 0)} instructions per cut (the ties the engine breaks by id "
                      f"differ from the liver's). Baseline {baseline('ll_misses_per_cut', 'll_misses_per_cut')}."]
    if e.get("toolchain"):
        lines += ["", f"Toolchain of the counts: {e['toolchain']}"]
    return lines


def paired(inputs):
    entries = [b for b in (inputs.bench or {}).get("benchmarks", []) if b.get("name", "").startswith("paired/")]
    if not entries:
        return None
    limits = {f["benchmark"]: f["max"] for f in inputs.budgets.get("figures", []) if f.get("kind") == "paired"}
    reference = inputs.budgets.get("reference", {}).get("commit", "?")
    rows = [(b["name"][len("paired/"):], short(b["head_us"]), short(b["reference_us"]), f"{b['ratio']:.3f}",
             f"[{b['ratio_low']:.3f}, {b['ratio_high']:.3f}]", f"{limits[b['name']]:g}" if b["name"] in limits else "-")
            for b in entries]
    return ["## Paired wall time against the reference", "",
            f"`ci/bench --paired` (`bench/paired_gate.py`): this build's engine and the reference commit's "
            f"({reference[:12]}, `bench/budgets.json`) cut the gated sweep on the liver and on the liver refined twice in "
            f"turns on one core, {entries[0].get('pairs', '?')} pairs; per figure the median of the pairs' ratios head / "
            "reference and its 95 % bootstrap interval. The gate fails a figure whose interval's lower end is above its "
            "limit. Medians of the rounds in microseconds.", ""] + table(
        ("figure", "head", "reference", "ratio", "95 % interval", "limit"), rows)


# The cost goals a cut is held to beyond the gate's budgets (the gate keeps each figure from
# getting worse; these say where it should get to): (what, the figure's reader, the goal, unit).
COST_GOALS = (
    ("instructions per cut, mean (callgrind)", lambda i: (i.median("instructions_per_cut") or {}).get("instructions_per_cut"),
     80000, "", 0),
    ("instructions per cut, p50 cut (callgrind)", lambda i: (i.median("instructions_per_cut") or {}).get("p50_cut"),
     60000, "", 0),
    ("gated sweep (bundled liver), cut p50", lambda i: (i.median("BM_CutSweep/0/iterations:1") or {}).get("p50_us"),
     12, " us", 1),
    ("gated sweep (bundled liver), cut p99", lambda i: (i.median("BM_CutSweep/0/iterations:1") or {}).get("p99_us"),
     60, " us", 1),
    ("same work on 64 copies against the liver, ids shuffled, p50 ratio",
     lambda i: (i.median("BM_CutScalingSameWork/order:1/iterations:1") or {}).get("p50_ratio_1M_over_16k"), 1.25, "", 2),
    ("peak memory of a cutting session, per tet", lambda i: (i.median("session_memory") or {}).get("bytes_per_tet"),
     160, " B", 1),
    ("8M-tet liver (refined three times), cut p50",
     lambda i: (i.median("BM_CutSweep/3/iterations:1") or {}).get("p50_us"), 100, " us", 1),
)


def cost_goals(inputs):
    if not inputs.bench:
        return None
    rows = []
    for what, read, goal, unit, decimals in COST_GOALS:
        value = read(inputs)
        if value is None:
            rows.append((what, "not measured", f"<= {fmt(goal, decimals)}{unit}", "-"))
        else:
            rows.append((what, f"{fmt(value, decimals)}{unit}", f"<= {fmt(goal, decimals)}{unit}",
                         "met" if value <= goal else f"not met ({fmt(value / goal, 2)} x the goal)"))
    return ["## Cost goals", "",
            "Where a cut's cost should get to, each goal beside this run's figure (the gate's budgets only keep "
            "the figures from getting worse). Where the instructions go, stage by stage: \"Instructions per "
            "cut\" below; why: [performance.md](performance.md).", ""] + table(("figure", "this run", "goal", ""), rows)


def session_memory(inputs):
    e = inputs.median("session_memory")
    if not e:
        return None
    return ["## Memory of a cutting session", "",
            f"`bench/session_memory.cpp`, a process of its own: read 64 copies of the liver ({fmt(e['tets'], 0)} tets) "
            f"from a binary VTU file, build the mesh, construct a Cutter, run the gated sweep. Peak resident size "
            f"{fmt(e['peak_rss_bytes'] / 1e6, 0)} MB: {fmt(e['bytes_per_tet'])} bytes per tet (peak after the file's read "
            f"{fmt(e.get('read_bytes_per_tet'))}, after the mesh's build {fmt(e['load_bytes_per_tet'])}, after the "
            f"Cutter's construction {fmt(e['cutter_bytes_per_tet'])}; at the start {fmt(e['start_bytes_per_tet'])})."]


def paper_table1(inputs):
    rows = (inputs.stats or {}).get("table1")
    if not rows:
        return None
    body = [(f"{r['paper_mesh']} {r['mesh']}", fmt(r["tets"], 0), fmt(r["cuts"], 0),
             beside_paper(r["operations"], r["paper"]["operations"], 0),
             with_interval(r, "removable_pct"), with_interval(r, "vertex_pct"), with_interval(r, "edge_pct"))
            for r in rows]
    return ["## The paper's Table 1 beside ours", "",
            "`tetcut stats`: each mesh cut by its cautery scenario (`corpus/scenarios/paper/`) with the combined "
            "strategy, pooled over its seeded sweeps (`sweeps` in the JSON; docs/paper.md). Removing a tet on the "
            "surface: % removable directly, % that would make a vertex singular, % an edge. Each cell is ours "
            "[95 % Wilson interval] events/operations / the paper's (p: Fisher's exact test of our counts against "
            "the paper's, rebuilt from its percentages; * when p < 0.05).",
            ""] + table(
        ("mesh", "tets", "cuts", "operations", "% removable", "% vertices", "% edges"), body)


def paper_table2(inputs):
    rows = (inputs.stats or {}).get("table2")
    if not rows:
        return None
    keys = ("vertex_unresolved_pct", "vertex_cardinality", "edge_unresolved_pct", "edge_cardinality",
            "global_unresolved_pct", "global_cardinality_per_operation")
    body = [(f"{r['paper_mesh']} {r['mesh']}",) + tuple(
        with_interval(r, k, 2 if k == "global_cardinality_per_operation" else 1) for k in keys)
        + (fmt(r.get("global_cardinality_per_selected"), 2), fmt(r.get("combined_unresolved_pct")))
        for r in rows]
    return ["## Table 2: the paper's neighbour search", "",
            "The neighbour strategy (paper 3.5): % of singularities it did not resolve and the mean number of tets "
            "it removed when it did. Global: over all operations, direct removals counting 1, tets removed per "
            "operation resolved (the paper's column: its figures reconstruct so); per selected tet (ours only): "
            "each selected tet a set swallowed counted. Ours [95 % interval: Wilson for rates, seeded bootstrap over "
            "the sweeps for mean sizes] (unresolved/singularities) / the paper's (for a rate, p: Fisher's exact test "
            "against the paper's rebuilt counts, * when p < 0.05; a mean size has no test); the last column is what the combined strategy left.", ""] + table(
        ("mesh", "vertex: % unresolved", "vertex: cardinality", "edge: % unresolved", "edge: cardinality",
         "global: % unresolved", "global: cardinality", "per selected", "combined: % unresolved"), body)


def paper_table2_wide(inputs):
    wide, paper = (inputs.stats or {}).get("table2_wide"), (inputs.stats or {}).get("table2")
    if not wide or not paper:
        return None
    ours = {r["mesh"]: r for r in paper}
    keys = ("vertex_unresolved_pct", "vertex_cardinality", "edge_unresolved_pct", "edge_cardinality")
    body = [(f"{r['paper_mesh']} {r['mesh']}",) + tuple(pair(r.get(k), ours[r["mesh"]].get(k)) for k in keys)
            + (pair(r.get("global_cardinality_per_operation"), ours[r["mesh"]].get("global_cardinality_per_operation"), 2),
               fmt(r.get("wide_unresolved_pct"))) for r in wide]
    return ["## Table 2, our wider search", "",
            "Strategy `wide` (not the paper's: whole vertex shells as candidates, rounds of repairs, smallest set "
            "first) in place of 3.5 on the same scenarios: each cell is wide / the paper's search (ours, from "
            "Table 2).", ""] + table(
        ("mesh", "vertex: % unresolved", "vertex: cardinality", "edge: % unresolved", "edge: cardinality",
         "global: cardinality", "wide: % unresolved"), body)


def strategies(inputs):
    rows = (inputs.stats or {}).get("strategies")
    if not rows:
        return None
    full = max(r["cuts"] for r in rows)
    stops = []
    body = []
    for r in rows:
        cuts = fmt(r["cuts"], 0)
        if not r.get("ok", True):
            stops.append(r.get("error", ""))
            cuts = f"{cuts} of {fmt(full, 0)} *"
        body.append((r["name"], cuts, fmt(r["requests"], 0), fmt(r["tets_created"], 0), fmt(r["removed_per_request"], 2),
                     fmt(r["unresolved"], 0), fmt(r["tets_after"], 0),
                     f"{short(r['worst_created_radius_ratio'])} / {r['mean_radius_ratio']:.3f}",
                     f"{short(r['p50_us'])} / {short(r['p99_us'])}"))
    mesh = rows[0].get("mesh", "")
    lines = [f"## Strategies on the {mesh} scenario", "",
             "Every strategy on one paper scenario (`tetcut stats --mesh` picks another), with our split templates "
             "and with sequential bisection. Quality is the radius ratio: the worst tet the cuts created, and the "
             "mean of the mesh after; times per cut in microseconds.", ""]
    lines += table(("strategy", "cuts", "requests", "tets created", "removed / request", "unresolved", "tets after",
                    "worst created / mean after", "p50 / p99 per cut"), body)
    if stops:
        reason = re.sub(r"^\S+:\d+: ", "", stops[0])
        lines += ["", f"\\* stopped early: {reason} (the comparison stops a run when its mesh passes twice its "
                      "initial size)."]
    return lines


def created_quality(q):
    """The worst created tet as "radius ratio / min dihedral", "-" when nothing was created."""
    if not q or not q.get("tets"):
        return "-"
    return f"{short(q['min_radius_ratio'])} / {fmt(q['min_dihedral_deg'], 1)}"


def quality(inputs):
    rows = (inputs.stats or {}).get("quality")
    if not rows:
        return None
    body = []
    stops = []
    for r in rows:
        mark = ""
        if not r.get("ok", True):
            reason = re.sub(r"^\S+:\d+: ", "", r.get("error", ""))
            stops.append(f"{r['paper_mesh']} {r['mesh']}, {r['strategy']}: {reason}")
            mark = " *"
        body.append((f"{r['paper_mesh']} {r['mesh']}", r["strategy"], short(r["input_worst_radius_ratio"]),
                     short(r["goal"]), created_quality(r["created"]) + mark,
                     created_quality(r["created_without_improvement"]), "yes" if r["goal_met"] else "**no**"))
    lines = ["## Quality of the tets the cuts create", "",
             "`tetcut stats`: each paper scenario with each strategy, with the improvement pass that ends every cut "
             "(flips, collapses, smoothing of the cut's own vertices; `CutParams::improve`) and without it. Each cell "
             "is the worst tet the cuts created: radius ratio / smallest dihedral angle in degrees, measured by the "
             "independent checker. Goal (issue 29): radius ratio at least min(0.1, the input's worst), half that for "
             "basic. The checker holds every cut with the pass to that floor (I7, no degradation).", ""]
    lines += table(("mesh", "strategy", "input worst", "goal", "with the pass", "without", "goal met"), body, right_from=2)
    if stops:
        lines += ["", "\\* stopped early (figures up to the stop): " + "; ".join(stops) + "."]
    strategies_rows = (inputs.stats or {}).get("strategies") or []
    if strategies_rows and "created" in strategies_rows[0]:
        bins = [f"{b / 10:.1f}-" for b in range(10)]
        hist = [(r["name"],) + tuple(fmt(n, 0) for n in r["created"]["radius_ratio_histogram"]) for r in strategies_rows]
        lines += ["", f"Radius ratios of the tets the cuts created on the {strategies_rows[0].get('mesh', '')} scenario, "
                      "with the pass: how many in each tenth.", ""]
        lines += table(["strategy"] + bins, hist)
        if "min_dihedral_histogram" in strategies_rows[0]["created"]:
            angle_bins = [f"{5 * b}-" for b in range(len(strategies_rows[0]["created"]["min_dihedral_histogram"]))]
            angles = [(r["name"],) + tuple(fmt(n, 0) for n in r["created"]["min_dihedral_histogram"]) for r in strategies_rows]
            lines += ["", "Smallest dihedral angles of the same tets, degrees: how many in each 5 degrees.", ""]
            lines += table(["strategy"] + angle_bins, angles)
    return lines


def quality_peer(inputs):
    on, off = inputs.peer_on, inputs.peer_off
    if not on:
        return None

    def row(name, spread):
        return (name, f"{short(spread['worst_radius_ratio'])} / {fmt(spread['worst_min_dihedral_deg'], 1)}",
                f"{short(spread['median_radius_ratio'])} / {fmt(spread['median_min_dihedral_deg'], 1)}")

    body = []
    for label, run in (("with the pass", on), ("without the pass", off)):
        if not run:
            continue
        s = run["summary"]
        body.append(row(f"tetcut {label}: created tets, every cut", s["tetcut_created_all"]))
        body.append(row(f"CGAL on the same cells, after tetcut {label}", s["selection_after_cgal"]))
    s = on["summary"]
    lines = ["## Beside CGAL's remeshing", "",
             "`tetcut_quality_peer` (bench/peers/): the gated liver sweep (16k tets, 8 mm tool, "
             f"{fmt(s['cuts'], 0)} cuts); after every cut that created tets ({fmt(s['cuts_sampled'], 0)} of them), "
             "CGAL 5.5's `tetrahedral_isotropic_remeshing` remeshes the created tets and their face neighbours "
             "(`cell_is_selected_map`), surface and selection boundary kept. Worst and median tet, radius ratio / "
             "smallest dihedral in degrees.", ""]
    lines += table(("", "worst", "median"), body)
    times = [f"tetcut's cut p50 {short(s['tetcut_p50_us'])} us, p99 {short(s['tetcut_p99_us'])} us with the pass"]
    if off:
        times.append(f"{short(off['summary']['tetcut_p50_us'])} / {short(off['summary']['tetcut_p99_us'])} us without")
    times.append(f"CGAL's remeshing of the selection alone p50 {short(s['cgal_remesh_p50_ms'])} ms, "
                 f"p99 {short(s['cgal_remesh_p99_ms'])} ms")
    lines += ["", "Times: " + "; ".join(times) + f". CGAL left the selection's worst tet worse than tetcut's in "
              f"{fmt(s['cgal_lowered_worst_radius_ratio'], 0)} of {fmt(s['cuts_sampled'], 0)} cuts by radius ratio."]
    return lines


def quality_sweeps(inputs):
    data = inputs.sweeps
    if not data or not data.get("rows"):
        return None
    body = []
    for r in data["rows"]:
        worst = "-"
        if "worst_created_radius_ratio" in r:
            worst = f"{short(r['worst_created_radius_ratio'])} / {fmt(r['worst_created_min_dihedral_deg'], 1)}"
        refused = fmt(r["refused"], 0) + (f" ({fmt(r.get('retried_cuts', 0), 0)} retried)" if r.get("retried_cuts") else "")
        body.append((r["mesh"], r["tool"], short(r["tool_diameter"]), fmt(r["tets"], 0), fmt(r["cuts"], 0), refused,
                     fmt(r["checker_violations"], 0), fmt(r.get("cuts_leaving_tissue", 0), 0), worst,
                     f"{short(r.get('p99_created_per_cut'))} / {fmt(r['max_created_per_cut'], 0)}",
                     f"{short(r.get('p99_created_within_reach_per_cut'))} / "
                     f"{fmt(100 * r.get('created_beyond_reach_share', 0), 0)}",
                     f"{short(r['p50_us'])} / {short(r['p99_us'])} / {short(r['max_us'])}",
                     f"{fmt(100 * r.get('volume_left_share_p50', 0), 1)} / {fmt(100 * r.get('volume_left_share_p99', 0), 1)}",
                     f"{fmt(100 * r.get('volume_removed_beyond_share_p50', 0), 1)} / "
                     f"{fmt(100 * r.get('volume_removed_beyond_share_p99', 0), 1)}",
                     fmt(r.get("tets_removed_beyond_reach", 0), 0), "yes" if r["goal_met"] else "**no**"))
    made_by = {}
    for r in data["rows"]:
        made_by.setdefault(r["mesh"], r["made_by"])
    lines = ["## Random sweeps on meshes from TetGen and CGAL", "",
             f"`tetcut_quality_sweeps` (bench/quality_sweeps.cpp): {data['sweeps_per_tool']} sweeps per mesh and tool "
             "along random chords of the bounding box, one cut every half tool diameter, default parameters "
             f"(combined, the improvement pass, floor 0.1, refinement {data.get('refinement', 'paper')}), the checker "
             "after every cut (I10, the tissue rule, included). Tools: 4, 8 and 12 % of the bounding box's diagonal, "
             "and 0.05 to 3 times the median edge (`0.05x` ...). Refused: cuts rolled back (the mesh as it was), and "
             "how many ok cuts auto made again with the graded rule. Left: ok cuts that left tissue the selection "
             "takes in the tool (`left_in_tool`). Worst created: radius ratio / smallest dihedral in degrees. Tets "
             "made per ok cut p99 / max; of them, within the cut's reach (the tool's ball grown by D_ref, by "
             "centroid) p99 / beyond it, in % of all tets made: the refinement's grading out to the mesh's size. Volume left in the tool and removed beyond it per ok cut, p50 / p99, in % "
             "of the tool's ball (estimates: `volume_left_in_tool`, docs/usage.md). Goal met: no refused cut and "
             "every created tet at min(0.1, the input's worst) or better. Meshes: "
             + "; ".join(f"{k}: {v}" for k, v in made_by.items()) + ".", ""]
    lines += table(("mesh", "tool", "diameter", "tets", "cuts", "refused", "checker", "left", "worst created",
                    "tets made p99 / max", "in reach p99 / beyond %", "p50 / p99 / max us", "vol. left %", "vol. beyond %", "beyond reach",
                    "goal met"), body, right_from=2)
    return lines


def resection(inputs):
    r = (inputs.stats or {}).get("resection")
    if not r:
        return None
    before, after = r.get("quality_before", {}), r.get("quality_after", {})
    return ["## The liver resection", "",
            f"`{r['scenario']}` with the combined strategy: {fmt(r['cuts'], 0)} cuts, {fmt(r['tets_before'], 0)} tets "
            f"before and {fmt(r['tets_after'], 0)} after, per cut p50 {short(r.get('p50_us'))} us and p99 "
            f"{short(r.get('p99_us'))} us; radius ratio worst {short(before.get('min_radius_ratio'))} before, "
            f"{short(after.get('min_radius_ratio'))} after, mean {fmt(before.get('mean_radius_ratio'), 3)} before, "
            f"{fmt(after.get('mean_radius_ratio'), 3)} after. `tetcut stats --html` draws it."]


def peers(inputs):
    found = peers_table.runs(inputs.bench or {})
    if not found:
        return None
    return ["## Peers on the same cuts", "",
            "`bench/peers/peers_bench.cpp` (issue 31): the gated liver sweep and one held-back random sweep per "
            "bundled mesh, through tetcut, blind removal (the tets whose centroid is in the tool, as SOFA and iMSTK "
            "remove them), CGAL 5.5's complex with `face_status` classification and undo, and TetGen 1.5's `-r` "
            "with a volume bound in the tool (8 cuts from the first that removes tissue), the independent checker "
            "after every cut. Singular vertices and edges are summed over the cuts' local reports (one a later cut "
            "touches again counts again) and counted once in the final mesh. Ratios are tetcut over the peer; "
            "`bench/budgets.json` gates the p50 ratios of the gated sweep.", ""] + peers_table.tables(found, peers_table.md_table)


# What each engine adapter stands for, in the table's words (docs/engines.md has the details).
ENGINE_STANDS_FOR = {
    "tetcut": "tetcut: refine, remove, resolve, improve",
    "imstk-style": "blind removal, iMSTK's algorithm (our model)",
    "sofa-style": "blind removal, SOFA's algorithm (our model)",
    "cgal": "CGAL 5.5 C3T3: remove, classify, undo",
    "cgal-remesh": "CGAL 5.5: remesh the tool's neighbourhood, then remove, classify, undo",
    "tetgen-local": "TetGen 1.5 -r on the tool's neighbourhood, then blind removal",
    "blind": "blind removal, a scan (the template)",
}

README_ENGINES_BEGIN = "<!-- engines table: generated by ci/results from bench/peers/engines_compare; do not edit -->"
README_ENGINES_END = "<!-- end of engines table -->"


def engines_table(e):
    """The engines figures as a Markdown table: the lines the README carries too."""
    rows = []
    for a in e["approaches"]:
        singular = f"{a['singular_vertices']} / {a['singular_edges']}"
        if a.get("tets_removed_per_cut") is not None:
            tets = f"{a['tets_removed_per_cut']:.2f} / {a['tets_created_per_cut']:.2f}"
        else:
            tets = f"net {a['net_tets_per_cut']:+.2f}"
        rows.append([ENGINE_STANDS_FOR.get(a["name"], a["name"]), f"`{a['name']}`",
                     f"{a['p50_us']:.0f} / {a['p99_us']:.0f}",
                     tets, f"{a['volume_removed_per_cut']:.0f}",
                     f"{a['volume_outside_tool_per_cut']:.0f}", f"{a['volume_left_in_tool_per_cut']:.0f}",
                     f"{a['cuts_objected']}", singular, f"{a['final_min_dihedral_deg']:.2g}",
                     f"{a.get('ratio_per_cut', float('nan')):.3g}", f"{a.get('ratio_per_volume', float('nan')):.3g}"])
    return table(["approach", "adapter", "cut p50 / p99 (us)", "tets removed / made per cut", "mm3 removed per cut",
                  "of it outside the tool", "mm3 left in the tool", "cuts that broke the mesh",
                  "singular vertices / edges left", "worst dihedral at the end (deg)", "tetcut / it, per cut",
                  "tetcut / it, per mm3"], rows, right_from=2)


def engines(inputs):
    e = inputs.engines
    if not e:
        return None
    return ["## Engines on the same cuts, through engine.h", "",
            f"`bench/peers/engines_compare.cpp` ([engines.md](engines.md)): the gated liver sweep ({e['cuts']} balls of "
            f"{e['tool_diameter']:g} mm) through every shipped engine adapter, interleaved cut by cut in one process, "
            "the approach that goes first rotating. The time is the adapter's cut call alone. Between cuts each "
            "mesh is read back, measured and fully checked, which evicts the caches: the times are cold, above the "
            "gated sweep's warm ones, and the ratios are what compare. Volumes are the drop of the mesh's volume and "
            "of its volume inside the ball (tets straddling the ball measured on 64 equal children); 'left in the "
            "tool' is the tissue still inside the ball after the cut. 'Broke the mesh': cuts after which the full "
            "check found more singular vertices, singular edges or flat tets than before. Ratios are tetcut's p50 "
            "over the approach's, per cut and per mm3 removed. 'Tets removed / made' comes from the change log; an "
            "approach without one (SOFA's arrays are dense, CGAL's and TetGen's remeshing replace vertices) shows the net change "
            "of the live tets. The iMSTK and SOFA rows are our models of those "
            "libraries' algorithms, not the libraries.", ""] + engines_table(e)


def update_readme_engines(readme_path, e):
    """Replaces the README's engines table (between its markers) with this run's."""
    with open(readme_path, encoding="utf-8") as f:
        text = f.read()
    begin, end = text.find(README_ENGINES_BEGIN), text.find(README_ENGINES_END)
    if begin < 0 or end < begin:
        sys.exit(f"results_md: {readme_path} has no engines table markers")
    block = README_ENGINES_BEGIN + "\n" + "\n".join(engines_table(e)) + "\n"
    text = text[:begin] + block + text[end:]
    tmp = readme_path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, readme_path)


def mechanics(inputs):
    runs = {b["name"]: b for b in (inputs.mechanics or {}).get("benchmarks", []) if b.get("run_type") != "aggregate"}
    frame = runs.get("BM_HapticFrame/iterations:1")
    scaling = runs.get("BM_UpdateScalingSameWork/iterations:1")
    if not frame or not scaling:
        return None
    body = ["## The change log's consumers: elasticity and the rendered surface", "",
            "`bench/mechanics_bench.cpp` (issue 30, [mechanics.md](mechanics.md)): `tetcut::mechanics`' tensor-mass "
            "model and rendered surface, updated from each cut's change log. Not gated: the haptic frame's p99 "
            "is a wall time that the machine's load moves.", "",
            "| figure | goal | measured |", "|---|---|---|",
            f"| haptic frame on the 16k liver (cut + model and surface update + one step), {frame['frames']:.0f} frames "
            f"| p99 <= 1,000 us | p50 {frame['p50_us']:.0f} us, p99 {frame['p99_us']:.0f} us, max {frame['max_us']:.0f} us "
            f"(thread CPU p99 {frame['cpu_p99_us']:.0f} us) |",
            f"| model + surface update per cut | - | p50 {frame['update_p50_us']:.1f} us, p99 {frame['update_p99_us']:.0f} us; "
            f"{frame['consumer_allocations']:.0f} allocations |",
            f"| update, same work, 1M / 16k liver | <= {scaling['goal_ratio']:.1f} | p50 {scaling['p50_ratio_1M_over_16k']:.2f}, "
            f"p99 {scaling['p99_ratio_1M_over_16k']:.2f} |"]
    strategies = ["basic", "neighbours", "combined", "wide"]
    for i, name in enumerate(strategies):
        r = runs.get(f"BM_StableStepAfterResection/{i}/iterations:1")
        if r:
            body.append(f"| stable time step after the bundled liver resection, {name} | - | "
                        f"{r['stable_dt_after_us']:.1f} us against {r['stable_dt_before_us']:.1f} us before "
                        f"({r['ratio_after_over_before']:.2f}) |")
    step, sparse = runs.get("BM_ExplicitStep"), runs.get("BM_ExplicitStepSparse")
    if step and sparse:
        body.append(f"| one explicit step, 16k liver: tensor loop / Eigen sparse product | - | "
                    f"{step['real_time']:.0f} us / {sparse['real_time']:.0f} us |")
    return body


def haptic_stress(inputs):
    h = inputs.haptic
    if not h:
        return None

    def spread(f):
        return f"p50 {f['p50']:.2f} us, p99 {f['p99']:.2f} us, max {f['max']:.2f} us ({f['n']} reads)"

    slower = 100.0 * (h["cut_with_readers_us"] / h["cut_alone_us"] - 1.0)
    return ["## Readers on other threads: the haptic stress harness", "",
            "`bench/haptic_stress.cpp` (issue 47, [mechanics.md](mechanics.md#snapshots-for-other-threads)): the "
            "gated sweep on the bundled liver, each cut followed by the model's and the surface's update, one "
            "step, the reaction force and a `SnapshotPublisher` publish with checksums; a haptic thread reads the "
            "latest frame every millisecond and a render thread every 1/60 s (`sleep_until` on `steady_clock`, "
            "default scheduling, no real-time priority, timer slack 1 ns), checking each frame's checksum. A read is the checksum "
            "over the whole frame, which a real haptic loop would not compute. Not gated: wall times that the "
            f"machine's load moves, on {h['hardware_threads']} hardware threads for three threads.", "",
            "| figure | goal | measured |", "|---|---|---|",
            f"| haptic reader's wait for a frame (the lease) | p99 <= 1 us | {spread(h['haptic']['wait_us'])} |",
            f"| render reader's wait for a frame | p99 <= 1 us | {spread(h['render']['wait_us'])} |",
            f"| haptic loop's lateness against its 1 ms schedule | p99 <= 100 us where the scheduling allows | "
            f"{spread(h['haptic']['late_us'])} |",
            f"| haptic reader's read of a whole frame (checksum) | - | {spread(h['haptic']['read_us'])} |",
            f"| cutter per cut (cut + update + step + reaction + publish with checksum), alone / with the readers "
            f"| <= 10 % slower | {h['cut_alone_us']:.0f} us / {h['cut_with_readers_us']:.0f} us ({slower:+.1f} %) |",
            f"| torn or backward frames read | 0 | {h['torn'] + h['backwards']} |"]


SECTIONS = [machine, cost_goals, budget_gate, cut_sweeps, swept_tool, paired, removal_requests, instructions, session_memory, paper_table1,
            paper_table2,
            paper_table2_wide, strategies, quality, quality_peer, quality_sweeps, peers, engines, mechanics, haptic_stress, resection]


def page(inputs):
    lines = ["# Results", "",
             "<!-- Generated by ci/results (tools/results/results_md.py): do not edit; run ci/results again. -->", "",
             "Every figure tetcut measures, generated by `ci/results` from `tetcut stats --json` and `ci/bench`'s "
             "Google Benchmark JSON on the machine named below. Times depend on that machine and its load; counts, "
             "the paper's tables and instruction counts do not. Why the figures are what they are: "
             "[performance.md](performance.md) and [paper.md](paper.md)."]
    for section in SECTIONS:
        body = section(inputs)
        if body:
            lines += [""] + body
    return "\n".join(lines) + "\n"


def load(path, what):
    if not path:
        return None
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"results_md: cannot read {what} {path}: {e}")


def main(argv):
    parser = argparse.ArgumentParser(description="Writes docs/results.md from measured outputs.")
    parser.add_argument("--bench", help="ci/bench's results JSON")
    parser.add_argument("--confirm", action="append", default=[], help="ci/bench's re-runs of wall times over budget")
    parser.add_argument("--budgets", required=True, help="bench/budgets.json")
    parser.add_argument("--stats", help="tetcut stats --json output")
    parser.add_argument("--peer", help="tetcut_quality_peer --json output (improvement pass on)")
    parser.add_argument("--peer-without-improvement", help="the same with --improve off")
    parser.add_argument("--sweeps", help="tetcut_quality_sweeps --json output")
    parser.add_argument("--mechanics", help="bench/mechanics_bench's JSON output")
    parser.add_argument("--haptic", help="bench/haptic_stress --json output")
    parser.add_argument("--engines", help="bench/peers/engines_compare --json output")
    parser.add_argument("--readme", help="a README whose engines table (between its markers) is rewritten too")
    parser.add_argument("--build-dir", help="the build the figures came from")
    parser.add_argument("--how", help="how the benchmarks were run")
    parser.add_argument("--out", help="the page (default: stdout)")
    args = parser.parse_args(argv[1:])
    inputs = Inputs(load(args.bench, "benchmark results"), [load(c, "re-run results") for c in args.confirm],
                    load(args.budgets, "budgets"),
                    load(args.stats, "tetcut stats output"), args.build_dir, args.how,
                    load(args.peer, "quality peer output"), load(args.peer_without_improvement, "quality peer output"),
                    load(args.sweeps, "quality sweeps output"), load(args.mechanics, "mechanics benchmark output"),
                    load(args.haptic, "haptic stress output"), load(args.engines, "engines comparison output"))
    if args.readme and inputs.engines:
        update_readme_engines(args.readme, inputs.engines)
    text = page(inputs)
    if not args.out:
        sys.stdout.write(text)
        return 0
    tmp = args.out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

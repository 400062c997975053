#!/usr/bin/env python3
"""`tetcut stats` end to end, as a user runs it: the JSON has its tables, and the HTML report is
self-contained, loads in headless Chromium (Debian's `chromium`) and draws its pictures.

usage: report_renders_in_chromium.py TETCUT CORPUS_DIR OUT_DIR

The screenshot is checked from its pixels (PNG decoded here, no imaging library needed): the
liver's surface colour and the cut surfaces' colour must both be on the page, and so must the
plot's line colour. Exit 0 when every check passes, 1 with the failed checks listed otherwise.
"""
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import zlib

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                  "--disable-dev-shm-usage", "--disable-extensions", "--disable-sync",
                  "--no-first-run", "--hide-scrollbars"]
PICTURE_IDS = ["latency-plot", "quality-histogram", "liver-before", "liver-after"]
MESHES = ["cylinder", "sheet", "liver-coarse", "liver-refined", "liver-local"]
SWEEPS = 2
# Table 2's mean set sizes: the JSON key and the counts of removal_counts() its ratio is made of.
MEAN_SIZES = {
    "vertex_cardinality": (("vertex_neighbour_set_tets",), ("vertex_resolved_by_neighbours",)),
    "edge_cardinality": (("edge_neighbour_set_tets",), ("edge_resolved_by_neighbours",)),
}

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
    return condition


def without_times(value):
    """The report with its per-cut times (the only figures that vary between runs) left out."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if k not in ("p50_us", "p99_us", "cut_us")}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def decode_png(data):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, "unsupported PNG layout %r" % (header,)
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, rows, bpp


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    tetcut, corpus, out = sys.argv[1:]
    os.makedirs(out, exist_ok=True)
    json_path, html_path = os.path.join(out, "stats.json"), os.path.join(out, "report.html")
    for p in (json_path, html_path):
        if os.path.exists(p):
            os.remove(p)

    # The reduced experiment (2 seeded sweeps a mesh, not the 10 of docs/paper.md's figures): the
    # same code paths, a fifth of the runs.
    run = subprocess.run([tetcut, "stats", "--corpus", corpus, "--sweeps", str(SWEEPS), "--json", json_path,
                          "--html", html_path],
                         capture_output=True, text=True, timeout=500)
    if not check(run.returncode == 0, "tetcut stats exit %d: %s" % (run.returncode, run.stderr.strip())):
        return report()
    check("Table 1" in run.stdout and "Table 2" in run.stdout, "the text output has Tables 1 and 2")

    # The JSON: one row per mesh in table1 and table2, the paper's figures beside ours.
    stats = json.load(open(json_path))
    for key in ("table1", "table2", "table2_wide", "strategies", "quality"):
        check(key in stats, "JSON key %s" % key)
    check([r["mesh"] for r in stats.get("table1", [])] == MESHES, "table1 rows are the five meshes in order")
    check([r["mesh"] for r in stats.get("table2", [])] == MESHES, "table2 rows are the five meshes in order")
    for row in stats.get("table1", []):
        check(row["operations"] > 0, "%s: removal operations" % row["mesh"])
        total = row["removable_pct"] + row["vertex_pct"] + row["edge_pct"]
        check(abs(total - 100) < 1e-9, "%s: removable + vertex + edge = 100 %% (got %r)" % (row["mesh"], total))
        check(abs(row["diff"]["removable_pct"] - (row["removable_pct"] - row["paper"]["removable_pct"])) < 1e-9,
              "%s: diff is ours minus the paper's" % row["mesh"])
    for row in stats.get("table2", []):
        check(row["combined_unresolved_pct"] == 0, "%s: combined leaves nothing unresolved" % row["mesh"])
        check(row["global_cardinality_per_selected"] >= 1, "%s: global cardinality >= 1" % row["mesh"])
        check(row["global_cardinality_per_operation"] >= row["global_cardinality_per_selected"],
              "%s: per operation >= per selected" % row["mesh"])
        check("resolved_by_flood" not in row["counts"], "%s: no flood any more" % row["mesh"])
    # Our wider search has rows of its own beside the paper's, and leaves nothing either.
    check([r["mesh"] for r in stats.get("table2_wide", [])] == MESHES, "table2_wide rows are the five meshes in order")
    for row in stats.get("table2_wide", []):
        check(row["ok"] and row["wide_unresolved_pct"] == 0, "%s: wide ran to the end, 0 unresolved" % row["mesh"])
        check(row["global_cardinality_per_selected"] >= 1, "%s: wide global cardinality >= 1" % row["mesh"])
        check(row["counts"]["requested"] > 0, "%s: wide made removal requests" % row["mesh"])
    names = [r["name"] for r in stats.get("strategies", [])]
    for name in ("basic", "neighbours", "combined", "combined, bisection"):
        check(name in names, "strategy row %s" % name)
    combined = [r for r in stats.get("strategies", []) if r["name"] == "combined"]
    check(combined and combined[0]["ok"] and combined[0]["unresolved"] == 0, "combined: ran to the end, 0 unresolved")

    # Every strategy row has the created tets' worst dihedral angle and their histogram,
    # with and without the improvement pass; per paper scenario, combined, neighbours and wide
    # create nothing below min(0.1, the input's worst), and the pass lifts what the runs without
    # it create.
    for row in stats.get("strategies", []):
        check("worst_created_min_dihedral_deg" in row, "%s: worst_created_min_dihedral_deg" % row["name"])
        check(sum(row["created"]["radius_ratio_histogram"]) == row["created"]["tets"],
              "%s: the created tets' histogram counts them all" % row["name"])
    quality = stats.get("quality", [])
    check(len(quality) == 5 * 4, "quality rows: 5 scenarios x 4 strategies (got %d)" % len(quality))
    for row in quality:
        if row["strategy"] != "basic":
            check(row["goal_met"] and row["ok"], "%s, %s: ran to the end and met the goal %.3g"
                  % (row["mesh"], row["strategy"], row["goal"]))
        if row["created"]["tets"] and row["created_without_improvement"]["tets"]:
            # The pass weighs the radius ratio and the smallest dihedral angle together: it may give
            # up some of one above its floor for the other, never both.
            with_pass, without = row["created"], row["created_without_improvement"]
            check(with_pass["min_radius_ratio"] >= without["min_radius_ratio"]
                  or with_pass["min_dihedral_deg"] >= without["min_dihedral_deg"],
                  "%s, %s: the pass does not make the worst created tet worse in both terms (%.3g against %.3g, "
                  "%.3g against %.3g degrees)" % (row["mesh"], row["strategy"], with_pass["min_radius_ratio"],
                                                 without["min_radius_ratio"], with_pass["min_dihedral_deg"],
                                                 without["min_dihedral_deg"]))

    # Every rate cell's interval is scipy's Wilson score interval of its counts;
    # every mean size's bootstrap interval lies between the smallest and largest ratio of one sweep
    # (a pooled ratio of resampled sweeps cannot leave that range), and its counts are the sweeps'.
    from scipy.stats import binomtest
    for table in ("table1", "table2", "table1_paper_order", "table2_paper_order", "table2_wide", "table1_revisit",
                  "table2_revisit", "table1_first_set", "table2_first_set"):
        for row in stats.get(table, []):
            where = "%s %s" % (table, row["mesh"])
            check(row.get("sweeps") == SWEEPS and row["offsets"][0] == [0, 0, 0] and len(row["offsets"]) == SWEEPS,
                  "%s: %d sweeps, the first as written" % (where, SWEEPS))
            for key, (lo, hi) in row.get("ci95", {}).items():
                k, n = row["count"][key]
                if key.endswith("_pct"):
                    if n == 0:
                        check(lo is None and hi is None, "%s %s: no interval without trials" % (where, key))
                        continue
                    ci = binomtest(k, n).proportion_ci(method="wilson")
                    check(abs(lo - 100 * ci.low) < 1e-9 and abs(hi - 100 * ci.high) < 1e-9,
                          "%s %s: Wilson [%r, %r] for %d/%d, scipy [%r, %r]"
                          % (where, key, lo, hi, k, n, 100 * ci.low, 100 * ci.high))
                elif key in MEAN_SIZES and n > 0:
                    num_keys, den_keys = MEAN_SIZES[key]
                    per_sweep = [(sum(c[x] for x in num_keys), sum(c[x] for x in den_keys)) for c in row["sweep_counts"]]
                    check((sum(a for a, _ in per_sweep), sum(b for _, b in per_sweep)) == (k, n),
                          "%s %s: the counts are the sweeps' sums" % (where, key))
                    ratios = [a / b for a, b in per_sweep if b > 0]
                    check(min(ratios) - 1e-12 <= lo <= hi <= max(ratios) + 1e-12,
                          "%s %s: bootstrap [%r, %r] within the sweeps' ratios %r" % (where, key, lo, hi, ratios))
    # Every rate's Fisher p is scipy's on our counts against the paper's rebuilt ones (the largest
    # over the counts the paper's figures admit); none without trials.
    from scipy.stats import fisher_exact
    for table in ("table1", "table2", "table1_paper_order", "table2_paper_order", "table1_revisit", "table2_revisit",
                  "table1_first_set", "table2_first_set"):
        for row in stats.get(table, []):
            check(len(row.get("fisher_p", {})) == 3, "%s %s: three rates tested" % (table, row["mesh"]))
            for key, p in row.get("fisher_p", {}).items():
                k, n = row["count"][key]
                (klo, khi), (nlo, nhi) = row["paper_count"][key]
                if n == 0:
                    check(p is None, "%s %s %s: no p without trials" % (table, row["mesh"], key))
                    continue
                expected = max(fisher_exact([[k, n - k], [pk, pn - pk]])[1]
                               for pk in range(klo, khi + 1) for pn in range(nlo, nhi + 1))
                check(p is not None and abs(p - expected) <= 1e-9 * expected + 1e-300,
                      "%s %s %s: Fisher p %r, scipy %r" % (table, row["mesh"], key, p, expected))
    # One logged configuration per edge singularity 3.5 searched.
    for table in ("table2", "table2_paper_order"):
        for row in stats.get(table, []):
            logged = sum(c["count"] for c in row.get("edge_search", []))
            check(logged == row["counts"]["edge_singularities"],
                  "%s %s: %d edge configurations logged for %d edge singularities"
                  % (table, row["mesh"], logged, row["counts"]["edge_singularities"]))

    # Deterministic: a second run (checking only at the end) gives the same figures, times aside.
    again_path = os.path.join(out, "stats-again.json")
    again = subprocess.run([tetcut, "stats", "--corpus", corpus, "--sweeps", str(SWEEPS), "--check", "end", "--json",
                            again_path],
                           capture_output=True, text=True, timeout=500)
    if check(again.returncode == 0, "second tetcut stats exit %d" % again.returncode):
        check(without_times(json.load(open(again_path))) == without_times(stats),
              "a second run gives the same figures (times aside)")

    # Self-contained: no script, no external resource.
    html = open(html_path, encoding="utf-8").read()
    check("<script" not in html and "<link" not in html, "no script or link elements")
    check(not re.search(r'(src|href)\s*=', html), "no src= or href= attributes")
    check(not re.search(r'https?://(?!www\.w3\.org/2000/svg)', html), "no URL but the SVG namespace")

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not check(chromium is not None, "chromium is installed (ci/deps installs it)"):
        return report()
    url = "file://" + os.path.abspath(html_path)
    profile = os.path.join(os.path.abspath(out), "chromium-profile")
    flags = CHROMIUM_FLAGS + ["--user-data-dir=" + profile]
    dom = subprocess.run([chromium] + flags + ["--dump-dom", url], capture_output=True, text=True, timeout=120)
    check(dom.returncode == 0, "chromium --dump-dom exit %d" % dom.returncode)
    for pid in PICTURE_IDS:
        check(('id="%s"' % pid) in dom.stdout, "the loaded page has the picture %s" % pid)
    for tid in ("table1", "table2", "table1-paper-order", "table2-paper-order", "edge-search", "table2-wide", "strategies",
                "created-histogram", "quality", "table1-revisit", "table2-revisit", "table1-first-set",
                "table2-first-set"):
        check(('id="%s"' % tid) in dom.stdout, "the loaded page has the table %s" % tid)
    check(dom.stdout.count("<polygon") > 2000, "the surface pictures have their triangles")

    png = os.path.join(out, "report.png")
    if os.path.exists(png):
        os.remove(png)
    # Tall enough for the page down to the resection's pictures, below Tables 1 and 2 in both orders.
    shot = subprocess.run([chromium] + flags + ["--window-size=1200,5400", "--screenshot=" + png, url],
                          capture_output=True, text=True, timeout=120)
    if not check(shot.returncode == 0 and os.path.exists(png), "chromium --screenshot wrote " + png):
        return report()
    width, height, rows, bpp = decode_png(open(png, "rb").read())
    check((width, height) == (1200, 5400), "screenshot size %dx%d" % (width, height))
    tissue = cut = plot = 0
    for line in rows:
        for x in range(0, len(line), bpp):
            r, g, b = line[x], line[x + 1], line[x + 2]
            if r > g + 40 and r > b + 40 and g < 140:
                tissue += 1                   # the liver's shaded red-brown surface
            elif r > 150 and g > 120 and b < 110 and r - b > 90:
                cut += 1                      # the yellow cut surfaces
            elif b > r + 50 and b > 120:
                plot += 1                     # the latency line and the "before" bars
    check(tissue > 20000, "the liver's surface is drawn (%d tissue-coloured pixels)" % tissue)
    check(cut > 2000, "the cut surfaces are drawn (%d cut-coloured pixels)" % cut)
    check(plot > 500, "the plot is drawn (%d plot-coloured pixels)" % plot)
    return report()


def report():
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("ok: tetcut stats JSON and HTML report; Chromium loaded the page and drew its pictures")
    return 0


if __name__ == "__main__":
    sys.exit(main())

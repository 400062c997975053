#!/usr/bin/env python3
"""The figures the gate reads from callgrind's output of bench/cut_instructions
(bench/instructions_gate.sh runs callgrind and calls this):

  callgrind_profile.py instructions OUT.json TOOLCHAIN CUTS PART...
      PART: the profile's parts in order (callgrind --dump-after='*one_measured_cut*' writes one
      per cut, and the rest after the last). Writes the instruction figures: the mean per cut over
      the sweep, the p50 and p90 cuts, and the mean per cut of each stage of Cutter::Pipeline
      (STAGES below: the inclusive cost of the stage's member functions, what the stage's
      CutTimings field times), with each stage's p50 and p90 cut beside it.

  callgrind_profile.py cache OUT.json TOOLCHAIN CUTS PART...
      PART: a profile taken with --cache-sim=yes. Writes the last-level misses per cut
      (instruction and data, read and write: ILmr + DLmr + DLmw) and the instructions per cut.

OUT.json is shaped as Google Benchmark's, one entry per figure, each with TOOLCHAIN, so that
bench/budget_gate.py gates it like any figure and refuses a count taken with another toolchain.
Exit 2 when a stage function is in no part: the compiler inlined it into Cutter::Pipeline::cut,
and the stage has no cost of its own to gate until it is marked [[gnu::noinline]] (or STAGES
names the function that now does its work).
"""
import json
import math
import os
import sys

# A stage of the cut, as CutTimings times it, and the Cutter::Pipeline member functions whose
# inclusive cost it is (engine/src/cut/cut_pipeline.hpp). "finish" is CutTimings::finish_us:
# the tissue audit, then the commit or the roll-back.
STAGES = [
    ("locate", ["tetcut::Cutter::Pipeline::locate("]),
    ("refine", ["tetcut::Cutter::Pipeline::refine("]),
    ("select", ["tetcut::Cutter::Pipeline::select("]),
    ("remove", ["tetcut::Cutter::Pipeline::remove_selected("]),
    ("improve", ["tetcut::Cutter::Pipeline::improve("]),
    ("finish", ["tetcut::Cutter::Pipeline::audit(", "tetcut::Cutter::Pipeline::commit(",
                "tetcut::Cutter::Pipeline::roll_back("]),
    # CutTimings::pieces_us: the search for the pieces the cut detached, and the debris.
    ("pieces", ["tetcut::Cutter::Pipeline::find_pieces("]),
]
# Must run in every sweep: a stage missing from the profile was inlined, not skipped.
REQUIRED = ["tetcut::Cutter::Pipeline::" + f + "(" for f in ("locate", "refine", "select", "remove_selected",
                                                           "improve", "audit", "find_pieces", "commit")]


class Part:
    """One part of a callgrind profile: its events, their totals, and the inclusive cost (every
    event) of the functions whose names start with one of the prefixes asked for. A function's
    inclusive cost is its own cost lines plus the cost line after each of its calls= lines (what
    the call cost, callees included); none of the stage functions calls itself or another."""

    def __init__(self, path, prefixes):
        self.events, self.totals, self.inclusive = [], None, {}
        names = {}  # callgrind's name compression: "(id) name" the first time, "(id)" after
        positions = 1  # leading position columns of a cost line ("line", or "instr line")
        current = None  # the prefix the current function's name starts with, if any
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                c = line[:1]
                if c.isdigit() or c in ("+", "-", "*"):
                    if current is not None:
                        acc = self.inclusive.setdefault(current, [0] * len(self.events))
                        for i, cost in enumerate(line.split()[positions:]):
                            acc[i] += int(cost)
                    continue
                key, sep, value = line.rstrip("\n").partition("=")
                if sep and key in ("fn", "cfn"):
                    name = value
                    if value.startswith("("):
                        ident, _, rest = value.partition(")")
                        if rest.strip():
                            names[ident] = rest.strip()
                        name = names.get(ident, "")
                    if key == "fn":
                        current = next((p for p in prefixes if name.startswith(p)), None)
                    continue
                key, sep, value = line.partition(":")
                if not sep:
                    continue
                if key == "events":
                    self.events = value.split()
                elif key == "positions":
                    positions = len(value.split())
                elif key == "totals" or (key == "summary" and self.totals is None):
                    self.totals = [int(t) for t in value.split()]

    def _event(self, values, event):
        i = self.events.index(event) if event in self.events else len(values)
        return values[i] if i < len(values) else 0

    def total(self, event="Ir"):
        return self._event(self.totals or [], event)

    def cost(self, prefixes, event="Ir"):
        return sum(self._event(self.inclusive.get(p, []), event) for p in prefixes)


def nearest_rank(values, q):
    """tetcut::percentile's nearest rank: the smallest value with at least a fraction q at or below."""
    ordered = sorted(values)
    return ordered[min(max(math.ceil(q * len(ordered)), 1), len(ordered)) - 1]


def entry(name, toolchain, **fields):
    return {"name": name, "run_name": name, "run_type": "iteration", "toolchain": toolchain, **fields}


def instructions(parts, cuts, toolchain):
    prefixes = [p for _, ps in STAGES for p in ps]
    read = [Part(p, prefixes) for p in parts]
    missing = [p for p in REQUIRED if not any(p in part.inclusive for part in read)]
    if missing:
        sys.exit("callgrind_profile: no cost of " + ", ".join(missing) + " in the profile: the compiler inlined it into "
                 "Cutter::Pipeline::cut, so the stage has no count of its own; mark it [[gnu::noinline]] in "
                 "engine/src/cut/cut_pipeline.hpp (or name the function that now does the stage's work in STAGES, "
                 "bench/callgrind_profile.py)")
    total = sum(p.total() for p in read)
    # One part per cut, then the tail after the last cut (the sweep's loop returning: a few
    # instructions), which is counted in the mean like every instruction of measured_cuts().
    per_cut = [p.total() for p in read[:cuts]] if len(read) > cuts else []
    whole = {"instructions_per_cut": total // cuts, "cuts": cuts, "instructions": total}
    if len(per_cut) == cuts:
        whole.update(p50_cut=nearest_rank(per_cut, 0.5), p90_cut=nearest_rank(per_cut, 0.9),
                     p99_cut=nearest_rank(per_cut, 0.99), max_cut=max(per_cut))
    out = [entry("instructions_per_cut", toolchain, **whole)]
    staged = 0
    for stage, ps in STAGES:
        stage_total = sum(p.cost(ps) for p in read)
        staged += stage_total
        fields = {"per_cut": stage_total // cuts, "instructions": stage_total}
        if len(per_cut) == cuts:
            each = [p.cost(ps) for p in read[:cuts]]
            fields.update(p50_cut=nearest_rank(each, 0.5), p90_cut=nearest_rank(each, 0.9))
        out.append(entry(f"instructions_per_cut/{stage}", toolchain, **fields))
    # The cut's own work around its stages: the clock, opening the transaction, the report.
    out.append(entry("instructions_per_cut/other", toolchain, per_cut=(total - staged) // cuts,
                     instructions=total - staged))
    return out


def cache(parts, cuts, toolchain):
    read = [Part(p, []) for p in parts]
    if not all("DLmw" in p.events for p in read):
        sys.exit("callgrind_profile: the profile has no cache events (callgrind --cache-sim=yes)")
    misses = sum(p.total(e) for p in read for e in ("ILmr", "DLmr", "DLmw"))
    d1 = sum(p.total(e) for p in read for e in ("D1mr", "D1mw"))
    total = sum(p.total() for p in read)
    return [entry("ll_misses_per_cut", toolchain, ll_misses_per_cut=misses // cuts, ll_misses=misses,
                  d1_misses_per_cut=d1 // cuts, instructions_per_cut=total // cuts, cuts=cuts)]


def main(argv):
    if len(argv) < 6 or argv[1] not in ("instructions", "cache"):
        print(__doc__, file=sys.stderr)
        return 2
    mode, out, toolchain, cuts, parts = argv[1], argv[2], argv[3], int(argv[4]), argv[5:]
    benchmarks = instructions(parts, cuts, toolchain) if mode == "instructions" else cache(parts, cuts, toolchain)
    with open(out + ".tmp", "w", encoding="utf-8") as f:
        json.dump({"context": {"source": "callgrind"}, "benchmarks": benchmarks}, f, indent=1)
    os.replace(out + ".tmp", out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

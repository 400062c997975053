#!/usr/bin/env bash
# Counts what a cut costs under callgrind on the fixed sweep of cut_instructions and writes it as a
# Google-Benchmark-shaped JSON file, so that budget_gate.py gates it like any figure.
#
#   bench/instructions_gate.sh BINARY OUT.json
#       instructions per cut on the gated liver sweep: the mean, the p50 and p90 cuts, and each
#       stage of the cut (bench/callgrind_profile.py), from one profile part per cut
#   bench/instructions_gate.sh --cache BINARY OUT.json
#       last-level cache misses per cut on the same sweep through 64 copies of the liver whose ids
#       are shuffled (~1M tets; cut_instructions --shuffled-copies), in callgrind's simulated caches
#       of the fixed sizes below, not the host's: deterministic like the count
#
# Without bench/callgrind_profile.py beside it (ci/bisect copies this script alone and runs it on
# older commits) it writes the whole cut's mean only, which is all a bisection reads.
set -euo pipefail
cache=0
if [ "${1:-}" = --cache ]; then cache=1; shift; fi
binary="$1"
out="$2"
here=$(cd "$(dirname "$0")" && pwd)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The simulated caches: 32 KiB 8-way L1s and an 8 MiB 16-way last level, 64-byte lines. Part of the
# figure's toolchain: other sizes are another figure.
cache_sizes="--I1=32768,8,64 --D1=32768,8,64 --LL=8388608,16,64"
if [ "$cache" -eq 1 ]; then
  # Instrumentation starts at the first cut (cut_instructions.cpp): building a million tets runs
  # at valgrind's uninstrumented speed.
  options=(--instr-atstart=no --cache-sim=yes $cache_sizes)
  args=(--shuffled-copies)
else
  # One part per cut, for the p50 and p90 cuts (a binary without one_measured_cut writes one part).
  options=(--dump-after='*one_measured_cut*')
  args=()
fi
valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" --toggle-collect='*measured_cuts*' \
  "${options[@]}" "$binary" "${args[@]}" >"$work/stdout" 2>"$work/stderr" || {
  cat "$work/stderr" >&2
  exit 2
}
cuts=$(awk '/^measured_cuts/ {print $2}' "$work/stdout")
# What the count depends on besides the source: the compiler and flags the binary was built with,
# the shared libraries whose code runs inside the cuts (libtet's predicates, libc, libstdc++), and
# valgrind itself. The gate refuses to compare counts taken with another toolchain.
libs=$(dpkg-query -W -f='${Package} ${Version}; ' libtet1.5 libc6 libstdc++6 2>/dev/null || true)
toolchain="$(sed -n 's/^toolchain //p' "$work/stdout"); ${libs}$(valgrind --version)"
[ "$cache" -eq 0 ] || toolchain="$toolchain; simulated caches ${cache_sizes//--/}"
# The parts in order: callgrind.out.1, .2, ... (one per cut), then callgrind.out (the rest).
parts=()
while IFS= read -r part; do parts+=("$part"); done < <(ls "$work"/callgrind.out.* 2>/dev/null | sort -t. -k3 -n)
parts+=("$work/callgrind.out")
# Each part's instruction total: its totals: line (summary: in older callgrinds), first event.
total=$(for p in "${parts[@]}"; do awk '/^totals:/ {t = $2} /^summary:/ && t == "" {t = $2} END {print t + 0}' "$p"; done |
  awk '{s += $1} END {printf "%d", s}')
if [ -z "$cuts" ] || [ -z "$total" ] || [ "$cuts" -eq 0 ]; then
  echo "instructions_gate: could not read the counts" >&2
  exit 2
fi
per_cut=$((total / cuts))
echo "callgrind: $total instructions in $cuts cuts = $per_cut per cut"
echo "toolchain: $toolchain"
if [ -f "$here/callgrind_profile.py" ]; then
  mode=instructions
  [ "$cache" -eq 0 ] || mode=cache
  python3 "$here/callgrind_profile.py" "$mode" "$out" "$toolchain" "$cuts" "${parts[@]}"
  python3 - "$out" <<'PY'
import json, sys
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    shown = ", ".join(f"{k} {v:,}" for k, v in b.items() if isinstance(v, int) and k not in ("cuts",))
    print(f"  {b['name']}: {shown}")
PY
else
  toolchain_json=$(python3 -c 'import json, sys; print(json.dumps(sys.argv[1]))' "$toolchain")
  cat >"$out.tmp" <<JSON
{"context": {"executable": "$binary"},
 "benchmarks": [{"name": "instructions_per_cut", "run_name": "instructions_per_cut", "run_type": "iteration",
                 "instructions_per_cut": $per_cut, "cuts": $cuts, "instructions": $total,
                 "toolchain": $toolchain_json}]}
JSON
  mv "$out.tmp" "$out"
fi

#!/usr/bin/env bash
# Counts instructions per cut with callgrind on the fixed sweep of cut_instructions and writes
# them as a Google-Benchmark-shaped JSON file, so that budget_gate.py gates them like any figure.
#   bench/instructions_gate.sh BINARY OUT.json
set -euo pipefail
binary="$1"
out="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" \
  --toggle-collect='*measured_cuts*' "$binary" >"$work/stdout" 2>"$work/stderr" || {
  cat "$work/stderr" >&2
  exit 2
}
cuts=$(awk '/^measured_cuts/ {print $2}' "$work/stdout")
# What the count depends on besides the source: the compiler and flags the binary was built with,
# the shared libraries whose code runs inside the cuts (libtet's predicates, libc, libstdc++), and
# valgrind itself. The gate refuses to compare counts taken with another toolchain.
libs=$(dpkg-query -W -f='${Package} ${Version}; ' libtet1.5 libc6 libstdc++6 2>/dev/null || true)
toolchain="$(sed -n 's/^toolchain //p' "$work/stdout"); ${libs}$(valgrind --version)"
toolchain_json=$(python3 -c 'import json, sys; print(json.dumps(sys.argv[1]))' "$toolchain")
total=$(awk '/^summary:/ {print $2} /^totals:/ {print $2}' "$work/callgrind.out" | tail -n 1)
if [ -z "$cuts" ] || [ -z "$total" ] || [ "$cuts" -eq 0 ]; then
  echo "instructions_gate: could not read the counts" >&2
  exit 2
fi
per_cut=$((total / cuts))
echo "callgrind: $total instructions in $cuts cuts = $per_cut per cut"
echo "toolchain: $toolchain"
cat >"$out.tmp" <<JSON
{"context": {"executable": "$binary"},
 "benchmarks": [{"name": "instructions_per_cut", "run_name": "instructions_per_cut", "run_type": "iteration",
                 "instructions_per_cut": $per_cut, "cuts": $cuts, "instructions": $total,
                 "toolchain": $toolchain_json}]}
JSON
mv "$out.tmp" "$out"

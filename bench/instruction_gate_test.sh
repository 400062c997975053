#!/usr/bin/env bash
# ctest instruction_gate_catches_slowdown (issue 18: a gate with teeth). Counts the instructions
# of the fixed liver sweep with callgrind for the clean build and for cut_instructions_planted
# (about 10 % more work in every cut, engine/src/cut/planted_slowdown.cpp), gates both against the
# checked-in bench/budgets.json, and expects:
#   clean build              within budget (exit 0)
#   planted slowdown         over budget (exit 1): +10 % against a +3 % tolerance
#   another toolchain        refused (exit 2), the message asking for a recalibration
#
#   instruction_gate_test.sh SOURCE_DIR CLEAN_BINARY PLANTED_BINARY WORK_DIR
set -uo pipefail
src=$1 clean=$2 planted=$3 work=$4
mkdir -p "$work"
status=0
fail() { echo "FAIL: $*"; status=1; }
# Only the instruction figure: the others are not measured here.
others=$(python3 -c 'import json, sys; print(",".join(f["benchmark"] for f in json.load(open(sys.argv[1]))["figures"] if f.get("kind") != "instructions"))' "$src/bench/budgets.json")
gate() { python3 "$src/bench/budget_gate.py" "$1" "$2" --skip-missing "$others"; }

"$src/bench/instructions_gate.sh" "$clean" "$work/clean.json" || { echo "FAIL: cannot count the clean build"; exit 1; }
"$src/bench/instructions_gate.sh" "$planted" "$work/planted.json" || { echo "FAIL: cannot count the planted build"; exit 1; }

out=$(gate "$work/clean.json" "$src/bench/budgets.json" 2>&1); rc=$?
echo "$out"
((rc == 0)) || fail "the clean build is not within budget (exit $rc): recalibrate if the toolchain changed, else a change made cuts slower"

out=$(gate "$work/planted.json" "$src/bench/budgets.json" 2>&1); rc=$?
echo "$out"
((rc == 1)) || fail "the planted slowdown passed the gate (exit $rc)"
grep -q "OVER BUDGET" <<<"$out" || fail "the planted slowdown is not reported over budget"

# The same count, calibrated with another toolchain: the gate must refuse to compare.
python3 - "$src/bench/budgets.json" "$work/other-toolchain.json" <<'PY'
import json, sys
budgets = json.load(open(sys.argv[1]))
for f in budgets["figures"]:
    if f.get("kind") == "instructions":
        f["toolchain"] = "Clang 99.0.0; Release: -O3 (another toolchain)"
json.dump(budgets, open(sys.argv[2], "w"))
PY
out=$(gate "$work/clean.json" "$work/other-toolchain.json" 2>&1); rc=$?
echo "$out"
((rc == 2)) || fail "a count from another toolchain was compared (exit $rc, expected 2)"
grep -q "recalibrate" <<<"$out" || fail "the refusal does not ask for a recalibration"

((status == 0)) && echo "the instruction gate passes the clean build, fails the planted slowdown and refuses another toolchain"
exit $status

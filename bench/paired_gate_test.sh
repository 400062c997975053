#!/usr/bin/env bash
# ctest paired_gate_catches_slowdown: the paired wall-time comparison (bench/paired_gate.py) has
# teeth and no false alarm. On the liver alone (--small-only), 10 pairs each:
#   a build that waits 1.5 us in every locate, against the clean build: the locate p50 row is over
#     its limit (the lower end of its interval above 1.05)
#   the clean build against itself: no row over its limit
# judged by bench/budget_gate.py on the checked-in limits of the liver's paired figures.
#
#   paired_gate_test.sh SOURCE_DIR PAIRED_MESHES CLEAN PLANTED WORK_DIR
set -uo pipefail
src=$1 meshes_tool=$2 clean=$3 planted=$4 work=$5
mkdir -p "$work/meshes"
status=0
fail() { echo "FAIL: $*"; status=1; }
"$meshes_tool" "$work/meshes" --small-only || { echo "FAIL: cannot write the meshes"; exit 1; }
# The liver's paired figures only: the 1M mesh is not cut here.
python3 - "$src/bench/budgets.json" "$work/budgets.json" <<'PY'
import json, sys
budgets = json.load(open(sys.argv[1]))
budgets["figures"] = [f for f in budgets["figures"] if f.get("kind") == "paired" and f["benchmark"].startswith("paired/16k")]
json.dump(budgets, open(sys.argv[2], "w"))
PY
compare() {  # HEAD REFERENCE NAME: the comparison, then the gate's verdict on it
  python3 "$src/bench/paired_gate.py" --head "$1" --reference "$2" --meshes "$work/meshes" --small-only \
    --pairs 10 --out "$work/$3.json" || { echo "FAIL: the $3 comparison did not run"; exit 1; }
  python3 "$src/bench/budget_gate.py" "$work/$3.json" "$work/budgets.json"
}

out=$(compare "$planted" "$clean" planted 2>&1); rc=$?
echo "$out"
((rc == 1)) || fail "the slowdown in locate passed the paired gate (exit $rc)"
grep -q "^paired locate p50, 16k liver.*OVER BUDGET" <<<"$out" || fail "the locate p50 row is not over its limit"

out=$(compare "$clean" "$clean" same 2>&1); rc=$?
echo "$out"
((rc == 0)) || fail "the clean build against itself failed the paired gate (exit $rc): a false alarm"

((status == 0)) && echo "the paired gate catches 1.5 us more in locate and passes the clean build against itself"
exit $status

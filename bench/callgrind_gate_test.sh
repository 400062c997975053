#!/usr/bin/env bash
# The callgrind gates have teeth: planted slowdowns (bench/planted/, built by bench/CMakeLists.txt)
# must fail the figure they aim at and pass the others.
#
#   callgrind_gate_test.sh instructions SOURCE_DIR CLEAN UNIFORM LOCATE WORK_DIR
#       ctest instruction_gate_catches_slowdown. Counts the liver sweep of the clean build and
#       of two planted ones, and expects:
#         clean build            within the checked-in bench/budgets.json (exit 0)
#         uniform, +10 % a cut   over budget on the whole cut's mean (exit 1)
#         locate, +10 % there    over budget on the locate row, and on nothing else: the whole
#                                cut (+2 %) passes, as it passed the gate before it had stages
#         another toolchain      refused (exit 2), the message asking for a recalibration
#   callgrind_gate_test.sh cache SOURCE_DIR CLEAN COLD_LINES WORK_DIR
#       ctest cache_gate_catches_layout_slowdown. A build that reads 64 cold cache lines in every
#       cut: every instruction row passes (a few hundred instructions more a cut, under 0.3 %) and
#       the last-level misses of the shuffled 1M sweep fail (about +14 %).
#
# The planted builds are judged against budgets calibrated here on the clean build, so that the
# test says whether the gate catches the slowdown whatever the checked-in baselines are (whether
# the clean build is within them is the first check, and ci/gate's).
set -uo pipefail
mode=$1 src=$2
status=0
fail() { echo "FAIL: $*"; status=1; }
# Gates RESULTS against BUDGETS on the callgrind figures alone; prints the table.
gate() {
  python3 "$src/bench/budget_gate.py" "$1" "$2" --skip-kinds time,count,paired${3:+,$3}
}
# Gates RESULTS against BUDGETS and expects ROW, and no other row, over budget (WHAT names the
# planted build in the messages).
expect_only_over() {
  local results=$1 budgets=$2 row=$3 what=$4 out rc rows
  out=$(gate "$results" "$budgets" 2>&1); rc=$?
  echo "$out"
  ((rc == 1)) || fail "$what passed the gate (exit $rc)"
  rows=$(grep "OVER BUDGET" <<<"$out" | sed -E 's/  +.*//' | sort)
  [[ $rows == "$row" ]] || fail "$what should fail '$row' alone; over budget: ${rows:-nothing}"
}
# The checked-in budgets' callgrind figures of the given kinds, calibrated on RESULTS.
calibrated() {
  local results=$1 out=$2 kinds=$3
  python3 - "$src/bench/budgets.json" "$out" "$kinds" <<'PY'
import json, sys
budgets = json.load(open(sys.argv[1]))
budgets["figures"] = [f for f in budgets["figures"] if f.get("kind") in sys.argv[3].split(",")]
json.dump(budgets, open(sys.argv[2], "w"))
PY
  /usr/bin/python3 "$src/bench/calibrate_budgets.py" instructions "$out" "$results" >/dev/null
}

case $mode in
  instructions)
    clean=$3 uniform=$4 locate=$5 work=$6
    mkdir -p "$work"
    for build in clean uniform locate; do
      "$src/bench/instructions_gate.sh" "${!build}" "$work/$build.json" >/dev/null ||
        { echo "FAIL: cannot count the $build build"; exit 1; }
    done

    out=$(gate "$work/clean.json" "$src/bench/budgets.json" cache 2>&1); rc=$?
    echo "$out"
    ((rc == 0)) || fail "the clean build is not within the checked-in budgets (exit $rc): recalibrate if the toolchain changed (ci/bench --recalibrate-instructions), else a change made cuts slower"

    calibrated "$work/clean.json" "$work/budgets.json" instructions
    out=$(gate "$work/uniform.json" "$work/budgets.json" 2>&1); rc=$?
    echo "$out"
    ((rc == 1)) || fail "the uniform slowdown passed the gate (exit $rc)"
    grep -q "^instructions per cut (callgrind) .*OVER BUDGET" <<<"$out" || fail "the uniform slowdown is not over budget on the whole cut"

    expect_only_over "$work/locate.json" "$work/budgets.json" "instructions in locate, per cut (callgrind)" \
      "the slowdown in locate"

    # The same count, calibrated with another toolchain: the gate must refuse to compare.
    python3 - "$work/budgets.json" "$work/other-toolchain.json" <<'PY'
import json, sys
budgets = json.load(open(sys.argv[1]))
for f in budgets["figures"]:
    f["toolchain"] = "Clang 99.0.0; Release: -O3 (another toolchain)"
json.dump(budgets, open(sys.argv[2], "w"))
PY
    out=$(gate "$work/clean.json" "$work/other-toolchain.json" 2>&1); rc=$?
    echo "$out"
    ((rc == 2)) || fail "a count from another toolchain was compared (exit $rc, expected 2)"
    grep -q "recalibrate" <<<"$out" || fail "the refusal does not ask for a recalibration"
    ((status == 0)) && echo "the instruction gate passes the clean build, fails the uniform slowdown on the whole cut and the slowdown in locate on locate alone, and refuses another toolchain"
    ;;
  cache)
    clean=$3 cold=$4 work=$5
    mkdir -p "$work"
    for build in clean cold; do
      "$src/bench/instructions_gate.sh" "${!build}" "$work/$build.instructions.json" >/dev/null &&
        "$src/bench/instructions_gate.sh" --cache "${!build}" "$work/$build.cache.json" >/dev/null ||
        { echo "FAIL: cannot count the $build build"; exit 1; }
      python3 "$src/bench/merge_results.py" "$work/$build.json" "$work/$build.instructions.json" "$work/$build.cache.json"
    done
    calibrated "$work/clean.json" "$work/budgets.json" instructions,cache
    expect_only_over "$work/cold.json" "$work/budgets.json" \
      "last-level cache misses per cut, shuffled 1M copies (callgrind)" "the cold reads"
    ((status == 0)) && echo "the cache gate fails a change that costs cache misses and passes its instructions"
    ;;
  *)
    echo "usage: callgrind_gate_test.sh instructions|cache ..." >&2
    exit 2 ;;
esac
exit $status

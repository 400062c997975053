#!/usr/bin/env bash
# ctest ci.bisect_planted_crash / ci.bisect_planted_slowdown (label slow): triage names the
# commit that planted a bug, in a throw-away history made in WORK_DIR:
#
#   c1  the current tree, as it is (tracked files and new ones not ignored)
#   c2  a note added          (nothing rebuilds)
#   c3  a README line         (nothing rebuilds)
#   c4  THE PLANTED BUG       (crash: fuzz/support/planted_bug.hpp on, one file rebuilds;
#                              slowdown: extra work in each cut of bench/cut_instructions.cpp,
#                              more instructions than the figure's budget)
#   c5  a note changed        (nothing rebuilds)
#   c6  a README line         (nothing rebuilds)
#
# crash:    `ci/bisect INPUT --good c1` on an input holding the planted marker names c4 and the
#           property (planted-bug); then `ci/fuzz-nightly` on msh22, with the marker among the
#           seeds, finds the crash, and its triage report names c4 ("first bad commit: ..."),
#           bisecting with no good commit given (it steps back from HEAD).
# slowdown: `ci/bisect --budget "instructions per cut"` (the figure's own budget as threshold,
#           no good commit given) names c4; so does `--budget "cut p50, 16k liver" --good c1`
#           (a wall-time figure: threshold halfway between the counts at c1 and c6).
# One bisection build folder serves every step (each step rebuilds one file at most), so the
# cost is one build of the engine per kind of build used.
#
#   bisect_planted_test.sh crash|slowdown SOURCE_DIR WORK_DIR
set -uo pipefail
kind=${1:?usage: bisect_planted_test.sh crash|slowdown SOURCE_DIR WORK_DIR}
src=$(cd "${2:?}" && pwd)
work=${3:?}
status=0
fail() { echo "FAIL: $*"; status=1; }
# Every build of the throw-away history compiles the same sources up to the planted file, run after
# run: with ccache (CMake takes the launcher from the environment) a machine that keeps its cache
# compiles them once, not in every ci/test. Paths are hashed relative to WORK_DIR.
if command -v ccache >/dev/null && [[ -z ${CMAKE_CXX_COMPILER_LAUNCHER:-} ]]; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$(realpath -m "$work")
fi

rm -rf "$work"
mkdir -p "$work/history"
repo=$work/history
# The tree's files: what git tracks plus new files it does not ignore; from a tarball (no
# .git), everything but the build folders.
if git -C "$src" rev-parse --git-dir >/dev/null 2>&1; then
  (cd "$src" && git ls-files -z --cached --others --exclude-standard |
    while IFS= read -r -d '' f; do [[ -e $f ]] && printf '%s\0' "$f"; done |
    tar --null -T - -cf -) | tar -C "$repo" -xf - || { echo "FAIL: cannot copy the tree"; exit 1; }
else
  tar -C "$src" --exclude=./build --exclude='./build-*' -cf - . | tar -C "$repo" -xf - ||
    { echo "FAIL: cannot copy the tree"; exit 1; }
fi

g() { git -C "$repo" "$@"; }
commit() { g add -A && g -c user.name=tetcut-test -c user.email=test@tetcut.invalid commit -qm "$1" && g rev-parse HEAD; }
g init -q -b main
# The marker input: a seed of msh22 (harmless until c4 switches the bug on).
printf 'TETCUT-PLANTED-BUG\n' >"$repo/corpus/fuzz/msh22/planted-marker"
c1=$(commit "c1: the tree as it is")
echo "a note" >"$repo/NOTES.txt"
c2=$(commit "c2: a note")
echo "A README line." >>"$repo/README.md"
c3=$(commit "c3: a README line")
case $kind in
  crash)
    file=fuzz/support/planted_bug.hpp
    sed -i 's/inline constexpr bool kPlantedReaderBug = false;/inline constexpr bool kPlantedReaderBug = true;/' "$repo/$file" ;;
  slowdown)
    # At least 4 instructions per turn of the loop (volatile: load, add, store, compare and
    # branch), so budget/2 turns put every cut over the figure's budget whatever the engine
    # costs: 20,000 turns were 120,000 instructions.
    budget=$(python3 -c 'import json, sys; print(int(next(f["max"] for f in json.load(open(sys.argv[1]))["figures"] if f["name"].startswith("instructions per cut"))))' "$repo/bench/budgets.json")
    file=bench/cut_instructions.cpp
    sed -i "s/  return cutter.cut(centre).tets_removed;/  volatile int k = 0; while (k < $((budget / 2))) k = k + 1; return cutter.cut(centre).tets_removed;/" "$repo/$file" ;;
  *) echo "usage: bisect_planted_test.sh crash|slowdown SOURCE_DIR WORK_DIR"; exit 2 ;;
esac
g diff --quiet -- "$file" && { echo "FAIL: planting the $kind in $file changed nothing (has the file changed?)"; exit 1; }
c4=$(commit "c4: plant the $kind")
echo "a note, changed" >"$repo/NOTES.txt"
c5=$(commit "c5: a note changed")
echo "Another README line." >>"$repo/README.md"
c6=$(commit "c6: another README line")
planted=$(g rev-parse --short "$c4")
echo "throw-away history in $repo; the $kind is planted in $planted"

# expect_first_bad OUTPUT WHAT: OUTPUT names c4 as the first bad commit.
expect_first_bad() {
  if grep -q "first bad commit: $planted c4: plant the $kind" <<<"$1"; then
    echo "ok: $2 names $planted"
  else
    fail "$2 does not name $planted as the first bad commit"
  fi
}

export TETCUT_BISECT_JOBS=${TETCUT_BISECT_JOBS:-2}
case $kind in
  crash)
    out=$("$repo/ci/bisect" "$repo/corpus/fuzz/msh22/planted-marker" --good "$c1" --work "$work/bisect" 2>&1)
    echo "$out"
    expect_first_bad "$out" "ci/bisect"
    grep -q '^property: planted-bug (tetcut-fuzz: planted-bug violated after operation 0 (read_msh22)' <<<"$out" ||
      fail "ci/bisect does not name the property broken"
    grep -q '^minimized input: ' <<<"$out" || fail "ci/bisect does not say what the minimized case is"

    # The nightly, on the planted target only, bisecting with no good commit given.
    TETCUT_FUZZ_TARGETS=msh22 TETCUT_FUZZ_SECONDS=10 TETCUT_FUZZ_JOBS=1 TETCUT_FUZZ_OUT="$work/nightly" \
      TETCUT_BISECT_WORK="$work/bisect" "$repo/ci/fuzz-nightly" 1 >"$work/nightly.log" 2>&1
    rc=$?
    report=$work/nightly/triage.md
    [[ -f $report ]] && cat "$report"
    ((rc == 1)) || { fail "ci/fuzz-nightly exited $rc, expected 1 (a new finding)"; tail -30 "$work/nightly.log"; }
    grep -q '^## msh22: planted-bug after operation 0 (read_msh22)' "$report" 2>/dev/null ||
      fail "the triage report has no planted-bug finding"
    expect_first_bad "$(cat "$report" 2>/dev/null)" "the triage report of ci/fuzz-nightly" ;;
  slowdown)
    out=$("$repo/ci/bisect" --budget "instructions per cut" --work "$work/bisect" 2>&1)
    echo "$out"
    expect_first_bad "$out" "ci/bisect --budget 'instructions per cut'"
    grep -qE "^property: instructions per cut [0-9]+ > $budget \(the commit before: [0-9]+\)" <<<"$out" ||
      fail "ci/bisect --budget does not give the counts against the budget"
    out=$("$repo/ci/bisect" --budget "cut p50, 16k liver" --good "$c1" --work "$work/bisect" 2>&1)
    echo "$out"
    expect_first_bad "$out" "ci/bisect --budget 'cut p50, 16k liver' --good c1"
    grep -q 'threshold halfway' <<<"$out" || fail "a wall-time figure is not bisected halfway between the counts"
    out=$("$repo/ci/bisect" --budget "cut" --work "$work/bisect" 2>&1)
    (($? == 2)) && grep -q "more than one figure" <<<"$out" || fail "an ambiguous figure is not refused: $out" ;;
esac
((status == 0)) && echo "triage names the planted commit ($kind)"
exit $status

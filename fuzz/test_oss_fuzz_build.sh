#!/usr/bin/env bash
# ctest fuzz.oss_fuzz_build: runs fuzz/oss_fuzz_build.sh as OSS-Fuzz would, with the variables
# pointing at local folders, and checks what it must produce. Lean on purpose: the format targets
# and mixed_ops, -O1, no sanitizer (the fuzz preset covers those); WORK persists in the build
# tree so a rerun only relinks. Exit 77 (ctest SKIP_RETURN_CODE) when the clang is absent:
# TETCUT_CLANG / TETCUT_CLANGXX, default clang-14 / clang++-14 (what ci/deps installs).
#   test_oss_fuzz_build.sh WORK_DIR
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cc=${TETCUT_CLANG:-clang-14}
cxx=${TETCUT_CLANGXX:-clang++-14}
if ! command -v "$cxx" >/dev/null || ! command -v "$cc" >/dev/null; then
  echo "SKIP: $cc or $cxx not installed"
  exit 77
fi
work=${1:?usage: test_oss_fuzz_build.sh WORK_DIR}
mkdir -p "$work"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

targets="msh22 msh41 msh10 vtu vtk medit tetgen off stl obj mixed_ops"
CC=$cc CXX=$cxx CFLAGS="-O1" CXXFLAGS="-O1" LIB_FUZZING_ENGINE=-fsanitize=fuzzer \
  OUT="$out" WORK="$work" TETCUT_FUZZ_TARGETS="$targets" "$here/oss_fuzz_build.sh"

status=0
expect() {
  if ! test "$@"; then
    echo "FAIL: expected test $*"
    status=1
  fi
}
for t in $targets; do
  expect -x "$out/$t"
  expect -s "$out/${t}_seed_corpus.zip"
  expect -s "$out/$t.options"
  grep -q '^\[libfuzzer\]' "$out/$t.options" || { echo "FAIL: $t.options has no [libfuzzer] section"; status=1; }
  case $t in
    mixed_ops) ;;
    *)
      expect -s "$out/$t.dict"
      grep -q "^dict = $t.dict" "$out/$t.options" || { echo "FAIL: $t.options does not name $t.dict"; status=1; }
      ;;
  esac
done
# The fuzzers must run from $OUT alone (libraries through the $ORIGIN rpath): unpack seed
# corpora and replay them (no coverage instrumentation here, so no fuzzing proper).
for t in msh22 mixed_ops; do
  corpus=$(mktemp -d -p "$out")
  (cd "$corpus" && unzip -q "$out/${t}_seed_corpus.zip")
  "$out/$t" -runs=0 "$corpus" || { echo "FAIL: $t did not replay its seed corpus from \$OUT"; status=1; }
done
# (ldd's output goes to a variable first: `ldd | grep -q` can fail under pipefail when grep
# exits at its first match and ldd dies of SIGPIPE.)
libraries=$(ldd "$out/mixed_ops")
grep -q "$out/lib/libtet" <<<"$libraries" || { echo "FAIL: mixed_ops does not load TetGen from \$OUT/lib"; status=1; }
((status == 0)) && echo "oss_fuzz_build outputs complete for: $targets"
exit $status

#!/usr/bin/env bash
# Builds the fuzz targets the way OSS-Fuzz and ClusterFuzzLite expect (their build.sh calls this).
#
# Honours the standard variables:
#   CC, CXX             compilers (clang)
#   CFLAGS, CXXFLAGS    sanitizer and coverage flags (-fsanitize=address,fuzzer-no-link ...)
#   LIB_FUZZING_ENGINE  what a fuzzer links with (-fsanitize=fuzzer, or a library)
#   OUT                 where the fuzzers and their files go
#   WORK                scratch space for the CMake build (default: a temporary folder)
#   SRC                 unused: the sources are the checkout this script lives in
# and TETCUT_FUZZ_TARGETS (space separated) to build fewer targets than all.
#
# Produces in $OUT, for every target T: the fuzzer T, T_seed_corpus.zip (corpus/fuzz/T and
# corpus/regressions/T), T.dict (when fuzz/dictionaries/T.dict exists) and T.options; shared
# libraries the runner image lacks (TetGen, GMP, MPFR) go to $OUT/lib, found through an
# $ORIGIN rpath.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
src=$(cd "$here/.." && pwd)
: "${CXX:?set CXX}" "${OUT:?set OUT}" "${LIB_FUZZING_ENGINE:?set LIB_FUZZING_ENGINE}"
CXXFLAGS=${CXXFLAGS:-}
work=${WORK:-$(mktemp -d)}
build=$work/tetcut-fuzz-build
default_targets="msh22 msh41 msh10 vtu vtk medit tetgen off stl obj mixed_ops checker_differential removal_sequence cut_sequence consumer_differential"
read -r -a targets <<<"${TETCUT_FUZZ_TARGETS:-$default_targets}"

# Limits per kind of input: a file, or an operation sequence (fuzz/operations/).
max_len_of() {
  case $1 in
    mixed_ops | checker_differential | removal_sequence | cut_sequence) echo 1024 ;;
    *) echo 8192 ;;
  esac
}

generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
# No CMAKE_BUILD_TYPE: the flags are exactly $CXXFLAGS, as OSS-Fuzz wants.
cmake -S "$src" -B "$build" "${generator[@]}" \
  -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DCMAKE_BUILD_TYPE= \
  -DCMAKE_BUILD_RPATH='$ORIGIN/lib' \
  -DCMAKE_EXE_LINKER_FLAGS="${LDFLAGS:-}" \
  -DTETCUT_FUZZ=ON \
  -DTETCUT_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
  -DTETCUT_BUILD_TESTS=OFF -DTETCUT_BUILD_BENCH=OFF -DTETCUT_BUILD_TOOLS=OFF
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/tetcut_fuzz_}"

mkdir -p "$OUT/lib"
# The sequence targets start from bundled meshes (input version 1) or small fuzz meshes (2),
# looked up next to the fuzzer when the source tree is not there (fuzz/operations/sequence_meshes.cpp).
mkdir -p "$OUT/tetcut_meshes"
cp "$src"/corpus/meshes/{cylinder,sheet,liver-coarse}.msh "$OUT/tetcut_meshes/"
cp "$src"/corpus/fuzz/meshes/{cylinder,sheet,liver}-small.msh "$OUT/tetcut_meshes/"
# A sequence target's seeds of an older input version (first byte 1) stay out of its seed
# corpus: they replay in ctest, but fuzzing them is an order of magnitude slower (their meshes
# are ten times larger; fuzz/operations/sequence_target.hpp).
legacy_seed() {
  case $1 in
    removal_sequence | cut_sequence) [[ $(head -c1 "$2" | od -An -tu1 | tr -d ' ') == 1 ]] ;;
    *) return 1 ;;
  esac
}
for t in "${targets[@]}"; do
  cp "$build/fuzz/$t" "$OUT/$t"
  # Libraries from outside the base image travel with the fuzzers.
  ldd "$OUT/$t" | awk '/=> \// {print $3}' | grep -E '/lib(tet|gmp|mpfr)[^/]*$' | while read -r lib; do
    [[ $lib == "$OUT/lib/"* ]] || cp -L "$lib" "$OUT/lib/"
  done

  rm -f "$OUT/${t}_seed_corpus.zip"
  seeds=()
  for dir in "$src/corpus/fuzz/$t" "$src/corpus/regressions/$t"; do
    [[ -d $dir ]] && while IFS= read -r -d '' f; do
      legacy_seed "$t" "$f" || seeds+=("$f")
    done < <(find "$dir" -type f -size +0 -print0 | sort -z)
  done
  if ((${#seeds[@]} > 0)); then
    # -j: flat, as the runner unpacks it into one corpus folder; names are unique per folder
    # but not across the two, so the regressions keep a prefix.
    tmp=$(mktemp -d)
    for f in "${seeds[@]}"; do
      case $f in
        "$src/corpus/regressions/"*) cp "$f" "$tmp/regression-$(basename "$f")" ;;
        *) cp "$f" "$tmp/$(basename "$f")" ;;
      esac
    done
    (cd "$tmp" && zip -q -X "$OUT/${t}_seed_corpus.zip" ./*)
    rm -rf "$tmp"
  fi

  dict_line=
  if [[ -f $here/dictionaries/$t.dict ]]; then
    cp "$here/dictionaries/$t.dict" "$OUT/$t.dict"
    dict_line="dict = $t.dict"
  fi
  {
    echo "[libfuzzer]"
    [[ -n $dict_line ]] && echo "$dict_line"
    echo "max_len = $(max_len_of "$t")"
    echo "timeout = 25"
  } >"$OUT/$t.options"
done
echo "oss_fuzz_build: ${#targets[@]} fuzzers in $OUT"

#!/usr/bin/env bash
# ctest ci.packages: the machines (ci/deps) and the ClusterFuzzLite build image
# (.clusterfuzzlite/Dockerfile) install their Debian packages from the one list,
# ci/packages.txt, through ci/packages; the image's packages are among the machines'; the
# image has what fuzz/oss_fuzz_build.sh calls; and the image's Ubuntu is the one project.yaml
# names for running the fuzzers.
#   packages_test.sh SOURCE_DIR
set -uo pipefail
src=${1:?usage: packages_test.sh SOURCE_DIR}
cd "$src" || exit 1
status=0
fail() { echo "FAIL: $*"; status=1; }

grep -q '"$here/packages" --for deps' ci/deps || fail "ci/deps does not read its packages from ci/packages --for deps"
grep -qE '^\s*(apt-get|\$sudo apt-get) install .*(cmake|libcgal)' ci/deps && fail "ci/deps names packages of its own"
grep -q 'COPY ci/packages ci/packages.txt' .clusterfuzzlite/Dockerfile || fail "the Dockerfile does not copy ci/packages"
grep -q 'apt-get install .*\$(/tmp/tetcut-packages/packages --for image)' .clusterfuzzlite/Dockerfile ||
  fail "the Dockerfile does not install ci/packages --for image"
install_lines=$(grep -c 'apt-get install' .clusterfuzzlite/Dockerfile)
((install_lines == 1)) || fail "the Dockerfile has $install_lines apt-get install lines; only the list's may install"

mapfile -t deps < <(ci/packages --for deps)
mapfile -t image < <(ci/packages --for image)
((${#deps[@]} > 10 && ${#image[@]} > 3)) || fail "ci/packages printed ${#deps[@]} and ${#image[@]} packages"
for p in "${image[@]}"; do
  printf '%s\n' "${deps[@]}" | grep -qx "$p" || fail "$p is in the image but not installed by ci/deps"
done
# What fuzz/oss_fuzz_build.sh runs, besides the image's clang: package that provides it.
for need in cmake:cmake ninja:ninja-build zip:zip libtet:libtet1.5-dev cgal:libcgal-dev; do
  printf '%s\n' "${image[@]}" | grep -qx "${need#*:}" || fail "the image lacks ${need#*:} (${need%%:*})"
done
# The image's Ubuntu and the one ClusterFuzzLite runs the fuzzers on are the same, and the
# workflows check out the repository before building, so that the action reads project.yaml.
base=$(sed -nE 's|^FROM gcr.io/oss-fuzz-base/base-builder:?([^ ]*).*|\1|p' .clusterfuzzlite/Dockerfile)
if [[ -n $base ]]; then
  grep -qx "base_os_version: $base" .clusterfuzzlite/project.yaml ||
    fail "the Dockerfile builds on $base but project.yaml does not say base_os_version: $base"
  for wf in .github/workflows/cflite_*.yml; do
    builds=$(grep -c 'clusterfuzzlite/actions/build_fuzzers' "$wf")
    checkouts=$(grep -c 'uses: actions/checkout' "$wf")
    ((checkouts >= builds)) || fail "$wf builds fuzzers $builds times after $checkouts checkouts"
  done
fi
ci/packages --for nowhere >/dev/null 2>&1 && fail "ci/packages accepted an unknown place"
((status == 0)) && echo "one package list: ${#deps[@]} for ci/deps, ${#image[@]} of them for the image"
exit $status

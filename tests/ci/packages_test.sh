#!/usr/bin/env bash
# ctest ci.packages: the machines (ci/deps) and the ClusterFuzzLite build image
# (.clusterfuzzlite/Dockerfile) install their Debian packages from the one list,
# ci/packages.txt, through ci/packages; the image's packages are among the machines'; and the
# image has what fuzz/oss_fuzz_build.sh calls.
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
ci/packages --for nowhere >/dev/null 2>&1 && fail "ci/packages accepted an unknown place"
((status == 0)) && echo "one package list: ${#deps[@]} for ci/deps, ${#image[@]} of them for the image"
exit $status

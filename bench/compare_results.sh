#!/usr/bin/env bash
# Google Benchmark's own comparison of two ci/bench results files: compare.py (Debian's
# libbenchmark-tools) prints the change of every benchmark and its two-sided Mann-Whitney U test
# over the repetitions, and writes the same as JSON, which bench/pr_table.py reads. ci/bench
# --compare runs this; so does ctest ci.pr_table, on its test data.
#
#   bench/compare_results.sh BASE.json HEAD.json OUT.json
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: bench/compare_results.sh BASE.json HEAD.json OUT.json" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# compare.py reads a time from every entry; the callgrind count (ci/bench --instructions) has none.
python3 "$here/merge_results.py" --timed-only "$work/base.json" "$1"
python3 "$here/merge_results.py" --timed-only "$work/head.json" "$2"
# Debian's interpreter: the U test needs python3-scipy.
/usr/bin/python3 /usr/share/benchmark/compare.py --no-color -a --dump_to_json "$3" \
  benchmarks "$work/base.json" "$work/head.json"

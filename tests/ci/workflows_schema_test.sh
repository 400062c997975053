#!/usr/bin/env bash
# ctest ci.workflows_schema: every workflow in .github/workflows/ passes the GitHub workflow
# schema (@action-validator/cli, installed by ci/deps), and the validator does reject a broken
# workflow. Not skipped when the validator is missing: that fails, naming ci/deps.
#   workflows_schema_test.sh SOURCE_DIR
set -uo pipefail
src=${1:?usage: workflows_schema_test.sh SOURCE_DIR}
cd "$src" || exit 1  # the validator checks `paths:` globs against the files under the current folder
if ! command -v action-validator >/dev/null; then
  echo "FAIL: action-validator not found: run ci/deps (it installs @action-validator/cli from npm)"
  exit 1
fi

status=0
for name in ci bench nightly cflite_pr cflite_build cflite_batch cflite_cron; do
  [[ -f .github/workflows/$name.yml ]] || { echo "FAIL: .github/workflows/$name.yml is missing"; status=1; }
done
shopt -s nullglob
checked=0
for wf in .github/workflows/*.yml .github/workflows/*.yaml; do
  checked=$((checked + 1))
  if out=$(action-validator "$wf" 2>&1); then
    echo "valid: $wf"
  else
    echo "FAIL: $wf does not pass the workflow schema:"
    echo "$out"
    status=1
  fi
done
((checked > 0)) || { echo "FAIL: no workflow files"; status=1; }

# The negative control: a job with a misspelt key must be refused, or the check above proves nothing.
broken=$(mktemp --suffix=.yml)
trap 'rm -f "$broken"' EXIT
sed 's/runs-on:/runs_on:/' .github/workflows/ci.yml >"$broken"
if action-validator "$broken" >/dev/null 2>&1; then
  echo "FAIL: the validator accepted a workflow whose job has 'runs_on' instead of 'runs-on'"
  status=1
else
  echo "refused, as it must be: a job with 'runs_on'"
fi
((status == 0)) && echo "$checked workflow files valid"
exit $status

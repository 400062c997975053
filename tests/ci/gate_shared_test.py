#!/usr/bin/env python3
"""ctest ci.gate_shared: .ci/run and the workflow ci.yml run the same steps, ci/test then
ci/gate, and neither calls ci/bench itself, so that the gate a pull request sees is the gate
main is held to (and a change to the gate, e.g. adding the instruction count, is one line in
ci/gate). Also: the gate's Markdown report names the bisect command of a figure over budget.

    gate_shared_test.py SOURCE_DIR      (Debian's python3: it reads YAML)
"""
import os
import subprocess
import sys
import tempfile

import yaml

from checks import check, verdict  # noqa: E402 (this folder is on sys.path: the script's own)


def commands(lines):
    """Shell lines that run one of our ci/ scripts, in order, without comments."""
    out = []
    for line in lines:
        line = line.split("#", 1)[0].strip()
        for word in line.split():
            if word.startswith("ci/"):
                out.append(word)
    return out


def main(src):
    with open(os.path.join(src, ".ci/run"), encoding="utf-8") as f:
        ci_run = commands(f.read().splitlines())
    with open(os.path.join(src, ".github/workflows/ci.yml"), encoding="utf-8") as f:
        workflow = yaml.safe_load(f)
    steps = [s for job in workflow["jobs"].values() for s in job.get("steps", [])]
    ci_yml = commands(line for s in steps if "run" in s for line in s["run"].splitlines())
    print(".ci/run runs:", ci_run)
    print("ci.yml runs: ", ci_yml)
    check(ci_run[-2:] == ["ci/test", "ci/gate"], ".ci/run does not end with ci/test then ci/gate")
    check([c for c in ci_yml if c != "ci/deps"] == ["ci/test", "ci/gate"],
          "ci.yml does not run ci/test then ci/gate (and nothing else of ci/ but ci/deps)")
    check("ci/bench" not in ci_run + ci_yml, "ci/bench is called directly instead of through ci/gate")
    with open(os.path.join(src, "ci/gate"), encoding="utf-8") as f:
        check("ci/bench" in commands(f.read().splitlines()), "ci/gate does not run ci/bench")
    on = workflow.get("on", workflow.get(True))  # PyYAML reads the key `on` as True
    check("push" in on and "pull_request" in on, "ci.yml does not run on push and pull_request")
    uploads = [s for s in steps if str(s.get("uses", "")).startswith("actions/upload-artifact")]
    uploaded = "\n".join(str(s.get("with", {}).get("path", "")) for s in uploads)
    check("bench-results.json" in uploaded and "gate-report.md" in uploaded,
          "ci.yml does not upload the results JSON and the gate's report")

    # The report of a gate that fails says how to bisect the figure over budget.
    testdata = os.path.join(src, "bench/testdata")
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "gate-report.md")
        run = subprocess.run([sys.executable, os.path.join(src, "bench/budget_gate.py"),
                              os.path.join(testdata, "pr_head.json"), os.path.join(testdata, "pr_budgets.json"),
                              "--markdown", report], capture_output=True, text=True)
        check(run.returncode == 1, f"budget_gate.py exited {run.returncode} on a figure over budget, expected 1")
        text = open(report, encoding="utf-8").read() if os.path.exists(report) else ""
        check("| instructions per cut (callgrind) | 330,000 | <= 320000 |" in text,
              "the Markdown report lacks the instruction row")
        check('ci/bisect --budget "instructions per cut" --good' in text,
              "the Markdown report does not give the bisect command of the figure over budget")
        check("cut p50" not in text.split("To find the commit")[-1],
              "the report asks to bisect a figure within budget")
    return verdict("ci.yml and .ci/run share ci/test and ci/gate")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

#!/usr/bin/env python3
"""ctest python.examples: each script of examples/python/ run as a user would, briefly.

    run_examples.py EXAMPLES_DIR WORK_DIR

cautery_env.py for 8 steps (it exits 1 if the checker objects at the end), plot_resection.py into
WORK_DIR (the PNG must exist and be non-trivial)."""
import os
import shutil
import subprocess
import sys


def main(examples, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    png = os.path.join(work, "resection.png")
    runs = [[sys.executable, os.path.join(examples, "cautery_env.py"), "--steps", "8"],
            [sys.executable, os.path.join(examples, "plot_resection.py"), "--out", png]]
    for command in runs:
        print("$", " ".join(command), flush=True)
        if subprocess.run(command, cwd=work).returncode != 0:
            print(f"FAIL: {command[1]}")
            return 1
    if not os.path.exists(png) or os.path.getsize(png) < 10000:
        print(f"FAIL: {png} missing or empty")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))

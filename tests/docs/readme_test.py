#!/usr/bin/env python3
"""ctest docs.readme_tour and docs.readme_library: every command README.md shows, run.

    readme_test.py tour README.md TETCUT SOURCE_DIR WORK_DIR
    readme_test.py library README.md SOURCE_DIR WORK_DIR BUILD_DIR CXX CXX_FLAGS BUILD_TYPE
    readme_test.py python README.md SOURCE_DIR WORK_DIR

tour: every ```sh block of the README, in order, as one shell session (so `export` carries over),
one command a line, in a fresh WORK_DIR with TETCUT's folder first on PATH; each command must
exit 0. The folder sees the bundled corpus as `corpus/` (the tour's paths are the repository's),
all of it but corpus/scenarios/paper/: only `tetcut stats` reads that, so the tour passes only if
`tetcut stats` finds the bundled corpus by itself, from any working folder.

library: the README's ```cmake block and its ```cpp block as an outside project (CMakeLists.txt
and main.cpp), configured against this build tree's tetcut package (find_package through
tetcut_DIR, as tests/consumer does), built with this build's compiler and flags, and run on the
bundled liver: it must exit 0 after printing its cuts.

python: the README's ```python block, run as written by this interpreter (PYTHONPATH must reach
the built module: ctest docs.readme_python sets it) in a fresh WORK_DIR that sees the bundled
corpus as `corpus/`; it must exit 0 after printing its cuts.

A plain ``` block (the set-up commands ci/bench and ci/test, which take minutes) is not run.
"""
import os
import re
import shutil
import subprocess
import sys


def blocks(readme, language):
    """The bodies of the README's fenced blocks whose info string is `language`."""
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    return re.findall(r"^```" + re.escape(language) + r"[ \t]*\n(.*?)^```[ \t]*$", text, re.M | re.S)


def fresh(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)


def corpus_without_paper_scenarios(source_corpus, into):
    """`into`/corpus: links to every entry of the bundled corpus but scenarios/paper/."""
    corpus = os.path.join(into, "corpus")
    os.makedirs(os.path.join(corpus, "scenarios"))
    for name in os.listdir(source_corpus):
        if name != "scenarios":
            os.symlink(os.path.join(source_corpus, name), os.path.join(corpus, name))
    scenarios = os.path.join(source_corpus, "scenarios")
    for name in os.listdir(scenarios):
        if name != "paper":
            os.symlink(os.path.join(scenarios, name), os.path.join(corpus, "scenarios", name))


def tour(readme, tetcut, source, work):
    commands = [line.strip() for block in blocks(readme, "sh") for line in block.splitlines()
                if line.strip() and not line.strip().startswith("#")]
    if not commands:
        print(f"FAIL: no ```sh block in {readme}")
        return 1
    fresh(work)
    corpus_without_paper_scenarios(os.path.join(source, "corpus"), work)
    script = "".join(f"echo '$ {c}'\n{c} || {{ echo \"FAILED (exit $?): {c}\" >&2; exit 1; }}\n"
                     for c in commands)
    env = dict(os.environ, PATH=os.path.dirname(os.path.abspath(tetcut)) + os.pathsep + os.environ["PATH"])
    run = subprocess.run(["bash", "-c", script], cwd=work, env=env)
    if run.returncode != 0:
        return 1
    print(f"the README's {len(commands)} tour commands ran, each exit 0")
    return 0


def library(readme, source, work, build, cxx, cxx_flags, build_type):
    cmake, cpp = blocks(readme, "cmake"), blocks(readme, "cpp")
    if len(cmake) != 1 or len(cpp) != 1:
        print(f"FAIL: expected one ```cmake and one ```cpp block in {readme}, found {len(cmake)} and {len(cpp)}")
        return 1
    project = os.path.join(work, "project")
    fresh(project)
    with open(os.path.join(project, "CMakeLists.txt"), "w", encoding="utf-8") as f:
        f.write("cmake_minimum_required(VERSION 3.25)\nproject(readme_library LANGUAGES CXX)\n" + cmake[0])
    with open(os.path.join(project, "main.cpp"), "w", encoding="utf-8") as f:
        f.write(cpp[0])
    binary = os.path.join(work, "build")
    steps = [["cmake", "-S", project, "-B", binary, "-G", "Ninja", f"-Dtetcut_DIR={build}",
              f"-DCMAKE_CXX_COMPILER={cxx}", f"-DCMAKE_CXX_FLAGS={cxx_flags}", f"-DCMAKE_BUILD_TYPE={build_type}"],
             ["cmake", "--build", binary]]
    for step in steps:
        run = subprocess.run(step, capture_output=True, text=True)
        if run.returncode != 0:
            print(f"FAIL: {' '.join(step)}\n{run.stdout}\n{run.stderr}")
            return 1
    targets = re.findall(r"add_executable\((\S+)", cmake[0])
    program = os.path.join(binary, targets[0] if targets else "my_simulator")
    run = subprocess.run([program, os.path.join(source, "corpus", "meshes", "liver.msh")], capture_output=True,
                         text=True)
    print(run.stdout, run.stderr)
    if run.returncode != 0 or "cut at" not in run.stdout:
        print(f"FAIL: the README's library snippet exited {run.returncode}")
        return 1
    print("the README's library snippet compiled, linked against the tetcut package and ran")
    return 0


def python(readme, source, work):
    code = blocks(readme, "python")
    if len(code) != 1:
        print(f"FAIL: expected one ```python block in {readme}, found {len(code)}")
        return 1
    fresh(work)
    os.symlink(os.path.join(source, "corpus"), os.path.join(work, "corpus"))
    script = os.path.join(work, "session.py")
    with open(script, "w", encoding="utf-8") as f:
        f.write(code[0])
    run = subprocess.run([sys.executable, script], cwd=work, capture_output=True, text=True)
    print(run.stdout, run.stderr)
    if run.returncode != 0 or "removed" not in run.stdout:
        print(f"FAIL: the README's Python session exited {run.returncode}")
        return 1
    print(f"the README's Python session ({len(code[0].splitlines())} lines) ran")
    return 0


def main(argv):
    if len(argv) >= 6 and argv[1] == "tour":
        return tour(*argv[2:6])
    if len(argv) >= 9 and argv[1] == "library":
        return library(*argv[2:9])
    if len(argv) >= 5 and argv[1] == "python":
        return python(*argv[2:5])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))

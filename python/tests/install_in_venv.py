#!/usr/bin/env python3
"""ctest python.pip_install_venv and python.wheel_install_venv: the module installed the way the
README says, into a fresh virtual environment, then the README's Python session run by that
environment's interpreter from a folder outside the checkout (no PYTHONPATH: the import must
find the installed module).

    install_in_venv.py pip|wheel README.md SOURCE_DIR CMAKE_BUILD_DIR WORK_DIR

pip:   the commands of the README's set-up block (`pip install`), as written, in the checkout, with
       HOME at WORK_DIR/home (so the block's ~/.venvs/... is made there).
wheel: docs/python.md's `python3 -m build --wheel --no-isolation`, then the wheel installed by
       pip into a second fresh environment (where a wheel would go on another machine).
Both with TETCUT_CMAKE_BUILD_DIR=CMAKE_BUILD_DIR, so that the backend (setup.py) packs the module
this build made instead of building it again, and PIP_NO_INDEX=1: no network.
Also checked: the distribution's version is the module's, and the stub is installed beside it."""
import glob
import os
import shutil
import subprocess
import sys

DEBIAN_PYTHON = "/usr/bin/python3"


def fenced_blocks(readme):
    """(info string, body) of every fenced block of the README, fence by fence."""
    with open(readme, encoding="utf-8") as f:
        lines = f.read().splitlines()
    out, info, body = [], None, []
    for line in lines:
        if line.startswith("```"):
            if info is None:
                info, body = line[3:].strip(), []
            else:
                out.append((info, "\n".join(body) + "\n"))
                info = None
        elif info is not None:
            body.append(line)
    return out


def setup_commands(readme):
    """The README's plain ``` block that installs the module (the one opening "From Python"):
    one command a line."""
    found = [body for info, body in fenced_blocks(readme) if info == "" and "pip install" in body]
    if len(found) != 1:
        raise SystemExit(f"FAIL: expected one plain block with `pip install` in {readme}, found {len(found)}")
    return [line for line in found[0].splitlines() if line.strip() and not line.strip().startswith("#")]


def run(command, **kwargs):
    print("$", command if isinstance(command, str) else " ".join(command), flush=True)
    result = subprocess.run(command, **kwargs)
    if result.returncode != 0:
        raise SystemExit(f"FAIL (exit {result.returncode}): {command}")


def environment(work):
    # Nothing but what is installed: no index, no extra wheel folder a machine's pip settings name.
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "PIP_FIND_LINKS", "PIP_EXTRA_INDEX_URL")}
    env.update(HOME=os.path.join(work, "home"), PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1",
               PYTHONDONTWRITEBYTECODE="1")
    return env


def session(python, readme, source, work, env):
    """The README's ```python block run by `python` in WORK/session, which sees the corpus."""
    code = [body for info, body in fenced_blocks(readme) if info == "python"]
    where = os.path.join(work, "session")
    os.makedirs(where)
    os.symlink(os.path.join(source, "corpus"), os.path.join(where, "corpus"))
    with open(os.path.join(where, "session.py"), "w", encoding="utf-8") as f:
        f.write(code[0])
    probe = ("import importlib.metadata, os, tetcut; "
             "print(tetcut.__file__); "
             "assert importlib.metadata.version('tetcut') == tetcut.__version__, tetcut.__version__; "
             "assert os.path.exists(os.path.join(os.path.dirname(tetcut.__file__), 'tetcut.pyi'))")
    found = subprocess.run([python, "-c", probe], cwd=where, env=env, capture_output=True, text=True)
    print(found.stdout, found.stderr)
    prefix = os.path.dirname(os.path.dirname(python))
    if found.returncode != 0 or not found.stdout.startswith(prefix):
        raise SystemExit(f"FAIL: tetcut is not the one installed in {prefix}")
    result = subprocess.run([python, "session.py"], cwd=where, env=env, capture_output=True, text=True)
    print(result.stdout[-2000:], result.stderr[-2000:])
    if result.returncode != 0 or "removed" not in result.stdout:
        raise SystemExit(f"FAIL: the README's Python session exited {result.returncode} in {prefix}")


def main(route, readme, source, build, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, "home"))
    env = environment(work)
    env["TETCUT_CMAKE_BUILD_DIR"] = os.path.abspath(build)
    if route == "pip":
        for command in setup_commands(readme):
            run(["bash", "-c", command], cwd=source, env=env)
        pythons = [os.path.join(folder, "python") for folder, _, files in os.walk(env["HOME"])
                   if folder.endswith(os.sep + "bin") and "python" in files]
        if len(pythons) != 1:
            raise SystemExit(f"FAIL: the README's set-up made {len(pythons)} environments under {env['HOME']}")
        session(pythons[0], readme, source, work, env)
    elif route == "wheel":
        dist = os.path.join(work, "dist")
        run([DEBIAN_PYTHON, "-m", "build", "--wheel", "--no-isolation", "--outdir", dist, source], cwd=work, env=env)
        wheels = glob.glob(os.path.join(dist, "tetcut-*.whl"))
        if len(wheels) != 1:
            raise SystemExit(f"FAIL: expected one wheel in {dist}, found {wheels}")
        venv = os.path.join(work, "venv")
        run([DEBIAN_PYTHON, "-m", "venv", "--system-site-packages", venv], env=env)
        run([os.path.join(venv, "bin", "pip"), "install", wheels[0]], cwd=work, env=env)
        session(os.path.join(venv, "bin", "python"), readme, source, work, env)
    else:
        print(__doc__, file=sys.stderr)
        return 2
    print(f"{route}: installed into a fresh environment; the README's session ran from outside the checkout")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 6:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:6]))

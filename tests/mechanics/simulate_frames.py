"""`tetcut simulate` end to end: frames ParaView reads (meshio reads them here), the report, a
blow-up that fails the run, bad input refused, and the same bits twice. With --resection, the
bundled liver resection (corpus/scenarios/liver-resection.scn) runs to its end without a blow-up.

Usage: /usr/bin/python3 simulate_frames.py TETCUT CORPUS_DIR WORK_DIR [--resection]
(Debian's interpreter: it sees python3-meshio; exit 77, skipped, only when meshio is missing.)
"""
import json
import math
import os
import shutil
import subprocess
import sys

try:
    import meshio
except ImportError:
    print("meshio is not installed (python3-meshio)")
    sys.exit(77)

tetcut, corpus, work = sys.argv[1:4]
resection = "--resection" in sys.argv[4:]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def simulate(*args):
    return subprocess.run([tetcut, "simulate", *args], capture_output=True, text=True)


liver = os.path.join(corpus, "meshes", "liver-coarse.msh")
common = ["--diameter", "8", "--sweep", "95,15,60", "95,200,60", "20", "--fix", "x>150", "--gravity", "0,0,-9.81"]

if resection:
    scenario = os.path.join(corpus, "scenarios", "liver-resection.scn")
    report = os.path.join(work, "resection.json")
    r = simulate(scenario, "--fix", "x>150", "--gravity", "0,0,-9.81", "--steps", "2", "--report", report)
    check(r.returncode == 0, f"the resection: exit {r.returncode}: {r.stderr}")
    if r.returncode == 0:
        summary = json.load(open(report))["summary"]
        check(summary["ok"] and summary["cuts_refused"] == 0, f"the resection: {summary}")
        check(summary["frames"] > 1000, f"the resection ran {summary['frames']} frames")
        print(f"resection: {summary['frames']} frames, stable step {summary['stable_dt_initial']:.3g} s before, "
              f"{summary['stable_dt_min']:.3g} s at worst after, {summary['frames_above_stable_dt']} frames above it")
else:
    # Frames and report.
    frames = os.path.join(work, "frames")
    os.makedirs(frames)
    report = os.path.join(work, "r.json")
    r = simulate(liver, *common, "--frames", frames, "--frame-every", "3", "--report", report)
    check(r.returncode == 0, f"exit {r.returncode}: {r.stderr}")
    data = json.load(open(report))
    check(data["summary"]["ok"], "summary not ok")
    check(len(data["frames"]) == data["summary"]["frames"] > 5, "frame count")
    # The default step is half the stable-step estimate before the cuts; the summary's worst is
    # the frames' (a cut can lower the estimate, or raise it by taking the stiffest tets).
    summary = data["summary"]
    check(summary["dt"] == 0.5 * summary["stable_dt_initial"] and summary["dt_factor"] == 0.5, f"dt: {summary}")
    check(summary["stable_dt_min"] == min([summary["stable_dt_initial"]] + [f["stable_dt"] for f in data["frames"]]),
          f"stable_dt_min: {summary}")
    check(summary["frames_above_stable_dt"] == sum(summary["dt"] > f["stable_dt"] for f in data["frames"]),
          f"frames_above_stable_dt: {summary}")
    for f in data["frames"]:
        for key in ("cut_us", "update_us", "step_us", "stable_dt", "max_displacement_m"):
            check(math.isfinite(f[key]) and f[key] >= 0, f"frame {f['frame']}: {key} = {f[key]}")
        check(0 < f["stable_dt"] < math.inf, f"frame {f['frame']}: stable_dt {f['stable_dt']}")
        check(math.isfinite(f["energy"]["total"]), f"frame {f['frame']}: energy")
    written = sorted(os.listdir(frames))
    check(written == [f"frame_{k:05d}.vtu" for k in range(0, len(data["frames"]), 3)], f"frames written: {written}")
    moved = 0.0
    for name in written:
        m = meshio.read(os.path.join(frames, name))
        tets = [c for c in m.cells if c.type == "tetra"]
        check(len(tets) == 1 and tets[0].data.shape[1] == 4, f"{name}: tets")
        u = m.point_data.get("displacement")
        check(u is not None and u.shape == (len(m.points), 3), f"{name}: displacement")
        if u is not None:
            check(all(math.isfinite(x) for x in u.ravel()), f"{name}: a displacement is not finite")
            moved = max(moved, float(abs(u).max()))
        label = m.cell_data.get("label")
        check(label is not None and len(label[0]) == len(tets[0].data), f"{name}: label")
    check(moved > 0, "nothing moved under gravity")
    # Same input, same bits.
    again = os.path.join(work, "again")
    os.makedirs(again)
    simulate(liver, *common, "--frames", again, "--frame-every", "3")
    for name in written:
        check(open(os.path.join(frames, name), "rb").read() == open(os.path.join(again, name), "rb").read(),
              f"{name} differs between two runs")
    # A time step far above the stable one blows up, and the run says so.
    r = simulate(liver, *common, "--dt", "0.002")
    check(r.returncode == 1 and "blow-up" in r.stderr, f"--dt 0.002: exit {r.returncode}: {r.stderr}")
    # Bad input.
    r = simulate(liver, *common[:5], "--fix", "w<3")
    check(r.returncode == 2 and "--fix" in r.stderr, f"--fix w<3: exit {r.returncode}: {r.stderr}")
    r = simulate(os.path.join(work, "missing.msh"), *common)
    check(r.returncode == 2 and "missing.msh" in r.stderr, f"missing mesh: exit {r.returncode}: {r.stderr}")
    r = simulate(liver, *common, "--poisson", "0.5")
    check(r.returncode == 2 and "Poisson" in r.stderr, f"--poisson 0.5: exit {r.returncode}: {r.stderr}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)

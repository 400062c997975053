#!/usr/bin/python3
"""Differential test of tetcut's readers and writers against meshio (Debian's python3-meshio).

    meshio_differential.py TETCUT_EXE CORPUS_DIR WORK_DIR [MESH.msh ...]

One way: each bundled mesh named (corpus/meshes; by default the paper's three kinds, cylinder,
sheet and coarse liver, which keep the test to seconds; the larger livers change nothing but
the time) is written by meshio in each format and setting
tetcut reads, read by `tetcut info --json`, and its canonical hash compared with the
original's. The other way: `tetcut convert` writes each format and setting it writes, meshio
reads the file, and the points (bit for bit) and the tets (same order) must be the original's.

meshio writes ASCII .vtu with 12 significant digits ("{:.11e}"), which changes the coordinates,
so every row is also run on a copy of each mesh rounded to 12 digits, whose reference hash comes
from a Gmsh 2.2 file this script writes itself with Python's repr (exact); the ASCII .vtu row is
checked on that copy only. Exit 0 when the table reads "same hash" in every row and the other
way agrees, 1 otherwise, 77 (skipped) when meshio is not installed. Needs /usr/bin/python3 (the
interpreter that sees Debian's packages).
"""
import json
import os
import subprocess
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:  # ctest: SKIP_RETURN_CODE 77
    print(f"skipped: {e} (ci/deps installs python3-meshio; run with /usr/bin/python3)")
    sys.exit(77)

# (format and setting, file extension, meshio.write keywords)
ROWS = [
    (".vtu, default (binary, zlib)", "vtu", {}),
    (".vtu, lzma", "vtu", {"compression": "lzma"}),
    (".vtu, base64 uncompressed", "vtu", {"binary": True, "compression": None}),
    (".vtk legacy, default (binary)", "vtk", {}),
    ("Gmsh 4.1 binary", "msh", {"file_format": "gmsh", "binary": True}),
    ("Gmsh 2.2 binary", "msh", {"file_format": "gmsh22", "binary": True}),
    ("ASCII .vtu", "vtu", {"binary": False}),
    ("ASCII .vtk", "vtk", {"binary": False}),
    ("Gmsh 2.2 ASCII", "msh", {"file_format": "gmsh22", "binary": False}),
    ("Gmsh 4.1 ASCII", "msh", {"file_format": "gmsh", "binary": False}),
    ("medit", "mesh", {}),
]
LOSSY_IN_MESHIO = {"ASCII .vtu"}  # 12 significant digits

# (file tetcut writes, extra `tetcut convert` arguments)
OUTPUTS = [
    ("o22.msh", []), ("o22b.msh", ["--binary"]),
    ("o41.msh", ["--format", "msh41"]), ("o41b.msh", ["--format", "msh41", "--binary"]),
    ("o.vtu", []), ("ob.vtu", ["--binary"]), ("oz.vtu", ["--compress", "zlib"]), ("ox.vtu", ["--compress", "lzma"]),
    ("o.vtk", []), ("ob.vtk", ["--binary"]), ("o.mesh", []), ("o.node", []),
]


def run(args):
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(args)}: exit {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def tetcut_hash(exe, path):
    return json.loads(run([exe, "info", path, "--json"]))["hash"]


def write_reference_msh22(path, points, tets):
    """Gmsh 2.2 ASCII with repr() coordinates: exact, and written by neither meshio nor tetcut."""
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(points))
        for i, p in enumerate(points):
            f.write("%d %r %r %r\n" % (i + 1, float(p[0]), float(p[1]), float(p[2])))
        f.write("$EndNodes\n$Elements\n%d\n" % len(tets))
        for i, t in enumerate(tets):
            f.write("%d 4 0 %d %d %d %d\n" % (i + 1, *(int(v) + 1 for v in t)))
        f.write("$EndElements\n")


def quietly(fn):
    """meshio prints warnings (missing gmsh tags, ASCII is for debugging) on both streams."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
        os.dup2(null.fileno(), 2)
        try:
            return fn()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])


def main():
    exe, corpus, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    meshes = sys.argv[4:] or ["cylinder.msh", "sheet.msh", "liver-coarse.msh"]
    row_failures = {label: [] for label, _, _ in ROWS}
    other_way_failures = []
    checked = 0
    for name in meshes:
        original = os.path.join(corpus, "meshes", name)
        m = quietly(lambda: meshio.read(original))
        points = m.points
        tets = m.cells_dict["tetra"]
        rounded = np.array([[float("%.11e" % c) for c in p] for p in points])
        reference12 = os.path.join(work, "ref12.msh")
        write_reference_msh22(reference12, rounded, tets)
        variants = [("as bundled", points, tetcut_hash(exe, original)),
                    ("12 digits", rounded, tetcut_hash(exe, reference12))]
        # One way: meshio writes, tetcut reads.
        for variant, pts, expected in variants:
            mesh = meshio.Mesh(pts, [("tetra", tets)])
            for label, ext, kwargs in ROWS:
                if variant == "as bundled" and label in LOSSY_IN_MESHIO:
                    continue
                path = os.path.join(work, "meshio." + ext)
                quietly(lambda: meshio.write(path, mesh, **kwargs))
                try:
                    got = tetcut_hash(exe, path)
                except RuntimeError as e:
                    got = str(e)
                checked += 1
                if got != expected:
                    row_failures[label].append(f"{name} ({variant}): {got} instead of {expected}")
        # The other way: tetcut writes, meshio reads.
        for out, extra in OUTPUTS:
            path = os.path.join(work, out)
            run([exe, "convert", original, path, *extra])
            kwargs = {"file_format": "gmsh"} if out.endswith(".msh") else {}
            back = quietly(lambda: meshio.read(path, **kwargs))
            back_tets = back.cells_dict.get("tetra")
            checked += 1
            if not np.array_equal(back.points, points):
                other_way_failures.append(f"{name} -> {out} {' '.join(extra)}: points differ")
            elif back_tets is None or not np.array_equal(back_tets, tets):
                other_way_failures.append(f"{name} -> {out} {' '.join(extra)}: tets differ")

    print(f"meshio {meshio.__version__}, {len(meshes)} bundled meshes, {checked} files compared\n")
    print("| written by meshio as | tetcut |")
    print("|---|---|")
    for label, _, _ in ROWS:
        note = " (on the meshes rounded to meshio's 12 digits)" if label in LOSSY_IN_MESHIO else ""
        print(f"| {label} | {'same hash' + note if not row_failures[label] else 'DIFFERENT'} |")
    print("\nwritten by tetcut, read by meshio: " + ("points and tets agree for every format and setting"
                                                     if not other_way_failures else "DISAGREE"))
    for label, failures in row_failures.items():
        for f in failures:
            print(f"FAIL {label}: {f}")
    for f in other_way_failures:
        print(f"FAIL tetcut -> meshio: {f}")
    return 0 if not other_way_failures and not any(row_failures.values()) else 1


if __name__ == "__main__":
    sys.exit(main())

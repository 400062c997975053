#!/usr/bin/python3
"""Differential test of tetcut's per-tet labels (RawMesh::labels) against meshio's cell_data.

    meshio_labels.py TETCUT_EXE CORPUS_DIR WORK_DIR

On the bundled cylinder with a label per tet (a few regions, ids up to 1000, so that a reader
that numbered labels itself or took another tag would differ):

- one way: meshio writes the mesh with its labels under the name each format's convention
  gives them (Gmsh: "gmsh:physical"; medit: "medit:ref"; VTK: "label", and in a second file
  "CellEntityIds"; TetGen: "tetgen:ref", the .ele's one attribute column) in every labelled
  format meshio writes (Gmsh 4.1: a cell block and a volume
  entity per label, the physical tag in $Entities, each node on a volume of one of its tets:
  meshio writes an entity only for the nodes' "gmsh:dim_tags"; the tets then come grouped by
  label); `tetcut convert` turns it into a
  medit file, which Python reads back: the references must be the labels, tet by tet;
- through cuts: `tetcut cut` and `tetcut remove` on that medit file write .vtu files whose
  labels meshio reads: every tet the operations left untouched (the same four vertex positions)
  keeps its label, every label is one of the file's, and the cut changed something;
- the other way: `tetcut convert` writes each format that carries labels from that medit file,
  meshio reads it, and the cell data ("gmsh:physical", "medit:ref", "label", "tetgen:ref") must be
  the labels
  (a legacy SCALARS array comes back as #T by 1, Gmsh 4.1 as a block per run of one label:
  compared flattened and concatenated).

Exit 0 when every row agrees, 1 otherwise, 77 (skipped) when meshio is not installed.
"""
import os
import subprocess
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:  # ctest: SKIP_RETURN_CODE 77
    print(f"skipped: {e} (ci/deps installs python3-meshio; run with /usr/bin/python3)")
    sys.exit(77)

from meshio_differential import quietly  # noqa: E402  (after the skip above)

# (row, extension, meshio.write keywords, the cell_data name meshio uses for the label)
ONE_WAY = [
    ("Gmsh 2.2 ASCII", "msh", {"file_format": "gmsh22", "binary": False}, "gmsh:physical"),
    ("Gmsh 2.2 binary", "msh", {"file_format": "gmsh22", "binary": True}, "gmsh:physical"),
    ("Gmsh 4.1 ASCII", "msh", {"file_format": "gmsh", "binary": False}, "gmsh:physical"),
    ("Gmsh 4.1 binary", "msh", {"file_format": "gmsh", "binary": True}, "gmsh:physical"),
    ("medit", "mesh", {}, "medit:ref"),
    ("ASCII .vtk", "vtk", {"binary": False}, "label"),
    ("binary .vtk", "vtk", {"binary": True}, "label"),
    ("ASCII .vtk, CellEntityIds", "vtk", {"binary": False}, "CellEntityIds"),
    ("ASCII .vtu", "vtu", {"binary": False}, "label"),
    ("binary .vtu, zlib", "vtu", {}, "label"),
    ("binary .vtu, CellEntityIds", "vtu", {}, "CellEntityIds"),
    ("TetGen .node/.ele", "ele", {}, "tetgen:ref"),
]
# (file tetcut writes, extra `tetcut convert` arguments, the cell_data name meshio reads it as)
OTHER_WAY = [
    ("o22.msh", [], "gmsh:physical"), ("o22b.msh", ["--binary"], "gmsh:physical"),
    ("o41.msh", ["--format", "msh41"], "gmsh:physical"), ("o41b.msh", ["--format", "msh41", "--binary"], "gmsh:physical"),
    ("o.mesh", [], "medit:ref"),
    ("o.vtk", [], "label"), ("ob.vtk", ["--binary"], "label"),
    ("o.vtu", [], "label"), ("ob.vtu", ["--binary"], "label"), ("oz.vtu", ["--compress", "zlib"], "label"),
    ("o.ele", [], "tetgen:ref"),
]


def run(args):
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(args)}: exit {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def medit_refs(path):
    """The tetrahedra's references of a medit file, read by hand (no meshio in between)."""
    with open(path) as f:
        tokens = f.read().split()
    at = next(i for i, t in enumerate(tokens) if t.lower() == "tetrahedra")
    n = int(tokens[at + 1])
    return [int(tokens[at + 2 + 5 * k + 4]) for k in range(n)]


def main():
    exe, corpus, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    m = quietly(lambda: meshio.read(os.path.join(corpus, "meshes", "cylinder.msh")))
    points, tets = m.points, m.cells_dict["tetra"]
    # Regions by height, numbered unevenly: 3, 7, 1000 (and 0, Gmsh's "no physical group").
    z = points[tets].mean(axis=1)[:, 2]
    labels = np.select([z < np.quantile(z, 0.25), z < np.quantile(z, 0.5), z < np.quantile(z, 0.75)],
                       [3, 7, 1000], 0).astype(np.int32)
    failures, checked = [], 0

    for row, ext, kwargs, name in ONE_WAY:
        data = {name: [labels]}
        cells, point_data, expected = [("tetra", tets)], {}, labels
        if name == "gmsh:physical":
            data["gmsh:geometrical"] = [labels]
        if kwargs.get("file_format") == "gmsh":
            regions = sorted(set(labels.tolist()))
            cells = [("tetra", tets[labels == l]) for l in regions]
            data = {name: [np.full(len(c), l, np.int32) for (_, c), l in zip(cells, regions)],
                    "gmsh:geometrical": [np.full(len(c), v + 1, np.int32) for v, (_, c) in enumerate(cells)]}
            dim_tags = np.zeros((len(points), 2), dtype=np.int32)
            dim_tags[:, 0] = 3
            for v, (_, c) in enumerate(cells):
                dim_tags[c.reshape(-1), 1] = v + 1
            assert len(set(dim_tags[:, 1].tolist())) == len(regions), "a region owns no node"
            point_data = {"gmsh:dim_tags": dim_tags}
            expected = np.concatenate(data[name])
        path = os.path.join(work, "meshio." + ext)
        mesh = meshio.Mesh(points, cells, cell_data=data, point_data=point_data)
        quietly(lambda: meshio.write(path, mesh, **kwargs))
        out = os.path.join(work, "tetcut.mesh")
        checked += 1
        try:
            run([exe, "convert", path, out])
            got = medit_refs(out)
        except (RuntimeError, ValueError, StopIteration) as e:
            failures.append(f"{row}: {e}")
            continue
        if got != expected.tolist():
            failures.append(f"{row}: tetcut read {sum(a != b for a, b in zip(got, expected))} labels wrong")

    source = os.path.join(work, "labelled.mesh")
    quietly(lambda: meshio.write(source, meshio.Mesh(points, [("tetra", tets)], cell_data={"medit:ref": [labels]})))
    for out, extra, name in OTHER_WAY:
        path = os.path.join(work, out)
        checked += 1
        try:
            run([exe, "convert", source, path, *extra])
        except RuntimeError as e:
            failures.append(f"{out}: {e}")
            continue
        kwargs = {"file_format": "gmsh"} if out.endswith(".msh") else {}
        back = quietly(lambda: meshio.read(path, **kwargs))
        got = back.cell_data.get(name)
        flat = None if got is None else np.concatenate([np.asarray(g).reshape(-1) for g in got])
        if flat is None or not np.array_equal(flat, labels) or not np.array_equal(back.cells_dict["tetra"], tets):
            failures.append(f"tetcut -> {out} {' '.join(extra)}: meshio's cell_data[{name!r}] is not the labels")

    # Through a sweep of cuts and a run of removals: the labels come back, untouched tets keep theirs.
    key = lambda pts, t: tuple(sorted(tuple(float(c) for c in pts[v]) for v in t))
    original = {key(points, t): int(l) for t, l in zip(tets, labels)}
    lo, hi = points.min(axis=0), points.max(axis=0)
    mid = 0.5 * (lo + hi)
    fr, to = f"{lo[0]:.6f},{mid[1]:.6f},{mid[2]:.6f}", f"{hi[0]:.6f},{mid[1]:.6f},{mid[2]:.6f}"
    operations = [
        ("tetcut cut", ["cut", source, "--diameter", "0.5", "--from", fr, "--to", to, "--step", "0.5"], "cut.vtu"),
        ("tetcut remove", ["remove", source, "--random", "200", "--seed", "3"], "removed.vtu"),
    ]
    for what, args, out in operations:
        path = os.path.join(work, out)
        checked += 1
        try:
            run([exe, *args, "-o" if what == "tetcut remove" else "--out", path])
        except RuntimeError as e:
            failures.append(f"{what}: {e}")
            continue
        back = quietly(lambda: meshio.read(path))
        got = back.cell_data.get("label")
        if got is None:
            failures.append(f"{what}: no cell data 'label' in its output")
            continue
        got = np.asarray(got[0]).reshape(-1)
        back_tets = back.cells_dict["tetra"]
        kept = [original.get(key(back.points, t)) for t in back_tets]
        wrong = sum(1 for k, l in zip(kept, got) if k is not None and k != l)
        untouched = sum(1 for k in kept if k is not None)
        changed_nothing = len(back_tets) == len(tets) and untouched == len(back_tets)
        if wrong or not set(got.tolist()) <= {0, 3, 7, 1000} or changed_nothing or untouched == 0:
            failures.append(f"{what}: {wrong} untouched tets relabelled, labels {sorted(set(got.tolist()))}, "
                            f"{untouched} of {len(back_tets)} tets untouched")

    for f in failures:
        print("FAIL", f)
    print(f"{checked} label round trips, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

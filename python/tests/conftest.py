"""Fixtures of the tetcut module's pytest suite (ctest python.pytest runs it with /usr/bin/python3,
PYTHONPATH at the built module, TETCUT_CLI at the built `tetcut`, TETCUT_SOURCE_DIR at the tree)."""
import itertools
import os
import pathlib

import numpy as np
import pytest

# Under ASan, ctest preloads the sanitizer runtime into this interpreter (python/tests/CMakeLists.txt);
# the `tetcut` processes the tests start carry their own, and must not get a second one.
os.environ.pop("LD_PRELOAD", None)

SOURCE = pathlib.Path(os.environ.get("TETCUT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CORPUS = SOURCE / "corpus" / "meshes"

# The README's sweep (README.md, "Cut."): 8 mm tool, y from 40 to 180, one cut every 4 mm.
README_SWEEP = dict(start=(95.0, 40.0, 100.0), end=(95.0, 180.0, 100.0), step=4.0)
README_DIAMETER = 8.0


def grid_arrays(cells, origin, size):
    """A box of cells[0] x cells[1] x cells[2] cells from `origin` spanning `size`, split as
    box_arrays splits its cells."""
    nx, ny, nz = cells
    axes = [np.linspace(origin[a], origin[a] + size[a], cells[a] + 1) for a in range(3)]
    points = np.array([(x, y, z) for x in axes[0] for y in axes[1] for z in axes[2]])
    index = lambda i, j, k: (i * (ny + 1) + j) * (nz + 1) + k
    tets = []
    for i, j, k in itertools.product(range(nx), range(ny), range(nz)):
        for perm in itertools.permutations(range(3)):
            corner = [i, j, k]
            path = [index(*corner)]
            for axis_step in perm:
                corner[axis_step] += 1
                path.append(index(*corner))
            tets.append(path)
    tets = np.array(tets, dtype=np.int64)
    p = points[tets]
    volume = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    flip = volume < 0
    tets[flip, 0], tets[flip, 1] = tets[flip, 1].copy(), tets[flip, 0].copy()
    return points, tets


def box_arrays(n=3, size=1.0):
    """A cube of n^3 cells, each split into the 6 tets around its main diagonal (Kuhn), which
    meet conformally across cells; every tet positively oriented."""
    return grid_arrays((n, n, n), (0.0, 0.0, 0.0), (size, size, size))


def plate_arrays():
    """The plate of the engine's fragments test (tests/engine/cut/fragments_test.cpp), coarser:
    4 x 2 x 0.2 from (0, 0, -0.1), in 16 x 8 x 2 cells (1,536 tets). A capsule of diameter 0.5 from
    (1, -0.3, 0) to (1, 2.3, 0) (PLATE_CUT) cuts it through, detaching the side x < 0.75."""
    return grid_arrays((16, 8, 2), (0.0, 0.0, -0.1), (4.0, 2.0, 0.2))


PLATE_CUT = dict(a=(1.0, -0.3, 0.0), b=(1.0, 2.3, 0.0))


@pytest.fixture
def box():
    import tetcut
    points, tets = box_arrays(4, 4.0)
    return tetcut.Mesh(points, tets)


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("TETCUT_CLI")
    if not path:
        pytest.fail("TETCUT_CLI is not set: run the suite through ctest (python.pytest)")
    return path


@pytest.fixture
def liver():
    import tetcut
    return tetcut.read(str(CORPUS / "liver.msh"))


def read_during_sweep(mesh, read):
    """The README's line swept at 1 mm steps (141 cuts) on `mesh` by another thread, while this one
    calls read(mesh) in a loop and tries mesh.surface(), which reads the live mesh: refused while
    the sweep holds it, which proves the reads ran during the sweep. Returns the sweep's reports,
    the reads, and the refusals' messages."""
    import threading

    import tetcut
    cutter = tetcut.Cutter(mesh, tool_diameter=README_DIAMETER)
    done, reads, refusals = [], [], []
    worker = threading.Thread(target=lambda: done.append(cutter.sweep(README_SWEEP["start"], README_SWEEP["end"], 1.0)))
    worker.start()
    while worker.is_alive():
        reads.append(read(mesh))
        try:
            mesh.surface()
        except RuntimeError as e:  # the sweep holds the live mesh while the GIL is free
            refusals.append(str(e))
    worker.join()
    return done[0], reads, refusals

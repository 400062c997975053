"""Per-tet labels from Python: Mesh(..., labels=), tetcut.read of a labelled file and
from_meshio's cell_data give mesh.labels, carried through cuts, sweeps and compaction as
`tetcut cut` carries them and written back by mesh.write and to_meshio; None for an unlabelled
mesh; bad labels raise."""
import re
import subprocess

import numpy as np
import pytest

import tetcut
from conftest import CORPUS, box_arrays, read_during_sweep


def side_labels(points, tets):
    """3 left of x = 2, 7 right of it, in the box of side 4 and 4^3 cells: no cell straddles the
    plane and a child lies inside its parent, so every tet a cut leaves must carry the label of
    the side its centroid is on."""
    return np.where(points[tets].mean(axis=1)[:, 0] < 2.0, 3, 7)


@pytest.fixture
def regions():
    points, tets = box_arrays(4, 4.0)
    return tetcut.Mesh(points, tets, labels=side_labels(points, tets))


def assert_labels_follow_the_sides(mesh):
    labels = mesh.labels
    assert labels is not None and labels.dtype == np.int64 and labels.shape == (mesh.num_tets,)
    np.testing.assert_array_equal(labels, side_labels(mesh.points, mesh.tets))
    assert set(labels.tolist()) == {3, 7}


def test_labels_are_the_given_ones_and_none_without():
    points, tets = box_arrays(4, 4.0)
    mesh = tetcut.Mesh(points, tets, labels=side_labels(points, tets).astype(np.uint8))
    np.testing.assert_array_equal(mesh.labels, side_labels(points, tets))
    assert tetcut.Mesh(points, tets).labels is None
    assert tetcut.Mesh(points, tets, labels=None).labels is None


def test_labels_follow_cuts_sweeps_and_compaction(regions):
    # A tool smaller than the cells (D_ref = 0.6 < 1): each cut splits before it removes.
    cutter = tetcut.Cutter(regions, tool_diameter=0.4)
    report = cutter.cut((2.0, 2.0, 4.0))  # on the plane x = 2: children on both sides
    assert report.ok and report.tets_created > 0
    assert_labels_follow_the_sides(regions)
    reports = cutter.sweep((0.5, 2.0, 0.0), (3.5, 2.0, 0.0), 0.5)
    assert len(reports) == 7 and all(r.ok for r in reports) and sum(r.tets_created for r in reports) > 0
    assert_labels_follow_the_sides(regions)
    labels, ids = regions.labels, regions.tet_ids
    tet_map, _ = regions.compact()
    np.testing.assert_array_equal(regions.labels[tet_map[ids]], labels)
    assert cutter.cut((4.0, 4.0, 4.0)).ok
    assert_labels_follow_the_sides(regions)


def test_write_and_read_keep_the_labels(tmp_path, regions):
    assert tetcut.Cutter(regions, tool_diameter=0.4).cut((2.0, 2.0, 4.0)).tets_created > 0
    for name in ["m.msh", "m.vtu", "m.mesh", "m.ele"]:
        regions.write(str(tmp_path / name))
        again = tetcut.read(str(tmp_path / name))
        np.testing.assert_array_equal(again.tets, regions.tets)
        np.testing.assert_array_equal(again.labels, regions.labels)


def test_a_sweep_gives_the_labels_tetcut_cut_writes(cli, tmp_path, regions):
    source, out = str(tmp_path / "regions.mesh"), str(tmp_path / "cut.vtu")
    regions.write(source)
    run = subprocess.run([cli, "cut", source, "--diameter", "0.4", "--from", "0.5,2,4", "--to", "3.5,2,4", "--step",
                          "0.5", "--out", out], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    mesh = tetcut.read(source)
    reports = tetcut.Cutter(mesh, tool_diameter=0.4).sweep((0.5, 2, 4), (3.5, 2, 4), 0.5)
    assert all(r.ok for r in reports) and sum(r.tets_created for r in reports) > 0
    assert mesh.hash() == re.search(r"^hash ([0-9a-f]{16})$", run.stdout, re.M).group(1)
    written = tetcut.read(out)
    np.testing.assert_array_equal(written.tets, mesh.tets)
    np.testing.assert_array_equal(written.labels, mesh.labels)
    assert_labels_follow_the_sides(mesh)


def test_a_file_with_one_label_keeps_it_everywhere():
    # Every bundled mesh is one Gmsh volume, physical tag 1.
    mesh = tetcut.read(str(CORPUS / "cylinder.msh"))
    assert mesh.labels is not None and set(mesh.labels.tolist()) == {1}
    assert tetcut.Cutter(mesh, tool_diameter=0.1).cut((0.0, 0.0, 4.0)).tets_created > 0
    np.testing.assert_array_equal(mesh.labels, np.ones(mesh.num_tets, dtype=np.int64))


def test_meshio_carries_the_labels_both_ways(regions):
    meshio = pytest.importorskip("meshio")
    tetcut.Cutter(regions, tool_diameter=0.4).cut((2.0, 2.0, 4.0))
    m = regions.to_meshio()
    np.testing.assert_array_equal(m.cell_data["label"][0], regions.labels)
    np.testing.assert_array_equal(tetcut.from_meshio(m).labels, regions.labels)
    # Under each format's name, over several tetra blocks (a triangle block between them), as
    # meshio reads a Gmsh file: the labels in the order of the tets.
    tets, labels = regions.tets, regions.labels
    half = len(tets) // 2
    triangle = np.array([[0, 1, 2]])
    for name in ["gmsh:physical", "medit:ref", "CellEntityIds", "tetgen:ref"]:
        split = meshio.Mesh(regions.points, [("tetra", tets[:half]), ("triangle", triangle), ("tetra", tets[half:])],
                            cell_data={name: [labels[:half], np.array([99]), labels[half:]]})
        np.testing.assert_array_equal(tetcut.from_meshio(split).labels, labels)
    # Real-valued cell data is something else: no labels.
    assert tetcut.from_meshio(meshio.Mesh(regions.points, [("tetra", tets)],
                                          cell_data={"label": [labels + 0.5]})).labels is None
    assert tetcut.from_meshio(meshio.Mesh(regions.points, [("tetra", tets)])).labels is None


@pytest.mark.parametrize("labels, error, words", [
    (np.zeros(10, int), ValueError, "labels: expected an array of shape (384,), one per tet, got shape (10,)"),
    (np.zeros((384, 1), int), ValueError, "got shape (384, 1)"),
    (np.full(384, -1), ValueError, "labels: -1 in row 0 is not a label"),
    (np.full(384, 2**31), ValueError, "2147483648 in row 0 is not a label"),
    (np.zeros(384), TypeError, "labels: expected integers, got dtype float64"),
])
def test_bad_labels_raise_naming_the_argument(labels, error, words):
    points, tets = box_arrays(4, 4.0)
    with pytest.raises(error) as e:
        tetcut.Mesh(points, tets, labels=labels)
    assert words in str(e.value)


def vessel_volume(mesh, label):
    """The volume of the tets labelled `label`, from the arrays alone."""
    p = mesh.points[mesh.tets]
    volumes = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6.0
    return volumes[mesh.labels == label].sum(), volumes.sum()


def vessel_box():
    """A vessel (label 2) along x through the box of side 4, in tissue labelled 1."""
    points, tets = box_arrays(4, 4.0)
    centroids = points[tets].mean(axis=1)
    labels = np.where(np.hypot(centroids[:, 1] - 2.0, centroids[:, 2] - 2.0) < 0.8, 2, 1)
    return tetcut.Mesh(points, tets, labels=labels)


def test_keep_labels_leaves_the_vessel_and_takes_the_tissue_above_it():
    mesh = vessel_box()
    vessel, total = vessel_volume(mesh, 2)
    cutter = tetcut.Cutter(mesh, tool_diameter=1.2, keep_labels=[2])
    reports = cutter.sweep((0.4, 2.0, 2.9), (3.6, 2.0, 2.9), 0.4)
    assert all(r.ok for r in reports) and sum(r.uncuttable_in_tool for r in reports) > 0
    kept, after = vessel_volume(mesh, 2)
    assert kept == pytest.approx(vessel, rel=1e-12)
    assert after < total - 0.5
    # Unprotected, the same sweep takes part of the vessel: the check above can fail.
    open_mesh = vessel_box()
    assert all(r.ok for r in tetcut.Cutter(open_mesh, tool_diameter=1.2).sweep((0.4, 2.0, 2.9), (3.6, 2.0, 2.9), 0.4))
    assert vessel_volume(open_mesh, 2)[0] < vessel - 0.05


def test_keep_labels_needs_labels():
    points, tets = box_arrays(2, 1.0)
    with pytest.raises(ValueError, match="no labels"):
        tetcut.Cutter(tetcut.Mesh(points, tets), tool_diameter=0.5, keep_labels=[2])


def test_keep_labels_names_a_label_no_tet_has():
    # A typo in keep_labels would protect nothing while looking like a protection.
    mesh = vessel_box()
    with pytest.raises(ValueError) as e:
        tetcut.Cutter(mesh, tool_diameter=1.2, keep_labels=[2, 7])
    assert "keep_labels: no tet is labelled 7 (the mesh's labels: 1, 2)" in str(e.value)
    with pytest.raises(TypeError, match="keep_labels: expected a sequence of labels"):
        tetcut.Cutter(mesh, tool_diameter=1.2, keep_labels=[-2])
    reports = tetcut.Cutter(mesh, tool_diameter=1.2, keep_labels=np.array([2])).sweep((0.4, 2.0, 2.9), (3.6, 2.0, 2.9), 0.4)
    assert sum(r.uncuttable_in_tool for r in reports) > 0  # a numpy array of labels works as well


def test_undo_gives_the_tets_back_their_labels(regions):
    before = regions.labels.copy()
    cutter = tetcut.Cutter(regions, tool_diameter=1.5, undo_history=3)
    for centre in [(1.5, 2.0, 4.0), (5.0, 5.0, 5.0), (2.5, 2.0, 4.0)]:  # the middle one misses the box
        cutter.cut(centre)
    assert cutter.undo_depth == 2
    cutter.undo()
    assert_labels_follow_the_sides(regions)
    cutter.undo()
    np.testing.assert_array_equal(regions.labels, before)
    assert_labels_follow_the_sides(regions)


def test_labels_are_read_during_another_threads_sweep_never_refused():
    # mesh.labels reads the labels each change published with the tets (published_mesh.hpp), as
    # mesh.tets does: a read during a sweep in another thread gives the labels before the sweep or
    # after it, rows as mesh.tets then, and is never refused.
    liver = tetcut.read(str(CORPUS / "liver.msh"))
    points, tets = liver.points, liver.tets
    halves = np.where(points[tets].mean(axis=1)[:, 1] < np.median(points[:, 1]), 3, 7)
    for attempt in range(5):
        mesh = tetcut.Mesh(points, tets, labels=halves)
        before = mesh.labels
        reports, reads, seen_busy = read_during_sweep(mesh, lambda m: m.labels)  # the reads never raise
        after = mesh.labels
        assert len(reports) == 141 and not np.array_equal(before, after)
        assert set(after.tolist()) == {3, 7}
        assert all(np.array_equal(r, before) or np.array_equal(r, after) for r in reads)
        if seen_busy:
            break
    assert seen_busy and reads

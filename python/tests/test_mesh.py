"""tetcut.read, tetcut.Mesh, its arrays, slot views, attributes and files; bad input raising."""
import copy
import pickle
import subprocess

import numpy as np
import pytest

import tetcut
from conftest import CORPUS, box_arrays


def test_mesh_from_arrays_copies_and_gives_them_back():
    points, tets = box_arrays(2)
    mesh = tetcut.Mesh(points, tets)
    assert mesh.num_tets == len(tets) == 48
    assert mesh.num_vertices == len(points)
    np.testing.assert_array_equal(mesh.points, points)
    np.testing.assert_array_equal(mesh.tets, tets)
    np.testing.assert_array_equal(mesh.tet_ids, np.arange(len(tets)))
    np.testing.assert_array_equal(mesh.vertex_ids, np.arange(len(points)))
    points[0] = 99.0  # a copy was taken
    assert mesh.points[0, 0] == 0.0
    assert mesh.points.dtype == np.float64 and mesh.tets.dtype == np.int64
    assert mesh.volume() == pytest.approx(1.0)


def test_mesh_accepts_any_array_like():
    points, tets = box_arrays(1)
    mesh = tetcut.Mesh(points.tolist(), tets.astype(np.uint32).tolist())
    assert mesh.hash() == tetcut.Mesh(points.astype(np.float32), tets.astype(np.int16)).hash()


@pytest.mark.parametrize("points, tets, error, words", [
    (np.zeros((4, 2)), [[0, 1, 2, 3]], ValueError, "points: expected an array of shape (#V, 3), got shape (4, 2)"),
    (np.zeros(12), [[0, 1, 2, 3]], ValueError, "got shape (12,)"),
    (np.eye(4)[:, :3], [[0, 1, 2]], ValueError, "tets: expected an array of shape (#T, 4), got shape (1, 3)"),
    (np.eye(4)[:, :3], [[0.0, 1.0, 2.0, 3.0]], TypeError, "tets: expected integer vertex indices, got dtype float64"),
    (np.array([["a", "b", "c"]]), [[0, 1, 2, 3]], TypeError, "points: expected real numbers"),
    (np.eye(4)[:, :3], np.zeros((0, 4), int), ValueError, "tets: no tetrahedra"),
    (np.eye(4)[:, :3], [[0, 1, -2, 3]], ValueError, "tets: negative vertex index -2 in row 0"),
    (np.eye(4)[:, :3], [[0, 1, 2, 2**40]], ValueError, "is out of range"),
    (np.eye(4)[:, :3], [[0, 1, 2, 7]], ValueError, "not a valid manifold mesh"),
])
def test_bad_arrays_raise_naming_the_argument(points, tets, error, words):
    with pytest.raises(error) as e:
        tetcut.Mesh(points, tets)
    assert words in str(e.value)


def test_nan_and_inverted_tets_are_refused_by_the_builder():
    points, tets = box_arrays(1)
    bad = points.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match="not a valid manifold mesh: .*(finite|NaN)"):
        tetcut.Mesh(bad, tets)
    inverted = tets.copy()
    inverted[0, [0, 1]] = inverted[0, [1, 0]]
    with pytest.raises(ValueError, match="not a valid manifold mesh"):
        tetcut.Mesh(points, inverted)


def test_read_errors_are_the_clis_line(tmp_path, cli):
    broken = tmp_path / "broken.msh"
    broken.write_text("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\nnot a node\n$EndNodes\n")
    for path in [broken, tmp_path / "missing.vtu"]:
        run = subprocess.run([cli, "check", str(path)], capture_output=True, text=True)
        assert run.returncode == 2
        with pytest.raises(ValueError) as e:
            tetcut.read(str(path))
        assert str(e.value) == run.stderr.strip().splitlines()[-1]
        assert str(path) in str(e.value)


def test_write_then_read_gives_the_same_mesh(tmp_path, box):
    for name, options in [("m.msh", {}), ("m.vtu", {"binary": True, "compression": "zlib"}), ("m.vtk", {}),
                          ("m.mesh", {})]:
        box.write(str(tmp_path / name), **options)
        again = tetcut.read(str(tmp_path / name))
        assert again.hash() == box.hash()
        np.testing.assert_array_equal(again.tets, box.tets)
    with pytest.raises(ValueError, match="compression"):
        box.write(str(tmp_path / "x.vtu"), compression="gzip")
    with pytest.raises(ValueError):
        box.write(str(tmp_path / "no-such-folder" / "x.vtu"))


def test_hash_is_the_clis(cli):
    path = CORPUS / "cylinder.msh"
    run = subprocess.run([cli, "info", str(path)], capture_output=True, text=True, check=True)
    assert f"{tetcut.read(str(path)).hash()}" in run.stdout


def test_surface_is_closed_and_outward(box):
    faces = box.surface()
    assert faces.shape == (6 * 4 * 4 * 2, 3)
    p = box.points[faces]
    normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    centre = box.points.mean(axis=0)
    assert np.all(np.einsum("ij,ij->i", normals, p.mean(axis=1) - centre) > 0)


def test_slot_views_lock_the_mesh_until_deleted(box):
    cutter = tetcut.Cutter(box, tool_diameter=1.5)
    slots = box.slot_tets
    assert not slots.flags.writeable
    np.testing.assert_array_equal(slots[box.live_tet_mask].astype(np.int64), box.tets)
    points = box.slot_points[1:]  # a view of the view keeps the lock
    del slots
    with pytest.raises(RuntimeError, match="slot view"):
        cutter.cut((2, 2, 4))
    with pytest.raises(RuntimeError, match="slot view"):
        box.compact()
    del points
    assert cutter.cut((2, 2, 4)).tets_removed > 0
    live = box.live_tet_mask
    assert live.sum() == box.num_tets and not live.all()  # tombstones
    np.testing.assert_array_equal(np.flatnonzero(live), box.tet_ids)
    np.testing.assert_array_equal(np.flatnonzero(box.live_vertex_mask), box.vertex_ids)


def morton_keys(points, lo, extent):
    """The Morton key of each point, 21 bits a coordinate (x lowest), as the engine's compact()
    sorts by: computed here bit by bit, independently of the engine's code."""
    cells = np.clip((points - lo) / extent * 2097151.0, 0, 2097151.0).astype(np.uint64)
    keys = np.zeros(len(points), dtype=np.uint64)
    for bit in range(21):
        for axis in range(3):
            keys |= ((cells[:, axis] >> np.uint64(bit)) & np.uint64(1)) << np.uint64(3 * bit + axis)
    return keys


def test_compact_renumbers_and_cutters_follow(box):
    cutter = tetcut.Cutter(box, tool_diameter=1.5)
    cutter.cut((0, 0, 0))
    before = box.hash()
    old_ids = box.tet_ids
    tet_map, vert_map = box.compact(order="kept")
    assert box.hash() == before
    np.testing.assert_array_equal(tet_map[old_ids], np.arange(box.num_tets))  # the relative order kept
    np.testing.assert_array_equal(box.tet_ids, np.arange(box.num_tets))
    assert (tet_map == -1).sum() == len(tet_map) - box.num_tets
    assert cutter.cut((4, 4, 4)).ok
    assert tetcut.check(box) == []
    with pytest.raises(ValueError, match="order must be 'curve' or 'kept'"):
        box.compact(order="hilbert")


def test_compact_numbers_ids_along_the_curve_by_default(box):
    cutter = tetcut.Cutter(box, tool_diameter=1.5)
    cutter.cut((2, 2, 4))
    before = box.hash()
    old_tet_ids, old_tets = box.tet_ids, box.tets
    old_vertex_ids, old_points = box.vertex_ids, box.points
    tet_map, vert_map = box.compact()
    assert box.hash() == before
    # Each tet and vertex is the one it was, under its new id.
    np.testing.assert_array_equal(box.points[vert_map[old_vertex_ids]], old_points)
    np.testing.assert_array_equal(box.tets[tet_map[old_tet_ids]], vert_map[old_tets])
    # The new ids run along the curve of the live vertices' box; equal keys keep the old order.
    points = box.points
    lo = points.min(axis=0)
    extent = (points.max(axis=0) - lo).max()
    centroids = 0.25 * (points[box.tets[:, 0]] + points[box.tets[:, 1]] + points[box.tets[:, 2]] + points[box.tets[:, 3]])
    for keys, old_to_new, old_ids in [(morton_keys(points, lo, extent), vert_map, old_vertex_ids),
                                      (morton_keys(centroids, lo, extent), tet_map, old_tet_ids)]:
        assert (keys[1:] >= keys[:-1]).all() and len(np.unique(keys)) > len(keys) // 2
        new_to_old = np.empty(len(keys), dtype=np.int64)
        new_to_old[old_to_new[old_ids]] = old_ids
        ties = keys[1:] == keys[:-1]
        assert (new_to_old[1:][ties] > new_to_old[:-1][ties]).all()
    assert not np.array_equal(tet_map[old_tet_ids], np.arange(box.num_tets))  # not the old order here
    assert cutter.cut((0, 0, 0)).ok
    assert tetcut.check(box) == []


def test_attributes_follow_the_cut(box):
    assert box.attribute_names == []
    box.set_vertex_attribute("temperature", 2.0 * box.points[:, 0])
    box.set_vertex_attribute("texcoord", box.points[:, :2])
    assert box.attribute_names == ["temperature", "texcoord"]
    tetcut.Cutter(box, tool_diameter=1.5).cut((2, 2, 4.1))
    # Edge splits interpolate every channel linearly: a linear field stays the same function.
    np.testing.assert_allclose(box.vertex_attribute("temperature"), 2.0 * box.points[:, 0], atol=1e-12)
    np.testing.assert_allclose(box.vertex_attribute("texcoord"), box.points[:, :2], atol=1e-12)
    with pytest.raises(KeyError):
        box.vertex_attribute("pressure")
    with pytest.raises(ValueError, match="another width"):
        box.set_vertex_attribute("texcoord", box.points)
    with pytest.raises(ValueError, match="expected shape"):
        box.set_vertex_attribute("x", np.zeros(3))
    with pytest.raises(TypeError):
        box.set_vertex_attribute("x", np.array(["a"] * box.num_vertices))


def test_read_the_bundled_liver(liver):
    assert liver.num_tets > 1000
    assert repr(liver).startswith("<tetcut.Mesh ")


def test_compact_gives_minus_one_for_removed_ids_as_int64(box):
    cutter = tetcut.Cutter(box, tool_diameter=1.5)
    for centre in [(2, 2, 4), (2, 2, 0), (3.5, 3.5, 3.5)]:  # the last frees the corner vertex
        assert cutter.cut(centre).tets_removed > 0
    live_tets, live_vertices = box.live_tet_mask, box.live_vertex_mask
    assert not live_tets.all() and not live_vertices.all()  # tombstones to compact away
    tet_map, vert_map = box.compact()
    for old_to_new, live in [(tet_map, live_tets), (vert_map, live_vertices)]:
        assert old_to_new.dtype == np.int64
        np.testing.assert_array_equal(old_to_new < 0, ~live)
        assert set(old_to_new[~live].tolist()) == {-1}  # not 4294967295
        np.testing.assert_array_equal(np.sort(old_to_new[old_to_new >= 0]), np.arange(live.sum()))


def test_every_index_array_is_int64_but_the_slot_views(box):
    tetcut.Cutter(box, tool_diameter=1.5).cut((2, 2, 4))
    report = tetcut.Cutter(box, tool_diameter=1.5).cut((2, 2, 3))
    arrays = [box.tets, box.tet_ids, box.vertex_ids, box.surface(), *box.compact()]
    arrays += [getattr(report.changes, n) for n in ["removed", "created", "parent", "parents", "parents_offsets",
                                                    "new_vertices", "new_vertex_edges", "new_vertex_from", "removed_vertices",
                                                    "moved_vertices", "moved_vertex_from"]]
    assert all(a.dtype == np.int64 for a in arrays)
    tetcut.Cutter(box, tool_diameter=1.5).cut((0, 4, 4))
    slots = box.slot_tets
    assert slots.dtype == np.uint32
    dead = ~box.live_tet_mask
    assert dead.any() and (slots[dead, 0] == 0xFFFFFFFF).all() and "0xFFFFFFFF" in type(box).slot_tets.__doc__


def test_points_no_tet_uses_are_refused_unless_dropped():
    points, tets = box_arrays(1)
    extra = np.vstack([points, [[5.0, 5.0, 5.0]], points[:1] + 9.0])
    with pytest.raises(ValueError) as e:
        tetcut.Mesh(extra, tets)
    assert "points: 2 of 10 points are used by no tet (rows 8, 9)" in str(e.value)
    assert "drop_unused_points=True" in str(e.value)
    mesh = tetcut.Mesh(extra, tets, drop_unused_points=True)
    assert mesh.num_vertices == 8
    np.testing.assert_array_equal(mesh.vertex_ids, np.arange(8))  # each row's row in the points given
    np.testing.assert_array_equal(mesh.points, extra[mesh.vertex_ids])


def test_reading_a_file_with_points_no_tet_uses_says_so(tmp_path):
    (tmp_path / "extra.msh").write_text(
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 7 7 7\n$EndNodes\n"
        "$Elements\n1\n1 4 2 1 1 1 2 3 4\n$EndElements\n")
    with pytest.warns(UserWarning, match="1 of 5 points are used by no tet"):
        mesh = tetcut.read(str(tmp_path / "extra.msh"))
    assert mesh.num_vertices == 4


def test_a_copy_is_the_same_mesh_and_shares_nothing(tmp_path):
    points, tets = box_arrays(4, 4.0)
    mesh = tetcut.Mesh(points, tets, labels=np.where(points[tets].mean(axis=1)[:, 0] < 2, 3, 7))
    mesh.set_vertex_attribute("t", mesh.points[:, 0])
    tetcut.Cutter(mesh, tool_diameter=1.5).cut((2, 2, 4))
    for other in [mesh.copy(), copy.copy(mesh), copy.deepcopy(mesh)]:
        assert other is not mesh and other.hash() == mesh.hash()
        np.testing.assert_array_equal(other.tet_ids, mesh.tet_ids)  # the same ids, tombstones and all
        np.testing.assert_array_equal(other.labels, mesh.labels)
        np.testing.assert_array_equal(other.vertex_attribute("t"), mesh.vertex_attribute("t"))
    twin = mesh.copy()
    assert tetcut.Cutter(twin, tool_diameter=1.5).cut((2, 2, 0)).tets_removed > 0
    assert twin.hash() != mesh.hash()
    assert tetcut.check(twin) == [] and tetcut.check(mesh) == []


def test_a_pickled_mesh_comes_back_compacted_with_labels_and_attributes():
    points, tets = box_arrays(4, 4.0)
    mesh = tetcut.Mesh(points, tets, labels=np.where(points[tets].mean(axis=1)[:, 0] < 2, 3, 7))
    mesh.set_vertex_attribute("scalar", mesh.points[:, 2])
    mesh.set_vertex_attribute("column", mesh.points[:, :1])
    mesh.set_vertex_attribute("uv", mesh.points[:, :2])
    tetcut.Cutter(mesh, tool_diameter=1.5).cut((2, 2, 4))
    again = pickle.loads(pickle.dumps(mesh))
    assert again.hash() == mesh.hash()
    np.testing.assert_array_equal(again.points, mesh.points)
    np.testing.assert_array_equal(again.tets, mesh.tets)
    np.testing.assert_array_equal(again.labels, mesh.labels)
    np.testing.assert_array_equal(again.tet_ids, np.arange(mesh.num_tets))  # dense ids, as compact(order="kept") gives
    for name in ["scalar", "column", "uv"]:
        np.testing.assert_array_equal(again.vertex_attribute(name), mesh.vertex_attribute(name))
    assert tetcut.Cutter(again, tool_diameter=1.5).cut((2, 2, 3)).ok
    with pytest.raises(ValueError, match="not a pickled tetcut.Mesh"):
        tetcut.Mesh.__new__(tetcut.Mesh).__setstate__((2, None, None, None, {}))


def test_attributes_come_back_in_the_shape_given_as_meshio_gives_them(box):
    box.set_vertex_attribute("scalar", box.points[:, 0])
    box.set_vertex_attribute("column", box.points[:, :1])
    box.set_vertex_attribute("uv", box.points[:, :2])
    assert box.vertex_attribute("scalar").shape == (box.num_vertices,)
    assert box.vertex_attribute("column").shape == (box.num_vertices, 1)
    assert box.vertex_attribute("uv").shape == (box.num_vertices, 2)
    box.set_vertex_attribute("column", box.points[:, 1])  # set again 1-D: 1-D from now on
    assert box.vertex_attribute("column").shape == (box.num_vertices,)
    tetcut.Cutter(box, tool_diameter=1.5).cut((2, 2, 4.1))  # new vertices, same shapes
    assert box.vertex_attribute("scalar").shape == (box.num_vertices,)
    np.testing.assert_allclose(box.vertex_attribute("scalar"), box.points[:, 0], atol=1e-12)

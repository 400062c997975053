"""tetcut.Cutter: cuts, sweeps, the report and its changes, the GIL, tetcut.stats and tetcut.check."""
import json
import pickle
import re
import subprocess

import numpy as np
import pytest

import tetcut
from conftest import CORPUS, PLATE_CUT, README_DIAMETER, README_SWEEP, box_arrays, plate_arrays, read_during_sweep


def test_the_readme_sweep_gives_the_hash_tetcut_cut_prints(cli, tmp_path):
    liver = str(CORPUS / "liver.msh")
    s, e, step = README_SWEEP["start"], README_SWEEP["end"], README_SWEEP["step"]
    run = subprocess.run([cli, "cut", liver, "--diameter", str(README_DIAMETER), "--from", ",".join(map(str, s)),
                          "--to", ",".join(map(str, e)), "--step", str(step)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    expected = re.search(r"^hash ([0-9a-f]{16})$", run.stdout, re.M).group(1)
    mesh = tetcut.read(liver)
    reports = tetcut.Cutter(mesh, tool_diameter=README_DIAMETER).sweep(**README_SWEEP)
    assert len(reports) == 36 and all(r.ok for r in reports)
    assert mesh.hash() == expected
    # The same cuts one by one from Python: the same mesh.
    again = tetcut.read(liver)
    cutter = tetcut.Cutter(again, tool_diameter=README_DIAMETER)
    for r in reports:
        assert cutter.cut(r.centre).tets_removed == r.tets_removed
    assert again.hash() == expected


def test_report_fields_and_changes_agree_with_the_mesh(box):
    cutter = tetcut.Cutter(box, tool_diameter=1.5, strategy="combined")
    live_before = set(box.tet_ids)
    verts_before = set(box.vertex_ids)
    report = cutter.cut(np.array([2.0, 2.0, 4.0]))
    assert report.ok and report.failure == ""
    assert report.tets_removed > 0 and report.tets_hit > 0 and report.quality_met
    assert report.d_ref == pytest.approx(1.5 * 1.5)
    assert report.time_us["total"] > 0 and report.wall_us >= report.time_us["total"] * 0.5
    assert list(report.centre) == [2.0, 2.0, 4.0]
    c = report.changes
    assert c is report.changes  # built once
    live_after = set(box.tet_ids)
    assert set(c.removed) == live_before - live_after
    assert set(c.created) == live_after - live_before
    assert len(c.parent) == len(c.created) == len(c.parents_offsets) - 1
    assert set(c.parent) <= set(c.removed)
    assert set(c.parents) <= set(c.removed)
    assert c.parents_offsets[-1] == len(c.parents)
    assert set(c.new_vertices) == set(box.vertex_ids) - verts_before
    on_edge = c.new_vertex_edges[:, 0] >= 0
    assert set(c.new_vertex_edges[on_edge].ravel()) <= verts_before
    np.testing.assert_allclose(c.new_vertex_weights.sum(axis=1), 1.0)
    # Positions of new vertices: the convex combination of old ones the log says.
    rows = {v: i for i, v in enumerate(box.vertex_ids)}
    slot = dict(zip(box.vertex_ids, box.points))
    for v, frm, w in zip(c.new_vertices, c.new_vertex_from, c.new_vertex_weights):
        if frm[0] >= 0 and all(f in rows for f in frm if f >= 0):
            expected = sum(wk * slot[f] for f, wk in zip(frm, w) if f >= 0)
            np.testing.assert_allclose(slot[v], expected, atol=1e-9)
    assert set(c.removed_vertices) == verts_before - set(box.vertex_ids)
    assert "removed" in repr(report)
    assert tetcut.check(box) == []


def test_moved_vertices_are_where_their_weights_on_the_old_points_put_them():
    # Small tools on the cylinder (about 0.4 of its median edge): the improvement pass moves a
    # few vertices that were there before, within the cut's reach.
    mesh = tetcut.read(str(CORPUS / "cylinder.msh"))
    cutter = tetcut.Cutter(mesh, tool_diameter=0.2)
    moved = 0
    for centre in np.linspace((0.0, -0.8, 0.5), (0.0, 0.8, 3.5), 52):
        before = dict(zip(mesh.vertex_ids, mesh.points))
        report = cutter.cut(tuple(centre))
        assert report.ok
        c = report.changes
        assert len(c.moved_vertices) == report.vertices_moved
        assert list(c.moved_vertices) == sorted(c.moved_vertices)
        after = dict(zip(mesh.vertex_ids, mesh.points))
        for v, frm, w, was in zip(c.moved_vertices, c.moved_vertex_from, c.moved_vertex_weights, c.moved_vertex_before):
            np.testing.assert_array_equal(was, before[v])
            assert not np.array_equal(after[v], before[v])
            np.testing.assert_allclose(w.sum(), 1.0)
            np.testing.assert_allclose(after[v], sum(wk * before[f] for f, wk in zip(frm, w) if f >= 0), atol=1e-12)
            moved += 1
        assert set(c.moved_vertices) <= set(after)
    assert moved > 0, "no cut moved a vertex there before: the test tests nothing"


def test_a_cut_in_the_air_changes_nothing(box):
    before = box.hash()
    r = tetcut.Cutter(box, tool_diameter=1.0).cut((50, 50, 50))
    assert r.ok and r.tets_removed == 0 and len(r.changes.removed) == 0
    assert box.hash() == before


def test_bad_parameters_raise_naming_the_keyword(box):
    for kwargs, words in [({"tool_diameter": -1}, "tool_diameter=-1: tool diameter must be a positive"),
                          ({"tool_diameter": float("nan")}, "tool_diameter=nan: tool diameter"),
                          ({"strategy": "greedy"}, "strategy: basic, neighbours, combined or wide, not 'greedy'"),
                          ({"split": "halves"}, "split: templates or bisection"), ({"order": "random"}, "order: direct-first, surface-first-by-id (or paper, its old name) or revisit, not 'random'"),
                          ({"neighbour_set": "largest"}, "neighbour_set: smallest or first, not 'largest'"),
                          ({"quality_floor": 2.0}, "quality_floor=2.0: the quality floor"),
                          ({"d_ref_factor": 0}, "d_ref_factor=0: D_ref factor"), ({"p": 1.0}, "p=1.0: p must"),
                          ({"search_depth": 65}, "search_depth=65: search depth must be between 1 and 64"),
                          ({"search_depth": -1}, "search_depth=-1: expected a non-negative integer"),
                          ({"max_tets_created": 2**40}, "max_tets_created=1099511627776")]:
        with pytest.raises(ValueError) as e:
            tetcut.Cutter(box, **{"tool_diameter": 1.0, **kwargs})
        assert words in str(e.value)
    for kwargs, words in [({"tool_diameter": "8"}, "tool_diameter: expected a real number, got str"),
                          ({"search_depth": 2.5}, "search_depth: expected a non-negative integer, got float"),
                          ({"improve": "yes"}, "improve: expected True or False, got str"),
                          ({"strategy": 3}, "strategy: expected a str, got int")]:
        with pytest.raises(TypeError) as e:
            tetcut.Cutter(box, **{"tool_diameter": 1.0, **kwargs})
        assert words in str(e.value)
    assert tetcut.Cutter(box, tool_diameter=1.0, order="paper", improve=False, search_depth=3).cut((2, 2, 4)).ok
    # The paper's readings (docs/usage.md): each order and 3.5 set choice cuts, and "paper" is the
    # old name of surface-first-by-id: the same mesh after the same cut.
    hashes = {}
    for order in ("direct-first", "surface-first-by-id", "paper", "revisit"):
        for neighbour_set in ("smallest", "first"):
            m = box.copy()
            assert tetcut.Cutter(m, tool_diameter=1.0, order=order, neighbour_set=neighbour_set,
                                 improve=False).cut((2, 2, 4)).ok
            hashes[order, neighbour_set] = m.hash()
    assert hashes["paper", "smallest"] == hashes["surface-first-by-id", "smallest"]
    assert hashes["paper", "first"] == hashes["surface-first-by-id", "first"]
    cutter = tetcut.Cutter(box, tool_diameter=1.0)
    with pytest.raises(ValueError, match="finite"):
        cutter.cut((np.nan, 0, 0))
    for bad in [(1, 2), "abc", [[1, 2, 3]], (1, 2, "3"), None]:
        with pytest.raises(TypeError, match="centre: expected 3 real numbers"):
            cutter.cut(bad)
    with pytest.raises(TypeError, match="one argument"):
        cutter.cut()
    with pytest.raises(TypeError, match="one argument"):
        cutter.cut((1, 2, 3), 4)
    with pytest.raises(TypeError, match="one argument"):
        cutter.cut(center=(1, 2, 3))
    with pytest.raises(OverflowError):
        cutter.cut((10**400, 0, 0))
    assert cutter.cut(centre=np.array([50, 50, 50], dtype=np.float32)).ok
    assert cutter.cut([50, 50, 50]).ok and cutter.cut((np.float64(50), 50.0, 50)).ok
    with pytest.raises(ValueError, match="step"):
        cutter.sweep((0, 0, 0), (1, 1, 1), 0.0)
    with pytest.raises(ValueError, match="step: more than 100000 cuts"):
        cutter.sweep((0, 0, 0), (1e6, 0, 0), 1.0)
    with pytest.raises(ValueError):
        cutter.tool_diameter = 0.0
    assert cutter.tool_diameter == 1.0
    cutter.tool_diameter = 2.0
    assert cutter.tool_diameter == 2.0 and cutter.strategy == "combined" and cutter.mesh is box


def test_two_cutters_on_one_mesh_stay_consistent(box):
    a, b = tetcut.Cutter(box, tool_diameter=1.5), tetcut.Cutter(box, tool_diameter=1.5)
    a.cut((2, 2, 4))
    b.cut((2, 2, 3.5))  # b re-indexes: a's cut changed the mesh behind its index
    a.cut((2, 2, 3))
    assert tetcut.check(box, level="full") == []


def live_copies(mesh):
    """points, vertex_ids, tets and tet_ids as the live engine arrays give them (the slot views)."""
    alive_v, alive_t = mesh.live_vertex_mask, mesh.live_tet_mask
    slot_points, slot_tets = mesh.slot_points, mesh.slot_tets
    rows = np.cumsum(alive_v) - 1
    copies = (slot_points[alive_v].copy(), np.flatnonzero(alive_v), rows[slot_tets[alive_t]].astype(np.int64),
              np.flatnonzero(alive_t))
    del slot_points, slot_tets  # the views lock the mesh against the next cut
    return copies


def expect_published_is_live(mesh):
    points, vertex_ids, tets, tet_ids = live_copies(mesh)
    assert np.array_equal(mesh.points, points) and np.array_equal(mesh.vertex_ids, vertex_ids)
    assert np.array_equal(mesh.tets, tets) and np.array_equal(mesh.tet_ids, tet_ids)
    assert (mesh.num_vertices, mesh.num_tets) == (len(points), len(tets))


def test_the_copies_read_the_mesh_each_change_published():
    # The copies read what each change published when it returned (O(changed) a cut), not the
    # engine's arrays: after every kind of change they must equal what those arrays hold.
    liver = tetcut.read(str(CORPUS / "liver.msh"))
    expect_published_is_live(liver)
    cutter = tetcut.Cutter(liver, tool_diameter=README_DIAMETER, undo_history=4)
    s, e = np.array(README_SWEEP["start"]), np.array(README_SWEEP["end"])
    for k in range(6):
        cutter.cut(tuple(s + (e - s) * k / 12))
        expect_published_is_live(liver)
    cutter.cut_segment(tuple(s), tuple(s + (e - s) / 6))
    expect_published_is_live(liver)
    for _ in range(3):
        cutter.undo()
        expect_published_is_live(liver)
    cutter.sweep(**README_SWEEP)
    expect_published_is_live(liver)
    liver.compact()
    expect_published_is_live(liver)
    expect_published_is_live(liver.copy())
    expect_published_is_live(pickle.loads(pickle.dumps(liver)))


def test_the_cut_releases_the_gil_and_the_copies_never_wait():
    # Were the GIL held, this thread could not run while the sweep does. It reads mesh.points all
    # along, never refused: each read is the mesh before the sweep or after it (a sweep publishes
    # when it returns). mesh.surface() reads the live mesh, so the sweep holding it refuses it:
    # proof that the reads ran during the sweep. A sweep lasts milliseconds: a few attempts make
    # a busy machine's scheduling moot.
    for attempt in range(5):
        liver = tetcut.read(str(CORPUS / "liver.msh"))
        before = liver.points
        reports, reads, seen_busy = read_during_sweep(liver, lambda m: m.points)  # the reads never raise
        assert len(reports) == 141 and tetcut.check(liver) == []
        after = liver.points
        assert all(np.array_equal(r, before) or np.array_equal(r, after) for r in reads)
        if seen_busy:
            break
    assert seen_busy and "in use by a cut in another thread" in seen_busy[0]
    assert len(reads) > 0


def test_stats_are_the_papers_tables_of_the_requests(liver):
    cutter = tetcut.Cutter(liver, tool_diameter=README_DIAMETER)
    reports = cutter.sweep(**README_SWEEP)
    s = tetcut.stats(cutter)
    assert set(s) == {"removal", "table1", "table2"}
    assert s["removal"]["tets_removed"] >= sum(r.requests for r in reports) > 0
    # Table 1 is over the requested tets with a face on the surface, as the paper's title says.
    assert s["table1"]["all_operations"] == s["removal"]["requested"]
    assert 0 < s["table1"]["operations"] == s["removal"]["surface_requested"] <= s["removal"]["requested"]
    assert s["table1"]["removable_pct"] == pytest.approx(
        100.0 * s["removal"]["surface_direct"] / s["removal"]["surface_requested"])
    assert s["table2"]["combined_unresolved_pct"] == 0.0


def test_check_levels_and_violations(box):
    assert tetcut.check(box, level="local") == tetcut.check(box, level="exact") == []
    violations = tetcut.check(box, radius_ratio_floor=0.99)
    assert [v.id for v in violations] == ["I7"]
    v = violations[0]
    assert v.count > 0 and 0 < len(v.tets) <= 8 and v.detail and "quality" in v.name
    assert set(v.tets) <= set(box.tet_ids)
    assert repr(v).startswith("I7 ")
    with pytest.raises(ValueError, match="local, full or exact"):
        tetcut.check(box, level="strict")


def test_misuse_raises_instead_of_crashing(box):
    half_made_mesh = tetcut.Mesh.__new__(tetcut.Mesh)  # __init__ never ran
    for use in [lambda: half_made_mesh.points, lambda: half_made_mesh.num_tets, lambda: half_made_mesh.hash(),
                lambda: tetcut.check(half_made_mesh), lambda: tetcut.Cutter(half_made_mesh)]:
        with pytest.raises((TypeError, RuntimeError)):
            use()
    half_made_cutter = tetcut.Cutter.__new__(tetcut.Cutter)
    for use in [lambda: half_made_cutter.cut((0, 0, 0)), lambda: half_made_cutter.sweep((0, 0, 0), (1, 1, 1), 1),
                lambda: half_made_cutter.cut_segment((0, 0, 0), (1, 1, 1)),
                lambda: half_made_cutter.tool_diameter, lambda: tetcut.stats(half_made_cutter)]:
        with pytest.raises((TypeError, RuntimeError)):
            use()
    for none_use in [lambda: tetcut.Cutter(None), lambda: tetcut.check(None), lambda: tetcut.stats(None),
                     lambda: tetcut.Cutter.cut(box, (0, 0, 0)), lambda: tetcut.Cutter.cut_segment(box, (0, 0, 0), (1, 1, 1))]:
        with pytest.raises(TypeError):
            none_use()
    for cls in [tetcut.CutReport, tetcut.Changes, tetcut.Violation]:
        with pytest.raises(TypeError, match="made by tetcut"):
            cls()
        with pytest.raises(TypeError):
            cls.__new__(cls)


def test_the_tool_diameter_is_required_and_keywords_are_named(box):
    # No default: the engine's 1.0 would be half a liver in metres, a tenth of one in millimetres.
    with pytest.raises(TypeError, match="tool_diameter is required"):
        tetcut.Cutter(box)
    with pytest.raises(TypeError) as e:
        tetcut.Cutter(box, tool_diam=8.0)
    assert "unknown keyword 'tool_diam' (did you mean 'tool_diameter'?)" in str(e.value)
    with pytest.raises(TypeError, match="unknown keyword 'colour'; the keywords: mesh, tool_diameter, strategy"):
        tetcut.Cutter(box, tool_diameter=1.0, colour="red")
    with pytest.raises(TypeError, match="takes the mesh and every parameter by keyword; got 2 positional"):
        tetcut.Cutter(box, 8.0)
    with pytest.raises(TypeError, match="mesh: expected a tetcut.Mesh, got str"):
        tetcut.Cutter("liver.msh", tool_diameter=8.0)
    assert tetcut.Cutter(mesh=box, tool_diameter=8.0).mesh is box


def sweep_cuts_of_the_cli(cli, mesh_path, start, end, step, diameter, tmp_path, *extra):
    report = str(tmp_path / "report.json")
    run = subprocess.run([cli, "cut", mesh_path, "--diameter", str(diameter), "--from", ",".join(map(repr, start)),
                          "--to", ",".join(map(repr, end)), "--step", repr(step), "--report", report, *extra],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    with open(report) as f:
        return json.load(f)


def test_the_sweep_ends_where_the_cli_ends_it_within_a_billionth_of_a_step(cli, tmp_path):
    # 1.4 / 0.05 is 27.999999999999996 in doubles: the end, 28 steps away, is cut too.
    start, end, step = (-0.8, 0.0, -0.2), (0.6, 0.0, -0.2), 0.05
    points, tets = box_arrays(4, 4.0)
    path = str(tmp_path / "box.vtu")
    tetcut.Mesh(points - 2.0, tets).write(path)  # the cube [-2, 2]^3
    mesh = tetcut.read(path)
    reports = tetcut.Cutter(mesh, tool_diameter=0.3).sweep(start, end, step)
    assert len(reports) == 29
    np.testing.assert_allclose(reports[-1].centre, end, atol=1e-12)
    cli_report = sweep_cuts_of_the_cli(cli, path, start, end, step, 0.3, tmp_path)
    assert cli_report["summary"]["cuts"] == 29 and cli_report["summary"]["hash"] == mesh.hash()
    # Half a step short of a whole number: the sweep stops before the end, as before.
    assert len(tetcut.Cutter(tetcut.Mesh(*box_arrays(2)), tool_diameter=0.1).sweep((0, 0, 0), (0.95, 0, 0), 0.1)) == 10


def test_the_report_counts_are_the_clis_and_the_changes_are_net_ids(cli, tmp_path):
    # The README's loop prints report.tets_removed: the counts `tetcut cut --report` gives, cut
    # by cut, every field it reports. report.changes lists net ids instead (a parent the
    # refinement replaced is "removed" though the tool never took it), so its length differs
    # whenever the cut refined.
    liver = str(CORPUS / "liver.msh")
    s, e, step = README_SWEEP["start"], README_SWEEP["end"], README_SWEEP["step"]
    cli_cuts = sweep_cuts_of_the_cli(cli, liver, s, e, step, README_DIAMETER, tmp_path)["cuts"]
    reports = tetcut.Cutter(tetcut.read(liver), tool_diameter=README_DIAMETER).sweep(**README_SWEEP)
    assert len(reports) == len(cli_cuts) == 36
    compared = 0
    for r, c in zip(reports, cli_cuts):
        for key, value in c.items():
            if key in ("index", "line") or key.endswith("_us"):
                continue
            assert getattr(r, key) == (list(value) if key == "centre" else value), key
            compared += 1
    assert compared > 36 * 20
    refined = [r for r in reports if r.tets_refined > 0]
    assert refined and all(len(r.changes.removed) > r.tets_removed for r in refined)


def test_change_arrays_are_read_only_and_the_same_on_every_read(box):
    report = tetcut.Cutter(box, tool_diameter=1.5).cut((2, 2, 4))
    changes = report.changes
    for name in ["removed", "created", "parent", "parents", "parents_offsets", "new_vertices", "new_vertex_edges",
                 "new_vertex_t", "new_vertex_from", "new_vertex_weights", "removed_vertices", "moved_vertices",
                 "moved_vertex_from", "moved_vertex_weights", "moved_vertex_before"]:
        a = getattr(changes, name)
        assert not a.flags.writeable, name
        with pytest.raises(ValueError, match="read-only"):
            a[...] = 0
    removed = changes.removed.copy()
    with pytest.raises(ValueError):
        report.changes.removed.sort()
    np.testing.assert_array_equal(report.changes.removed, removed)
    assert report.changes.removed is changes.removed


def test_pieces_left_in_the_tool_are_reported():
    # The basic strategy's splits (paper 3.4) leave pieces of unselected tets in the tool that
    # their one request does not take (the README's sweep through the coarse liver).
    basic = tetcut.Cutter(tetcut.read(str(CORPUS / "liver-coarse.msh")), tool_diameter=README_DIAMETER, strategy="basic")
    reports = basic.sweep(**README_SWEEP)
    assert sum(r.left_in_tool for r in reports) > 0 and sum(r.kept_pieces_requested for r in reports) > 0
    assert any(r.left_in_tool != r.kept_pieces_requested for r in reports)  # two fields, not one twice
    assert all(r.kept_pieces_requested <= r.requests for r in reports)
    assert any(r.left_in_tool == 0 and r.unresolved == 0 for r in reports)  # and a cut that emptied its tool


def test_a_tool_larger_than_the_organ_empties_it_and_every_function_says_so(tmp_path):
    mesh = tetcut.read(str(CORPUS / "cylinder.msh"))
    report = tetcut.Cutter(mesh, tool_diameter=1000.0).cut((0, 0, 2))
    assert report.ok and mesh.num_tets == 0 and mesh.num_vertices == 0  # ok: it removed what it was asked to
    assert tetcut.check(mesh) == [] and mesh.volume() == 0.0
    assert mesh.points.shape == (0, 3) and mesh.tets.shape == (0, 4) and mesh.surface().shape == (0, 3)
    with pytest.raises(ValueError, match=r"the mesh has no tets .*\(tetcut.read refuses one\)"):
        mesh.write(str(tmp_path / "empty.msh"))
    assert not (tmp_path / "empty.msh").exists()
    # And read refuses what would be one: the two agree.
    (tmp_path / "none.msh").write_text("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n0\n$EndNodes\n$Elements\n0\n$EndElements\n")
    with pytest.raises(ValueError, match="no tetrahedra"):
        tetcut.read(str(tmp_path / "none.msh"))
    again = pickle.loads(pickle.dumps(mesh))
    assert again.num_tets == 0 and again.hash() == mesh.hash() and mesh.copy().num_tets == 0


def test_the_tissue_rule_in_the_report(box):
    # What a cut took is what the mesh lost; what it left in its ball is a share of the ball; the
    # report says which refinement ran, and a refused cut why.
    cutter = tetcut.Cutter(box, tool_diameter=1.5)
    before = box.volume()
    report = cutter.cut((2.0, 2.0, 2.0))
    assert report.ok and report.refusal == "none"
    assert report.volume_removed == pytest.approx(before - box.volume(), rel=1e-9)
    ball = np.pi / 6 * 1.5 ** 3
    assert 0 <= report.volume_left_in_tool <= ball
    assert 0 <= report.volume_removed_beyond_tool <= report.volume_removed
    assert report.tets_removed_beyond_tool <= report.tets_removed + report.tets_removed_by_improvement
    assert report.left_in_tool == 0 and report.tets_removed_beyond_reach == 0
    assert report.refinement == "paper" and report.retries == 0  # auto: this tool is not fine for the box
    assert "finish" in report.time_us
    # A tool much finer than the box's edges: auto takes the graded rule.
    fine = tetcut.Cutter(tetcut.Mesh(*box_arrays(4, 4.0)), tool_diameter=0.1)
    assert fine.cut((2.05, 1.95, 2.1)).refinement == "graded"
    # A budget no cut can keep: refused, named.
    tight = tetcut.Cutter(tetcut.Mesh(*box_arrays(4, 4.0)), tool_diameter=0.1, max_tets_created=10)
    refused = tight.cut((2.05, 1.95, 2.1))
    assert not refused.ok and refused.refusal == "tet budget" and "budget" in refused.failure


def test_the_dihedral_floor_is_a_keyword_and_every_report_keeps_it():
    mesh = tetcut.read(str(CORPUS / "liver.msh"))
    cutter = tetcut.Cutter(mesh, tool_diameter=README_DIAMETER, min_dihedral_deg=15.0)
    reports = cutter.sweep(**README_SWEEP)
    assert all(r.ok for r in reports)
    made = [r for r in reports if r.tets_created > 0]
    assert made, "the sweep creates tets"
    # Each created tet reaches min(15, its host's): the worst over the cut reaches the cut's lowest floor.
    assert all(r.min_dihedral_deg >= r.dihedral_floor_deg - 1e-7 for r in made)
    assert all(r.dihedral_floor_deg <= 15.0 for r in made)
    assert any(r.min_dihedral_deg_before_improvement < r.min_dihedral_deg for r in made)  # the pass lifted angles
    with pytest.raises(ValueError, match="min_dihedral_deg"):
        tetcut.Cutter(mesh, tool_diameter=1.0, min_dihedral_deg=80.0)


def test_cut_segment_cuts_the_capsule_and_records_its_changes_as_cut_does(box):
    a, b = (1.0, 2.0, 4.0), (3.0, 2.0, 4.0)
    ball = tetcut.Cutter(box.copy(), tool_diameter=1.5).cut(a)
    cutter = tetcut.Cutter(box, tool_diameter=1.5)
    live_before, verts_before = set(box.tet_ids), set(box.vertex_ids)
    report = cutter.cut_segment(a, b)
    assert report.ok and report.tets_removed > 0 and report.left_in_tool == 0
    assert list(report.centre) == list(a) and list(report.end) == list(b) and ball.end is None
    assert repr(report).startswith("<tetcut.CutReport from (1, 2, 4) to (3, 2, 4): ok, ")
    # The capsule takes the tissue between its ends, which the ball at one end does not.
    assert report.volume_removed > 2 * ball.volume_removed > 0
    c = report.changes
    assert set(c.removed) == live_before - set(box.tet_ids)
    assert set(c.created) == set(box.tet_ids) - live_before
    assert set(c.new_vertices) == set(box.vertex_ids) - verts_before
    assert set(c.parent) <= set(c.removed)
    assert tetcut.check(box) == []
    # The arguments as cut() reads them: any 3 real numbers, by position or keyword.
    assert cutter.cut_segment(b=(50, 50, 50), a=np.array([50, 50, 51], dtype=np.float32)).ok
    with pytest.raises(TypeError, match="b: expected 3 real numbers"):
        cutter.cut_segment((0, 0, 0), (1, 2))
    with pytest.raises(ValueError, match="a: coordinates must be finite"):
        cutter.cut_segment((np.nan, 0, 0), (0, 0, 0))
    for bad in [lambda: cutter.cut_segment((0, 0, 0)), lambda: cutter.cut_segment((0, 0, 0), (1, 1, 1), (2, 2, 2)),
                lambda: cutter.cut_segment((0, 0, 0), a=(1, 1, 1)), lambda: cutter.cut_segment(a=(0, 0, 0), c=(1, 1, 1))]:
        with pytest.raises(TypeError, match="takes two arguments, a and b"):
            bad()


def test_a_zero_length_cut_segment_is_the_ball_bit_for_bit(box):
    centre = (2.0, 2.0, 4.0)
    other = box.copy()
    ball = tetcut.Cutter(box, tool_diameter=1.5).cut(centre)
    segment = tetcut.Cutter(other, tool_diameter=1.5).cut_segment(centre, centre)
    assert ball.ok and ball.tets_removed > 0
    assert other.hash() == box.hash()
    np.testing.assert_array_equal(other.slot_points, box.slot_points)
    np.testing.assert_array_equal(other.slot_tets, box.slot_tets)
    for name in ("removed", "created", "parent", "new_vertices", "new_vertex_weights", "moved_vertices"):
        np.testing.assert_array_equal(getattr(segment.changes, name), getattr(ball.changes, name))
    assert (segment.tets_removed, segment.tets_created) == (ball.tets_removed, ball.tets_created)
    assert list(segment.end) == list(centre) and ball.end is None


def test_a_swept_sweep_joins_its_centres_by_capsules_as_tetcut_cut_swept(cli, tmp_path):
    # Centres two diameters apart: balls leave tissue between them, capsules take it.
    path = str(CORPUS / "cylinder.msh")
    start, end, step = (-0.8, -0.3, 2.0), (0.8, -0.3, 2.0), 0.4
    balls = tetcut.Cutter(tetcut.read(path), tool_diameter=0.2).sweep(start, end, step)
    mesh = tetcut.read(path)
    capsules = tetcut.Cutter(mesh, tool_diameter=0.2).sweep(start, end, step, swept=True)
    assert len(balls) == 5 and len(capsules) == 4 and all(r.ok for r in balls + capsules)
    for k, r in enumerate(capsules):
        assert r.centre == balls[k].centre and r.end == balls[k + 1].centre
        assert balls[k].end is None
    assert sum(r.volume_removed for r in capsules) > 1.5 * sum(r.volume_removed for r in balls)
    cli_report = sweep_cuts_of_the_cli(cli, path, start, end, step, 0.2, tmp_path, "--swept")
    assert cli_report["summary"]["hash"] == mesh.hash()
    assert [c["end"] for c in cli_report["cuts"]] == [r.end for r in capsules]
    assert [c["tets_removed"] for c in cli_report["cuts"]] == [r.tets_removed for r in capsules]
    # A sweep of one centre is one ball, swept or not.
    one = tetcut.Cutter(tetcut.read(path), tool_diameter=0.2).sweep(start, start, step, swept=True)
    assert len(one) == 1 and one[0].end is None


def face_connected_pieces(mesh):
    """The mesh's face-connected pieces recounted from its arrays: a union-find over the tets
    that share a face, each piece as the set of its tets' engine ids."""
    tets = mesh.tets
    parent = list(range(len(tets)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    first_with = {}
    for t, corners in enumerate(tets):
        for skip in range(4):
            face = tuple(sorted(np.delete(corners, skip)))
            other = first_with.setdefault(face, t)
            if other != t:
                parent[root(t)] = root(other)
    pieces = {}
    for t, tet_id in enumerate(mesh.tet_ids):
        pieces.setdefault(root(t), set()).add(int(tet_id))
    return list(pieces.values())


def volumes_and_centroids(mesh, tet_ids):
    """Each tet's volume and centroid, recounted from the mesh's arrays."""
    rows = np.searchsorted(mesh.tet_ids, tet_ids)  # tet_ids are in id order
    assert (mesh.tet_ids[rows] == tet_ids).all()
    p = mesh.points[mesh.tets[rows]]  # #P by 4 by 3
    volume = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0]) / 6
    return volume, p.mean(axis=1)


def test_a_cut_through_a_plate_detaches_the_piece_numpy_counts_on_the_mesh():
    mesh = tetcut.Mesh(*plate_arrays())
    cutter = tetcut.Cutter(mesh, tool_diameter=0.5)
    assert cutter.pieces == 1 and cutter.last_fragments() == []
    report = cutter.cut_segment(**PLATE_CUT)
    assert report.ok and report.fragments == 1 and not report.fragment_search_bounded
    assert report.fragment_tets_visited >= len(report.detached[0].tets)
    assert (report.debris_pieces_removed, report.debris_tets_removed, report.debris_volume_removed) == (0, 0, 0.0)
    assert cutter.pieces == 2
    [piece] = report.detached
    assert not piece.removed and repr(piece).startswith(f"<tetcut.Fragment {len(piece.tets)} tets, volume ")
    # The mesh's own pieces, recounted: the smaller one is the piece, the organ tet is in the other.
    pieces = sorted(face_connected_pieces(mesh), key=len)
    assert len(pieces) == 2
    assert set(piece.tets.tolist()) == pieces[0] and piece.organ in pieces[1]
    assert piece.tets.dtype == np.int64 and (np.diff(piece.tets) > 0).all()  # sorted ids
    volume, centroids = volumes_and_centroids(mesh, piece.tets)
    assert piece.volume == pytest.approx(volume.sum(), rel=1e-12)
    np.testing.assert_allclose(piece.centroid, (volume[:, None] * centroids).sum(axis=0) / volume.sum(), atol=1e-12)
    # The side x < 0.75 as built (the tool's radius around x = 1), to within the cells the cut took.
    assert piece.volume == pytest.approx(0.75 * 2 * 0.2, rel=0.25) and piece.centroid[0] < 0.75
    # Copies: the Cutter's list is the report's, a new array on each access, and the report keeps its
    # pieces after the next cut, which detaches nothing.
    assert [f.tets.tolist() for f in cutter.last_fragments()] == [piece.tets.tolist()]
    piece.tets[:] = -1
    assert (report.detached[0].tets >= 0).all()
    after = cutter.cut((3.0, 1.0, 0.0))
    assert after.ok and after.tets_removed > 0 and after.fragments == 0 and after.detached == []
    assert cutter.last_fragments() == [] and cutter.pieces == 2
    assert len(report.detached) == 1 and tetcut.check(mesh) == []


def test_debris_volume_removes_the_detached_piece_in_the_same_cut_apart_from_the_tissue():
    points, tets = plate_arrays()
    mesh = tetcut.Mesh(points, tets)
    before = mesh.volume()
    cutter = tetcut.Cutter(mesh, tool_diameter=0.5, debris_volume=0.5)
    report = cutter.cut_segment(**PLATE_CUT)
    assert report.ok and report.fragments == 1 and report.debris_pieces_removed == 1
    [piece] = report.detached
    assert piece.removed and repr(piece).endswith(", removed as debris>")
    assert report.debris_tets_removed == len(piece.tets)
    assert report.debris_volume_removed == pytest.approx(piece.volume)
    assert cutter.pieces == 1 and len(face_connected_pieces(mesh)) == 1
    # Gone, in the cut's change log, and not counted as tissue: the same cut without debris removes
    # the same tissue.
    assert not set(piece.tets.tolist()) & set(mesh.tet_ids.tolist())
    assert set(piece.tets.tolist()) <= set(report.changes.removed.tolist())
    assert mesh.volume() == pytest.approx(before - report.volume_removed - report.debris_volume_removed, rel=1e-12)
    kept = tetcut.Cutter(tetcut.Mesh(points, tets), tool_diameter=0.5).cut_segment(**PLATE_CUT)
    assert (kept.tets_removed, kept.volume_removed) == (report.tets_removed, report.volume_removed)
    assert kept.debris_pieces_removed == 0 and kept.detached[0].volume == pytest.approx(piece.volume)
    assert tetcut.check(mesh) == []
    # A piece above the volume stays, reported.
    large = tetcut.Cutter(tetcut.Mesh(points, tets), tool_diameter=0.5, debris_volume=0.1).cut_segment(**PLATE_CUT)
    assert large.fragments == 1 and large.debris_pieces_removed == 0 and not large.detached[0].removed


def test_the_pieces_parameters_are_keywords_checked_as_the_others_and_a_sweep_keeps_each_cuts_pieces():
    points, tets = plate_arrays()
    mesh = tetcut.Mesh(points, tets)
    with pytest.raises(ValueError, match="debris_volume=-1.0: .*debris volume"):
        tetcut.Cutter(mesh, tool_diameter=0.5, debris_volume=-1.0)
    with pytest.raises(ValueError, match="fragment_search_bound=0: .*fragment search bound"):
        tetcut.Cutter(mesh, tool_diameter=0.5, fragment_search_bound=0)
    with pytest.raises(TypeError, match="debris_volume: expected a real number"):
        tetcut.Cutter(mesh, tool_diameter=0.5, debris_volume="small")
    # A bound below the smaller side: the search stops, reports no piece, and the count stays short.
    bounded = tetcut.Cutter(mesh.copy(), tool_diameter=0.5, fragment_search_bound=10)
    r = bounded.cut_segment(**PLATE_CUT)
    assert r.ok and r.fragment_search_bounded and r.fragments == 0 and bounded.pieces == 1
    # A swept sweep across the plate: the cut that completes the separation reports the piece, the
    # others none, each report its own (copied when its cut returned).
    cutter = tetcut.Cutter(mesh, tool_diameter=0.5, debris_volume=0.5)
    reports = cutter.sweep(PLATE_CUT["a"], PLATE_CUT["b"], 0.65, swept=True)
    assert len(reports) == 4 and all(r.ok for r in reports)
    assert [r.fragments for r in reports].count(1) == 1 and sum(r.fragments for r in reports) == 1
    detaching = next(r for r in reports if r.fragments)
    assert detaching.debris_pieces_removed == 1 and detaching.detached[0].removed
    assert [len(f.tets) for f in cutter.last_fragments()] == [len(f.tets) for f in reports[-1].detached]
    assert cutter.pieces == 1 and tetcut.check(mesh) == []


def test_undo_takes_cuts_back_bit_for_bit_and_says_why_when_it_cannot(box):
    none = box.hash()
    cutter = tetcut.Cutter(box, tool_diameter=1.5, undo_history=2)
    assert cutter.undo_history == 2 and cutter.undo_depth == 0
    with pytest.raises(RuntimeError, match="no cut to undo"):
        cutter.undo()
    a = cutter.cut((1.0, 1.0, 4.0))
    after_a = box.hash()
    b = cutter.cut_segment((3.0, 1.0, 4.0), (3.0, 3.0, 3.5))
    assert a.ok and b.ok and a.tets_removed > 0 and b.tets_removed > 0
    after_b = box.hash()
    assert cutter.undo_depth == 2
    changes = cutter.undo()
    assert changes.undo and not a.changes.undo
    assert box.hash() == after_a and cutter.undo_depth == 1
    # What came back is what b took, under its ids; what went is what b made.
    np.testing.assert_array_equal(changes.created, b.changes.removed)
    np.testing.assert_array_equal(changes.removed, b.changes.created)
    assert tetcut.check(box) == []
    # b again: the same mesh as the first time.
    assert cutter.cut_segment((3.0, 1.0, 4.0), (3.0, 3.0, 3.5)).tets_removed == b.tets_removed
    assert box.hash() == after_b
    cutter.undo()
    cutter.undo()
    assert box.hash() == none and cutter.undo_depth == 0
    with pytest.raises(RuntimeError, match="every cut kept .* was taken back"):
        cutter.undo()
    # Nothing kept by default; a compaction empties the history, and the message says so.
    assert tetcut.Cutter(box, tool_diameter=1.5).undo_history == 0
    cutter.cut((1.0, 1.0, 4.0))
    box.compact()
    with pytest.raises(RuntimeError, match="undo"):
        cutter.undo()
    with pytest.raises(ValueError, match="undo_history"):
        tetcut.Cutter(box, tool_diameter=1.5, undo_history=5000)
    with pytest.raises(ValueError, match="undo_history"):
        cutter.undo_history = 5000

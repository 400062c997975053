"""Property tests (python3-hypothesis): any sequence of cuts keeps the checker clean, and a refused
cut leaves the mesh bit-identical. Few examples, so the suite stays quick."""
import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

import tetcut
from conftest import box_arrays

POINTS, TETS = box_arrays(4, 4.0)

coordinate = st.floats(min_value=-0.5, max_value=4.5, allow_nan=False)
centre = st.tuples(coordinate, coordinate, coordinate)


# derandomize: the same examples on every run (determinism: a red CI run reproduces as it is);
# database=None: nothing written into the tree.
@settings(max_examples=12, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(cuts=st.lists(centre, min_size=1, max_size=6),
       diameter=st.floats(min_value=0.4, max_value=2.5),
       strategy=st.sampled_from(["basic", "neighbours", "combined", "wide"]))
def test_random_cut_sequences_keep_the_mesh_valid(cuts, diameter, strategy):
    mesh = tetcut.Mesh(POINTS, TETS)
    cutter = tetcut.Cutter(mesh, tool_diameter=diameter, strategy=strategy)
    volume = mesh.volume()
    for c in cuts:
        before = mesh.hash()
        report = cutter.cut(c)
        if not report.ok:
            assert mesh.hash() == before  # atomic: refused means untouched
        assert tetcut.check(mesh) == [], (c, report)
        assert mesh.volume() <= volume + 1e-9
        volume = mesh.volume()
        changes = report.changes
        assert len(np.intersect1d(changes.created, mesh.tet_ids)) == len(changes.created)

"""tetcut.check_engine: any engine's adapter (engine.h) under the independent checker, from Python.

The same harness as `tetcut check-engine` (tests/harness/ tests it in depth): here, that the
binding carries its answers, passes and failures alike, and turns a bad adapter into ValueError.
"""
import os

import pytest

import tetcut
from conftest import SOURCE

TETCUT = os.environ.get("TETCUT_ADAPTER_TETCUT")
BLIND = os.environ.get("TETCUT_ADAPTER_BLIND")
pytestmark = pytest.mark.skipif(not TETCUT or not BLIND, reason="run by ctest, which says where the adapters are")

CYLINDER_SCENARIO = str(SOURCE / "corpus" / "scenarios" / "cylinder-cut.scn")
CYLINDER = str(SOURCE / "corpus" / "meshes" / "cylinder.msh")


def test_tetcut_passes_what_blind_removal_breaks():
    [ours] = tetcut.check_engine(TETCUT, scenarios=[CYLINDER_SCENARIO])
    assert ours["ok"] and ours["failed_operation"] is None
    assert ours["run"] == ours["operations"] > 100
    assert ours["singular_vertices"] == ours["singular_edges"] == 0
    [blind] = tetcut.check_engine(BLIND, scenarios=[CYLINDER_SCENARIO])
    assert not blind["ok"]
    assert blind["failed_operation"] >= 1
    assert blind["invariants"][0] in ("I5", "I6")
    assert "cylinder-cut.scn:" in blind["failed_operation_name"]
    assert blind["engine_error"] == "" and blind["signal"] == 0


def test_random_sweeps_one_plan_each():
    plans = tetcut.check_engine(TETCUT, meshes=[CYLINDER], sweeps=2, cuts=5, seed=3)
    assert [p["plan"] for p in plans] == ["sweep cylinder.msh seed 3", "sweep cylinder.msh seed 4"]
    assert all(p["ok"] and p["run"] == 5 for p in plans)


def test_bad_input_is_value_error():
    with pytest.raises(ValueError, match="nonexistent"):
        tetcut.check_engine("/nonexistent/libadapter.so", meshes=[CYLINDER])
    with pytest.raises(ValueError, match="scenarios or meshes"):
        tetcut.check_engine(TETCUT)
    with pytest.raises(ValueError, match="no-such.scn"):
        tetcut.check_engine(TETCUT, scenarios=["no-such.scn"])

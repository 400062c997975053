"""tetcut.from_meshio and Mesh.to_meshio, through meshio's own files (python3-meshio)."""
import meshio
import numpy as np
import pytest

import tetcut
from conftest import CORPUS


def test_to_meshio_and_back_keeps_mesh_and_attributes(box):
    box.set_vertex_attribute("temperature", box.points[:, 2])
    box.set_vertex_attribute("texcoord", box.points[:, :2])
    tetcut.Cutter(box, tool_diameter=1.5).cut((2, 2, 4))
    m = box.to_meshio()
    assert m.cells[0].type == "tetra"
    np.testing.assert_array_equal(m.cells[0].data, box.tets)
    assert m.point_data["temperature"].shape == (box.num_vertices,)
    again = tetcut.from_meshio(m)
    assert again.hash() == box.hash()
    np.testing.assert_array_equal(again.vertex_attribute("texcoord"), box.vertex_attribute("texcoord"))


@pytest.mark.parametrize("name", ["m.vtu", "m.msh", "m.mesh"])
def test_round_trip_through_meshio_files(tmp_path, name):
    liver = tetcut.read(str(CORPUS / "liver.msh"))
    tetcut.Cutter(liver, tool_diameter=8.0).sweep((95, 40, 100), (95, 80, 100), 4.0)
    path = str(tmp_path / name)
    meshio.write(path, liver.to_meshio(), **({"file_format": "gmsh22", "binary": False} if name.endswith("msh") else {}))
    assert tetcut.read(path).hash() == liver.hash()   # meshio's file, tetcut's reader
    liver.write(str(tmp_path / ("t" + name)))
    assert tetcut.from_meshio(meshio.read(str(tmp_path / ("t" + name)))).hash() == liver.hash()  # and back


def test_from_meshio_without_tets_and_with_unused_points():
    tri = meshio.Mesh(np.eye(3), [("triangle", np.array([[0, 1, 2]]))])
    with pytest.raises(ValueError, match="no 'tetra' cells"):
        tetcut.from_meshio(tri)
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [5, 5, 5]], dtype=float)
    m = meshio.Mesh(points, [("tetra", np.array([[0, 1, 2, 3]]))], point_data={"w": np.arange(5.0)})
    with pytest.raises(ValueError, match=r"1 of 5 points are used by no tet \(rows 4\)"):
        tetcut.from_meshio(m)
    mesh = tetcut.from_meshio(m, drop_unused_points=True)
    assert mesh.num_vertices == 4  # the unused point is not a vertex
    np.testing.assert_array_equal(mesh.vertex_attribute("w"), [0, 1, 2, 3])  # 1-D, as meshio gave it

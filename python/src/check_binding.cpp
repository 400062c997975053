// tetcut.check: the independent checker (tetcut::invariants) on a Mesh, its violations as Python
// objects. The checker reads the engine's raw arrays and recomputes every invariant itself, so
// the ids it names are engine ids (slots: mesh.tet_ids / mesh.vertex_ids map rows to them).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "mesh_handle.hpp"
#include "signature_doc.hpp"
#include "tetcut/invariants/check.hpp"

namespace py = pybind11;

namespace tetcut::python {

namespace {

namespace inv = tetcut::invariants;

py::array_t<std::int64_t> int64_array(const std::vector<std::int64_t>& values) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

struct PyViolation {
  std::string id, name, detail;
  std::uint64_t count = 0;
  std::vector<std::int64_t> tets, vertices;
};

inv::CheckLevel level_from(const std::string& s) {
  if (s == "local") return inv::CheckLevel::kLocal;
  if (s == "full") return inv::CheckLevel::kFull;
  if (s == "exact") return inv::CheckLevel::kExact;
  throw py::value_error("tetcut: level: local, full or exact, not '" + s + "'");
}

std::vector<PyViolation> check(const MeshPtr& held, const std::string& level, double radius_ratio_floor) {
  MeshHandle& h = *held;
  inv::CheckOptions options;
  options.level = level_from(level);
  options.radius_ratio_floor = radius_ratio_floor;
  MeshUse use(h);
  inv::CheckReport report;
  {
    py::gil_scoped_release release;
    report = inv::check_mesh(h.mesh.raw_view(), options);
  }
  std::vector<PyViolation> out;
  for (const inv::Violation& v : report.violations) {
    out.push_back({inv::id_string(v.id), inv::description(v.id), v.detail, v.count,
                   std::vector<std::int64_t>(v.tets.begin(), v.tets.end()),
                   std::vector<std::int64_t>(v.vertices.begin(), v.vertices.end())});
  }
  return out;
}

}  // namespace

void bind_check(py::module_& m) {
  py::class_<PyViolation> violation(m, "Violation", "One violated invariant, as tetcut.check() reports it; repr: \"I7 quality: detail\".");
  made_by_the_module_only(violation);
  violation.def_readonly("id", &PyViolation::id, "\"I1\" .. \"I9\" (docs/design.md, invariants).")
      .def_readonly("name", &PyViolation::name, "What it means: \"manifold vertex shells\".")
      .def_readonly("count", &PyViolation::count, "Offending elements in all.")
      .def_property_readonly("tets", [](const PyViolation& v) { return int64_array(v.tets); },
                             "int64: the first offending tets (engine ids, at most 8).")
      .def_property_readonly("vertices", [](const PyViolation& v) { return int64_array(v.vertices); },
                             "int64: the first offending vertices (engine ids, at most 8).")
      .def_readonly("detail", &PyViolation::detail, "One line: the first offence.")
      .def("__repr__", [](const PyViolation& v) { return v.id + " " + v.name + ": " + v.detail; });

  m.def("check", &check, py::arg("mesh").none(false), py::kw_only(), py::arg("level") = "full", py::arg("radius_ratio_floor") = 0.0,
        signature_doc("check", "mesh, *, level='full', radius_ratio_floor=0.0", R"doc(Runs the independent invariant checker and returns the violations (an empty list: valid).

level: "full" (I1-I9, O(#T)), "exact" (full plus the boundary's self-intersection, CGAL) or
"local", which on a whole mesh, with no operation to look around, is the full check (as in the
C++ API). radius_ratio_floor: an absolute I7 floor (0: off). An empty mesh (a cut removed every
tet) is valid. Releases the GIL.)doc").c_str());
}

}  // namespace tetcut::python

// The `tetcut` Python module: the engine, the checker and the change log, numpy in and out.
// Each part is bound in its own file; python/tetcut.pyi is the hand-written stub
// (Debian has no stub generator that keeps docstrings), held to this module by mypy's stubtest.
#include <pybind11/pybind11.h>

#include "mesh_handle.hpp"

PYBIND11_MODULE(tetcut, m) {
  // Every function's docstring starts with its signature in CPython's form (signature_doc.hpp),
  // which inspect.signature() reads; pybind11's own signature line would come before it.
  pybind11::options options;
  options.disable_function_signatures();
  m.doc() = R"doc(tetcut: manifold-preserving tissue removal on tetrahedral meshes (Forest, Delingette, Ayache 2002).

read() or Mesh() a mesh, Cutter() a tool on it, cut() or sweep() it, check() it: numpy in and out.
docs/python.md has the whole API.)doc";
  m.attr("__version__") = TETCUT_VERSION;
  tetcut::python::bind_mesh(m);
  tetcut::python::bind_cutter(m);
  tetcut::python::bind_check(m);
  tetcut::python::bind_engine_check(m);
}

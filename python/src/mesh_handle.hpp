// The Python `tetcut.Mesh`: a TetMesh shared between the Python object and every Cutter on it,
// with what the binding needs to keep Python's promises on top of the engine's:
//
//   - a cut runs with the GIL released (design: the simulator's other threads keep running), so
//     nothing else may touch the mesh meanwhile: every method takes the mesh's Use, and a second
//     user (another thread's cut, mesh.surface()) gets RuntimeError instead of a race; except
//     the copies of the mesh itself (points, vertex_ids, tets, tet_ids, labels, the counts), which
//     read the state each change publishes when it returns (PublishedMesh) and never wait;
//   - several Cutters may share one mesh: each remembers the mesh's version when it last
//     indexed or cut it, and re-indexes (Cutter::reset) when another one has cut since;
//   - slot views (mesh.slot_tets, mesh.slot_points) point into the engine's own arrays, which a
//     cut may grow (reallocate) or rewrite: while one is alive the mesh refuses to change, so a
//     view can never dangle;
//   - per-tet labels (mesh.labels), when the mesh came with them, follow every cut's ChangeLog
//     and every compaction, as `tetcut cut` carries them (MeshLabels below).
#pragma once

#include <pybind11/pybind11.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <span>

#include "tetcut/change_log.hpp"
#include "tetcut/mechanics/tet_labels.hpp"
#include "tetcut/mesh.hpp"
#include "published_mesh.hpp"

namespace tetcut::python {

// A mesh's labels (RawMesh::labels, by TetId): none, one for every tet (a Gmsh file's single
// volume, as every bundled mesh: each tet a cut makes has it too, so cuts pay nothing, as in the
// scenario runner), or several, tracked by mechanics::TetLabels through each cut's ChangeLog.
class MeshLabels {
 public:
  // `labels` by TetId of `mesh` (the builder keeps a file's tet order); empty: unlabelled.
  void set(const TetMesh& mesh, std::span<const std::uint32_t> labels) {
    one_.reset();
    tracked_ = false;
    if (labels.empty()) return;
    bool one = true;
    for (std::uint32_t l : labels) one = one && l == labels[0];
    if (one) {
      one_ = labels[0];
      return;
    }
    tracker_ = mechanics::TetLabels(mesh, labels);
    tracker_.keep_history(history_);
    tracked_ = true;
  }
  // The labels of the tets each of the last `logs` cuts took, for their undo (Cutter.undo()):
  // the most any Cutter on this mesh keeps (its undo_history).
  void keep_history(std::uint32_t logs) {
    history_ = std::max(history_, logs);
    tracker_.keep_history(history_);
  }
  [[nodiscard]] bool labelled() const { return tracked_ || one_.has_value(); }
  // After a cut that succeeded, with its log.
  void apply(const TetMesh& mesh, const ChangeLog& log) {
    if (tracked_) tracker_.apply(mesh, log);
  }
  void renumber(const Renumbering& renumbering) {
    if (tracked_) tracker_.renumber(renumbering);
  }
  [[nodiscard]] std::uint32_t label(TetId t) const { return one_ ? *one_ : tracker_.label(t); }

 private:
  std::optional<std::uint32_t> one_;
  bool tracked_ = false;
  std::uint32_t history_ = 0;
  mechanics::TetLabels tracker_;
};

struct MeshHandle {
  TetMesh mesh;
  MeshLabels labels;
  // mesh as the last change that returned left it: what the copies (points, tets, ...) read, so
  // that a reader is never refused while a cut in another thread runs (published_mesh.hpp).
  PublishedMesh published;
  // Width-1 attribute channels set from a 1-D array: vertex_attribute() gives them back 1-D, as
  // meshio's point_data has them; the others come back #V by width.
  std::set<std::string> flat_attributes;
  std::atomic<bool> in_use{false};
  std::uint64_t version = 0;  // mutations so far (cuts, compactions)
  std::uint32_t slot_views = 0;  // alive slot views; changed with the GIL held
};
using MeshPtr = std::shared_ptr<MeshHandle>;

// Exclusive use of a mesh for one call: taken with the GIL held, kept while the GIL is released.
class MeshUse {
 public:
  explicit MeshUse(MeshHandle& handle) : handle_(handle) {
    if (handle_.in_use.exchange(true)) {
      throw std::runtime_error("tetcut: the mesh is in use by a cut in another thread");
    }
  }
  ~MeshUse() { handle_.in_use.store(false); }
  MeshUse(const MeshUse&) = delete;
  MeshUse& operator=(const MeshUse&) = delete;

 private:
  MeshHandle& handle_;
};

// For the classes only the module makes (CutReport, Changes, Violation, the slot views' lock):
// Python's T.__new__(T) would give an instance with no C++ value behind it, which a method
// would then read. pybind11 makes its instances without tp_new, so refusing it costs nothing.
// (Mesh and Cutter, which Python does make, take their holder in every method instead:
// pybind11 refuses an instance whose __init__ never ran.)
inline void made_by_the_module_only(pybind11::handle cls) {
  reinterpret_cast<PyTypeObject*>(cls.ptr())->tp_new = [](PyTypeObject* type, PyObject*, PyObject*) -> PyObject* {
    PyErr_Format(PyExc_TypeError, "%s objects are made by tetcut, not directly", type->tp_name);
    return nullptr;
  };
}

// Before a mutation: no slot view may be alive (see the top of this file).
void require_no_slot_views(const MeshHandle& handle);

// The bindings, one concept per file (mesh_binding.cpp, cutter_binding.cpp, check_binding.cpp).
void bind_mesh(pybind11::module_& m);
void bind_cutter(pybind11::module_& m);
void bind_check(pybind11::module_& m);
void bind_engine_check(pybind11::module_& m);

}  // namespace tetcut::python

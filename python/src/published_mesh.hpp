// What mesh.points, mesh.vertex_ids, mesh.tets, mesh.tet_ids, mesh.labels and the counts read: the mesh as the
// last change that returned left it, kept beside the live one so that a reader on another Python
// thread never waits for a cut and is never refused (docs/python.md, "Threads").
//
// Why a copy kept current under the GIL rather than the engine's arrays or a SnapshotPublisher: a
// cut runs with the GIL released, rewriting the live arrays, so a reader may not touch them then
// (thread_contract.hpp). Every reader of this copy holds the GIL for its whole read (it builds a
// NumPy array, never releasing it), and a change publishes here only once it has taken the GIL
// back, before it returns to Python: the GIL alone orders the two, so one copy is enough and no
// reader ever sees half a publish. A publish copies the slots the change log names (the tets it
// removed and created, the vertices it created, moved and removed), as they now are in the mesh,
// and the labels of the tets it created: O(what changed), not O(#T). A build, a copy or a
// compaction copies it all. The labels are `Labels` (mesh_handle.hpp's MeshLabels: labelled(),
// label(TetId)), applied to the change before it publishes.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::python {

class PublishedMesh {
 public:
  // All of it: after a build, a copy, a compaction, a change of the labels.
  template <class Labels>
  void publish_all(const TetMesh& mesh, const Labels& labels) {
    resize_to(mesh);
    const auto tets = mesh.raw_tets();
    std::copy(tets.begin(), tets.end(), tets_.begin());
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) copy_vertex(mesh, v);
    labelled_ = labels.labelled();
    if (labelled_)
      for (std::uint32_t t = 0; t < tets.size(); ++t)
        if (tets[t][0] != kDeadTetMarker) labels_[t] = labels.label(TetId{t});
    num_tets_ = mesh.num_tets();
    num_vertices_ = mesh.num_vertices();
  }
  // What `log` changed (a cut's or an undo's net log, already applied to `mesh`). An undo gives
  // the arrays back their length from before the cut, so the slots past the end are gone.
  template <class Labels>
  void publish(const TetMesh& mesh, const Labels& labels, const ChangeLog& log) {
    resize_to(mesh);
    const auto tets = mesh.raw_tets();
    auto tet = [&](TetId t) {
      if (t.value >= tets_.size()) return;
      tets_[t.value] = tets[t.value];
      if (labelled_ && tets[t.value][0] != kDeadTetMarker) labels_[t.value] = labels.label(t);
    };
    auto vertex = [&](VertId v) {
      if (v.value < positions_.size()) copy_vertex(mesh, v.value);
    };
    for (TetId t : log.removed) tet(t);
    for (const CreatedTet& c : log.created) tet(c.tet);
    for (const CreatedVertex& v : log.vertices) vertex(v.vertex);
    for (const MovedVertex& v : log.moved) vertex(v.vertex);
    for (VertId v : log.removed_vertices) vertex(v);
    num_tets_ = mesh.num_tets();
    num_vertices_ = mesh.num_vertices();
  }

  // By slot, as the mesh's own arrays and named as TetMesh names them (a dead tet:
  // kDeadTetMarker in column 0).
  [[nodiscard]] std::span<const std::array<std::uint32_t, 4>> tets() const { return tets_; }
  [[nodiscard]] std::span<const Vec3> positions() const { return positions_; }
  // By slot as tets(); meaningful for a live slot of a labelled mesh only.
  [[nodiscard]] bool labelled() const { return labelled_; }
  [[nodiscard]] std::span<const std::uint32_t> labels() const { return labels_; }
  [[nodiscard]] bool is_live(VertId v) const { return vertex_live_[v.value] != 0; }
  [[nodiscard]] std::uint32_t vertex_capacity() const { return static_cast<std::uint32_t>(positions_.size()); }
  [[nodiscard]] std::uint32_t num_tets() const { return num_tets_; }
  [[nodiscard]] std::uint32_t num_vertices() const { return num_vertices_; }

 private:
  // Slots only grow between compactions; a compaction shrinks them (publish_all). A new slot is
  // dead until the log names it: a tet a cut made and removed again is in no log.
  void resize_to(const TetMesh& mesh) {
    tets_.resize(mesh.raw_tets().size(), {kDeadTetMarker, kDeadTetMarker, kDeadTetMarker, kDeadTetMarker});
    labels_.resize(mesh.raw_tets().size());
    positions_.resize(mesh.vertex_capacity());
    vertex_live_.resize(mesh.vertex_capacity());
  }
  void copy_vertex(const TetMesh& mesh, std::uint32_t v) {
    vertex_live_[v] = mesh.is_live(VertId{v}) ? 1 : 0;
    positions_[v] = mesh.position(VertId{v});
  }

  std::vector<std::array<std::uint32_t, 4>> tets_;
  std::vector<Vec3> positions_;
  std::vector<std::uint8_t> vertex_live_;
  std::vector<std::uint32_t> labels_;
  bool labelled_ = false;
  std::uint32_t num_tets_ = 0, num_vertices_ = 0;
};

}  // namespace tetcut::python

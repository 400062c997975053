// The differential check of the consumers (design: "a differential test compares them with a
// rebuild after every cut"): a TensorMassModel and a RenderedSurface kept up to date from each
// cut's ChangeLog are compared with the same built from scratch on the mesh as it is, and the
// created tets' labels with what geometry alone says they are.
//
//   tensors, masses   |incremental - rebuilt| <= tolerance x scale, entry by entry; the scale of
//                     a tensor is the sum over its tets of their largest |entry| (a vertex's, an
//                     edge's), of a mass the mass. Why a tolerance: a subtraction does not undo
//                     an addition in floating point, so each cut leaves a rounding residue of
//                     about 1e-16 of the largest contribution it touched (a parent before its
//                     split is up to a few times a child's). Measured (worst_relative_error()):
//                     at most 2.5e-15 over the bundled sweeps of consumer_differential_test.cpp.
//                     1e-11 leaves three orders of magnitude for long sequences, and is eight
//                     below a real error: a tet too many or too few at a vertex is of the order
//                     of 1 / (its tets) of the scale.
//   counts, labels    exact: tets per vertex and per edge, the set of edges, surface triangles
//                     (vertex ids and orientation), triangles per vertex, every live tet's label.
//   normals           the running sums as the tensors; the unit normal against the mesh's own
//                     boundary_normal() to 1e-9 x its conditioning (scale / |sum|); and one fan
//                     per surface vertex (its triangles' far edges make one cycle).
//   displacements     the model starts from an affine field u = A X + b (velocities likewise),
//                     which the check also puts in two attribute channels of the mesh: a vertex a
//                     cut creates must get in the model what the engine interpolates in its
//                     channels (attributes.hpp), to 1e-12 of the field's size (the same weights,
//                     summed in another order).
//   labels            the witness keeps the pre-cut tets; a tet that was not there takes the label
//                     of the lowest-id pre-cut tet gone after the cut that contains its centroid
//                     (label_rule.hpp, steps 1 and 2), found by a search of every pre-cut tet, not
//                     through the log. Only a centroid no such tet contains (a smoothing moved
//                     the surface outward: step 3) takes its label from the log's parents, each
//                     checked to be a pre-cut tet the cut took away.
//
// Cost O(#T) per cut (the rebuild, the snapshot, the comparison): tests and fuzzers only.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/mechanics/rendered_surface.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::mechanics {

inline constexpr double kDifferentialTolerance = 1e-11;

// The first difference found, as a sentence naming the entity; nullopt when they agree.
// `worst` (when given) is raised to the largest |difference| / scale met.
std::optional<std::string> compare(const TensorMassModel& incremental, const TensorMassModel& rebuilt,
                                   const TetMesh& mesh, double tolerance, double* worst = nullptr);
std::optional<std::string> compare(const RenderedSurface& incremental, const RenderedSurface& rebuilt,
                                   const TetMesh& mesh, double tolerance, double* worst = nullptr);
// One fan per surface vertex: the far edges of its triangles form a single cycle (O(#triangles)).
std::optional<std::string> fan_problem(const RenderedSurface& surface);

class DifferentialCheck {
 public:
  // `labels` by TetId of `mesh` (empty: all 0); `params.materials` should differ per label for
  // the labels to matter to the tensors.
  // Adds the attribute channels "differential_u" and "differential_v" (width 3) to `mesh`.
  DifferentialCheck(TetMesh& mesh, ModelParams params, std::vector<std::uint32_t> labels,
                    double tolerance = kDifferentialTolerance);

  // Before each cut: the witness's snapshot of the tets (O(#T)).
  void before(const TetMesh& mesh);
  // After it: applies `log` (the cut's, or a corrupted copy) to both consumers, rebuilds both
  // from the mesh, compares. The first problem found, or nullopt.
  std::optional<std::string> after(const TetMesh& mesh, const ChangeLog& log);
  // Undo logs (ChangeLog::undo): the model keeps `logs` cuts' worth of what they took
  // (TensorMassModel::keep_history), and the witness its own snapshot of the tets and labels
  // before each of as many cuts, from which a restored tet must get the label it had then.
  void keep_history(std::uint32_t logs);

  [[nodiscard]] const TensorMassModel& model() const { return model_; }
  [[nodiscard]] const RenderedSurface& surface() const { return surface_; }
  [[nodiscard]] double worst_relative_error() const { return worst_; }

 private:
  [[nodiscard]] Vec3 field_u(const Vec3& x) const;
  [[nodiscard]] Vec3 field_v(const Vec3& x) const;
  // The label of the lowest-id pre-cut tet gone after the cut that contains p; kNoLabel if none.
  [[nodiscard]] std::uint32_t locate_label(const Vec3& p) const;
  // Step 3 for created tet t: the lowest-id parent's label, or a reason the log's parents of t
  // are not pre-cut tets the cut took away.
  [[nodiscard]] std::optional<std::string> label_from_parents(const ChangeLog& log, TetId t,
                                                              std::uint32_t& label) const;

  ModelParams params_;
  double tolerance_;
  TensorMassModel model_;
  RenderedSurface surface_;
  std::vector<std::uint32_t> labels_;  // the witness's, by TetId
  std::vector<std::array<std::uint32_t, 4>> before_tets_;
  std::vector<Vec3> before_positions_;
  std::vector<std::array<Vec3, 2>> before_boxes_;
  std::vector<std::uint32_t> before_labels_;
  std::vector<std::uint8_t> gone_;
  struct Witness {
    std::vector<std::array<std::uint32_t, 4>> tets;
    std::vector<std::uint32_t> labels;
  };
  std::vector<Witness> witness_history_;  // before each kept cut, newest last
  std::uint32_t history_limit_ = 0;  // per pre-cut tet: live before, not there unchanged after
  std::uint32_t channel_u_ = 0, channel_v_ = 0;
  Vec3 origin_{};
  double field_scale_ = 1.0;
  double worst_ = 0.0;
};

}  // namespace tetcut::mechanics

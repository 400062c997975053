// Linear elasticity on linear tetrahedra in the tensor-mass form of Cotin, Delingette and Ayache
// ("A hybrid elastic model for real-time cutting, deformations, and force feedback for surgery
// training and simulation", The Visual Computer 16, 2000), the model the paper's simulator cut.
//
// The stiffness matrix is never assembled: each vertex i keeps its own 3x3 tensor K_ii and each
// edge (i, j) the tensor K_ij (K_ji = K_ij^T), sums over the tets around them of
//   K_ij(T) = V_T (lambda m_i m_j^T + mu m_j m_i^T + mu (m_i . m_j) I),
// m_i the gradient of vertex i's barycentric coordinate in T (its rest shape), so the elastic
// force on i is F_i = -(K_ii u_i + sum over edges (i, j) of K_ij u_j). Masses are lumped: each
// vertex gets a quarter of rho V_T of every tet around it.
//
// A cut (paper 3.2: "we not only update the adjacency information ... but also the mechanical
// information") reaches the model through its ChangeLog in O(tets changed): the removed tets'
// contributions are subtracted, the created tets' added, and every created vertex takes the
// displacement and velocity the log's barycentric origin gives (as the mesh interpolates its
// attribute channels, attributes.hpp). Subtraction is not exact in floating point: a tensor
// updated by many cuts differs from a rebuild's in its last bits (differential.hpp states the
// tolerance), never more.
//
// Configuration. The tool lives in the deformed (world) configuration; the engine cuts the rest
// mesh. rest_point() maps a world point to the rest configuration through the deformed tet that
// contains it (barycentric coordinates are the same in both): that is where a cut is centred.
//
// Units: the mesh is in `length_unit` metres (bundled meshes: mm, 1e-3); material, gravity,
// masses, forces, energies and time are SI; displacements are returned in metres.
//
// Per-tet labels choose the material (ModelParams::label_materials, else materials[label]); a tet a cut creates
// takes its parent's label (the parent containing its centroid when it has several: a flip's
// child; label_rule.hpp).
//
// Time stepping: semi-implicit (symplectic) Euler with mass-proportional damping gamma,
//   v <- (v + dt M^-1 (f_ext - K u)) / (1 + gamma dt),  u <- u + dt v,
// explicit in the stiffness (one pass over vertices and edges, no solve); fixed vertices keep
// u = v = 0. Undamped, it is stable for dt < 2 / omega_max; stable_time_step() gives the CFL
// estimate h_min / c (smallest altitude over the pressure wave speed), which sees one tet alone:
// 0.88 of 2 / omega_max on the bundled liver, but 1.10 of it (above) on a beam.
// StableStepEstimator (stable_step.hpp) estimates the step from the spectrum instead.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mechanics/label_rule.hpp"
#include "tetcut/mechanics/material.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::mechanics {

using Tensor3 = std::array<double, 9>;  // 3x3, row-major

struct ModelParams {
  std::vector<Material> materials = std::vector<Material>(1);  // by label (default: one, liver-like); a label past the end takes the last
  // A material for each of these labels (a file's region ids: Gmsh physical tags, medit
  // references; RawMesh::labels), sorted by label, each label once; a label not listed takes
  // `materials`' rule above. `tetcut simulate --material LABEL:E,NU,RHO`.
  std::vector<std::pair<std::uint32_t, Material>> label_materials;
  double length_unit = 1e-3;                    // metres per mesh unit
  double damping = 0.0;                         // gamma, 1/s (mass-proportional)
  Vec3 gravity{};                               // m / s2
};
[[nodiscard]] std::optional<std::string> validate(const ModelParams& params);

// What apply() found inconsistent between a ChangeLog and the model (0 each for a log that is
// the mesh's own): a removed tet the model did not have, a created tet it already had, a parent
// that is not among the tets the log removes, a created vertex whose origin is not a model vertex.
struct ApplyProblems {
  std::uint32_t removed_not_live = 0, created_already_live = 0, parent_not_removed = 0, origin_not_live = 0;
  [[nodiscard]] std::uint32_t total() const {
    return removed_not_live + created_already_live + parent_not_removed + origin_not_live;
  }
};

struct Energy {
  double kinetic = 0, elastic = 0, gravity = 0;  // J; gravity: -sum m g . u
  [[nodiscard]] double total() const { return kinetic + elastic + gravity; }
};

class TensorMassModel {
 public:
  static constexpr std::uint32_t kNoLabel = mechanics::kNoLabel;

  // From scratch: every live tet of the mesh, in id order (O(#T)). `tet_labels`, indexed by
  // TetId, at least tet_capacity() long, or empty (every tet label 0). Displacements and
  // velocities start at zero, no vertex fixed.
  TensorMassModel(const TetMesh& mesh, ModelParams params, std::span<const std::uint32_t> tet_labels = {});

  // Room for this many tet and vertex ids, and edges in proportion, so that cuts up to there
  // allocate nothing (the constructor makes room for half as much again as the mesh has).
  void reserve(std::uint32_t tets, std::uint32_t vertices);

  // The cut's net change (change_log.hpp), the mesh as it is after it: O(tets and vertices in
  // the log, times their shells). Vertices first (their origins are values from before), then
  // the created tets' labels (their parents are still here), then removals, then creations.
  // An undo's log (ChangeLog::undo, Cutter::undo()) gives the tets it restores the labels the
  // undone cut found them with, and the vertices it restores or moves back the displacement,
  // velocity and fixing they had when that cut was applied, from the history below (the state
  // at the cut: a step since moved their neighbours, not them). With none kept for it, restored
  // tets take the label of the tet the undo removes that holds their centroid (label_rule.hpp),
  // restored vertices start at rest and free, and moved-back ones keep their state.
  ApplyProblems apply(const TetMesh& mesh, const ChangeLog& log);
  // How many applied logs keep what they took, for their undo (newest first; the Cutter's
  // CutParams::undo_history). 0, the default: none. Reused slots: no allocation once each has
  // held a cut as large.
  void keep_history(std::uint32_t logs);

  // ---- boundary conditions and state -----------------------------------------------------
  void set_fixed(VertId v, bool fixed);
  [[nodiscard]] bool is_fixed(VertId v) const { return fixed_[v.value] != 0; }
  // Fixes every live vertex whose rest position (mesh units) satisfies `predicate`; returns how
  // many. A vertex a cut creates is fixed when every vertex of its origin is.
  std::uint32_t fix_where(const TetMesh& mesh, const std::function<bool(const Vec3&)>& predicate);
  void set_displacement(VertId v, const Vec3& u) { u_[v.value] = u; }
  void set_velocity(VertId v, const Vec3& w) { v_[v.value] = w; }
  [[nodiscard]] const Vec3& displacement(VertId v) const { return u_[v.value]; }
  [[nodiscard]] const Vec3& velocity(VertId v) const { return v_[v.value]; }

  // One explicit step of dt seconds (O(#V + #E)).
  void step(double dt);
  // The elastic force -K u at every vertex (into `out`, #vertex capacity): the step's product.
  void elastic_forces(std::vector<Vec3>& out) const;
  // K x for any x by vertex id (#vertex capacity; N/m times x's unit): the same product, for
  // the stable-step estimate (stable_step.hpp), which iterates on vectors other than u.
  void stiffness_product(std::span<const Vec3> x, std::vector<Vec3>& out) const;
  // CFL estimate of the largest stable step: smallest altitude of a live tet (metres) over the
  // fastest pressure wave speed among the materials in use. O(#T).
  struct StableStep {
    double dt = 0, min_altitude = 0, wave_speed = 0;
  };
  [[nodiscard]] StableStep stable_time_step(const TetMesh& mesh) const;
  [[nodiscard]] Energy energy() const;  // O(#V + #E)

  // The point of the rest configuration (mesh units) that sits at world point `x` (mesh units)
  // once displaced. `locate_at_rest` finds the live tet containing a rest point (e.g.
  // Cutter::tet_containing): a few fixed-point steps X <- x - u(X) give a start near the answer,
  // then a walk through the deformed tets settles it (barycentric coordinates are the same in
  // both configurations). nullopt when x is outside the deformed tissue or the walk does not
  // settle within `max_steps` tets.
  [[nodiscard]] std::optional<Vec3> rest_point(const TetMesh& mesh, const Vec3& x,
                                               const std::function<TetId(const Vec3&)>& locate_at_rest,
                                               std::uint32_t max_steps = 4096) const;

  // ---- what the differential tests compare -----------------------------------------------
  [[nodiscard]] std::uint32_t vertex_capacity() const { return static_cast<std::uint32_t>(mass_.size()); }
  [[nodiscard]] std::uint32_t tet_capacity() const { return static_cast<std::uint32_t>(tets_.size()); }
  [[nodiscard]] bool has_tet(TetId t) const { return t.value < tets_.size() && tets_[t.value][0] != kDead; }
  [[nodiscard]] std::uint32_t label(TetId t) const { return labels_[t.value]; }
  [[nodiscard]] std::uint32_t tets_at(VertId v) const { return vertex_tets_[v.value]; }
  [[nodiscard]] const Tensor3& vertex_stiffness(VertId v) const { return vertex_k_[v.value]; }
  [[nodiscard]] double mass(VertId v) const { return mass_[v.value]; }  // kg
  // Sum over the tets around v of the largest |entry| of their K_ii: the scale of its tensor.
  [[nodiscard]] double vertex_scale(VertId v) const { return vertex_scale_[v.value]; }

  struct Edge {
    VertId a, b;        // a < b; the tensor is K_ab (K_ba is its transpose)
    Tensor3 k{};
    double scale = 0;   // sum over its tets of the largest |entry| of their K_ab
    std::uint32_t tets = 0;  // 0: a free slot
  };
  [[nodiscard]] std::uint32_t edge_count() const { return live_edges_; }
  [[nodiscard]] std::span<const Edge> edge_slots() const { return edges_; }  // tets == 0: free
  [[nodiscard]] const Edge* find_edge(VertId a, VertId b) const;

  [[nodiscard]] const ModelParams& params() const { return params_; }
  [[nodiscard]] const Material& material_of(std::uint32_t label) const;

 private:
  static constexpr std::uint32_t kDead = 0xFFFFFFFFu;
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;

  void grow(std::uint32_t tets, std::uint32_t vertices);
  template <int kSign>
  void product(std::span<const Vec3> x, std::vector<Vec3>& out) const;
  // Adds (sign +1) or subtracts (-1) tet t's contribution, from the model's own copy of its
  // vertices and rest positions.
  void accumulate(TetId t, double sign);
  std::uint32_t edge_slot(VertId a, VertId b, bool create);
  void release_edge(std::uint32_t slot);
  void grow_edge_index(std::size_t capacity);
  std::uint32_t inherited_label(const TetMesh& mesh, const ChangeLog& log, const CreatedTet& c,
                                ApplyProblems& problems) const;

  ModelParams params_;
  // per tet (TetId): its vertices (kDead in [0] when the model does not have it), its label
  std::vector<std::array<std::uint32_t, 4>> tets_;
  std::vector<std::uint32_t> labels_;
  // per vertex (VertId)
  std::vector<Vec3> rest_;  // mesh units, as the mesh has it
  std::vector<Tensor3> vertex_k_;
  std::vector<double> vertex_scale_, mass_;
  std::vector<std::uint32_t> vertex_tets_;
  std::vector<std::uint8_t> fixed_;
  std::vector<Vec3> u_, v_;
  mutable std::vector<Vec3> force_;
  // edges: slots with a free list, and an open-addressing index (linear probing) by vertex pair,
  // homed by the lower vertex (tensor_mass.cpp edge_home) so that a cut reads few cache lines
  std::vector<Edge> edges_;
  std::vector<std::uint32_t> free_edges_;
  std::vector<std::uint32_t> edge_index_;
  std::uint32_t live_edges_ = 0;
  // scratch for apply()
  std::vector<std::uint32_t> created_labels_;
  // apply()'s scratch: a created or moved vertex's state, computed before any is written.
  struct Interpolated {
    std::uint32_t vertex;
    Vec3 u, v;
    bool fixed;
  };
  std::vector<Interpolated> interpolated_;
  // What each applied log took, for its undo: a ring of history_limit_ slots, the newest
  // history_count_ of them ending at history_top_.
  struct Taken {
    std::vector<std::pair<TetId, std::uint32_t>> tets;  // removed tets and their labels, sorted by id
    std::vector<Interpolated> vertices;                 // removed and moved vertices' state before
  };
  void keep(const ChangeLog& log);
  [[nodiscard]] const Interpolated* taken_state(const Taken* taken, VertId v) const;
  std::vector<Taken> history_;
  std::uint32_t history_top_ = 0, history_count_ = 0;
};

}  // namespace tetcut::mechanics

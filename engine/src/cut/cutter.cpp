// The public Cutter: its one allocation (the pipeline, at construction) and forwarding to it
// (cut_pipeline.cpp).
#include "tetcut/cut.hpp"

#include <cmath>

#include "cut/cut_pipeline.hpp"

namespace tetcut {

std::optional<std::string> validate(const CutParams& p) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(p.tool_diameter)) return "tool diameter must be a positive finite length";
  if (!positive(p.d_ref_factor)) return "D_ref factor must be a positive finite number";
  if (!positive(p.d_ref())) return "D_ref (d_ref_factor x tool diameter) must be a positive finite length";
  if (!std::isfinite(p.p) || p.p <= 1.0) return "p must be a finite number greater than 1";
  if (p.search_depth == 0 || p.search_depth > 64) return "search depth must be between 1 and 64";
  if (p.max_refine_iterations == 0 || p.max_refine_iterations > 64) return "refinement iteration bound must be between 1 and 64";
  if (p.max_tets_created == 0) return "the per-cut tet budget must be positive";
  if (!(p.quality_floor >= 0.0 && p.quality_floor <= 1.0)) return "the quality floor must be a radius ratio between 0 and 1";
  if (!(p.min_dihedral_deg >= 0.0 && p.min_dihedral_deg <= 70.0))
    return "the dihedral floor min_dihedral_deg must be an angle between 0 and 70 degrees";
  if (!(p.debris_volume >= 0.0 && std::isfinite(p.debris_volume)))
    return "the debris volume must be a finite volume, 0 or more (0: detached pieces are only reported)";
  if (p.fragment_search_bound == 0) return "the fragment search bound must be at least one tet";
  if (p.undo_history > 4096) return "the undo history undo_history must be at most 4096 cuts";
  return std::nullopt;
}

// Every call that changes the mesh holds it for writing (thread_contract.hpp); tet_containing()
// only reads it.
Cutter::Cutter(TetMesh& mesh, const CutParams& params)
    : pipeline_([&] {
        const MeshWriteScope writing(mesh, "Cutter's constructor");
        return std::make_unique<Pipeline>(mesh, params);
      }()) {}
Cutter::~Cutter() = default;
Cutter::Cutter(Cutter&&) noexcept = default;
Cutter& Cutter::operator=(Cutter&&) noexcept = default;

void Cutter::prepare() {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::prepare()");
  pipeline_->prepare();
}
void Cutter::reset() {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::reset()");
  pipeline_->reset();
}
Renumbering Cutter::compact(IdOrder order) {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::compact()");
  return pipeline_->compact(order);
}
std::optional<std::string> Cutter::set_uncuttable(std::span<const TetId> tets) {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::set_uncuttable()");
  return pipeline_->set_uncuttable(tets);
}
bool Cutter::uncuttable(TetId t) const { return pipeline_->uncuttable(t); }
bool Cutter::indexes_current_mesh() const { return pipeline_->indexes_current_mesh(); }
std::optional<std::string> Cutter::set_params(const CutParams& params) { return pipeline_->set_params(params); }
const CutParams& Cutter::params() const { return pipeline_->params(); }
CutReport Cutter::cut(const Vec3& centre, ChangeLog* log) {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::cut()");
  return pipeline_->cut(centre, centre, log);
}
CutReport Cutter::cut_segment(const Vec3& a, const Vec3& b, ChangeLog* log) {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::cut_segment()");
  return pipeline_->cut(a, b, log);
}
CutReport Cutter::remove(TetId t, ChangeLog* log) {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::remove()");
  return pipeline_->remove(t, log);
}
std::optional<std::string> Cutter::undo(ChangeLog* log) {
  const MeshWriteScope writing(pipeline_->mesh(), "Cutter::undo()");
  return pipeline_->undo(log);
}
std::uint32_t Cutter::undo_depth() const { return pipeline_->undo_depth(); }
std::optional<Cutter::CutReach> Cutter::last_undone_reach() const { return pipeline_->last_undone_reach(); }
TetId Cutter::tet_containing(const Vec3& p) {
  const MeshReadScope reading(pipeline_->mesh(), "Cutter::tet_containing()");
  return pipeline_->tet_containing(p);
}
const RemovalReport& Cutter::removal_report() const { return pipeline_->removal_report(); }
TetMesh& Cutter::mesh() { return pipeline_->mesh(); }
const std::vector<TetId>& Cutter::last_removed() const { return pipeline_->last_removed(); }
std::span<const RawMovedVertex> Cutter::last_moved() const { return pipeline_->last_moved(); }
std::span<const Fragment> Cutter::last_fragments() const { return pipeline_->last_fragments(); }
std::uint32_t Cutter::pieces() const { return pipeline_->pieces(); }
const std::vector<TetId>& Cutter::last_created() const { return pipeline_->last_created(); }
std::span<const TetId> Cutter::last_left_in_tool() const { return pipeline_->last_left_in_tool(); }
double Cutter::last_min_dihedral_held() const { return pipeline_->last_min_dihedral_held(); }

}  // namespace tetcut

// The public Cutter: its one allocation (the pipeline, at construction), the check that the mesh
// still has the ids it indexed, and forwarding to the pipeline (cut_pipeline.cpp).
#include "tetcut/cut.hpp"

#include <cmath>

#include "cut/cut_pipeline.hpp"

namespace tetcut {

std::optional<std::string> validate(const CutParams& p) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(p.tool_diameter)) return "tool diameter must be a positive finite length";
  if (!positive(p.d_ref_factor)) return "D_ref factor must be a positive finite number";
  if (!std::isfinite(p.p) || p.p <= 1.0) return "p must be a finite number greater than 1";
  if (p.search_depth == 0 || p.search_depth > 64) return "search depth must be between 1 and 64";
  if (p.max_refine_iterations == 0 || p.max_refine_iterations > 64) return "refinement iteration bound must be between 1 and 64";
  if (p.max_tets_created == 0) return "the per-cut tet budget must be positive";
  if (!(p.quality_floor >= 0.0 && p.quality_floor <= 1.0)) return "the quality floor must be a radius ratio between 0 and 1";
  if (p.coarser_retries > 8) return "coarser retries must be between 0 and 8";
  return std::nullopt;
}

Cutter::Cutter(TetMesh& mesh, const CutParams& params) : pipeline_(std::make_unique<Pipeline>(mesh, params)) {}
Cutter::~Cutter() = default;
Cutter::Cutter(Cutter&&) noexcept = default;
Cutter& Cutter::operator=(Cutter&&) noexcept = default;

void Cutter::prepare() { pipeline_->prepare(); }
void Cutter::reset() { pipeline_->reset(); }

Renumbering Cutter::compact() {
  Renumbering map = pipeline_->mesh_.compact();
  detail::UncuttableTets uncuttable = std::move(pipeline_->uncuttable_);
  pipeline_->reset();
  uncuttable.renumber(map);
  pipeline_->uncuttable_ = std::move(uncuttable);
  return map;
}

std::optional<std::string> Cutter::set_uncuttable(std::span<const TetId> tets) {
  if (!indexes_current_mesh()) return "the mesh was compacted or replaced since this Cutter indexed it";
  TetMesh& mesh = pipeline_->mesh_;
  for (TetId t : tets)
    if (t.value >= mesh.tet_capacity() || !mesh.is_live(t)) return "tet " + std::to_string(t.value) + " is not live";
  pipeline_->uncuttable_.assign(mesh, tets);
  return std::nullopt;
}

bool Cutter::uncuttable(TetId t) const {
  return pipeline_->mesh_.is_live(t) && pipeline_->uncuttable_.contains(pipeline_->mesh_, t);
}

bool Cutter::indexes_current_mesh() const { return pipeline_->indexes_current_mesh(); }
std::optional<std::string> Cutter::set_params(const CutParams& params) { return pipeline_->set_params(params); }
const CutParams& Cutter::params() const { return pipeline_->params_; }
CutReport Cutter::cut(const Vec3& centre, ChangeLog* log) { return pipeline_->cut(centre, log); }
CutReport Cutter::remove(TetId t, ChangeLog* log) { return pipeline_->remove(t, log); }
TetId Cutter::tet_containing(const Vec3& p) { return pipeline_->tet_containing(p); }
const RemovalReport& Cutter::removal_report() const { return pipeline_->remover_.report(); }
TetMesh& Cutter::mesh() { return pipeline_->mesh_; }
const std::vector<TetId>& Cutter::last_removed() const { return pipeline_->net_removed_; }
const std::vector<TetId>& Cutter::last_created() const { return pipeline_->net_created_; }

}  // namespace tetcut

// The local level: the checker's own incidence, kept up to date from what each operation says
// it removed and created, and the same per-vertex link analysis as the full level run on the
// vertices of those tets only.
//
// Why the vertices of the removed and created tets are enough: a face or edge whose star changed
// belongs to a removed or created tet, so all its vertices are touched; an untouched vertex has
// exactly the star it had before the operation, and the mesh was valid then.
#include <algorithm>
#include <cmath>
#include <string>

#include "engine_records.hpp"
#include "no_degradation.hpp"
#include "report_builder.hpp"
#include "tet_checks.hpp"
#include "tetcut/invariants/check.hpp"
#include "tissue_rule.hpp"
#include "vertex_link.hpp"

namespace tetcut::invariants {

using detail::RawTet;
using detail::ReportBuilder;
using detail::str;

namespace {
constexpr RawTet kDeadTet{kDeadTetMarker, kDeadTetMarker, kDeadTetMarker, kDeadTetMarker};

bool references_in_range(const RawTet& q, std::size_t vertex_count) {
  return q[0] < vertex_count && q[1] < vertex_count && q[2] < vertex_count && q[3] < vertex_count;
}
}  // namespace

struct LocalChecker::Scratch {
  detail::VertexLinkChecker link;
  detail::NoDegradationCheck no_degradation;
  std::vector<std::uint32_t> touched;
  detail::TetGrid grid;                      // I10: which tets may meet a tool
  std::vector<std::uint32_t> near_tool;
  std::vector<RawTet> removed_uncuttable;    // the operation's, as they were
};

LocalChecker::~LocalChecker() = default;
LocalChecker::LocalChecker(LocalChecker&&) noexcept = default;
LocalChecker& LocalChecker::operator=(LocalChecker&&) noexcept = default;

LocalChecker::LocalChecker(const RawMeshView& mesh) : scratch_(std::make_unique<Scratch>()) { reset(mesh); }

void LocalChecker::reset(const RawMeshView& mesh) {
  const auto raw = mesh.tets;
  const auto positions = mesh.positions;
  known_tets_.assign(raw.begin(), raw.end());
  known_volume_.assign(raw.size(), 0.0);
  known_rounding_.assign(raw.size(), 0.0);
  excluded_.assign(raw.size(), 0);
  for (auto& list : vertex_to_tets_) list.clear();  // their memory stays
  vertex_to_tets_.resize(positions.size());
  touched_stamp_.assign(positions.size(), 0);
  stamp_ = 0;
  live_tets_ = 0;
  live_vertices_ = 0;
  for (std::uint32_t t = 0; t < raw.size(); ++t) {
    const RawTet& q = raw[t];
    if (q[0] == kDeadTetMarker) continue;
    ++live_tets_;
    if (!references_in_range(q, positions.size())) continue;  // the full check reports it
    known_volume_[t] = detail::tet_volume(q, positions);
    known_rounding_[t] = detail::tet_volume_rounding_bound(q, positions);
    for (std::uint32_t v : q) vertex_to_tets_[v].push_back(t);
  }
  for (const auto& list : vertex_to_tets_)
    if (!list.empty()) ++live_vertices_;
  scratch_->grid = detail::TetGrid{};
  uncuttable_.clear();
  any_uncuttable_ = false;
}

void LocalChecker::set_uncuttable(RawIds tets) {
  uncuttable_.assign(known_tets_.size(), 0);
  any_uncuttable_ = false;
  for (std::uint32_t t : tets) {
    if (t >= known_tets_.size() || known_tets_[t][0] == kDeadTetMarker) continue;  // a bad id names nothing
    uncuttable_[t] = 1;
    any_uncuttable_ = true;
  }
}

// One after_operation() call, step by step: room for the mesh's ids, the removed tets forgotten,
// the created ones admitted (I1, I4, I7 on each), the touched vertices' shells checked (I1-I8),
// then what holds over the whole operation (I8's counts, I9, I7's no-degradation rule, I10).
struct LocalChecker::Operation {
  Operation(LocalChecker& checker, const RawMeshView& mesh, const CheckOptions& check_options)
      : c(checker),
        options(check_options),
        engine(detail::usable_records(mesh, report)),
        raw(mesh.tets),
        positions(mesh.positions),
        judge_quality(check_options.quality_rule == QualityRule::kNoDegradation),
        touched(checker.scratch_->touched),
        removed_uncuttable(checker.scratch_->removed_uncuttable),
        grid(checker.scratch_->grid),
        no_degradation(checker.scratch_->no_degradation),
        geometry(check_options.radius_ratio_floor, report) {}

  // The checker's per-tet and per-vertex records cover the mesh's ids; a new stamp for the
  // vertices this operation touches.
  void make_room() {
    if (c.known_tets_.size() < raw.size()) {
      c.known_tets_.resize(raw.size(), kDeadTet);
      c.known_volume_.resize(raw.size(), 0.0);
      c.known_rounding_.resize(raw.size(), 0.0);
      c.excluded_.resize(raw.size(), 0);
    }
    if (c.any_uncuttable_ && c.uncuttable_.size() < raw.size()) c.uncuttable_.resize(raw.size(), 0);
    if (c.vertex_to_tets_.size() < positions.size()) {
      c.vertex_to_tets_.resize(positions.size());
      c.touched_stamp_.resize(positions.size(), 0);
    }
    if (++c.stamp_ == 0) {  // wrapped: forget every old stamp
      std::fill(c.touched_stamp_.begin(), c.touched_stamp_.end(), 0);
      c.stamp_ = 1;
    }
    touched.clear();
  }

  void touch(std::uint32_t v) {
    if (v < c.touched_stamp_.size() && c.touched_stamp_[v] != c.stamp_) {
      c.touched_stamp_[v] = c.stamp_;
      touched.push_back(v);
    }
  }

  // I8: the operation's account of what it did does not match the mesh.
  void misreported(std::uint32_t t, const char* claim, const char* fact) {
    report.add(Invariant::kI8Bookkeeping, {t}, {}, [&] {
      return std::string("the operation reports ") + claim + " tet " + str(t) + ", " + fact;
    });
  }

  // Removed tets leave the index; their old vertices are remembered from it, not from the mesh.
  void forget_removed(RawIds removed) {
    no_degradation.begin();
    removed_uncuttable.clear();
    for (std::uint32_t t : removed) {
      if (t >= c.known_tets_.size() || c.known_tets_[t][0] == kDeadTetMarker) {
        misreported(t, "removing", "which was not live");
        continue;
      }
      if (references_in_range(c.known_tets_[t], positions.size())) {
        // Vertices that were there before an operation never move (only the ones it made may):
        // the tet's volume now, from the same positions, is bit for bit the one remembered.
        const double now = detail::tet_volume(c.known_tets_[t], positions);
        if (now != c.known_volume_[t])
          report.add(Invariant::kI8Bookkeeping, {t}, {}, [&] {
            return "a vertex of removed tet " + str(t) + " moved: its volume was " + detail::num(c.known_volume_[t]) +
                   " and is " + detail::num(now);
          });
        if (judge_quality) no_degradation.add_removed(t, c.known_tets_[t]);
        if (c.any_uncuttable_ && c.uncuttable_[t]) {
          removed_uncuttable.push_back(c.known_tets_[t]);
          uncuttable_volume.add(-c.known_volume_[t]);
          uncuttable_abs += std::abs(c.known_volume_[t]);
        }
      }
      if (c.any_uncuttable_) c.uncuttable_[t] = 0;
      if (grid.built()) grid.erase(t);
      for (std::uint32_t v : c.known_tets_[t]) {
        if (v >= c.vertex_to_tets_.size()) continue;
        auto& list = c.vertex_to_tets_[v];
        const auto it = std::find(list.begin(), list.end(), t);
        if (it == list.end()) continue;
        *it = list.back();
        list.pop_back();
        if (list.empty()) --c.live_vertices_;
        touch(v);
      }
      removed_volume.add(c.known_volume_[t]);
      removed_abs += std::abs(c.known_volume_[t]);
      rounding += c.known_rounding_[t];
      c.known_tets_[t] = kDeadTet;
      --c.live_tets_;
    }
  }

  // Created tets enter the index as the mesh now has them; I1 (references), I4, I7 on each.
  void admit_created(RawIds created, RawIds removed) {
    for (std::uint32_t t : created) {
      if (t >= raw.size() || raw[t][0] == kDeadTetMarker) {
        misreported(t, "creating", "which is not live in the mesh");
        continue;
      }
      if (c.known_tets_[t][0] != kDeadTetMarker) {
        misreported(t, "creating", "which was already live and not removed");
        continue;
      }
      const RawTet& q = raw[t];
      c.known_tets_[t] = q;
      ++c.live_tets_;
      if (!detail::check_references(t, q, positions, report)) continue;  // kept out of the index
      for (std::uint32_t v : q) {
        auto& list = c.vertex_to_tets_[v];
        if (list.empty()) ++c.live_vertices_;
        list.push_back(t);
        touch(v);
      }
      const detail::TetGeometryChecker::Shape shape = geometry.check(t, q, positions);
      if (judge_quality) no_degradation.add_created(t, q, shape.ratio, shape.dihedral_deg);
      c.known_volume_[t] = detail::tet_volume(q, positions);
      c.known_rounding_[t] = detail::tet_volume_rounding_bound(q, positions);
      if (grid.built()) grid.insert(t, q, positions);
      if (!removed_uncuttable.empty()) inherit_uncuttable(t, q);
      created_volume.add(c.known_volume_[t]);
      created_abs += std::abs(c.known_volume_[t]);
      rounding += c.known_rounding_[t];
    }
    for (std::uint32_t t : removed)
      if (t < raw.size() && raw[t][0] != kDeadTetMarker && c.known_tets_[t][0] == kDeadTetMarker)
        misreported(t, "removing", "but it is still live in the mesh");
  }

  // A made tet is uncuttable when its centroid lies in an uncuttable tet the operation replaced.
  void inherit_uncuttable(std::uint32_t t, const RawTet& q) {
    const Vec3 centroid = 0.25 * (positions[q[0]] + positions[q[1]] + positions[q[2]] + positions[q[3]]);
    for (const RawTet& u : removed_uncuttable)
      if (detail::tet_contains(centroid, positions[u[0]], positions[u[1]], positions[u[2]], positions[u[3]])) {
        c.uncuttable_[t] = 1;
        uncuttable_volume.add(c.known_volume_[t]);
        uncuttable_abs += std::abs(c.known_volume_[t]);
        break;
      }
  }

  // The shells of the touched vertices, in vertex order (the full level's order restricted).
  void check_shells() {
    std::sort(touched.begin(), touched.end());
    detail::LinkContext ctx;
    ctx.tets = c.known_tets_;
    ctx.excluded = c.excluded_;
    ctx.touched_stamp = c.touched_stamp_.data();
    ctx.stamp = c.stamp_;
    ctx.engine = engine;
    ctx.report = &report;
    for (std::uint32_t v : touched) {
      const auto& shell = c.vertex_to_tets_[v];
      shell_tets += shell.size();
      for (std::uint32_t t : shell) {
        // The engine must not have changed a tet the operation did not report (checked once per
        // tet, at its smallest touched vertex).
        const RawTet& q = c.known_tets_[t];
        bool first = true;
        for (std::uint32_t x : q)
          if (x < v && c.touched_stamp_[x] == c.stamp_) first = false;
        if (first && (t >= raw.size() || raw[t] != q)) {
          report.add(Invariant::kI8Bookkeeping, {t}, {v}, [&] {
            return "tet " + str(t) + " changed in the mesh without the operation reporting it";
          });
        }
      }
      if (!shell.empty()) c.scratch_->link.check(ctx, v, shell);
      else if (engine != nullptr) detail::compare_unused_vertex(*engine, v, report);
    }
    for (std::uint32_t v : touched)
      for (std::uint32_t t : c.vertex_to_tets_[v]) c.excluded_[t] = 0;
  }

  // What holds over the whole operation, and the report.
  CheckReport finish(std::optional<double> expected_volume_change) {
    CheckReport out;
    out.operation = options.operation;
    // I8: counts, kept by the checker from the operations alone.
    if (engine != nullptr) detail::compare_counts(*engine, c.live_tets_, c.live_vertices_, positions.size(), report);

    const double change = created_volume.value() - removed_volume.value();
    if (expected_volume_change) {
      detail::check_volume(change, *expected_volume_change, std::max(removed_abs, created_abs),
                           options.volume_rel_tolerance, "the volume change of the operation", report, rounding);
    }

    if (judge_quality) no_degradation.finish(positions, options.quality_floor, options.min_dihedral_deg, report);

    // I10: uncuttable tissue neither went nor grew.
    if (!removed_uncuttable.empty() &&
        std::abs(uncuttable_volume.value()) > options.volume_rel_tolerance * uncuttable_abs + rounding) {
      report.add(Invariant::kI10Tissue, {}, {}, [&] {
        return "the uncuttable tets the operation made have a volume " + detail::num(uncuttable_volume.value()) +
               " different from the uncuttable tets it replaced: uncuttable tissue went or grew";
      });
    }
    // I10: the tool's tissue.
    if (options.tool) {
      if (!grid.built()) grid.build(c.known_tets_, positions);
      grid.candidates(options.tool->centre, options.tool->radius, c.scratch_->near_tool);
      detail::check_tissue_rule(*options.tool, c.scratch_->near_tool, c.known_tets_, positions, c.uncuttable_, report);
    }

    geometry.finish(out);
    out.volume = change;
    out.tets_checked = shell_tets;
    out.vertices_checked = touched.size();
    report.finish(out);
    return out;
  }

  LocalChecker& c;
  const CheckOptions& options;
  ReportBuilder report;
  const EngineRecordsView* engine;
  std::span<const RawTet> raw;
  std::span<const Vec3> positions;
  const bool judge_quality;
  std::vector<std::uint32_t>& touched;
  std::vector<RawTet>& removed_uncuttable;  // the operation's, as they were
  detail::TetGrid& grid;
  detail::NoDegradationCheck& no_degradation;
  detail::TetGeometryChecker geometry;
  detail::VolumeSum removed_volume, created_volume;
  double removed_abs = 0.0, created_abs = 0.0;
  detail::VolumeSum uncuttable_volume;  // made minus replaced, of uncuttable tets
  double uncuttable_abs = 0.0;
  double rounding = 0.0;  // what rounding alone can put into the volume change
  std::uint64_t shell_tets = 0;
};

CheckReport LocalChecker::after_operation(const RawMeshView& mesh, RawIds removed, RawIds created,
                                          const CheckOptions& options,
                                          std::optional<double> expected_volume_change) {
  Operation op(*this, mesh, options);
  op.make_room();
  op.forget_removed(removed);
  op.admit_created(created, removed);
  op.check_shells();
  return op.finish(expected_volume_change);
}

}  // namespace tetcut::invariants

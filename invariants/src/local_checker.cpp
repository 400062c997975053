// The local level: the checker's own incidence, kept up to date from what each operation says
// it removed and created, and the same per-vertex link analysis as the full level run on the
// vertices of those tets only.
//
// Why the vertices of the removed and created tets are enough: a face or edge whose star changed
// belongs to a removed or created tet, so all its vertices are touched; an untouched vertex has
// exactly the star it had before the operation, and the mesh was valid then.
//
// Why the checker keeps its own copy of the positions: an existing vertex may move (the
// improvement pass smooths within a cut's reach), so the mesh no longer shows the removed tets as
// they were. The copy gives their old shape, and comparing it with the mesh at the touched
// vertices is how a move is seen at all.
#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <utility>

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

// Bit for bit: a vertex that did not move is exactly where it was, whatever rounding would allow.
bool same_position(const Vec3& a, const Vec3& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
         std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

// "(x, y, z)". Appended piece by piece: GCC 12's -Wrestrict misfires on "(" + std::string.
std::string text(const Vec3& p) {
  std::string out = detail::num(p.x);
  out.insert(0, 1, '(');
  return out.append(", ").append(detail::num(p.y)).append(", ").append(detail::num(p.z)).append(")");
}

// A reported move reproduces the position to this fraction of the distance to the vertices it
// combines: the rounding of a sum of four weighted positions, with room to spare.
constexpr double kMoveTolerance = 1e-9;
// The weights of a reported move are affine: they sum to 1 up to rounding.
constexpr double kWeightSumTolerance = 1e-12;
// As the tissue rule: a distance within a relative 1e-9 of the cut's reach is the engine's
// rounding, not a move out of reach.
constexpr double kReachTolerance = 1e-9;
}  // namespace

struct LocalChecker::Scratch {
  detail::VertexLinkChecker link;
  detail::NoDegradationCheck no_degradation;
  std::vector<std::uint32_t> touched;
  detail::TetGrid grid;                      // I10: which tets may meet a tool
  std::vector<std::uint32_t> near_tool;
  std::vector<RawTet> removed_uncuttable;    // the operation's, as they were
  std::vector<std::uint32_t> live_before;    // touched vertices that had tets before the operation
  std::vector<std::pair<std::uint32_t, std::uint32_t>> reported_moves;  // (vertex, index in moved)
  std::vector<std::uint32_t> created_sorted;  // the operation's created tets, to look up
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
  known_positions_.assign(positions.begin(), positions.end());
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
        old_positions(checker.known_positions_),
        judge_quality(check_options.quality_rule == QualityRule::kNoDegradation),
        touched(checker.scratch_->touched),
        live_before(checker.scratch_->live_before),
        created_sorted(checker.scratch_->created_sorted),
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
      // New vertices: where they are is where they were (nothing was there to move).
      c.known_positions_.insert(c.known_positions_.end(),
                                positions.begin() + static_cast<std::ptrdiff_t>(c.known_positions_.size()),
                                positions.end());
      old_positions = c.known_positions_;
      c.vertex_to_tets_.resize(positions.size());
      c.touched_stamp_.resize(positions.size(), 0);
    }
    if (++c.stamp_ == 0) {  // wrapped: forget every old stamp
      std::fill(c.touched_stamp_.begin(), c.touched_stamp_.end(), 0);
      c.stamp_ = 1;
    }
    touched.clear();
    live_before.clear();
  }

  // Whether v is touched for the first time by this operation.
  bool touch(std::uint32_t v) {
    if (v >= c.touched_stamp_.size() || c.touched_stamp_[v] == c.stamp_) return false;
    c.touched_stamp_[v] = c.stamp_;
    touched.push_back(v);
    return true;
  }

  // I8: the operation's account of what it did does not match the mesh.
  void misreported(std::uint32_t t, const char* claim, const char* fact) {
    report.add(Invariant::kI8Bookkeeping, {t}, {}, [&] {
      return std::string("the operation reports ") + claim + " tet " + str(t) + ", " + fact;
    });
  }

  // Removed tets leave the index; their old vertices are remembered from it, and their old
  // positions from the checker's copy, not from the mesh.
  void forget_removed(RawIds removed) {
    no_degradation.begin();
    removed_uncuttable.clear();
    for (std::uint32_t t : removed) {
      if (t >= c.known_tets_.size() || c.known_tets_[t][0] == kDeadTetMarker) {
        misreported(t, "removing", "which was not live");
        continue;
      }
      if (references_in_range(c.known_tets_[t], old_positions.size())) {
        // A live tet's corners move only when an operation remakes it (check_moves): at the
        // positions the checker last saw, its volume is bit for bit the one remembered. A corner
        // moved while the tet was kept (reported then) shows here again.
        const double now = detail::tet_volume(c.known_tets_[t], old_positions);
        if (now != c.known_volume_[t])
          report.add(Invariant::kI8Bookkeeping, {t}, {}, [&] {
            return "a vertex of removed tet " + str(t) + " moved since the tet was made: its volume was " +
                   detail::num(c.known_volume_[t]) + " and is " + detail::num(now);
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
        if (touch(v)) live_before.push_back(v);  // it had tet t
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
        // Untouched so far, so its list is as it was before the operation.
        const bool was_live = !list.empty();
        if (list.empty()) ++c.live_vertices_;
        list.push_back(t);
        if (touch(v) && was_live) live_before.push_back(v);
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

  // A made tet is uncuttable when its centroid (now) lies in an uncuttable tet the operation
  // replaced (as it was).
  void inherit_uncuttable(std::uint32_t t, const RawTet& q) {
    const Vec3 centroid = 0.25 * (positions[q[0]] + positions[q[1]] + positions[q[2]] + positions[q[3]]);
    for (const RawTet& u : removed_uncuttable)
      if (detail::tet_contains(centroid, old_positions[u[0]], old_positions[u[1]], old_positions[u[2]],
                               old_positions[u[3]])) {
        c.uncuttable_[t] = 1;
        uncuttable_volume.add(c.known_volume_[t]);
        uncuttable_abs += std::abs(c.known_volume_[t]);
        break;
      }
  }

  // Had tets in the checker's index before the operation.
  bool was_live_before(std::uint32_t v) const {
    if (v >= c.vertex_to_tets_.size()) return false;
    if (c.touched_stamp_[v] != c.stamp_) return !c.vertex_to_tets_[v].empty();  // its list is as it was
    return std::binary_search(live_before.begin(), live_before.end(), v);
  }

  // I8: an existing vertex moves only as the operation reports it (options.moved), within the
  // cut's reach, to where its entry's weights put it, and with every tet around it remade. The
  // touched vertices are the ones whose shell changed: a move that keeps the whole shell is seen
  // when the operation reports it, or at the next operation that touches the vertex.
  void check_moves(RawIds created) {
    std::sort(live_before.begin(), live_before.end());
    auto& reported = c.scratch_->reported_moves;
    reported.clear();
    for (std::uint32_t i = 0; i < options.moved.size(); ++i) reported.push_back({options.moved[i].vertex, i});
    std::sort(reported.begin(), reported.end());
    created_sorted.clear();
    if (!reported.empty() || std::any_of(touched.begin(), touched.end(), [&](std::uint32_t v) { return moved(v); })) {
      for (std::uint32_t t : created) created_sorted.push_back(t);
      std::sort(created_sorted.begin(), created_sorted.end());
    }

    for (std::size_t k = 0; k < reported.size(); ++k) {
      // Named, not a structured binding: clang 14 cannot capture one in the lambda below.
      const std::uint32_t v = reported[k].first, i = reported[k].second;
      auto reported_but = [&](const char* fact) {
        report.add(Invariant::kI8Bookkeeping, {}, {v}, [&] { return "vertex " + str(v) + " reported moved but " + fact; });
      };
      if (k > 0 && reported[k - 1].first == v) reported_but("it is reported twice");
      else if (!was_live_before(v)) reported_but("it was not there before the operation");
      else if (v >= positions.size() || !moved(v)) reported_but("it did not move");
      else if (c.touched_stamp_[v] != c.stamp_) judge_move(v, &options.moved[i]);  // the touched: below
    }
    for (std::uint32_t v : touched) {
      if (!moved(v) || !was_live_before(v) || c.vertex_to_tets_[v].empty()) continue;
      const auto it = std::lower_bound(reported.begin(), reported.end(), std::make_pair(v, 0u));
      judge_move(v, it != reported.end() && it->first == v ? &options.moved[it->second] : nullptr);
    }
  }

  // v is not where the checker last saw it.
  bool moved(std::uint32_t v) const { return v < positions.size() && !same_position(positions[v], old_positions[v]); }

  // A vertex that was there before, is there after and moved: `entry` is its report, if any.
  void judge_move(std::uint32_t v, const RawMovedVertex* entry) {
    const Vec3 was = old_positions[v], is = positions[v];
    auto move_text = [&] { return "vertex " + str(v) + " moved from " + text(was) + " to " + text(is); };
    if (entry == nullptr)
      report.add(Invariant::kI8Bookkeeping, {}, {v}, [&] { return move_text() + " and the operation did not report it"; });
    const std::optional<ToolRule>& tool = options.tool ? options.tool : options.reach;
    if (!tool) {
      report.add(Invariant::kI8Bookkeeping, {}, {v}, [&] {
        return "an operation without a tool moved vertex " + str(v) + " from " + text(was) + " to " + text(is);
      });
    } else {
      const double reach = tool->radius + tool->d_ref;
      const double distance = std::max(detail::distance_to_axis(*tool, was), detail::distance_to_axis(*tool, is));
      if (!(distance <= reach * (1.0 + kReachTolerance)))
        report.add(Invariant::kI8Bookkeeping, {}, {v}, [&] {
          return move_text() + ", " + detail::num(distance) + " from the tool's axis: beyond the cut's reach " +
                 detail::num(reach) + " (radius + d_ref)";
        });
    }
    if (entry != nullptr) check_reported_position(v, *entry);
    // A kept tet keeps its shape: every tet around a moved vertex is one the operation made.
    for (std::uint32_t t : c.vertex_to_tets_[v])
      if (!std::binary_search(created_sorted.begin(), created_sorted.end(), t)) {
        report.add(Invariant::kI8Bookkeeping, {t}, {v}, [&] {
          return move_text() + " but tet " + str(t) + " around it was kept: a tet the operation did not create changed shape";
        });
        break;
      }
  }

  // The entry puts v where it is: an affine combination of vertices that were there before, at
  // their old positions.
  void check_reported_position(std::uint32_t v, const RawMovedVertex& entry) {
    auto wrong = [&](const std::string& fact) {
      report.add(Invariant::kI8Bookkeeping, {}, {v}, [&] { return "the reported move of vertex " + str(v) + " " + fact; });
    };
    if (entry.count < 1 || entry.count > entry.from.size()) {
      wrong("combines " + str(entry.count) + " vertices, not 1 to 4");
      return;
    }
    Vec3 combined{};
    double weight_sum = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < entry.count; ++i) {
      const std::uint32_t f = entry.from[i];
      if (!was_live_before(f)) {
        wrong("combines vertex " + str(f) + ", which was not there before the operation");
        return;
      }
      combined = combined + entry.weight[i] * old_positions[f];
      weight_sum += entry.weight[i];
      scale = std::max(scale, norm(positions[v] - old_positions[f]));
    }
    if (!(std::abs(weight_sum - 1.0) <= kWeightSumTolerance)) {
      wrong("has weights summing to " + detail::num(weight_sum) + ", not 1");
      return;
    }
    const double off = norm(combined - positions[v]);
    if (!(off <= kMoveTolerance * (scale > 0.0 ? scale : 1.0)))
      wrong("puts it at " + text(combined) + ", " + detail::num(off) + " from where it is, " + text(positions[v]));
  }

  // The checker's copy of the positions follows the vertices this operation touched or reported
  // (all that may have moved, as far as the checker can see).
  void remember_positions() {
    for (std::uint32_t v : touched)
      if (v < positions.size()) c.known_positions_[v] = positions[v];
    for (const RawMovedVertex& entry : options.moved)
      if (entry.vertex < positions.size() && entry.vertex < c.known_positions_.size())
        c.known_positions_[entry.vertex] = positions[entry.vertex];
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

    if (judge_quality)
      no_degradation.finish(old_positions, positions, options.quality_floor, options.min_dihedral_deg,
                            options.tool ? &*options.tool : nullptr, report);

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
      // A capsule's candidates: those near the ball about its midpoint that holds it.
      const ToolRule& tool = *options.tool;
      const Vec3 end = tool.end.value_or(tool.centre);
      grid.candidates(0.5 * (tool.centre + end), tool.radius + 0.5 * norm(end - tool.centre), c.scratch_->near_tool);
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
  std::span<const Vec3> old_positions;  // the checker's copy: as they were before the operation
  const bool judge_quality;
  std::vector<std::uint32_t>& touched;
  std::vector<std::uint32_t>& live_before;
  std::vector<std::uint32_t>& created_sorted;
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
  op.check_moves(created);
  op.check_shells();
  CheckReport out = op.finish(expected_volume_change);
  op.remember_positions();
  return out;
}

}  // namespace tetcut::invariants

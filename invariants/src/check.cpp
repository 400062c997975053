// The full and exact levels: one linear pass over the tets, a counting sort into the checker's
// own vertex->tets incidence, one link analysis per vertex, one geometric pass.
#include "tetcut/invariants/check.hpp"

#include <string>

#include "boundary_self_intersection.hpp"
#include "engine_records.hpp"
#include "report_builder.hpp"
#include "tet_checks.hpp"
#include "vertex_link.hpp"

namespace tetcut::invariants {

const char* id_string(Invariant id) {
  switch (id) {
    case Invariant::kI1References: return "I1";
    case Invariant::kI2Adjacency: return "I2";
    case Invariant::kI3Conformity: return "I3";
    case Invariant::kI4Orientation: return "I4";
    case Invariant::kI5VertexShell: return "I5";
    case Invariant::kI6EdgeShell: return "I6";
    case Invariant::kI7Quality: return "I7";
    case Invariant::kI8Bookkeeping: return "I8";
    case Invariant::kI9Volume: return "I9";
    case Invariant::kI10Tissue: return "I10";
  }
  return "I?";
}

const char* description(Invariant id) {
  switch (id) {
    case Invariant::kI1References: return "references";
    case Invariant::kI2Adjacency: return "adjacency";
    case Invariant::kI3Conformity: return "conformity";
    case Invariant::kI4Orientation: return "orientation";
    case Invariant::kI5VertexShell: return "manifold vertex shells";
    case Invariant::kI6EdgeShell: return "manifold edge shells";
    case Invariant::kI7Quality: return "quality";
    case Invariant::kI8Bookkeeping: return "bookkeeping";
    case Invariant::kI9Volume: return "volume";
    case Invariant::kI10Tissue: return "tissue";
  }
  return "unknown";
}

const Violation* CheckReport::find(Invariant id) const {
  for (const Violation& v : violations)
    if (v.id == id) return &v;
  return nullptr;
}

std::string to_string(const CheckReport& report) {
  std::string out;
  for (const Violation& v : report.violations) {
    out += id_string(v.id);
    out += ' ';
    out += description(v.id);
    out += ": " + std::to_string(v.count) + " offending; " + v.detail + '\n';
  }
  for (const std::string& note : report.notes) out += "note: " + note + '\n';
  return out;
}

namespace {

using detail::RawTet;
using detail::ReportBuilder;
using detail::str;

void check_boundary_geometry(const RawMeshView& src, std::span<const detail::BoundaryTriangle> boundary,
                             const ReportBuilder& so_far, ReportBuilder& report, CheckReport& out) {
  // The surface test needs a consistently oriented 2-manifold boundary; otherwise the
  // combinatorial invariants already say what is wrong.
  for (Invariant id : {Invariant::kI1References, Invariant::kI3Conformity, Invariant::kI4Orientation,
                       Invariant::kI5VertexShell, Invariant::kI6EdgeShell}) {
    if (so_far.has(id)) {
      out.notes.push_back(std::string("exact level: boundary self-intersection test skipped: ") + id_string(id) +
                          " is violated, so the boundary is not a consistently oriented 2-manifold");
      return;
    }
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(boundary.size());
  for (const auto& b : boundary) triangles.push_back(b.v);
  const detail::SelfIntersections found =
      detail::find_boundary_self_intersections(src.positions, triangles, kMaxListed);
  if (!found.tested) {
    out.notes.push_back("exact level: boundary self-intersection test skipped: " + found.message);
    return;
  }
  for (const auto& [i, j] : found.first_pairs) {
    const auto& a = boundary[i];
    const auto& b = boundary[j];
    report.add(Invariant::kI3Conformity, {a.tet, b.tet}, {}, [&] {
      return "the boundary intersects itself: face (" + str(a.v[0]) + ", " + str(a.v[1]) + ", " + str(a.v[2]) +
             ") of tet " + str(a.tet) + " and face (" + str(b.v[0]) + ", " + str(b.v[1]) + ", " + str(b.v[2]) +
             ") of tet " + str(b.tet) + " (" + str(found.pair_count) + " intersecting pairs)";
    });
  }
  report.add_count(Invariant::kI3Conformity, found.pair_count - found.first_pairs.size());
}

CheckReport run_full(const RawMeshView& src, const CheckOptions& options) {
  CheckReport out;
  out.operation = options.operation;
  ReportBuilder report;
  const EngineRecordsView* engine = detail::usable_records(src, report);
  const auto tet_count = static_cast<std::uint32_t>(src.tets.size());
  const auto vertex_count = static_cast<std::uint32_t>(src.positions.size());

  // Pass 1: references (I1), and the incidence counts of the tets that passed.
  std::vector<std::uint8_t> excluded(tet_count, 0);
  std::vector<std::uint32_t> offsets(static_cast<std::size_t>(vertex_count) + 1, 0);
  std::uint64_t live_tets = 0;
  for (std::uint32_t t = 0; t < tet_count; ++t) {
    const RawTet& q = src.tets[t];
    if (src.has_tombstones && q[0] == kDeadTetMarker) {
      excluded[t] = 1;
      continue;
    }
    ++live_tets;
    if (!detail::check_references(t, q, src.positions, report)) {
      excluded[t] = 1;
      continue;
    }
    for (std::uint32_t v : q) ++offsets[v + 1];
  }
  for (std::uint32_t v = 0; v < vertex_count; ++v) offsets[v + 1] += offsets[v];

  // The checker's own vertex->tets incidence: a counting sort, flat, no per-vertex allocation.
  std::vector<std::uint32_t> incidence(offsets[vertex_count]);
  {
    std::vector<std::uint32_t> cursor(offsets.begin(), offsets.end() - 1);
    for (std::uint32_t t = 0; t < tet_count; ++t) {
      if (excluded[t]) continue;
      for (std::uint32_t v : src.tets[t]) incidence[cursor[v]++] = t;
    }
  }

  // Pass 2: one link analysis per vertex (I1 duplicates, I2, I3, I5, I6, I8 per vertex).
  const bool exact = options.level == CheckLevel::kExact;
  std::vector<detail::BoundaryTriangle> boundary;
  detail::LinkContext ctx;
  ctx.tets = src.tets;
  ctx.excluded = excluded;
  ctx.engine = engine;
  ctx.boundary = exact ? &boundary : nullptr;
  ctx.report = &report;
  detail::VertexLinkChecker link;
  std::uint64_t used_vertices = 0;
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    const std::span<const std::uint32_t> shell(incidence.data() + offsets[v], offsets[v + 1] - offsets[v]);
    if (!shell.empty()) {
      ++used_vertices;
      link.check(ctx, v, shell);
      continue;
    }
    if (engine != nullptr) detail::compare_unused_vertex(*engine, v, report);
  }

  // Pass 3: geometry of every tet that passed I1 and is not a duplicate.
  detail::TetGeometryChecker geometry(options.radius_ratio_floor, report);
  for (std::uint32_t t = 0; t < tet_count; ++t)
    if (!excluded[t]) geometry.check(t, src.tets[t], src.positions);
  geometry.finish(out);
  out.volume = geometry.volume();
  out.tets_checked = live_tets;
  out.vertices_checked = used_vertices;
  if (options.expected_volume) {
    detail::check_volume(out.volume, *options.expected_volume, *options.expected_volume,
                         options.volume_rel_tolerance, "the total volume", report);
  }

  if (engine != nullptr) detail::compare_counts(*engine, live_tets, used_vertices, vertex_count, report);

  if (exact) check_boundary_geometry(src, boundary, report, report, out);
  report.finish(out);
  return out;
}

}  // namespace

CheckReport check_raw(const RawMeshView& mesh, const CheckOptions& options) {
  RawMeshView tets_only = mesh;
  tets_only.engine.reset();
  return run_full(tets_only, options);
}

CheckReport check_mesh(const RawMeshView& mesh, const CheckOptions& options) { return run_full(mesh, options); }

}  // namespace tetcut::invariants

// Fuzz target checker_differential: the local checker (after_operation, O(operation)) and the
// full check (check_mesh, O(#T)) must reach the same verdict after every edit, including edits
// that break the manifold on purpose (removing any boundary or interior tet, or a few adjacent
// ones): both must say ok or not, and agree on whether I5 (vertex shells) and I6 (edge shells)
// are violated. A disagreement aborts with both reports.
//
// Once the mesh is not valid the sequence stops: the engine's operations assume a manifold mesh
// (replace_tets() walks vertex shells), and the local checker assumes the mesh was valid before
// each operation.
//
// Input: version byte, box (3 cell counts, 3 side lengths), then per edit an opcode and its
// arguments.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "cut/spatial_index.hpp"
#include "operations/mesh_edits.hpp"
#include "refine/edge_split.hpp"
#include "refine/refine.hpp"
#include "support/fuzz_failure.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

namespace {

using namespace tetcut;
namespace inv = tetcut::invariants;

constexpr std::uint32_t kMaxBoxCells = 2;
constexpr std::size_t kMaxEdits = 40;
constexpr std::uint32_t kMaxEdgesPerSplit = 6;
constexpr std::uint32_t kMaxSetSize = 4;
constexpr std::uint32_t kMaxTetsToRefine = 600;

enum class Edit : std::uint8_t { kSplit, kRemoveBoundaryTet, kRemoveAnyTet, kRemoveAdjacentSet, kRefine, kLast = kRefine };

const char* edit_name(Edit edit) {
  switch (edit) {
    case Edit::kSplit: return "split";
    case Edit::kRemoveBoundaryTet: return "remove boundary tet";
    case Edit::kRemoveAnyTet: return "remove tet";
    case Edit::kRemoveAdjacentSet: return "remove set";
    case Edit::kRefine: return "refine";
  }
  return "?";
}

// Also the net change of the last edit, for the local checker.
struct Workspace : fuzz::EditWorkspace {
  std::vector<TetId> removed, created;
};

void remove_adjacent_set(TetMesh& mesh, Workspace& ws, FuzzedDataProvider& input) {
  const TetId seed = fuzz::consume_live_tet(mesh, input);
  std::vector<TetId>& set = ws.tets;
  set.assign(1, seed);
  const std::uint32_t want = input.ConsumeIntegralInRange<std::uint32_t>(1, kMaxSetSize);
  // Grow across faces from tets already in the set, as the tool's cavity grows.
  while (set.size() < want && input.remaining_bytes() > 0) {
    const TetId from = set[input.ConsumeIntegralInRange<std::size_t>(0, set.size() - 1)];
    const FaceRef next = mesh.neighbour(from, input.ConsumeIntegralInRange<int>(0, 3));
    if (next.valid() && std::find(set.begin(), set.end(), next.tet) == set.end()) set.push_back(next.tet);
  }
  std::sort(set.begin(), set.end());
  mesh.remove_tets(set);
}

bool has(const inv::CheckReport& report, inv::Invariant id) { return report.find(id) != nullptr; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!fuzz::has_version(data, size)) return 0;
  FuzzedDataProvider input(data + 1, size - 1);
  TetMesh mesh = fuzz::consume_built_box_mesh(input, kMaxBoxCells);
  inv::LocalChecker local(mesh.raw_view());
  Workspace ws;
  // As in CheckedMesh: TETCUT_FUZZ_TRACE=1 prints each edit and the verdict, for triage.
  const char* env = std::getenv("TETCUT_FUZZ_TRACE");
  const bool tracing = env != nullptr && *env != '\0' && *env != '0';

  for (std::size_t i = 1; i <= kMaxEdits && input.remaining_bytes() > 0 && mesh.num_tets() > 0; ++i) {
    const Edit edit =
        static_cast<Edit>(input.ConsumeIntegralInRange<std::uint8_t>(0, static_cast<std::uint8_t>(Edit::kLast)));
    // Each edit is a transaction: its net change, as the journal records it, is what the local
    // checker is told.
    mesh.begin_transaction();
    switch (edit) {
      case Edit::kSplit:
        fuzz::consume_edges(mesh, input, kMaxEdgesPerSplit, ws.edges);
        ws.splitter.split(mesh, ws.edges, input.ConsumeBool() ? SplitMethod::kBisection : SplitMethod::kTemplates);
        break;
      case Edit::kRemoveBoundaryTet: {
        const TetId t = fuzz::consume_live_tet_where(mesh, input, [&](TetId c) { return mesh.boundary_face_count(c) > 0; });
        if (t.valid()) mesh.remove_tets(std::span<const TetId>(&t, 1));
        break;
      }
      case Edit::kRemoveAnyTet: {
        const TetId t = fuzz::consume_live_tet(mesh, input);
        mesh.remove_tets(std::span<const TetId>(&t, 1));
        break;
      }
      case Edit::kRemoveAdjacentSet: remove_adjacent_set(mesh, ws, input); break;
      case Edit::kRefine: {
        const Tool ball = fuzz::consume_ball(input, fuzz::bounding_box(mesh), 0.08, 0.3);
        RefineParams params;
        params.d_ref = 3.0 * ball.radius;
        params.max_iterations = input.ConsumeIntegralInRange<std::uint32_t>(1, 4);
        params.focus = ball;
        scan_tets_meeting(mesh, ball, ws.tets);  // O(#T): the targets' meshes are small
        if (mesh.num_tets() <= kMaxTetsToRefine) ws.refiner.refine(mesh, ws.tets, params, ws.region);
        break;
      }
    }
    mesh.transaction_changes(ws.removed, ws.created);
    mesh.commit();

    inv::CheckOptions options;
    options.level = inv::CheckLevel::kLocal;
    options.quality_rule = inv::QualityRule::kReportOnly;  // raw edits: the levels are compared, not the engine
    options.operation = edit_name(edit);
    const inv::CheckReport local_report = local.after_operation(mesh.raw_view(), ws.removed, ws.created, options);
    options.level = inv::CheckLevel::kFull;
    const inv::CheckReport full_report = inv::check_mesh(mesh.raw_view(), options);
    const bool agree = local_report.ok() == full_report.ok() &&
                       has(local_report, inv::Invariant::kI5VertexShell) == has(full_report, inv::Invariant::kI5VertexShell) &&
                       has(local_report, inv::Invariant::kI6EdgeShell) == has(full_report, inv::Invariant::kI6EdgeShell);
    if (!agree)
      fuzz::fail("checker-differential", i, edit_name(edit),
                 "local check: " + (local_report.ok() ? std::string("ok") : inv::to_string(local_report)) +
                     " | full check: " + (full_report.ok() ? std::string("ok") : inv::to_string(full_report)));
    if (tracing)
      std::fprintf(stderr, "tetcut-fuzz: operation %zu (%s): -%zu +%zu tets -> %u tets; %s\n", i, edit_name(edit),
                   ws.removed.size(), ws.created.size(), mesh.num_tets(),
                   full_report.ok() ? "valid" : inv::to_string(full_report).c_str());
    if (!full_report.ok()) break;  // non-manifold now: nothing downstream is defined on it
  }
  return 0;
}

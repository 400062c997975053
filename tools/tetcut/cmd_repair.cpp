// `tetcut repair IN -o OUT [--verbose]`. Makes a mesh manifold and positively
// oriented with tetcut::generators::repair_mesh, says what changed (counts, then the elements:
// the first ones, or all with --verbose), validates the result with the mesh builder, writes it
// and prints its canonical hash.
#include <ostream>
#include <string>

#include "command.hpp"
#include "command_parser.hpp"
#include "mesh_input.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/generators/repair.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::cli {
namespace {

using namespace tetcut::generators;

// Changes listed without --verbose.
constexpr std::size_t kListedChanges = 20;

constexpr RepairAction kActions[] = {
    RepairAction::kReoriented,         RepairAction::kRemovedInvalid,
    RepairAction::kRemovedFlat,        RepairAction::kRemovedDuplicate,
    RepairAction::kRemovedOverSharedFace, RepairAction::kRemovedSingularEdge,
    RepairAction::kRemovedSingularVertex,
};

void print_change(const RepairChange& c, std::ostream& out) {
  out << "  tet " << c.tet << ": " << to_string(c.action);
  if (c.at_b != kNoIndex)
    out << " (edge " << c.at_a << "-" << c.at_b << ")";
  else if (c.at_a != kNoIndex)
    out << " (vertex " << c.at_a << ")";
  out << '\n';
}

}  // namespace

int cmd_repair(Args args, std::ostream& out, std::ostream& err) {
  std::optional<std::string> in_arg, out_path;
  bool verbose = false;
  CommandParser parser("repair", "tetcut repair IN -o OUT [--verbose]",
                       "Makes a non-manifold or inverted mesh manifold and positively oriented with the smallest\n"
                       "change it can, and reports what it changed.\n",
                       "exit: 0, 1 the mesh could not be repaired, 2 unreadable input or bad usage");
  CLI::App& app = parser.app();
  opt::text(app, "IN", in_arg, "the mesh to repair", "")->required();
  opt::text(app, "-o,--out", out_path, "the repaired mesh", "OUT")->required();
  opt::flag(app, "--verbose", verbose, "list every change, not the first " + std::to_string(kListedChanges));
  if (const auto code = parser.parse(args, out, err)) return *code;
  const std::string& in = *in_arg;

  const std::optional<RawMesh> mesh = load_mesh(in, err);
  if (!mesh) return kExitBadInput;
  const RepairResult repaired = repair_mesh(*mesh);
  const RepairReport& r = repaired.report;

  out << in << ": " << mesh->positions.size() << " vertices, " << mesh->tets.size() << " tets\n";
  if (r.unchanged()) out << "nothing to repair\n";
  for (RepairAction action : kActions)
    if (const auto n = r.count(action)) out << to_string(action) << ": " << n << '\n';
  if (r.singular_edges_fixed || r.singular_vertices_fixed)
    out << "singular edges fixed: " << r.singular_edges_fixed
        << ", singular vertices fixed: " << r.singular_vertices_fixed << " (" << r.rounds
        << " sweeps)\n";
  if (!r.dropped_vertices.empty()) out << "dropped vertices: " << r.dropped_vertices.size() << '\n';
  const std::size_t listed = verbose ? r.changes.size() : std::min(r.changes.size(), kListedChanges);
  if (listed > 0) out << "changes (input tet indices):\n";
  for (std::size_t i = 0; i < listed; ++i) print_change(r.changes[i], out);
  if (listed < r.changes.size())
    out << "  ... and " << r.changes.size() - listed << " more (--verbose lists all)\n";

  if (!repaired.ok()) {
    err << "tetcut: " << in << ": " << repaired.error << '\n';
    return kExitViolated;
  }
  const BuildResult built = build_mesh(*repaired.mesh, BuildOptions{.reorient_inverted = false, .require_manifold = true});
  if (!built.ok()) {
    err << "tetcut: " << in << ": repair left a problem: " << built.problems.front().message << '\n';
    return kExitViolated;
  }
  const WriteResult written = write_mesh(*out_path, *repaired.mesh);
  if (!written.ok) {
    err << "tetcut: " << (written.error.empty() ? *out_path + ": cannot write" : written.error) << '\n';
    return kExitBadInput;
  }
  out << *out_path << ": " << repaired.mesh->positions.size() << " vertices, "
      << repaired.mesh->tets.size() << " tets, hash " << hash_to_hex(canonical_hash(*repaired.mesh))
      << '\n';
  return kExitOk;
}

}  // namespace tetcut::cli

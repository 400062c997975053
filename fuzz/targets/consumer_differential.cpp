// Fuzz target consumer_differential: the change log's consumers (tetcut::mechanics) against a
// rebuild after every cut of a random cut sequence (mechanics/differential.hpp): the stiffness
// tensors, masses, labels and rendered surface updated from each cut's ChangeLog must equal the
// same built from scratch, and the displacements of created vertices what the engine
// interpolated in its attribute channels. So a wrong or missing change-log entry is a finding
// ("consumer-differential"), as is any invariant the local checker finds broken after a cut.
//
// Input: version byte (kInputVersion, mesh_edits.hpp), then (FuzzedDataProvider) one of the small
// fuzz meshes (corpus/fuzz/meshes), the removal strategy, then up to kMaxCuts cuts, each a centre
// in the bounding box grown by 10 % and a tool diameter of 0.3 to 2 mean edges.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "operations/checked_mesh.hpp"
#include "operations/mesh_edits.hpp"
#include "operations/sequence_meshes.hpp"
#include "operations/sequence_target.hpp"
#include "support/fuzz_failure.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/differential.hpp"

namespace {

using namespace tetcut;
namespace inv = tetcut::invariants;

constexpr std::size_t kMaxCuts = 12;

// Labels 0..3 by a hash of the tet id, each its own material: an inherited label gone wrong
// changes the tensors, not only the label.
mechanics::ModelParams four_materials() {
  mechanics::ModelParams p;
  p.materials = {{3000, 0.45, 1000}, {6000, 0.40, 1050}, {1500, 0.45, 980}, {12000, 0.30, 1100}};
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!fuzz::has_version(data, size)) return 0;
  FuzzedDataProvider input(data + 1, size - 1);
  const fuzz::BundledMesh& start = fuzz::sequence_mesh(fuzz::kSequenceVersionSmall, input.ConsumeIntegral<std::uint8_t>());
  fuzz::CheckedMesh checked(start.mesh);
  TetMesh& mesh = checked.mesh();
  const auto strategy = static_cast<RemovalStrategy>(input.ConsumeIntegralInRange<std::uint8_t>(0, 3));
  Cutter cutter(mesh, {.tool_diameter = start.mean_edge, .strategy = strategy});
  std::vector<std::uint32_t> labels(mesh.tet_capacity());
  for (std::uint32_t t = 0; t < labels.size(); ++t) labels[t] = (t * 2654435761u >> 7) % 4;
  mechanics::DifferentialCheck check(mesh, four_materials(), std::move(labels));
  std::vector<double> volume(mesh.tet_capacity(), 0.0);
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) volume[t] = mesh.volume(TetId{t});

  const fuzz::Box& box = start.box;
  for (std::size_t i = 0; i < kMaxCuts && input.remaining_bytes() > 0 && mesh.num_tets() > 0; ++i) {
    const Vec3 size = box.hi - box.lo;
    const Vec3 centre{fuzz::consume_in(input, box.lo.x - 0.1 * size.x, box.hi.x + 0.1 * size.x),
                      fuzz::consume_in(input, box.lo.y - 0.1 * size.y, box.hi.y + 0.1 * size.y),
                      fuzz::consume_in(input, box.lo.z - 0.1 * size.z, box.hi.z + 0.1 * size.z)};
    CutParams params = cutter.params();
    params.tool_diameter = fuzz::consume_in(input, 0.3, 2.0) * start.mean_edge;
    if (cutter.set_params(params)) continue;
    checked.begin("cut");
    if (checked.tracing())
      checked.describe(fuzz::to_string(centre) + " diameter " + std::to_string(params.tool_diameter));
    check.before(mesh);
    ChangeLog log;
    const CutReport report = cutter.cut(centre, &log);
    double change = 0;
    for (TetId t : log.removed) change -= volume[t.value];
    volume.resize(mesh.tet_capacity(), 0.0);
    for (const CreatedTet& c : log.created) change += volume[c.tet.value] = mesh.volume(c.tet);
    // An ok cut is held to the tissue rule with its tool, and every cut to the theta it held.
    const inv::ToolRule tool{.centre = centre, .radius = params.tool_diameter / 2, .d_ref = params.d_ref(),
                             .left = cutter.last_left_in_tool()};
    checked.end(log, change, inv::QualityRule::kNoDegradation, report.ok ? &tool : nullptr,
                std::min(params.min_dihedral_deg, cutter.last_min_dihedral_held()));
    if (const auto problem = check.after(mesh, log))
      fuzz::fail("consumer-differential", checked.operation_index(), checked.operation_name(), *problem);
  }
  checked.full_check();
  return 0;
}

// The removal stage's planted bug alone (planted_removal_bug_test.cpp plants it together with a
// lying audit): a removal stage that removes nothing and reports ok. The cut's own audit of the
// tissue rule sees selected tissue in the tool that no request asked for, and refuses the cut:
// rolled back, the mesh as it was, the refusal named.
#include <gtest/gtest.h>

#include <string>

#include "cut/removal_loop.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::detail {

void RemovalLoop::reserve(std::uint32_t) {}

bool RemovalLoop::run(const Context& ctx, CutReport& report) {
  report.requested = static_cast<std::uint32_t>(ctx.selection.removal().size());
  return true;
}

}  // namespace tetcut::detail

namespace tetcut::testing {
namespace {

TEST(PlantedRemovalBug, TheCutsOwnAuditRefusesACutThatRemovedNothingItSelected) {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/liver.msh");
  ASSERT_TRUE(read.mesh.has_value());
  BuildResult built = build_mesh(*read.mesh);
  ASSERT_TRUE(built.ok());
  TetMesh mesh = std::move(*built.mesh);
  Cutter cutter(mesh, {.tool_diameter = 8.0});
  std::uint32_t refused = 0;
  for (double y = 40; y <= 180; y += 16) {
    const std::uint64_t before = canonical_hash(mesh);
    const CutReport r = cutter.cut({95, y, 100});
    if (r.requested == 0) continue;
    EXPECT_FALSE(r.ok) << "cut at y " << y << ": " << r.requested << " selected, none removed, reported ok";
    EXPECT_EQ(r.refusal, CutRefusal::kTissueRule);
    EXPECT_NE(r.failure.find("never requested"), std::string::npos) << r.failure;
    EXPECT_EQ(canonical_hash(mesh), before) << "a refused cut leaves the mesh as it was";
    ++refused;
  }
  EXPECT_GT(refused, 3u);
}

}  // namespace
}  // namespace tetcut::testing

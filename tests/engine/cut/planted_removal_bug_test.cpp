// A planted bug the tissue rule (I10) must catch: this program links its own RemovalLoop and
// TissueAudit ahead of the engine's (the linker takes a symbol from the first object that defines
// it, and then never pulls the engine's removal_loop.o and tissue_audit.o): a removal stage that
// removes nothing, and an audit that reports the cut ok with nothing left in the tool. Every
// other invariant holds after such a cut (nothing changed but the refinement, which is valid);
// only the tissue rule sees that the tool's tissue is still there, and so the local checker, the
// scenario runner and everything built on them must fail. (planted_removal_only_test.cpp plants
// the first bug alone: the cut's own audit refuses it.)
#include <gtest/gtest.h>

#include <string>

#include "checked.hpp"
#include "cut/removal_loop.hpp"
#include "cut/tissue_audit.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::detail {

void RemovalLoop::reserve(std::uint32_t) {}

// The bug: T_removal counted as requested, and nothing removed.
bool RemovalLoop::run(const Context& ctx, CutReport& report) {
  report.requested = static_cast<std::uint32_t>(ctx.selection.removal().size());
  return true;
}

// And a report that says so: nothing left in the tool.
void TissueAudit::reserve(std::uint32_t) {}
std::optional<std::string> TissueAudit::run(const Context&, CutReport& report) {
  left_.clear();
  report.left_in_tool = 0;
  return std::nullopt;
}

}  // namespace tetcut::detail

namespace tetcut::testing {
namespace {

TetMesh liver() {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/liver.msh");
  EXPECT_TRUE(read.mesh.has_value());
  BuildResult built = build_mesh(*read.mesh);
  EXPECT_TRUE(built.ok());
  return std::move(*built.mesh);
}

TEST(PlantedRemovalBug, TheTissueRuleCatchesACutThatReportsOkAndRemovesNothing) {
  TetMesh mesh = liver();
  Cutter cutter(mesh, {.tool_diameter = 8.0});
  invariants::LocalChecker local(mesh.raw_view());
  std::uint32_t caught = 0, selecting = 0;
  for (double y = 40; y <= 180; y += 16) {
    const Vec3 centre{95, y, 100};
    const CutReport r = cutter.cut(centre);
    ASSERT_TRUE(r.ok) << r.failure;
    EXPECT_EQ(r.tets_removed, 0u);
    EXPECT_EQ(r.left_in_tool, 0u);
    selecting += r.requested > 0 ? 1 : 0;
    const invariants::CheckReport with_tool =
        local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), cut_check(cutter, centre));
    const invariants::Violation* v = with_tool.find(invariants::Invariant::kI10Tissue);
    if (r.requested > 0) {
      ASSERT_NE(v, nullptr) << "cut at y " << y << ": " << r.requested << " tets selected, none removed, no I10";
      EXPECT_NE(v->detail.find("still there"), std::string::npos) << v->detail;
      ++caught;
    }
    for (const invariants::Violation& other : with_tool.violations)
      EXPECT_EQ(other.id, invariants::Invariant::kI10Tissue) << other.detail;
  }
  EXPECT_GT(selecting, 3u);
  EXPECT_EQ(caught, selecting);
}

TEST(PlantedRemovalBug, AScenarioStopsAtTheFirstCutThatLeavesItsTissue) {
  const std::string text = "mesh " + std::string(TETCUT_CORPUS_DIR) + "/meshes/liver.msh\ndiameter 8\ncut 95,100,100\n";
  const scenario::ParseResult parsed = scenario::parse(text, "planted.scn", ".");
  ASSERT_TRUE(parsed.scenario.has_value()) << parsed.error;
  const scenario::RunResult r = scenario::run(*parsed.scenario);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.failed_line, 3u);
  EXPECT_NE(r.reason.find("I10"), std::string::npos) << r.reason;
}

}  // namespace
}  // namespace tetcut::testing

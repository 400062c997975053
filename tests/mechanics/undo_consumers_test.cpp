// The consumers through Cutter::undo() (ChangeLog::undo): the elastic model, the rendered surface
// and the labels, each kept from the cuts' and the undos' logs alone, against a rebuild after
// every operation (differential.hpp), the witness's labels for a restored tet being the ones it
// had before the cut that took it; the independent checker after each operation too. Then the
// planted bug: an undo log that forgets a tet it restores.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <string>

#include "../engine/checked.hpp"  // cut_check
#include "mechanics_test_support.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mechanics/differential.hpp"
#include "tetcut/mechanics/tet_labels.hpp"

namespace tetcut {
namespace {

using mechanics::DifferentialCheck;

struct UndoRun {
  std::uint32_t cuts = 0, undos = 0, restored_tets = 0, moved_back = 0;
  std::optional<std::string> problem;
};

// The small-tool sweep of the cylinder (a tool of 0.2, about 0.4 of its median edge: its pass
// moves vertices there before, consumer_differential_test.cpp's MovedVertices), with undo_history
// 3: after every third cut, two undos. Each log, as given or as `corrupt` changes an undo's, is
// applied to the consumers and checked.
template <class Corrupt>
UndoRun sweep_with_undos(Corrupt corrupt) {
  TetMesh mesh = testing::load_bundled("cylinder.msh");
  const double diameter = 0.2;
  Cutter cutter(mesh, {.tool_diameter = diameter, .undo_history = 3});
  DifferentialCheck check(mesh, testing::four_materials(), testing::hashed_labels(mesh));
  check.keep_history(3);
  mechanics::TetLabels labels(mesh, testing::hashed_labels(mesh));
  labels.keep_history(3);
  invariants::LocalChecker local(mesh.raw_view());
  UndoRun run;
  const Vec3 from{0, -0.8, 0.5}, to{0, 0.8, 3.5};
  const int steps = static_cast<int>(norm(to - from) / (diameter / 3));
  auto after = [&](const ChangeLog& log, const invariants::CheckOptions& o) {
    const invariants::CheckReport l = local.after_operation(mesh.raw_view(), cutter.last_removed(), cutter.last_created(), o);
    if (!l.ok()) return run.problem = "checker: " + invariants::to_string(l), false;
    if ((run.problem = check.after(mesh, log))) return false;
    if (labels.apply(mesh, log) != 0) return run.problem = "labels: orphans", false;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      if (mesh.is_live(TetId{t}) && labels.label(TetId{t}) != check.model().label(TetId{t}))
        return run.problem = "labels: tet " + std::to_string(t) + " differs from the model's", false;
    return true;
  };
  for (int k = 0; k <= steps && !run.problem; ++k) {
    const Vec3 centre = from + (static_cast<double>(k) / steps) * (to - from);
    check.before(mesh);
    ChangeLog log;
    const CutReport r = cutter.cut(centre, &log);
    if (!r.ok) return run.problem = "cut refused: " + r.failure, run;
    ++run.cuts;
    if (!after(log, testing::cut_check(cutter, centre))) break;
    if (k % 3 != 2) continue;
    for (int u = 0; u < 2 && !run.problem; ++u) {
      check.before(mesh);
      ChangeLog back;
      if (auto refused = cutter.undo(&back)) return run.problem = "undo refused: " + *refused, run;
      ++run.undos;
      run.restored_tets += static_cast<std::uint32_t>(back.created.size());
      run.moved_back += static_cast<std::uint32_t>(back.moved.size());
      corrupt(back);
      after(back, testing::undo_check(cutter));
    }
  }
  return run;
}

TEST(UndoConsumers, TheModelSurfaceAndLabelsEqualARebuildAfterEveryCutAndUndo) {
  const UndoRun run = sweep_with_undos([](ChangeLog&) {});
  EXPECT_FALSE(run.problem) << *run.problem;
  EXPECT_GT(run.undos, 0u);
  EXPECT_GT(run.restored_tets, 0u);
  EXPECT_GT(run.moved_back, 0u) << "no undo moved a vertex back: the sweep tests less than it says";
  std::printf("%u cuts, %u undos: %u tets restored, %u vertices moved back\n", run.cuts, run.undos, run.restored_tets,
              run.moved_back);
}

TEST(PlantedLogBug, AnUndoLogThatForgetsARestoredTetFailsTheDifferentialCheck) {
  const UndoRun run = sweep_with_undos([](ChangeLog& log) {
    if (!log.created.empty()) log.created.pop_back();
  });
  ASSERT_TRUE(run.problem) << "the check passed an undo log that forgot a tet it restored";
  EXPECT_NE(run.problem->find("mechanics"), std::string::npos) << *run.problem;
}

}  // namespace
}  // namespace tetcut

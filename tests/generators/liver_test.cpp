// The liver generator: CGAL Mesh_3 on Debian's segmented liver, repaired to a manifold. A coarse
// cell size keeps this fast; the corpus livers are checked by corpus_test.
#include <gtest/gtest.h>

#include <filesystem>

#include "tetcut/canonical_hash.hpp"
#include "tetcut/generators/liver.hpp"
#include "tetcut/generators/singularities.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::generators {
namespace {

TEST(Liver, ACoarseLiverIsManifoldAndDeterministic) {
  if (!std::filesystem::exists(kCgalDataTarball)) GTEST_SKIP() << kCgalDataTarball << " not installed";
  LiverOptions o;
  o.cell_size = 20.0;
  RepairReport repair;
  const GenResult a = generate_liver(o, &repair);
  ASSERT_TRUE(a.ok()) << a.error;
  EXPECT_GT(a.mesh->tets.size(), 300u);
  EXPECT_TRUE(find_singularities(*a.mesh).empty());
  EXPECT_TRUE(build_mesh(*a.mesh, BuildOptions{.reorient_inverted = false, .require_manifold = true}).ok());
  const GenResult b = generate_liver(o);
  ASSERT_TRUE(b.ok()) << b.error;
  EXPECT_EQ(canonical_hash(*a.mesh), canonical_hash(*b.mesh));
}

// A real mesh from another tool, as it comes: CGAL Mesh_3's complex at the corpus liver's size
// has singular vertices or edges. The independent checker and the generators' own singularity
// finder must agree that it is not a manifold, and repair must make it one.
TEST(Liver, RawMesh3OutputIsDiagnosedNonManifoldByTheChecker) {
  LiverOptions o;
  o.cell_size = 8.0;
  o.repair = false;
  const GenResult raw = generate_liver(o);
  ASSERT_TRUE(raw.ok()) << raw.error;
  const auto singular = find_singularities(*raw.mesh);
  ASSERT_FALSE(singular.empty()) << "Mesh_3's output is expected to have singularities here";
  const invariants::CheckReport report = invariants::check_raw(*raw.mesh);
  EXPECT_FALSE(report.ok());
  EXPECT_TRUE(report.find(invariants::Invariant::kI5VertexShell) || report.find(invariants::Invariant::kI6EdgeShell));
  EXPECT_FALSE(build_mesh(*raw.mesh).ok()) << "the builder refuses it too";
  const RepairResult repaired = repair_mesh(*raw.mesh);
  ASSERT_TRUE(repaired.ok()) << repaired.error;
  EXPECT_TRUE(invariants::check_raw(*repaired.mesh, {.level = invariants::CheckLevel::kExact}).ok());
}

TEST(Liver, AMissingImageIsReportedByName) {
  LiverOptions o;
  o.image_path = "/nonexistent/liver.inr.gz";
  const GenResult r = generate_liver(o);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("/nonexistent/liver.inr.gz"), std::string::npos) << r.error;
}

TEST(Liver, TheSizeCalibrationIsMonotone) {
  EXPECT_GT(liver_cell_size_for_tets(4000), liver_cell_size_for_tets(8500));
  EXPECT_GT(liver_cell_size_for_tets(8500), liver_cell_size_for_tets(16000));
}

}  // namespace
}  // namespace tetcut::generators

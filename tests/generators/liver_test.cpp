// The liver generator: CGAL Mesh_3 on Debian's segmented liver, repaired to a manifold. A coarse
// cell size keeps this fast; the corpus livers are checked by corpus_test.
#include <gtest/gtest.h>

#include <filesystem>

#include "tetcut/canonical_hash.hpp"
#include "tetcut/generators/liver.hpp"
#include "tetcut/generators/singularities.hpp"
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

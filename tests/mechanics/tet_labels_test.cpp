// Per-tet labels beyond the elastic model: TetLabels (what the command line carries through a
// cut and writes back) follows compaction, and a material per label (ModelParams::
// label_materials) reaches the tensors of exactly the tets with that label.
#include <gtest/gtest.h>

#include "mechanics_test_support.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mechanics/tet_labels.hpp"
#include "tetcut/mechanics/tensor_mass.hpp"

namespace tetcut {
namespace {

TEST(TetLabels, LabelsFollowTheirTetsThroughCutsAndCompaction) {
  TetMesh mesh = testing::load_bundled("cylinder.msh");
  const std::vector<std::uint32_t> initial = testing::hashed_labels(mesh);
  mechanics::TetLabels labels(mesh, initial);
  Cutter cutter(mesh, {.tool_diameter = 0.8 * mesh.mean_edge_length()});
  const BoundingBox box = bounding_box(mesh);
  for (const Vec3& centre : testing::lancet_sweep(box, 4)) {
    ChangeLog log;
    ASSERT_TRUE(cutter.cut(centre, &log).ok);
    EXPECT_EQ(labels.apply(mesh, log), 0u);
  }
  // Each live tet's label, keyed by its vertex positions (which compaction keeps).
  auto by_shape = [&](const TetMesh& m, auto label_of) {
    std::vector<std::pair<std::array<double, 12>, std::uint32_t>> out;
    for (std::uint32_t t = 0; t < m.tet_capacity(); ++t) {
      if (!m.is_live(TetId{t})) continue;
      std::array<double, 12> key{};
      const auto v = m.tet(TetId{t});
      for (int i = 0; i < 4; ++i) {
        const Vec3 p = m.position(v[i]);
        key[3 * i] = p.x, key[3 * i + 1] = p.y, key[3 * i + 2] = p.z;
      }
      out.emplace_back(key, label_of(TetId{t}));
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto before = by_shape(mesh, [&](TetId t) { return labels.label(t); });
  labels.renumber(cutter.compact());
  const auto after = by_shape(mesh, [&](TetId t) { return labels.label(t); });
  EXPECT_EQ(before, after);
  std::uint32_t distinct = 0;
  for (std::uint32_t l = 0; l < 4; ++l)
    distinct += std::any_of(after.begin(), after.end(), [&](const auto& e) { return e.second == l; }) ? 1 : 0;
  EXPECT_EQ(distinct, 4u);
}

TEST(LabelMaterials, ALabelsMaterialReachesExactlyItsTets) {
  BuildResult built = build_mesh(make_box_mesh(3, 3, 3, {0, 0, 0}, {1, 1, 1}));
  ASSERT_TRUE(built.ok());
  const TetMesh& mesh = *built.mesh;
  // Region 1000 in the lower half by centroid, region 7 above (file-like ids, far past the
  // `materials` vector).
  std::vector<std::uint32_t> labels(mesh.tet_capacity());
  for (std::uint32_t t = 0; t < labels.size(); ++t) {
    const auto v = mesh.tet(TetId{t});
    const double z = (mesh.position(v[0]).z + mesh.position(v[1]).z + mesh.position(v[2]).z + mesh.position(v[3]).z) / 4;
    labels[t] = z < 0.5 ? 1000 : 7;
  }
  mechanics::ModelParams uniform;
  uniform.length_unit = 1.0;
  mechanics::ModelParams stiff_below = uniform;
  stiff_below.label_materials = {{7, uniform.materials[0]}, {1000, {9000, 0.45, 1000}}};
  ASSERT_FALSE(mechanics::validate(stiff_below));
  const mechanics::TensorMassModel a(mesh, uniform, labels), b(mesh, stiff_below, labels);
  EXPECT_EQ(b.material_of(1000).young, 9000);
  EXPECT_EQ(b.material_of(7).young, 3000);
  EXPECT_EQ(b.material_of(8).young, 3000);  // not listed: the `materials` rule
  // A vertex whose tets are all above keeps its tensor; one whose tets are all below has it
  // scaled by the ratio of the moduli (same Poisson ratio: K is linear in E).
  std::uint32_t above = 0, below = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const Vec3 p = mesh.position(VertId{v});
    const auto& ka = a.vertex_stiffness(VertId{v});
    const auto& kb = b.vertex_stiffness(VertId{v});
    if (p.z > 0.9) {
      ++above;
      for (int i = 0; i < 9; ++i) EXPECT_EQ(ka[i], kb[i]);
    } else if (p.z < 0.1) {
      ++below;
      for (int i = 0; i < 9; ++i) EXPECT_NEAR(kb[i], 3 * ka[i], 1e-12 * std::abs(3 * ka[i]) + 1e-300);
    }
  }
  EXPECT_GT(above, 0u);
  EXPECT_GT(below, 0u);
  // The stable step sees the fastest material in use.
  EXPECT_LT(b.stable_time_step(mesh).dt, a.stable_time_step(mesh).dt);
  mechanics::ModelParams unsorted = stiff_below;
  std::swap(unsorted.label_materials[0], unsorted.label_materials[1]);
  EXPECT_TRUE(mechanics::validate(unsorted));
}

}  // namespace
}  // namespace tetcut

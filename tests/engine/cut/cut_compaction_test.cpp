// A Cutter indexes its mesh's tet ids. compact() renumbers them, and assigning another mesh into
// the object replaces them: either behind the Cutter's back must be caught (the cut refused with
// a message, the mesh untouched), never a cut on stale ids. Compacting through the Cutter is the
// way that keeps it current.
#include <gtest/gtest.h>

#include "checked.hpp"
#include "test_meshes.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"

namespace tetcut {
namespace {

constexpr Vec3 kTopCentre{0.5, 0.5, 1.0};
constexpr Vec3 kBottomCentre{0.5, 0.5, 0.0};

TetMesh box() { return testing::build_or_fail(make_box_mesh(4, 4, 4)); }

// A mesh with tombstones, so that compact() really renumbers.
void cut_once(Cutter& cutter) {
  const CutReport r = cutter.cut(kTopCentre);
  ASSERT_TRUE(r.ok) << r.failure;
  ASSERT_GT(r.tets_removed, 0u);
  ASSERT_GT(cutter.mesh().tet_capacity(), cutter.mesh().num_tets());
}

// The Cutter is current again: it cuts, removes, and leaves a valid mesh.
void expect_current_and_cutting(Cutter& cutter) {
  EXPECT_TRUE(cutter.indexes_current_mesh());
  const CutReport r = cutter.cut(kBottomCentre);
  EXPECT_TRUE(r.ok) << r.failure;
  EXPECT_GT(r.tets_removed, 0u);
  EXPECT_TRUE(testing::mesh_is_valid(cutter.mesh()));
}

TEST(CutterAndCompaction, MeshCompactedBehindTheCuttersBackIsRefusedAndLeftUntouched) {
  TetMesh mesh = box();
  Cutter cutter(mesh, {.tool_diameter = 0.5});
  cut_once(cutter);
  ASSERT_TRUE(cutter.indexes_current_mesh());
  const TetId some_tet = cutter.tet_containing(kBottomCentre);
  ASSERT_TRUE(some_tet.valid());

  mesh.compact();  // the wrong order: the Cutter's index still holds the old ids
  EXPECT_FALSE(cutter.indexes_current_mesh());
  const std::uint64_t hash = canonical_hash(mesh);
  const std::uint32_t capacity = mesh.tet_capacity();

  const CutReport cut = cutter.cut(kBottomCentre);
  EXPECT_FALSE(cut.ok);
  EXPECT_NE(cut.failure.find("Cutter::compact()"), std::string::npos) << cut.failure;
  EXPECT_EQ(cut.tets_removed, 0u);
  const CutReport removal = cutter.remove(TetId{0});
  EXPECT_FALSE(removal.ok);
  EXPECT_NE(removal.failure.find("Cutter::compact()"), std::string::npos) << removal.failure;
  EXPECT_FALSE(cutter.tet_containing(kBottomCentre).valid()) << "no tet found through stale ids";
  EXPECT_EQ(canonical_hash(mesh), hash);
  EXPECT_EQ(mesh.tet_capacity(), capacity);

  cutter.reset();  // re-indexes the compacted mesh
  expect_current_and_cutting(cutter);
}

TEST(CutterAndCompaction, CompactingThroughTheCutterKeepsItCurrent) {
  TetMesh mesh = box();
  Cutter cutter(mesh, {.tool_diameter = 0.5});
  cut_once(cutter);
  const std::uint32_t live = mesh.num_tets();
  cutter.compact();
  EXPECT_EQ(mesh.tet_capacity(), live);
  expect_current_and_cutting(cutter);
}

TEST(CutterAndCompaction, AnotherMeshAssignedIntoTheHeldObjectIsRefusedUntilReset) {
  TetMesh mesh = box();
  Cutter cutter(mesh, {.tool_diameter = 0.5});
  cut_once(cutter);
  mesh = box();  // a new case in the same object, even one with the very same content
  EXPECT_FALSE(cutter.indexes_current_mesh());
  EXPECT_FALSE(cutter.cut(kTopCentre).ok);
  cutter.reset();
  expect_current_and_cutting(cutter);
}

TEST(CutterAndCompaction, ACopyOfAMeshIsANewObjectAFreshCutterMayIndex) {
  const TetMesh original = box();
  TetMesh copy = original;
  Cutter cutter(copy, {.tool_diameter = 0.5});
  EXPECT_TRUE(cutter.indexes_current_mesh());
  EXPECT_TRUE(cutter.cut(kTopCentre).ok);
}

}  // namespace
}  // namespace tetcut

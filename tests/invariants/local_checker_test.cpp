// The local level agrees with the full level, operation after operation.
#include <gtest/gtest.h>

#include <vector>

#include "core/random.hpp"
#include "test_support.hpp"

namespace tetcut::invariants::testing {
namespace {

// Splits tet t at its centroid into four (vertex i replaced by the centroid in child i: each
// child keeps the parent's orientation).
std::vector<TetId> split_at_centroid(TetMesh& mesh, TetId t) {
  const auto parent = mesh.tet(t);
  Vec3 c{};
  for (VertId v : parent) c = c + 0.25 * mesh.position(v);
  const VertId centre = mesh.add_vertex(c);
  std::vector<TetMesh::TetVerts> children;
  for (int i = 0; i < 4; ++i) {
    TetMesh::TetVerts child = parent;
    child[i] = centre;
    children.push_back(child);
  }
  std::vector<TetId> created;
  const TetId removed[] = {t};
  mesh.replace_tets(removed, children, &created);
  return created;
}

// I7 judges a split at the centroid like any transaction: the children are worse than their
// parent, so with F = 1 (the floor is then the parent's own ratio) each is a violation naming the
// tet it replaces; with F below every child's ratio, nothing is.
TEST(LocalChecker, I7ACreatedTetWorseThanWhatItReplacedIsNamedWithItsHost) {
  auto check = [](double floor) {
    TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
    LocalChecker local(mesh.raw_view());
    const TetId t{17};
    const std::vector<TetId> created = split_at_centroid(mesh, t);
    const TetId removed[] = {t};
    return local.after_operation(mesh.raw_view(), removed, created, {.quality_floor = floor}, 0.0);
  };
  const CheckReport strict = check(1.0);
  const Violation* v = strict.find(Invariant::kI7Quality);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->count, 4u);
  EXPECT_NE(v->detail.find("its hosts: 17 ("), std::string::npos) << v->detail;
  EXPECT_TRUE(check(0.05).ok()) << to_string(check(0.05));
}

// The dihedral term of I7, per created tet: a centroid split's children have smaller angles than
// their parent; at theta = 70 degrees (the floor is then the parent's own smallest angle) each
// child is a violation naming its angle and its host; at theta = 0 and F = 0, none is.
TEST(LocalChecker, I7ACreatedTetWithASmallerDihedralThanItsHostIsNamed) {
  auto check = [](double theta) {
    TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
    LocalChecker local(mesh.raw_view());
    const TetId t{17};
    const std::vector<TetId> created = split_at_centroid(mesh, t);
    const TetId removed[] = {t};
    return local.after_operation(mesh.raw_view(), removed, created, {.quality_floor = 0.0, .min_dihedral_deg = theta}, 0.0);
  };
  const CheckReport strict = check(70.0);
  const Violation* v = strict.find(Invariant::kI7Quality);
  ASSERT_NE(v, nullptr);
  EXPECT_GT(v->count, 0u);
  EXPECT_NE(v->detail.find("smallest dihedral angle"), std::string::npos) << v->detail;
  EXPECT_NE(v->detail.find("its hosts: 17 ("), std::string::npos) << v->detail;
  EXPECT_TRUE(check(0.0).ok()) << to_string(check(0.0));
}

// A raw split is reported, not judged by I7's no-degradation rule (a Cutter transaction's).
const CheckOptions kRawSplit{.quality_rule = QualityRule::kReportOnly};

TEST(LocalChecker, AValidSplitPassesAndKeepsTheVolume) {
  TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
  LocalChecker local(mesh.raw_view());
  const TetId t{17};
  const double before = mesh.volume(t);
  const std::vector<TetId> created = split_at_centroid(mesh, t);
  ASSERT_EQ(created.size(), 4u);
  const TetId removed[] = {t};
  const CheckReport report = local.after_operation(mesh.raw_view(), removed, created, kRawSplit, 0.0);
  EXPECT_TRUE(report.ok()) << to_string(report);
  EXPECT_NEAR(report.volume, 0.0, 1e-15);
  EXPECT_EQ(report.quality.tets, 4u);
  EXPECT_EQ(report.vertices_checked, 5u);
  EXPECT_TRUE(check_mesh(mesh.raw_view()).ok()) << to_string(check_mesh(mesh.raw_view()));
  EXPECT_GT(before, 0.0);
}

TEST(LocalChecker, I9AWrongVolumeChangeIsNamed) {
  TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
  LocalChecker local(mesh.raw_view());
  const TetId t{3};
  const std::vector<TetId> created = split_at_centroid(mesh, t);
  const TetId removed[] = {t};
  const CheckReport report = local.after_operation(mesh.raw_view(), removed, created, kRawSplit, -1e-3);
  EXPECT_EQ(names(report), "I9") << to_string(report);
}

TEST(LocalChecker, RemovalReducesTheVolumeByTheRemovedTet) {
  TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
  LocalChecker local(mesh.raw_view());
  const TetId t{0};
  const double v = mesh.volume(t);
  const TetId removed[] = {t};
  mesh.remove_tets(removed);
  const CheckReport report = local.after_operation(mesh.raw_view(), removed, {}, {}, -v);
  EXPECT_TRUE(report.ok()) << to_string(report);
  EXPECT_DOUBLE_EQ(report.volume, -v);
}

TEST(LocalChecker, AnOperationThatLiesAboutWhatItRemovedIsI8) {
  TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
  LocalChecker local(mesh.raw_view());
  const TetId removed[] = {TetId{5}};
  mesh.remove_tets(removed);
  const TetId claimed[] = {TetId{6}};  // still live
  const CheckReport report = local.after_operation(mesh.raw_view(), claimed, {});
  EXPECT_TRUE(has(report, Invariant::kI8Bookkeeping)) << to_string(report);
}

// `tetcut check --level local` on a file pretends one operation replaced every tet by itself;
// that must check the whole mesh like the full level does.
TEST(LocalChecker, ReplacingEveryTetByItselfChecksTheWholeMesh) {
  for (bool bowtie : {false, true}) {
    RawMesh raw = make_box_mesh(2, 2, 2);
    if (bowtie) raw = weld(raw, make_box_mesh(2, 2, 2, {1, 1, 1}, {1, 1, 1}));
    BuildOptions build;
    build.require_manifold = false;
    BuildResult built = build_mesh(raw, build);
    ASSERT_TRUE(built.ok());
    const TetMesh& mesh = *built.mesh;
    std::vector<TetId> all;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      if (mesh.is_live(TetId{t})) all.push_back(TetId{t});
    LocalChecker local(mesh.raw_view());
    const CheckReport report = local.after_operation(mesh.raw_view(), all, all, {}, 0.0);
    EXPECT_EQ(names(report), bowtie ? "I5" : "") << to_string(report);
    EXPECT_EQ(names(report), names(check_mesh(mesh.raw_view())));
    EXPECT_EQ(report.vertices_checked, raw.positions.size());
  }
}

std::string listed(const CheckReport& r, Invariant id) {
  const Violation* v = r.find(id);
  if (v == nullptr) return "-";
  std::string out = std::to_string(v->count);
  out += ':';
  for (std::uint32_t x : v->vertices) {
    out += ' ';
    out += std::to_string(x);
  }
  return out;
}

// Random removals of boundary tets from a box, one at a time, until the first one that breaks
// the mesh (often: removing a tet whose opposite vertex or edge is on the surface pinches it,
// paper 3.3). After every removal the local check of that removal and the full check of the
// whole mesh must say the same.
TEST(LocalChecker, AgreesWithTheFullCheckOnRandomRemovals) {
  SplitMix64 rng(0x7e7c07);
  const RawMesh box = make_box_mesh(3, 3, 2);
  int ended_i5 = 0, ended_i6 = 0, steps = 0;
  for (int trial = 0; trial < 60; ++trial) {
    TetMesh mesh = build_or_fail(box);
    LocalChecker local(mesh.raw_view());
    for (int step = 0; step < 40 && mesh.num_tets() > 0; ++step) {
      std::vector<TetId> candidates;
      for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
        if (mesh.is_live(TetId{t}) && mesh.boundary_face_count(TetId{t}) > 0) candidates.push_back(TetId{t});
      ASSERT_FALSE(candidates.empty());
      const TetId removed[] = {candidates[rng.below(static_cast<std::uint32_t>(candidates.size()))]};
      mesh.remove_tets(removed);
      ++steps;
      const CheckReport local_report = local.after_operation(mesh.raw_view(), removed, {});
      const CheckReport full_report = check_mesh(mesh.raw_view());
      ASSERT_EQ(local_report.ok(), full_report.ok())
          << "trial " << trial << " step " << step << "\nlocal:\n" << to_string(local_report) << "full:\n"
          << to_string(full_report);
      ASSERT_EQ(names(local_report), names(full_report)) << "trial " << trial << " step " << step;
      // The same singular vertices and edges, not just the same invariant names.
      ASSERT_EQ(listed(local_report, Invariant::kI5VertexShell), listed(full_report, Invariant::kI5VertexShell));
      ASSERT_EQ(listed(local_report, Invariant::kI6EdgeShell), listed(full_report, Invariant::kI6EdgeShell));
      if (!full_report.ok()) {
        ended_i5 += has(full_report, Invariant::kI5VertexShell);
        ended_i6 += has(full_report, Invariant::kI6EdgeShell);
        break;
      }
    }
  }
  // The walk must actually have met both kinds of singularity, or it proved little.
  EXPECT_GT(ended_i5, 5);
  EXPECT_GT(ended_i6, 5);
  EXPECT_GT(steps, 100);
}

// Splits keep the mesh valid: the local and full levels agree on a long sequence of them, and
// the local checker's own index follows the id reuse of the engine's free list.
TEST(LocalChecker, AgreesWithTheFullCheckOnRandomSplits) {
  SplitMix64 rng(42);
  TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
  LocalChecker local(mesh.raw_view());
  for (int step = 0; step < 200; ++step) {
    std::vector<TetId> live;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
      if (mesh.is_live(TetId{t})) live.push_back(TetId{t});
    const TetId t = live[rng.below(static_cast<std::uint32_t>(live.size()))];
    const std::vector<TetId> created = split_at_centroid(mesh, t);
    const TetId removed[] = {t};
    const CheckReport local_report = local.after_operation(mesh.raw_view(), removed, created, kRawSplit, 0.0);
    ASSERT_TRUE(local_report.ok()) << "step " << step << ": " << to_string(local_report);
    const CheckReport full_report = check_mesh(mesh.raw_view());
    ASSERT_TRUE(full_report.ok()) << "step " << step << ": " << to_string(full_report);
  }
  CheckOptions options;
  options.expected_volume = 1.0;
  EXPECT_TRUE(check_mesh(mesh.raw_view(), options).ok()) << to_string(check_mesh(mesh.raw_view(), options));
}

}  // namespace
}  // namespace tetcut::invariants::testing

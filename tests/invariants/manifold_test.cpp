// I5 and I6 on hand-built meshes, valid and non-manifold alike.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_support.hpp"

namespace tetcut::invariants::testing {
namespace {

const Vec3 kO{0, 0, 0}, kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

TEST(Manifold, OneTetIsValid) {
  const RawMesh raw{{kO, kX, kY, kZ}, {{0, 1, 2, 3}}};
  EXPECT_TRUE(check_raw(raw, exact()).ok()) << to_string(check_raw(raw, exact()));
}

TEST(Manifold, TwoTetsSharingAFaceAreValid) {
  const RawMesh raw{{kO, kX, kY, kZ, {1, 1, 1}}, {{0, 1, 2, 3}, {1, 2, 3, 4}}};
  RawMesh oriented = raw;
  orient_positive(oriented);
  EXPECT_TRUE(check_raw(oriented, exact()).ok()) << to_string(check_raw(oriented, exact()));
}

TEST(Manifold, TwoTetsSharingOnlyAVertexAreI5) {
  RawMesh raw{{kO, kX, kY, kZ, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}, {{0, 1, 2, 3}, {0, 4, 5, 6}}};
  orient_positive(raw);
  const CheckReport report = check_raw(raw, exact());
  EXPECT_EQ(names(report), "I5") << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI5VertexShell)->vertices, std::vector<std::uint32_t>{0});
  EXPECT_NE(report.find(Invariant::kI5VertexShell)->detail.find("2 face-connected components"), std::string::npos);
}

TEST(Manifold, TwoTetsSharingOnlyAnEdgeAreI6) {
  RawMesh raw{{kO, kX, kY, kZ, {0.5, -1, -1}, {0.5, 0.2, -1}}, {{0, 1, 2, 3}, {0, 1, 4, 5}}};
  orient_positive(raw);
  const CheckReport report = check_raw(raw, exact());
  ASSERT_TRUE(has(report, Invariant::kI6EdgeShell)) << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI6EdgeShell)->vertices, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(report.find(Invariant::kI6EdgeShell)->count, 1u);
  // The edge's end points are singular too: their shells fall apart.
  EXPECT_EQ(report.find(Invariant::kI5VertexShell)->vertices, (std::vector<std::uint32_t>{0, 1}));
}

TEST(Manifold, BowtieOfBoxesAtACornerIsI5Only) {
  const RawMesh raw = weld(make_box_mesh(2, 2, 2), make_box_mesh(2, 2, 2, {1, 1, 1}, {1, 1, 1}));
  const CheckReport report = check_raw(raw);
  EXPECT_EQ(names(report), "I5") << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI5VertexShell)->vertices, std::vector<std::uint32_t>{26});
}

TEST(Manifold, BowtieOfBoxesAlongAnEdgeIsI6) {
  const RawMesh raw = weld(make_box_mesh(2, 2, 2), make_box_mesh(2, 2, 2, {1, 1, 0}, {1, 1, 1}));
  const CheckReport report = check_raw(raw);
  EXPECT_EQ(names(report), "I5 I6") << to_string(report);
  // The shared edge x = y = 1 is split in two by its middle vertex.
  EXPECT_EQ(report.find(Invariant::kI6EdgeShell)->count, 2u);
  EXPECT_EQ(report.find(Invariant::kI5VertexShell)->count, 3u);
}

// A tunnel pinched to a point: tets coning a cylindrical band onto its centre. The centre's
// shell is one face-connected ring, every edge through it is a manifold fan, yet its link is an
// annulus (Euler characteristic 0): only the disk-or-sphere test sees it.
RawMesh pinched_tunnel(int segments) {
  RawMesh raw;
  raw.positions.push_back({0, 0, 0});
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * std::numbers::pi * i / segments;
    raw.positions.push_back({std::cos(a), std::sin(a), -1});
    raw.positions.push_back({std::cos(a), std::sin(a), +1});
  }
  for (int i = 0; i < segments; ++i) {
    const auto lo = static_cast<std::uint32_t>(1 + 2 * i), hi = lo + 1;
    const auto lo2 = static_cast<std::uint32_t>(1 + 2 * ((i + 1) % segments)), hi2 = lo2 + 1;
    raw.tets.push_back({0, lo, hi, lo2});
    raw.tets.push_back({0, hi, hi2, lo2});
  }
  orient_positive(raw);
  return raw;
}

TEST(Manifold, PinchedTunnelIsCaughtByTheLinkEulerCharacteristic) {
  const RawMesh raw = pinched_tunnel(8);
  const CheckReport report = check_raw(raw, exact());
  EXPECT_EQ(names(report), "I5") << to_string(report);
  const Violation* v = report.find(Invariant::kI5VertexShell);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->vertices, std::vector<std::uint32_t>{0});
  EXPECT_EQ(v->count, 1u);
  EXPECT_NE(v->detail.find("Euler characteristic 0"), std::string::npos) << v->detail;
}

TEST(Manifold, KuhnBoxWithBothCapsOfALinkRemovedIsI5) {
  // The centre vertex 13 of a 2x2x2 Kuhn box has a sphere link. The two tets of the upper corner
  // cube whose faces opposite the centre lie in the top plane z = 1, and the two of the lower
  // corner cube in the bottom plane z = 0, are its link's two polar caps. Without them the link
  // is an annulus, and the shell stays face-connected.
  RawMesh raw = make_box_mesh(2, 2, 2);
  std::vector<std::array<std::uint32_t, 4>> kept;
  int removed = 0;
  for (const auto& t : raw.tets) {
    bool has_centre = false;
    bool top = true, bottom = true;
    for (std::uint32_t v : t) {
      if (v == 13) {
        has_centre = true;
        continue;
      }
      top = top && raw.positions[v].z == 1.0;
      bottom = bottom && raw.positions[v].z == 0.0;
    }
    if (has_centre && (top || bottom)) {
      ++removed;
      continue;
    }
    kept.push_back(t);
  }
  ASSERT_EQ(removed, 4);
  raw.tets = kept;
  const CheckReport report = check_raw(raw);
  const Violation* v = report.find(Invariant::kI5VertexShell);
  ASSERT_NE(v, nullptr) << to_string(report);
  EXPECT_EQ(v->vertices, std::vector<std::uint32_t>{13});
  EXPECT_NE(v->detail.find("Euler characteristic 0"), std::string::npos) << v->detail;
  EXPECT_FALSE(has(report, Invariant::kI6EdgeShell)) << to_string(report);
}

TEST(Manifold, AnInternalCavityIsStillAManifold) {
  // Removing one interior tet leaves a void: its vertices' links become disks, nothing singular.
  RawMesh raw = make_box_mesh(3, 3, 3);
  std::size_t interior = raw.tets.size();
  for (std::size_t t = 0; t < raw.tets.size() && interior == raw.tets.size(); ++t) {
    bool inside = true;
    for (std::uint32_t v : raw.tets[t]) {
      const Vec3& p = raw.positions[v];
      inside = inside && p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1 && p.z > 0 && p.z < 1;
    }
    if (inside) interior = t;
  }
  ASSERT_LT(interior, raw.tets.size());
  raw.tets.erase(raw.tets.begin() + static_cast<std::ptrdiff_t>(interior));
  const CheckReport report = check_raw(raw, exact());
  EXPECT_TRUE(report.ok()) << to_string(report);
}

}  // namespace
}  // namespace tetcut::invariants::testing

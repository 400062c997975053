#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "core/random.hpp"
#include "test_meshes.hpp"
#include "tetcut/canonical_hash.hpp"

namespace tetcut {
namespace {

// The same mesh with vertices and tets renumbered, and each tet's vertex list rotated by an even
// permutation (same orientation).
RawMesh renumbered(const RawMesh& raw, std::uint64_t seed) {
  SplitMix64 rng(seed);
  std::vector<std::uint32_t> perm(raw.positions.size());
  std::iota(perm.begin(), perm.end(), 0u);
  for (std::size_t i = perm.size(); i > 1; --i) std::swap(perm[i - 1], perm[rng.below(static_cast<std::uint32_t>(i))]);
  RawMesh out;
  out.positions.resize(raw.positions.size());
  for (std::size_t v = 0; v < perm.size(); ++v) out.positions[perm[v]] = raw.positions[v];
  for (const auto& t : raw.tets) {
    std::array<std::uint32_t, 4> m = {perm[t[0]], perm[t[1]], perm[t[2]], perm[t[3]]};
    if (rng.below(2)) m = {m[1], m[0], m[3], m[2]};  // two swaps: even
    out.tets.push_back(m);
  }
  for (std::size_t i = out.tets.size(); i > 1; --i) std::swap(out.tets[i - 1], out.tets[rng.below(static_cast<std::uint32_t>(i))]);
  return out;
}

TEST(CanonicalHash, IgnoresNumbering) {
  const RawMesh raw = make_box_mesh(3, 2, 2);
  const std::uint64_t h = canonical_hash(raw);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) EXPECT_EQ(canonical_hash(renumbered(raw, seed)), h);
}

TEST(CanonicalHash, TetMeshAndRawAgree) {
  const RawMesh raw = make_box_mesh(2, 2, 2);
  EXPECT_EQ(canonical_hash(testing::build_or_fail(raw)), canonical_hash(raw));
}

TEST(CanonicalHash, SeesOrientationPositionsAndTets) {
  const RawMesh raw = make_box_mesh(2, 2, 2);
  const std::uint64_t h = canonical_hash(raw);
  RawMesh flipped = raw;
  std::swap(flipped.tets[5][0], flipped.tets[5][1]);
  EXPECT_NE(canonical_hash(flipped), h);
  RawMesh moved = raw;
  moved.positions[13].x = std::nextafter(moved.positions[13].x, 2.0);
  EXPECT_NE(canonical_hash(moved), h);
  RawMesh fewer = raw;
  fewer.tets.pop_back();
  EXPECT_NE(canonical_hash(fewer), h);
}

TEST(CanonicalHash, IsSixteenHexDigits) {
  EXPECT_EQ(hash_to_hex(0x0123456789abcdefull), "0123456789abcdef");
  EXPECT_EQ(hash_to_hex(1), "0000000000000001");
}

}  // namespace
}  // namespace tetcut

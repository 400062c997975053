// The checker's verdict does not depend on the engine's face table.
//
// Were the engine's kFaceVerts wrong (say, its faces 0 and 1 swapped), the builder would match
// faces under that table and produce an adjacency that is reciprocal and pairs equal vertex
// triples under it: a checker reading the same table would find nothing to say. The engine's
// table is constexpr, so we do what the builder would have done with a wrong one: recompute the
// adjacency of a valid mesh under every permutation of the face labels, plant it through the
// test-only friend of TetMesh, and ask the checker. It owns its face table (invariants/src/
// tet_tables.hpp), so it must name I2, and only I2, for every permutation but the identity.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include "test_support.hpp"
#include "tet_mesh_test_access.hpp"
#include "tetcut/detail/local_tables.hpp"

namespace tetcut::invariants::testing {
namespace {

using FaceTable = std::array<std::array<std::uint8_t, 3>, 4>;
using Adjacency = std::vector<std::array<std::uint32_t, 4>>;

// The engine's table with its labels permuted: label f names the face the engine calls perm[f].
FaceTable permuted_face_table(const std::array<int, 4>& perm) {
  FaceTable table{};
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) table[f][k] = kFaceVerts[perm[f]][k];
  return table;
}

std::array<std::uint32_t, 3> face_key(const TetMesh& mesh, std::uint32_t t, const FaceTable& table, int f) {
  const auto v = mesh.raw_tets()[t];
  std::array<std::uint32_t, 3> key{v[table[f][0]], v[table[f][1]], v[table[f][2]]};
  std::sort(key.begin(), key.end());
  return key;
}

// What the builder does, under `table`: faces with the same three vertices are neighbours,
// each referring to the other as (tet << 2) | its label of the face.
Adjacency adjacency_under(const TetMesh& mesh, const FaceTable& table) {
  std::map<std::array<std::uint32_t, 3>, std::vector<std::uint32_t>> owners;  // key -> packed (tet, label)
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    for (int f = 0; f < 4; ++f) owners[face_key(mesh, t, table, f)].push_back((t << 2) | static_cast<std::uint32_t>(f));
  Adjacency adj(mesh.tet_capacity(), {TetMesh::kNoNeighbour, TetMesh::kNoNeighbour, TetMesh::kNoNeighbour,
                                      TetMesh::kNoNeighbour});
  for (const auto& [key, refs] : owners) {
    if (refs.size() != 2) continue;
    adj[refs[0] >> 2][refs[0] & 3u] = refs[1];
    adj[refs[1] >> 2][refs[1] & 3u] = refs[0];
  }
  return adj;
}

// All a checker sharing `table` could verify about `adj`: reciprocal, and across each face the
// neighbour has the same three vertices (under `table`).
bool consistent_under(const TetMesh& mesh, const Adjacency& adj, const FaceTable& table) {
  for (std::uint32_t t = 0; t < adj.size(); ++t)
    for (std::uint32_t f = 0; f < 4; ++f) {
      const std::uint32_t n = adj[t][f];
      if (n == TetMesh::kNoNeighbour) continue;
      if (adj[n >> 2][n & 3u] != ((t << 2) | f)) return false;
      if (face_key(mesh, n >> 2, table, static_cast<int>(n & 3u)) != face_key(mesh, t, table, static_cast<int>(f)))
        return false;
    }
  return true;
}

TEST(WrongEngineFaceTable, TheAdjacencyHookRebuildsTheEnginesAdjacencyFromTheRightTable) {
  TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
  const Adjacency original = TetMeshTestAccess::adjacency(mesh);
  EXPECT_EQ(adjacency_under(mesh, permuted_face_table({0, 1, 2, 3})), original);
}

TEST(WrongEngineFaceTable, TheCheckerNamesI2ForAdjacencyBuiltFromAnyPermutedFaceTable) {
  std::array<int, 4> perm = {0, 1, 2, 3};
  int permutations = 0;
  while (std::next_permutation(perm.begin(), perm.end())) {  // every one but the identity
    ++permutations;
    TetMesh mesh = build_or_fail(make_box_mesh(2, 2, 2));
    ASSERT_TRUE(check_mesh(mesh.raw_view()).ok());
    const FaceTable wrong = permuted_face_table(perm);
    const Adjacency adj = adjacency_under(mesh, wrong);
    ASSERT_TRUE(consistent_under(mesh, adj, wrong)) << "a checker reading the wrong table would agree with it";
    ASSERT_NE(adj, TetMeshTestAccess::adjacency(mesh));
    TetMeshTestAccess::adjacency(mesh) = adj;

    const std::string label = "faces relabelled " + std::to_string(perm[0]) + std::to_string(perm[1]) +
                              std::to_string(perm[2]) + std::to_string(perm[3]);
    const CheckReport full = check_mesh(mesh.raw_view());
    EXPECT_EQ(names(full), "I2") << label << "\n" << to_string(full);

    // The local level, asked about every tet, sees the same.
    std::vector<TetId> all;
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) all.push_back(TetId{t});
    LocalChecker local(mesh.raw_view());
    const CheckReport region = local.after_operation(mesh.raw_view(), all, all);
    EXPECT_EQ(names(region), "I2") << label << "\n" << to_string(region);
  }
  EXPECT_EQ(permutations, 23);
}

}  // namespace
}  // namespace tetcut::invariants::testing

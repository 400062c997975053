// The checker's own tet tables (invariants/src/tet_tables.hpp) hold the conventions they were
// derived from, checked with the exact predicate rather than against the engine's tables.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "tet_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::invariants::testing {
namespace {

using detail::kTetEdges;
using detail::kTetFaces;

const Vec3 kCorner[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

TEST(CheckerTables, TheReferenceTetIsPositive) {
  EXPECT_EQ(orientation(kCorner[0], kCorner[1], kCorner[2], kCorner[3]), 1);
}

TEST(CheckerTables, EveryFaceTurnsCounterClockwiseSeenFromOutside) {
  for (int f = 0; f < 4; ++f) {
    const auto& face = kTetFaces[f];
    // Its vertex f lies behind it: (face, f) is negative.
    EXPECT_EQ(orientation(kCorner[face[0]], kCorner[face[1]], kCorner[face[2]], kCorner[f]), -1) << "face " << f;
  }
}

TEST(CheckerTables, TheSixEdgesAreDistinctAndEachListsTheTwoVerticesOffIt) {
  std::set<std::pair<int, int>> edges;
  for (const auto& e : kTetEdges) {
    EXPECT_LT(e[0], e[1]);
    edges.insert({e[0], e[1]});
    std::set<int> all = {e[0], e[1], e[2], e[3]};
    EXPECT_EQ(all.size(), 4u);
  }
  EXPECT_EQ(edges.size(), 6u);
}

}  // namespace
}  // namespace tetcut::invariants::testing

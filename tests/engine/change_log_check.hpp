// What every ChangeLog promises a consumer (change_log.hpp), checked against the mesh before the
// operation and after it: shared by the journal's tests and the cut's.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::testing {

// The net ChangeLog of `log` checked against the mesh before (`before`) and after (`mesh`): what a
// consumer relies on. Returns the number of created vertices with more than two origins.
inline int expect_log_describes(const TetMesh& before, const TetMesh& mesh, const ChangeLog& log) {
  for (TetId r : log.removed) {
    EXPECT_TRUE(before.is_live(r)) << "removed tet " << r.value << " was not there before";
    EXPECT_FALSE(mesh.is_live(r)) << "removed tet " << r.value << " is still there";
  }
  EXPECT_TRUE(std::is_sorted(log.removed.begin(), log.removed.end()));
  for (const CreatedTet& c : log.created) {
    EXPECT_TRUE(mesh.is_live(c.tet));
    EXPECT_GE(c.parents_count, 1u);
    if (c.parents_count == 0) continue;
    EXPECT_EQ(c.parent, log.parents_of(c)[0]);
    for (TetId p : log.parents_of(c)) {
      // A parent is a tet there before that the operation replaced: never one it made itself.
      EXPECT_TRUE(before.is_live(p)) << "tet " << c.tet.value << ": parent " << p.value << " was made by the operation";
      EXPECT_TRUE(std::binary_search(log.removed.begin(), log.removed.end(), p)) << "parent " << p.value << " not removed";
    }
  }
  int beyond_edges = 0;
  for (const CreatedVertex& v : log.vertices) {
    EXPECT_TRUE(mesh.is_live(v.vertex));
    EXPECT_FALSE(before.is_live(v.vertex));
    Vec3 p{};
    double sum = 0.0;
    for (int i = 0; i < v.count; ++i) {
      EXPECT_TRUE(before.is_live(v.from[i]));
      EXPECT_NE(v.weight[i], 0.0);  // negative only for a vertex moved just outside (change_log.hpp)
      p = p + v.weight[i] * before.position(v.from[i]);
      sum += v.weight[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_LT(norm(p - mesh.position(v.vertex)), 1e-12) << "vertex " << v.vertex.value;
    for (std::uint32_t ch = 0; ch < mesh.attributes().channel_count(); ++ch) {
      double want = 0.0;
      for (int i = 0; i < v.count; ++i) want += v.weight[i] * before.attributes().value(ch, v.from[i])[0];
      EXPECT_NEAR(mesh.attributes().value(ch, v.vertex)[0], want, 1e-12);
    }
    beyond_edges += v.count > 2;
  }
  // A vertex there before that moved: where it was and where it is, over the old positions, with
  // every tet around it new.
  EXPECT_TRUE(std::is_sorted(log.moved.begin(), log.moved.end(),
                             [](const MovedVertex& x, const MovedVertex& y) { return x.vertex < y.vertex; }));
  for (const MovedVertex& v : log.moved) {
    EXPECT_TRUE(before.is_live(v.vertex));
    EXPECT_TRUE(mesh.is_live(v.vertex));
    EXPECT_EQ(v.before, before.position(v.vertex)) << "moved vertex " << v.vertex.value;
    EXPECT_NE(v.before, mesh.position(v.vertex)) << "moved vertex " << v.vertex.value << " did not move";
    Vec3 p{};
    double sum = 0.0;
    for (int i = 0; i < v.count; ++i) {
      EXPECT_TRUE(before.is_live(v.from[i]));
      p = p + v.weight[i] * before.position(v.from[i]);
      sum += v.weight[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_LT(norm(p - mesh.position(v.vertex)), 1e-12) << "moved vertex " << v.vertex.value;
    for (std::uint32_t ch = 0; ch < mesh.attributes().channel_count(); ++ch) {
      double want = 0.0;
      for (int i = 0; i < v.count; ++i) want += v.weight[i] * before.attributes().value(ch, v.from[i])[0];
      EXPECT_NEAR(mesh.attributes().value(ch, v.vertex)[0], want, 1e-12);
    }
    std::vector<TetId> shell;
    mesh.vertex_shell(v.vertex, shell);
    for (TetId t : shell)
      EXPECT_TRUE(std::any_of(log.created.begin(), log.created.end(), [&](const CreatedTet& c) { return c.tet == t; }))
          << "tet " << t.value << " around moved vertex " << v.vertex.value << " is not new";
  }
  for (VertId v : log.removed_vertices) {
    EXPECT_TRUE(before.is_live(v));
    EXPECT_FALSE(mesh.is_live(v));
  }
  return beyond_edges;
}

}  // namespace tetcut::testing

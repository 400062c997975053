#include <gtest/gtest.h>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

const Vec3 kCorner[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

TEST(LocalTables, ReferenceTetIsPositive) {
  EXPECT_EQ(orientation(kCorner[0], kCorner[1], kCorner[2], kCorner[3]), 1);
}

TEST(LocalTables, FaceNormalsPointAwayFromTheOppositeVertex) {
  for (int f = 0; f < 4; ++f) {
    const Vec3& a = kCorner[kFaceVerts[f][0]];
    const Vec3& b = kCorner[kFaceVerts[f][1]];
    const Vec3& c = kCorner[kFaceVerts[f][2]];
    // The opposite vertex must lie below the face seen counter-clockwise from outside: the
    // tet (face, opposite) is then negative in our convention.
    EXPECT_EQ(orientation(a, b, c, kCorner[f]), -1) << "face " << f;
  }
}

TEST(LocalTables, EveryEdgeLiesOnExactlyTheTwoFacesListed) {
  for (int e = 0; e < 6; ++e) {
    int faces_with_edge = 0;
    for (int f = 0; f < 4; ++f) {
      int hits = 0;
      for (int k = 0; k < 3; ++k) hits += kFaceVerts[f][k] == kEdgeVerts[e][0] || kFaceVerts[f][k] == kEdgeVerts[e][1];
      if (hits == 2) {
        ++faces_with_edge;
        EXPECT_TRUE(kEdgeFaces[e][0] == f || kEdgeFaces[e][1] == f) << "edge " << e << " face " << f;
      }
    }
    EXPECT_EQ(faces_with_edge, 2);
  }
}

TEST(Predicates, OrientationIsExactForNearlyFlatTets) {
  // d is on the plane z = 0 only up to one ulp: a naive determinant may get the sign wrong,
  // the exact predicate must not.
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_EQ(orientation(a, b, c, {0.3, 0.3, 0.0}), 0);
  EXPECT_EQ(orientation(a, b, c, {0.3, 0.3, 1e-300}), 1);
  EXPECT_EQ(orientation(a, b, c, {0.3, 0.3, -1e-300}), -1);
  const Vec3 p{0.1, 0.1, 0.1}, q{0.2, 0.2, 0.2}, r{0.30000000000000004, 0.30000000000000004, 0.30000000000000004};
  EXPECT_EQ(orientation(a, p, q, r), 0);  // collinear points: flat
}

}  // namespace
}  // namespace tetcut

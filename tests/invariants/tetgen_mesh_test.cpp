// Real meshes from another tool: TetGen (through libtet) tetrahedralizes closed surfaces we give
// it; the checker must find them valid at the exact level, as an engine mesh too.
#include <gtest/gtest.h>

#include <tetgen.h>

#include <string>
#include <vector>

#include "test_support.hpp"

namespace tetcut::invariants::testing {
namespace {

struct Surface {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> polygons;
};

Surface octahedron() {
  return {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
          {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

Surface cube() {
  return {{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}},
          {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}}};
}

// TetGen's tets as a RawMesh, each made positive should TetGen's order differ from ours.
// Returns how many had to be swapped (none with TetGen 1.5: its order is ours).
std::size_t tetrahedralize_surface(const Surface& s, const char* switches, RawMesh& out_mesh) {
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(s.points.size());
  in.pointlist = new REAL[3 * s.points.size()];
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    in.pointlist[3 * i] = s.points[i].x;
    in.pointlist[3 * i + 1] = s.points[i].y;
    in.pointlist[3 * i + 2] = s.points[i].z;
  }
  in.numberoffacets = static_cast<int>(s.polygons.size());
  in.facetlist = new tetgenio::facet[s.polygons.size()];
  for (std::size_t f = 0; f < s.polygons.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = static_cast<int>(s.polygons[f].size());
    facet.polygonlist[0].vertexlist = new int[s.polygons[f].size()];
    for (std::size_t k = 0; k < s.polygons[f].size(); ++k) facet.polygonlist[0].vertexlist[k] = s.polygons[f][k];
  }
  std::string sw(switches);  // tetrahedralize wants a mutable char*
  tetrahedralize(sw.data(), &in, &out);

  out_mesh = {};
  for (int i = 0; i < out.numberofpoints; ++i)
    out_mesh.positions.push_back({out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]});
  const auto first = static_cast<std::uint32_t>(out.firstnumber);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    const int* c = out.tetrahedronlist + static_cast<std::ptrdiff_t>(t) * out.numberofcorners;
    out_mesh.tets.push_back({static_cast<std::uint32_t>(c[0]) - first, static_cast<std::uint32_t>(c[1]) - first,
                             static_cast<std::uint32_t>(c[2]) - first, static_cast<std::uint32_t>(c[3]) - first});
  }
  std::size_t swapped = 0;
  for (auto& t : out_mesh.tets) {
    const auto& p = out_mesh.positions;
    if (orientation(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) < 0) {
      std::swap(t[1], t[2]);
      ++swapped;
    }
  }
  return swapped;
}

void expect_valid_everywhere(const RawMesh& raw, double volume) {
  CheckOptions options = exact();
  options.expected_volume = volume;
  const CheckReport report = check_raw(raw, options);
  EXPECT_TRUE(report.ok()) << to_string(report);
  EXPECT_TRUE(report.notes.empty());
  EXPECT_EQ(report.tets_checked, raw.tets.size());
  const TetMesh mesh = build_or_fail(raw);
  const CheckReport engine_report = check_mesh(mesh.raw_view(), options);
  EXPECT_TRUE(engine_report.ok()) << to_string(engine_report);
}

TEST(TetGenMeshes, AnOctahedronFromTetGenIsValidAtTheExactLevel) {
  RawMesh raw;
  const std::size_t swapped = tetrahedralize_surface(octahedron(), "pq1.4a0.01Q", raw);
  ASSERT_GT(raw.tets.size(), 50u);
  // TetGen 1.5 orders its tets the way we do (det(b - a, c - a, d - a) > 0).
  EXPECT_EQ(swapped, 0u);
  expect_valid_everywhere(raw, 4.0 / 3.0);
}

TEST(TetGenMeshes, ABoxFromTetGenIsValidAtTheExactLevel) {
  RawMesh raw;
  tetrahedralize_surface(cube(), "pq1.4a0.005Q", raw);
  ASSERT_GT(raw.tets.size(), 200u);
  expect_valid_everywhere(raw, 2.0);
}

TEST(TetGenMeshes, AMirroredTetGenMeshIsInvertedEverywhere) {
  RawMesh raw;
  tetrahedralize_surface(octahedron(), "pQ", raw);
  for (auto& t : raw.tets) std::swap(t[1], t[2]);  // the other convention
  const CheckReport report = check_raw(raw);
  EXPECT_EQ(names(report), "I4") << to_string(report);
  EXPECT_EQ(report.find(Invariant::kI4Orientation)->count, raw.tets.size());
}

TEST(TetGenMeshes, ATetGenBoxWithAnInnerFaceTetRemovedStaysCheckedTheSameWayEveryRun) {
  RawMesh a, b;
  tetrahedralize_surface(cube(), "pq1.4a0.01Q", a);
  tetrahedralize_surface(cube(), "pq1.4a0.01Q", b);
  ASSERT_EQ(a.tets, b.tets);
  a.tets.erase(a.tets.begin());
  b.tets.erase(b.tets.begin());
  EXPECT_EQ(to_string(check_raw(a, exact())), to_string(check_raw(b, exact())));
}

}  // namespace
}  // namespace tetcut::invariants::testing

// TetGen 1.5 on the tool's neighbourhood only, behind engine.h: the fair form of the remeshing
// peer (peers_bench's TetGen remeshes the whole mesh at every cut). A cut
//   1. selects the tets that meet the tool's ball (the centroid within the radius plus the tet's
//      own reach), grown until the part's boundary is a 2-manifold (neighbourhood.hpp), which
//      TetGen's reconstruction of the input mesh needs;
//   2. hands TetGen that part alone with `-rYQ` and a volume bound on the selected tets (a regular
//      tet of edge D_ref = 1.5 x the tool's diameter, tetcut's own refinement bound; -1 on the
//      tets the growth added): TetGen refines and may flip inside the part, and keeps its boundary
//      faces as they are (-Y), so the part's surface is still the rest of the mesh's;
//   3. puts TetGen's tets in the part's place, after checking that its boundary faces are the
//      part's own;
//   4. removes the new tets whose centroid is in the tool, blindly, as peers_bench's TetGen peer
//      does: refinement by remeshing, removal without a manifold test.
// The bookkeeping between cuts is a tetcut::TetMesh. No change log (TetGen's output replaces the
// part's tets and may drop none of its points, but is not told apart here): the harness checks the
// whole mesh after every cut. A TetGen failure or a boundary it changed is TETCUT_ENGINE_ERROR,
// the mesh as it was.
#include <tetcut/harness/engine.h>
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "neighbourhood.hpp"
#include "adapters/tet_mesh_adapter.hpp"
#include "tetcut/mesh.hpp"

namespace {

using tetcut::TetId;
using tetcut::TetMesh;
using tetcut::Vec3;
using tetcut::VertId;
using tetcut::adapters::TetMeshEngine;
using Face = std::array<std::uint32_t, 3>;

// The boundary faces of a set of tets (vertex ids sorted), each once, in order: every face
// sorted, and those that occur once kept.
std::vector<Face> boundary_faces(const std::vector<TetMesh::TetVerts>& tets) {
  std::vector<Face> faces;
  faces.reserve(4 * tets.size());
  for (const auto& t : tets) {
    for (int f = 0; f < 4; ++f) {
      Face face{};
      int n = 0;
      for (int i = 0; i < 4; ++i) {
        if (i != f) face[n++] = t[i].value;
      }
      std::sort(face.begin(), face.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end());
  std::vector<Face> out;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i == 1) out.push_back(faces[i]);
    i = j;
  }
  return out;
}

int cut_tool(TetMeshEngine& e, const Vec3& a, const Vec3& b, double diameter) {
  const double radius = diameter / 2;
  const auto positions = e.mesh.positions();
  const std::vector<TetId> selection = tetcut::adapters::tets_meeting_tool(e.mesh, a, b, radius);
  if (selection.empty()) return TETCUT_ENGINE_OK;
  std::optional<std::vector<TetId>> grown = tetcut::peers::manifold_neighbourhood(e.mesh, selection, 0);
  if (!grown) grown = tetcut::peers::manifold_neighbourhood(e.mesh, selection, -1);
  const std::vector<TetId>& part = *grown;

  // The part as TetGen's input, its vertices numbered locally.
  std::map<std::uint32_t, int> local;
  std::vector<VertId> global;
  std::vector<TetMesh::TetVerts> part_tets;
  for (TetId t : part) {
    part_tets.push_back(e.mesh.tet(t));
    for (VertId v : part_tets.back()) {
      if (local.emplace(v.value, static_cast<int>(global.size())).second) global.push_back(v);
    }
  }
  const double d_ref = 1.5 * diameter;
  const double max_volume = d_ref * d_ref * d_ref / (6.0 * std::sqrt(2.0));
  tetgenio in, result;
  in.numberofpoints = static_cast<int>(global.size());
  in.pointlist = new REAL[3 * global.size()];
  for (std::size_t i = 0; i < global.size(); ++i) {
    const Vec3& p = positions[global[i].value];
    in.pointlist[3 * i] = p.x;
    in.pointlist[3 * i + 1] = p.y;
    in.pointlist[3 * i + 2] = p.z;
  }
  in.numberoftetrahedra = static_cast<int>(part.size());
  in.numberofcorners = 4;
  in.tetrahedronlist = new int[4 * part.size()];
  in.tetrahedronvolumelist = new REAL[part.size()];
  for (std::size_t t = 0; t < part.size(); ++t) {
    for (int k = 0; k < 4; ++k) in.tetrahedronlist[4 * t + k] = local.at(part_tets[t][k].value);
    in.tetrahedronvolumelist[t] = std::binary_search(selection.begin(), selection.end(), part[t],
                                                     [](TetId x, TetId y) { return x.value < y.value; })
                                      ? max_volume
                                      : -1.0;
  }
  char switches[] = "raYQ";
  try {
    tetrahedralize(switches, &in, &result);
  } catch (...) {
    e.error = "TetGen failed on the tool's neighbourhood (" + std::to_string(part.size()) + " tets)";
    return TETCUT_ENGINE_ERROR;
  }
  if (result.numberoftetrahedra <= 0 || result.numberofpoints < in.numberofpoints) {
    e.error = "TetGen returned " + std::to_string(result.numberoftetrahedra) + " tets and " +
              std::to_string(result.numberofpoints) + " points for a part of " + std::to_string(part.size()) + " tets";
    return TETCUT_ENGINE_ERROR;
  }
  // TetGen keeps the input points first, in order; the rest are new.
  std::vector<VertId> vertex_of(static_cast<std::size_t>(result.numberofpoints));
  for (int i = 0; i < in.numberofpoints; ++i) {
    const Vec3 p{result.pointlist[3 * i], result.pointlist[3 * i + 1], result.pointlist[3 * i + 2]};
    if (!(p == positions[global[static_cast<std::size_t>(i)].value])) {
      e.error = "TetGen moved input point " + std::to_string(i);
      return TETCUT_ENGINE_ERROR;
    }
    vertex_of[static_cast<std::size_t>(i)] = global[static_cast<std::size_t>(i)];
  }
  std::vector<TetMesh::TetVerts> added(static_cast<std::size_t>(result.numberoftetrahedra));
  std::vector<std::size_t> new_points;
  for (std::size_t t = 0; t < added.size(); ++t) {
    for (int k = 0; k < 4; ++k) {
      const auto i = static_cast<std::size_t>(result.tetrahedronlist[4 * t + static_cast<std::size_t>(k)]);
      if (i >= static_cast<std::size_t>(in.numberofpoints) && !vertex_of[i].valid()) {
        vertex_of[i] = e.mesh.add_vertex({result.pointlist[3 * i], result.pointlist[3 * i + 1], result.pointlist[3 * i + 2]});
      }
      added[t][k] = vertex_of[i];
    }
  }
  if (boundary_faces(added) != boundary_faces(part_tets)) {
    e.error = "TetGen changed the boundary of the tool's neighbourhood";
    return TETCUT_ENGINE_ERROR;
  }
  std::vector<TetId> created;
  e.mesh.replace_tets(part, added, &created);
  // Blind removal of the new tets in the tool.
  e.mesh.remove_tets(tetcut::adapters::centroids_in_tool(e.mesh, created, a, b, radius));
  return TETCUT_ENGINE_OK;
}

// Blind removal of one tet.
int remove_one(TetMeshEngine& e, TetId t) {
  e.mesh.remove_tets(std::vector<TetId>{t});
  return TETCUT_ENGINE_OK;
}

const tetcut_engine_api kApi = tetcut::adapters::TetMeshEntries<cut_tool, remove_one>::api(
    "tetgen-local", "TetGen 1.5 -rYQ on the tool's neighbourhood, then blind removal");

}  // namespace

extern "C" const tetcut_engine_api* tetcut_engine_adapter(void) { return &kApi; }

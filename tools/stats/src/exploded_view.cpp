#include "tetcut/stats/exploded_view.hpp"

#include <cassert>
#include <cmath>
#include <cstdint>

#include "core/pieces.hpp"

namespace tetcut::stats {

void explode_pieces(const TetMesh& mesh, std::vector<render::SurfaceTriangle>& triangles, double gap) {
  const Pieces found = face_connected_pieces(mesh);
  const std::uint32_t pieces = found.count;
  const std::vector<std::uint32_t>& label = found.of_tet;
  if (pieces < 2) return;

  // Each triangle's piece, walking the faces in boundary_surface()'s order.
  std::vector<std::uint32_t> piece_of;
  piece_of.reserve(triangles.size());
  for (std::uint32_t i = 0; i < mesh.tet_capacity(); ++i) {
    if (!mesh.is_live(TetId{i})) continue;
    for (int f = 0; f < 4; ++f)
      if (mesh.is_boundary_face(TetId{i}, f)) piece_of.push_back(label[i]);
  }
  assert(piece_of.size() == triangles.size());
  if (piece_of.size() != triangles.size()) return;

  std::vector<Vec3> centre(pieces, Vec3{0, 0, 0});
  std::vector<std::uint64_t> faces(pieces, 0);
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const render::SurfaceTriangle& s = triangles[k];
    centre[piece_of[k]] = centre[piece_of[k]] + (1.0 / 3.0) * (s.a + s.b + s.c);
    ++faces[piece_of[k]];
  }
  std::uint32_t largest = 0;
  for (std::uint32_t p = 0; p < pieces; ++p) {
    if (faces[p] > 0) centre[p] = (1.0 / static_cast<double>(faces[p])) * centre[p];
    if (faces[p] > faces[largest]) largest = p;
  }
  std::vector<Vec3> shift(pieces, Vec3{0, 0, 0});
  for (std::uint32_t p = 0; p < pieces; ++p) {
    if (p == largest) continue;
    const Vec3 d = centre[p] - centre[largest];
    const double length = norm(d);
    if (length > 0) shift[p] = (gap / length) * d;
  }
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const Vec3 s = shift[piece_of[k]];
    triangles[k].a = triangles[k].a + s;
    triangles[k].b = triangles[k].b + s;
    triangles[k].c = triangles[k].c + s;
  }
}

}  // namespace tetcut::stats

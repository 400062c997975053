#include "operations/mesh_edits.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "support/fuzz_failure.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::fuzz {

double consume_unit(FuzzedDataProvider& input) {
  return static_cast<double>(input.ConsumeIntegral<std::uint16_t>()) / 65535.0;
}

double consume_in(FuzzedDataProvider& input, double lo, double hi) { return lo + (hi - lo) * consume_unit(input); }

RawMesh consume_box_mesh(FuzzedDataProvider& input, std::uint32_t max_cells) {
  const std::uint32_t nx = input.ConsumeIntegralInRange<std::uint32_t>(1, max_cells);
  const std::uint32_t ny = input.ConsumeIntegralInRange<std::uint32_t>(1, max_cells);
  const std::uint32_t nz = input.ConsumeIntegralInRange<std::uint32_t>(1, max_cells);
  const Vec3 size{consume_in(input, 0.25, 4.0), consume_in(input, 0.25, 4.0), consume_in(input, 0.25, 4.0)};
  return make_box_mesh(nx, ny, nz, Vec3{0, 0, 0}, size);
}

TetMesh consume_built_box_mesh(FuzzedDataProvider& input, std::uint32_t max_cells) {
  BuildResult built = build_mesh(consume_box_mesh(input, max_cells));
  if (!built.ok()) fail("build", 0, "build box", "make_box_mesh gave a mesh build_mesh refuses");
  return std::move(*built.mesh);
}

TetId consume_live_tet(const TetMesh& mesh, FuzzedDataProvider& input) {
  return consume_live_tet_where(mesh, input, [](TetId) { return true; });
}

void consume_edges(const TetMesh& mesh, FuzzedDataProvider& input, std::uint32_t max_edges, std::vector<Edge>& out) {
  out.clear();
  const std::uint32_t n = input.ConsumeIntegralInRange<std::uint32_t>(1, max_edges);
  for (std::uint32_t i = 0; i < n; ++i) {
    const TetId t = consume_live_tet(mesh, input);
    if (!t.valid()) return;
    const int e = input.ConsumeIntegralInRange<int>(0, 5);
    out.push_back({mesh.vertex(t, kEdgeVerts[e][0]), mesh.vertex(t, kEdgeVerts[e][1])});
  }
}

std::string to_string(const Vec3& p) {
  // Built by appending: `"(" + std::string&&` trips GCC 12's -Wrestrict at -O3 (bug 105651).
  std::string out = "(";
  out += std::to_string(p.x);
  out += ", ";
  out += std::to_string(p.y);
  out += ", ";
  out += std::to_string(p.z);
  out += ')';
  return out;
}

Box bounding_box(const TetMesh& mesh) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Box box{{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.is_live(VertId{v})) continue;
    const Vec3& p = mesh.position(VertId{v});
    box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
    box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
  }
  if (box.lo.x > box.hi.x) box = Box{};  // no live vertex
  return box;
}

Tool consume_ball(FuzzedDataProvider& input, const Box& box, double min_fraction, double max_fraction) {
  const Vec3 margin = 0.1 * (box.hi - box.lo);
  const Vec3 lo = box.lo - margin;
  const Vec3 span = (box.hi + margin) - lo;
  Tool ball;
  ball.a = ball.b = {lo.x + span.x * consume_unit(input), lo.y + span.y * consume_unit(input),
                 lo.z + span.z * consume_unit(input)};
  ball.radius = std::max(box.diagonal(), 1e-9) * consume_in(input, min_fraction, max_fraction);
  return ball;
}


bool removable_by_paper_rule(const TetMesh& mesh, TetId t) {
  int boundary_faces[4];
  int count = 0;
  for (int f = 0; f < 4; ++f)
    if (mesh.is_boundary_face(t, f)) boundary_faces[count++] = f;
  switch (count) {
    case 0:
      for (int i = 0; i < 4; ++i)
        if (mesh.is_boundary_vertex(mesh.vertex(t, i))) return false;
      return true;
    case 1:
      // Face i is opposite vertex i.
      return !mesh.is_boundary_vertex(mesh.vertex(t, boundary_faces[0]));
    case 2:
      return !mesh.is_boundary_edge(t, kEdgeIndex[boundary_faces[0]][boundary_faces[1]]);
    default:
      return true;
  }
}

}  // namespace tetcut::fuzz

// count_components: the face-connected pieces of the live tets, from the raw tets alone (why and
// how: components.hpp).
#include "components.hpp"

#include <algorithm>
#include <array>
#include <tuple>

#include "tetcut/invariants/check.hpp"

namespace tetcut::invariants {

namespace {

// A face of a tet, keyed by its vertex ids in increasing order.
struct FaceKey {
  std::array<std::uint32_t, 3> v;
  std::uint32_t tet;
};

}  // namespace

Components count_components(const RawMeshView& mesh) {
  const auto tet_count = static_cast<std::uint32_t>(mesh.tets.size());
  auto live = [&](std::uint32_t t) { return !(mesh.has_tombstones && mesh.tets[t][0] == kDeadTetMarker); };

  std::vector<FaceKey> faces;
  faces.reserve(4 * static_cast<std::size_t>(tet_count));
  for (std::uint32_t t = 0; t < tet_count; ++t) {
    if (!live(t)) continue;
    const auto& q = mesh.tets[t];
    // Face i omits vertex i; which side it faces does not matter here, only the vertex set.
    for (int i = 0; i < 4; ++i) {
      std::array<std::uint32_t, 3> v{};
      int n = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i) v[n++] = q[j];
      std::sort(v.begin(), v.end());
      faces.push_back({v, t});
    }
  }
  std::sort(faces.begin(), faces.end(), [](const FaceKey& a, const FaceKey& b) {
    return std::tie(a.v, a.tet) < std::tie(b.v, b.tet);
  });

  // A face met twice joins its two tets; met more often (I3 broken) it joins them all.
  detail::DisjointSets sets(tet_count);
  for (std::size_t i = 1; i < faces.size(); ++i)
    if (faces[i].v == faces[i - 1].v) sets.unite(faces[i - 1].tet, faces[i].tet);

  // Every root is the lowest tet of its set, so numbering the roots as met in tet order numbers
  // the pieces in order of their lowest tet.
  Components out;
  out.of_tet.assign(tet_count, kNoComponent);
  for (std::uint32_t t = 0; t < tet_count; ++t) {
    if (!live(t)) continue;
    const std::uint32_t root = sets.find(t);
    out.of_tet[t] = root == t ? out.count++ : out.of_tet[root];
  }
  return out;
}

}  // namespace tetcut::invariants

#include "tetcut/canonical_hash.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <vector>

#include "core/random.hpp"

namespace tetcut {
namespace {

// A position as three 64-bit words, +0.0 and -0.0 made equal so that a mesh read back from a
// file that printed "-0" hashes like the original.
std::array<std::uint64_t, 3> position_key(const Vec3& p) {
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); };
  return {bits(p.x), bits(p.y), bits(p.z)};
}

std::uint64_t tet_key(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  std::array<std::array<std::uint64_t, 3>, 4> keys = {position_key(a), position_key(b), position_key(c),
                                                      position_key(d)};
  // Insertion sort that counts swaps: the parity of the sorting permutation says whether the
  // tet's orientation matches the sorted order, so reorienting a tet changes the hash.
  int swaps = 0;
  for (int i = 1; i < 4; ++i)
    for (int j = i; j > 0 && keys[j] < keys[j - 1]; --j) {
      std::swap(keys[j], keys[j - 1]);
      ++swaps;
    }
  std::uint64_t h = mix64(0x7E7C07ull + static_cast<std::uint64_t>(swaps & 1));
  for (const auto& k : keys)
    for (std::uint64_t w : k) h = mix64(h ^ w) + 0x9E3779B97F4A7C15ull;
  return h;
}

std::uint64_t fold(std::vector<std::uint64_t>& keys) {
  std::sort(keys.begin(), keys.end());
  std::uint64_t h = mix64(keys.size());
  for (std::uint64_t k : keys) h = mix64(h ^ k) + 0x9E3779B97F4A7C15ull;
  return h;
}

}  // namespace

std::uint64_t canonical_hash(const RawMesh& mesh) {
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.tets.size());
  for (const auto& t : mesh.tets)
    keys.push_back(tet_key(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], mesh.positions[t[3]]));
  return fold(keys);
}

std::uint64_t canonical_hash(const TetMesh& mesh) {
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.num_tets());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    const auto& v = mesh.tet(TetId{t});
    keys.push_back(tet_key(mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2]), mesh.position(v[3])));
  }
  return fold(keys);
}

std::string hash_to_hex(std::uint64_t hash) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return buf;
}

}  // namespace tetcut

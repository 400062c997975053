// Meshes the benchmarks run on: the bundled corpus (the default of every benchmark) and
// structured boxes of a requested size. Loaded once per process.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "tetcut/box_mesh.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace tetcut::bench {

// A bundled mesh by file name ("liver.msh"); aborts with a message if it is missing, since a
// benchmark on the wrong mesh would gate nothing.
inline const TetMesh& corpus_mesh(const std::string& name) {
  static std::map<std::string, TetMesh> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  const std::string path = std::string(TETCUT_CORPUS_DIR) + "/meshes/" + name;
  ReadResult read = read_mesh(path);
  if (!read.mesh) {
    std::fprintf(stderr, "bench: cannot read %s: %s\n", path.c_str(), read.error ? read.error->message().c_str() : "?");
    std::abort();
  }
  BuildResult built = build_mesh(*read.mesh);
  if (!built.ok()) {
    std::fprintf(stderr, "bench: %s does not build: %s\n", path.c_str(), built.problems.front().message.c_str());
    std::abort();
  }
  return cache.emplace(name, std::move(*built.mesh)).first->second;
}

// The axis-aligned box around a mesh's live vertices: where the sweeps draw their chords.
struct Bounds {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};
inline Bounds bounds(const TetMesh& mesh) {
  Bounds b;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.is_live(VertId{v})) continue;
    const Vec3 p = mesh.position(VertId{v});
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

// 64 disjoint copies of the bundled liver side by side (~1M tets), copy 0 the original: a sweep
// over copy 0 does exactly the work it does on the lone liver, and only the size of the mesh
// around it differs (cut_bench.cpp BM_CutScalingSameWork, mechanics_bench.cpp BM_UpdateScalingSameWork).
inline const TetMesh& replicated_corpus_liver() {
  static const TetMesh mesh = [] {
    const RawMesh one = corpus_mesh("liver.msh").to_raw();
    RawMesh all;
    for (int copy = 0; copy < 64; ++copy) {
      const Vec3 shift{250.0 * (copy % 8), 250.0 * (copy / 8), 0.0};
      const auto base = static_cast<std::uint32_t>(all.positions.size());
      for (const Vec3& p : one.positions) all.positions.push_back(p + shift);
      for (const auto& t : one.tets) all.tets.push_back({t[0] + base, t[1] + base, t[2] + base, t[3] + base});
    }
    return std::move(*build_mesh(all).mesh);
  }();
  return mesh;
}

}  // namespace tetcut::bench

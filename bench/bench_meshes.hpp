// Meshes the benchmarks run on: the bundled corpus (the default of every benchmark) and
// structured boxes of a requested size. Loaded once per process.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "mesh_orders.hpp"
#include "tetcut/bounding_box.hpp"
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

// How the ids of the 64 copies below are ordered (mesh_orders.hpp): copy by copy, as they were
// appended (copy 0 keeps the lone liver's layout); shuffled with a fixed seed (copy 0's tets
// scattered through the whole mesh, as in a large mesh assembled or edited over time); or shuffled
// and then compacted (TetMesh::compact(): the ids along a space-filling curve), as a user mends
// the scatter.
enum class CopiesOrder { kCopies, kShuffled, kCurve };

// 64 disjoint copies of the bundled liver side by side (~1M tets), copy 0 the original, as raw
// arrays in copy order: a sweep over copy 0 does the work it does on the lone liver, and only the
// size of the mesh around it differs.
inline RawMesh replicated_corpus_liver_raw() {
  const RawMesh one = corpus_mesh("liver.msh").to_raw();
  RawMesh all;
  for (int copy = 0; copy < 64; ++copy) {
    const Vec3 shift{250.0 * (copy % 8), 250.0 * (copy / 8), 0.0};
    const auto base = static_cast<std::uint32_t>(all.positions.size());
    for (const Vec3& p : one.positions) all.positions.push_back(p + shift);
    for (const auto& t : one.tets) all.tets.push_back({t[0] + base, t[1] + base, t[2] + base, t[3] + base});
  }
  return all;
}

// The 64 copies built, with their ids in `order` (cut_bench.cpp BM_CutScalingSameWork,
// mechanics_bench.cpp BM_UpdateScalingSameWork, cut_instructions.cpp's cache sweep). Built once
// per order and process.
inline const TetMesh& replicated_corpus_liver(CopiesOrder order = CopiesOrder::kCopies) {
  static std::map<CopiesOrder, TetMesh> cache;
  auto it = cache.find(order);
  if (it != cache.end()) return it->second;
  RawMesh raw = replicated_corpus_liver_raw();
  if (order != CopiesOrder::kCopies) raw = shuffled(raw);
  // Copies of a valid liver are manifold by construction: the shell checks would cost a second
  // (several under valgrind, bench/instructions_gate.sh --cache) and find nothing.
  TetMesh& mesh = cache.emplace(order, std::move(*build_mesh(raw, {.require_manifold = false}).mesh)).first->second;
  if (order == CopiesOrder::kCurve) mesh.compact(IdOrder::kAlongCurve);
  return mesh;
}

}  // namespace tetcut::bench

// Meshes the benchmarks run on: the bundled corpus (the default of every benchmark) and
// structured boxes of a requested size. Loaded once per process.
#pragma once

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

}  // namespace tetcut::bench

// Writes the meshes both sides of the paired wall-time comparison cut (paired_sweep.cpp), as raw
// arrays (raw_mesh_file.hpp): the bundled liver and the liver refined twice (~1M tets, the mesh of
// the "cut p50, 1M liver" figure).
//
//   paired_meshes OUT_DIR [--small-only]
//       writes OUT_DIR/liver.raw and OUT_DIR/liver-1M.raw (--small-only: the liver alone, for
//       paired_sweep --small-only)
#include <cstdio>
#include <string>
#include <utility>

#include "raw_mesh_file.hpp"
#include "refined_liver.hpp"

int main(int argc, char** argv) {
  const bool small_only = argc == 3 && std::string(argv[2]) == "--small-only";
  if (argc != 2 && !small_only) {
    std::fprintf(stderr, "usage: paired_meshes OUT_DIR [--small-only]\n");
    return 2;
  }
  const std::string dir = argv[1];
  for (const auto& [level, name] : {std::pair{0, "liver.raw"}, std::pair{2, "liver-1M.raw"}}) {
    if (small_only && level > 0) continue;
    const std::string path = dir + "/" + name;
    if (!tetcut::bench::write_raw_mesh_file(path, tetcut::bench::refined_corpus_liver(level).to_raw())) {
      std::fprintf(stderr, "paired_meshes: cannot write %s\n", path.c_str());
      return 2;
    }
  }
  return 0;
}

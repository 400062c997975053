// The memory of a cutting session, per tet: what a simulator holds to cut a mesh. One process
// per session, so that its peak resident size is the session's own:
//
//   session_memory --write FILE.vtu   writes 64 copies of the bundled liver (~1M tets,
//                                     bench_meshes.hpp) as binary VTU, the session's input
//   session_memory FILE.vtu OUT.json  reads FILE (tetcut::read_mesh, then build_mesh), constructs a
//                                     Cutter, runs the gated sweep (on copy 0), and writes the peak
//                                     resident size after each step (Linux VmHWM) over the mesh's
//                                     tets, as Google Benchmark JSON for bench/budget_gate.py
//
// The peak is the process's, libraries and the reader's raw arrays included: a user's session
// pays for those too.
#include <cstdio>
#include <fstream>
#include <string>

#include "bench_meshes.hpp"
#include "gated_sweep.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

namespace {

// The process's peak resident size so far, in bytes (VmHWM in /proc/self/status), 0 if unknown.
double peak_rss_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0;
  return 0.0;
}

int write_input(const std::string& path) {
  const tetcut::WriteResult written =
      tetcut::write_mesh(path, tetcut::bench::replicated_corpus_liver_raw(), {.binary = true});
  if (!written.ok) {
    std::fprintf(stderr, "session_memory: %s\n", written.error.c_str());
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--write") return write_input(argv[2]);
  if (argc != 3) {
    std::fprintf(stderr, "usage: session_memory --write FILE.vtu | session_memory FILE.vtu OUT.json\n");
    return 2;
  }
  const double at_start = peak_rss_bytes();
  tetcut::ReadResult read = tetcut::read_mesh(argv[1]);
  if (!read.mesh) {
    std::fprintf(stderr, "session_memory: %s\n", read.error->message().c_str());
    return 2;
  }
  const double after_read = peak_rss_bytes();
  tetcut::BuildResult built = tetcut::build_mesh(*read.mesh);
  read.mesh.reset();  // a simulator keeps the mesh, not the file's arrays
  if (!built.ok()) {
    std::fprintf(stderr, "session_memory: %s does not build\n", argv[1]);
    return 2;
  }
  tetcut::TetMesh& mesh = *built.mesh;
  const double tets = mesh.num_tets();
  const double after_load = peak_rss_bytes();
  tetcut::Cutter cutter(mesh, {.tool_diameter = tetcut::bench::kGatedToolDiameter});
  const double after_cutter = peak_rss_bytes();
  std::uint64_t removed = 0;
  for (const tetcut::Vec3& c : tetcut::bench::gated_sweep_centres()) removed += cutter.cut(c).tets_removed;
  const double peak = peak_rss_bytes();
  std::FILE* out = std::fopen(argv[2], "w");
  if (!out) {
    std::fprintf(stderr, "session_memory: cannot write %s\n", argv[2]);
    return 2;
  }
  std::fprintf(out,
               "{\"context\": {\"source\": \"session_memory\"},\n \"benchmarks\": [{\"name\": \"session_memory\", "
               "\"run_name\": \"session_memory\", \"run_type\": \"iteration\", \"tets\": %.0f, \"tets_removed\": %llu,\n"
               "  \"peak_rss_bytes\": %.0f, \"bytes_per_tet\": %.1f, \"start_bytes_per_tet\": %.1f,\n"
               "  \"read_bytes_per_tet\": %.1f, \"load_bytes_per_tet\": %.1f, \"cutter_bytes_per_tet\": %.1f}]}\n",
               tets, static_cast<unsigned long long>(removed), peak, peak / tets, at_start / tets, after_read / tets,
               after_load / tets, after_cutter / tets);
  std::fclose(out);
  std::printf("session memory: peak %.0f MB over %.0f tets = %.1f bytes per tet (start %.1f, after the read %.1f, "
              "after the build %.1f, after the Cutter %.1f)\n",
              peak / 1e6, tets, peak / tets, at_start / tets, after_read / tets, after_load / tets, after_cutter / tets);
  return 0;
}

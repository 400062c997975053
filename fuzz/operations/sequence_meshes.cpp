#include "operations/sequence_meshes.hpp"

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>

#include "operations/sequence_target.hpp"
#include "support/fuzz_failure.hpp"
#include "tetcut/io.hpp"
#include "tetcut/mesh_builder.hpp"

#ifndef TETCUT_FUZZ_MESH_DIR
#define TETCUT_FUZZ_MESH_DIR "corpus/meshes"
#endif
#ifndef TETCUT_FUZZ_SMALL_MESH_DIR
#define TETCUT_FUZZ_SMALL_MESH_DIR "corpus/fuzz/meshes"
#endif

namespace tetcut::fuzz {

namespace {

// $env when set, else `built_in` when it is a folder, else tetcut_meshes/ next to the executable:
// OSS-Fuzz runs the fuzzers away from the source tree, and fuzz/oss_fuzz_build.sh puts every
// mesh there.
std::string mesh_dir(const char* env_name, const char* built_in) {
  const char* env = std::getenv(env_name);
  if (env != nullptr && *env != '\0') return env;
  std::error_code ec;
  if (std::filesystem::is_directory(built_in, ec)) return built_in;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) return (exe.parent_path() / "tetcut_meshes").string();
  return built_in;
}

}  // namespace

std::string sequence_mesh_dir() { return mesh_dir("TETCUT_MESH_DIR", TETCUT_FUZZ_MESH_DIR); }
std::string fuzz_mesh_dir() { return mesh_dir("TETCUT_FUZZ_MESH_DIR", TETCUT_FUZZ_SMALL_MESH_DIR); }

namespace {

std::unique_ptr<BundledMesh> load(std::uint8_t version, std::size_t index) {
  auto out = std::make_unique<BundledMesh>();
  const bool bundled = version == kSequenceVersionBundled;
  out->path = (bundled ? sequence_mesh_dir() : fuzz_mesh_dir()) + "/" +
              std::string(bundled ? kBundledMeshes[index] : kFuzzMeshes[index]);
  ReadResult read = read_mesh(out->path);
  if (!read.mesh)
    fail("bundled-mesh", 0, "load", out->path + ": " + (read.error ? read.error->message() : "unreadable") +
                                        (bundled ? " (set TETCUT_MESH_DIR to the folder of the bundled meshes)"
                                                  : " (set TETCUT_FUZZ_MESH_DIR to the folder of the fuzz meshes)"));
  BuildResult built = build_mesh(*read.mesh);
  if (!built.ok()) fail("bundled-mesh", 0, "load", out->path + ": not a valid mesh: " + built.problems.front().message);
  out->mesh = std::move(*built.mesh);
  out->box = bounding_box(out->mesh);
  out->mean_edge = out->mesh.mean_edge_length();
  return out;
}

}  // namespace

const BundledMesh& sequence_mesh(std::uint8_t version, std::size_t index) {
  static std::unique_ptr<BundledMesh> cache[2][kSequenceMeshCount];
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  index %= kSequenceMeshCount;
  std::unique_ptr<BundledMesh>& slot = cache[version == kSequenceVersionBundled ? 0 : 1][index];
  if (!slot) slot = load(version, index);
  return *slot;
}

}  // namespace tetcut::fuzz

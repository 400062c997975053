#include "operations/sequence_support.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>

#include "tetcut/io.hpp"
#include "tetcut/local_tables.hpp"
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

bool legacy_versions_from_env() {
  const char* env = std::getenv("TETCUT_FUZZ_CURRENT_VERSION_ONLY");
  return env == nullptr || *env == '\0' || std::string_view(env) == "0";
}

std::string format_number(double x) {
  if (x == 0.0) x = 0.0;  // no "-0"
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return ec == std::errc{} ? std::string(buffer, end) : std::string("0");
}

std::string format_point(const Vec3& p) {
  return format_number(p.x) + "," + format_number(p.y) + "," + format_number(p.z);
}

double round_to(double x, double quantum) {
  // Dividing by 1/quantum (an exact integer power of ten for quantum <= 1) and reading the
  // result back through text gives the double the text "k e-d" denotes: what a scenario reads.
  const double k = std::round(x / quantum);
  std::string text = format_number(k) + "e" + std::to_string(static_cast<int>(std::lround(std::log10(quantum))));
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

double coordinate_quantum(double diagonal, int digits) {
  const double d = diagonal > 0.0 && std::isfinite(diagonal) ? diagonal : 1.0;
  return std::pow(10.0, std::floor(std::log10(d)) - digits);
}

std::uint32_t ScenarioRecorder::add(std::string line) {
  if (!enabled_) return 0;
  lines_.push_back(std::move(line));
  return lines();
}

void ScenarioRecorder::replace(std::uint32_t number, std::string line) {
  if (enabled_ && number >= 1 && number <= lines_.size()) lines_[number - 1] = std::move(line);
}

void ScenarioRecorder::map_operation(std::size_t index, std::uint32_t number) {
  if (!enabled_) return;
  if (operation_lines_.size() <= index) operation_lines_.resize(index + 1, 0);
  operation_lines_[index] = number;
}

std::uint32_t ScenarioRecorder::line_of(std::size_t index) const {
  return index < operation_lines_.size() ? operation_lines_[index] : 0;
}

std::string ScenarioRecorder::text() const {
  std::string out;
  for (const std::string& line : lines_) {
    out += line;
    out += '\n';
  }
  return out;
}

}  // namespace tetcut::fuzz

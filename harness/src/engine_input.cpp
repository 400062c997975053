#include "tetcut/harness/engine_input.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "tetcut/io.hpp"
#include "tetcut/scenario/sweep.hpp"

namespace tetcut::harness {

namespace {

// The input's bytes in order; past the end every read is 0, so that any input decodes.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  [[nodiscard]] bool done() const { return next_ >= bytes_.size(); }
  std::uint8_t byte() { return done() ? 0 : bytes_[next_++]; }
  std::uint16_t u16() {
    const std::uint16_t high = byte();
    return static_cast<std::uint16_t>(high << 8 | byte());
  }
  // In [0, 1], from one byte or two.
  double unit8() { return byte() / 255.0; }
  double unit16() { return u16() / 65535.0; }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t next_ = 0;
};

struct Decoder {
  const FuzzMesh& mesh;
  MeshBox box;
  double edge = 1.0;
  EnginePlan& plan;

  Vec3 point(ByteReader& in) const {
    auto across = [](double low, double high, double u) {
      const double margin = (high - low) / 10;
      return low - margin + u * (high - low + 2 * margin);
    };
    const double x = across(box.low.x, box.high.x, in.unit16());
    const double y = across(box.low.y, box.high.y, in.unit16());
    const double z = across(box.low.z, box.high.z, in.unit16());
    return {x, y, z};
  }
  double diameter(ByteReader& in) const { return edge * std::exp2(4 * in.unit8() - 2); }

  void cut(const Vec3& a, const std::optional<Vec3>& b, double d) {
    EngineOperation op{EngineOperation::Kind::kCut, a, b, d, ""};
    op.name = "cut " + std::to_string(plan.operations.size() + 1) + " at " + point_text(a);
    if (b) op.name += " to " + point_text(*b);
    plan.operations.push_back(std::move(op));
  }

  void cut_operation(ByteReader& in) {
    const std::uint8_t opcode = in.byte() % 4;
    if (opcode < 2) {
      const Vec3 a = point(in);
      cut(a, std::nullopt, diameter(in));
    } else if (opcode == 2) {
      const Vec3 a = point(in);
      const Vec3 b = point(in);
      cut(a, b, diameter(in));
    } else {
      const Vec3 from = point(in);
      const Vec3 to = point(in);
      const double d = diameter(in);
      const double step = d * (0.25 + 0.75 * in.unit8());
      const bool swept = (in.byte() & 1) != 0;
      std::vector<scenario::CutTool> cuts = scenario::sweep_cuts(from, to, step, swept);
      if (cuts.size() > kMaxSweepCuts) cuts.resize(kMaxSweepCuts);
      for (const scenario::CutTool& tool : cuts) cut(tool.centre, tool.end, d);
    }
  }

  void removal_operation(ByteReader& in) {
    const auto& tets = mesh.mesh.tets;
    const auto& t = tets[in.u16() % tets.size()];
    Vec3 centroid{};
    for (std::uint32_t v : t) centroid = centroid + 0.25 * mesh.mesh.positions[v];
    EngineOperation op{EngineOperation::Kind::kRemoveAt, centroid, std::nullopt, 0.0, ""};
    op.name = "remove " + std::to_string(plan.operations.size() + 1) + " at " + point_text(centroid);
    plan.operations.push_back(std::move(op));
  }
};

}  // namespace

std::string_view target_name(EngineTarget target) {
  return target == EngineTarget::kCutSequence ? "cut_sequence" : "removal_sequence";
}

std::optional<EngineTarget> engine_target(std::string_view name) {
  if (name == "cut_sequence") return EngineTarget::kCutSequence;
  if (name == "removal_sequence") return EngineTarget::kRemovalSequence;
  return std::nullopt;
}

std::vector<FuzzMesh> load_fuzz_meshes(const std::string& corpus_dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(fs::path(corpus_dir) / "fuzz" / "meshes", ec)) {
    if (entry.is_regular_file() && entry.path().extension() == ".msh") {
      paths.push_back(fs::absolute(entry.path()).lexically_normal().string());
    }
  }
  std::sort(paths.begin(), paths.end());
  if (paths.empty()) throw std::runtime_error(corpus_dir + "/fuzz/meshes: no .msh file");
  std::vector<FuzzMesh> meshes;
  for (const std::string& path : paths) {
    ReadResult read = read_mesh(path);
    if (!read.mesh) throw std::runtime_error(read.error->message());
    meshes.push_back({path, std::move(*read.mesh)});
  }
  return meshes;
}

EnginePlan decode_engine_input(std::span<const std::uint8_t> bytes, EngineTarget target,
                               const std::vector<FuzzMesh>& meshes) {
  EnginePlan plan;
  ByteReader in(bytes);
  if (bytes.size() < 2 || in.byte() != kEngineInputVersion || meshes.empty()) return plan;
  const FuzzMesh& mesh = meshes[in.byte() % meshes.size()];
  plan.name = std::string(target_name(target)) + " on " + std::filesystem::path(mesh.path).filename().string();
  plan.mesh_path = mesh.path;
  plan.mesh = mesh.mesh;
  Decoder decoder{mesh, bounding_box(mesh.mesh), median_edge_length(mesh.mesh), plan};
  while (!in.done() && plan.operations.size() < kMaxEngineOperations) {
    if (target == EngineTarget::kCutSequence) {
      decoder.cut_operation(in);
    } else {
      decoder.removal_operation(in);
    }
  }
  if (plan.operations.size() > kMaxEngineOperations) plan.operations.resize(kMaxEngineOperations);
  return plan;
}

}  // namespace tetcut::harness

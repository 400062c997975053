// `tetcut info MESH [--json]`: what a mesh is made of, how good it is, and whether it is a
// manifold, from the independent checker's full level (so a non-manifold file is described,
// not refused).
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "args.hpp"
#include "command.hpp"
#include "json_writer.hpp"
#include "mesh_input.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut::cli {

namespace {

namespace inv = tetcut::invariants;

// Faces that belong to exactly one tet, counted from the raw tets by sorting their vertex
// triples: works on any file, manifold or not (a face of three tets is not boundary).
std::uint64_t count_boundary_faces(const RawMesh& mesh) {
  std::vector<std::array<std::uint32_t, 3>> faces;
  faces.reserve(mesh.tets.size() * 4);
  for (const auto& t : mesh.tets) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> f{};
      int k = 0;
      for (int i = 0; i < 4; ++i) {
        if (i != skip) f[k++] = t[i];
      }
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end());
  std::uint64_t boundary = 0;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i == 1) ++boundary;
    i = j;
  }
  return boundary;
}

struct BoundingBox {
  Vec3 min;
  Vec3 max;
};

std::optional<BoundingBox> bounding_box(const RawMesh& mesh) {
  if (mesh.positions.empty()) return std::nullopt;
  BoundingBox box{mesh.positions.front(), mesh.positions.front()};
  for (const Vec3& p : mesh.positions) {
    box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
    box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
  }
  return box;
}

struct MeshInfo {
  std::uint64_t vertices = 0;
  std::uint64_t tets = 0;
  std::uint64_t boundary_faces = 0;
  double volume = 0.0;
  inv::QualityStats quality;
  std::optional<BoundingBox> box;
  bool manifold = false;
  bool oriented = false;
  std::vector<std::string> violated;  // ids of the invariants the full check found violated
  std::string hash;
};

MeshInfo describe(const RawMesh& mesh) {
  MeshInfo info;
  info.vertices = mesh.positions.size();
  info.tets = mesh.tets.size();
  info.boundary_faces = count_boundary_faces(mesh);
  const inv::CheckReport report = inv::check_raw(mesh, inv::CheckOptions{});
  info.volume = report.volume;
  info.quality = report.quality;
  info.box = bounding_box(mesh);
  info.manifold = true;
  for (const inv::Violation& v : report.violations) {
    info.violated.emplace_back(inv::id_string(v.id));
    if (v.id == inv::Invariant::kI1References || v.id == inv::Invariant::kI3Conformity ||
        v.id == inv::Invariant::kI5VertexShell || v.id == inv::Invariant::kI6EdgeShell) {
      info.manifold = false;
    }
  }
  info.oriented = report.find(inv::Invariant::kI4Orientation) == nullptr;
  info.hash = hash_to_hex(canonical_hash(mesh));
  return info;
}

void write_json(const std::string& path, const MeshInfo& info, std::ostream& out) {
  JsonWriter json(out);
  json.begin_object();
  json.field("file", path);
  json.field("vertices", info.vertices);
  json.field("tets", info.tets);
  json.field("boundary_faces", info.boundary_faces);
  json.field("volume", info.volume);
  // Without tets there is no quality to report: null, not a 0 that reads as "flat tets".
  const auto stat = [&](std::string_view name, double v) {
    json.key(name);
    if (info.tets == 0) {
      json.null();
    } else {
      json.value(v);
    }
  };
  stat("min_radius_ratio", info.quality.min_radius_ratio);
  stat("mean_radius_ratio", info.quality.mean_radius_ratio);
  stat("min_dihedral_deg", info.quality.min_dihedral_deg);
  stat("mean_min_dihedral_deg", info.quality.mean_min_dihedral_deg);
  json.key("radius_ratio_histogram");
  json.begin_array();
  for (const std::uint64_t n : info.quality.radius_ratio_histogram) json.value(n);
  json.end_array();
  json.key("bounding_box");
  if (info.box) {
    json.begin_object();
    json.key("min");
    json.begin_array();
    for (const double c : {info.box->min.x, info.box->min.y, info.box->min.z}) json.value(c);
    json.end_array();
    json.key("max");
    json.begin_array();
    for (const double c : {info.box->max.x, info.box->max.y, info.box->max.z}) json.value(c);
    json.end_array();
    json.end_object();
  } else {
    json.null();
  }
  json.field("manifold", info.manifold);
  json.field("oriented", info.oriented);
  json.key("violated");
  json.begin_array();
  for (const std::string& id : info.violated) json.value(id);
  json.end_array();
  json.field("hash", info.hash);
  json.end_object();
  json.finish();
}

void write_text(const std::string& path, const MeshInfo& info, std::ostream& out) {
  const auto num = [](double d) { return json_number(d); };
  out << "file:                  " << path << '\n'
      << "vertices:              " << info.vertices << '\n'
      << "tets:                  " << info.tets << '\n'
      << "boundary faces:        " << info.boundary_faces << '\n'
      << "volume:                " << num(info.volume) << '\n';
  if (info.tets > 0) {
    out << "radius ratio:          min " << num(info.quality.min_radius_ratio) << ", mean "
        << num(info.quality.mean_radius_ratio) << '\n'
        << "min dihedral (deg):    min " << num(info.quality.min_dihedral_deg) << ", mean "
        << num(info.quality.mean_min_dihedral_deg) << '\n'
        << "radius ratio histogram:";
    for (const std::uint64_t n : info.quality.radius_ratio_histogram) out << ' ' << n;
    out << "   (bins of 0.1 from 0 to 1)\n";
  } else {
    out << "quality:               none (no tets)\n";
  }
  out << "bounding box:          ";
  if (info.box) {
    out << '(' << num(info.box->min.x) << ", " << num(info.box->min.y) << ", "
        << num(info.box->min.z) << ") - (" << num(info.box->max.x) << ", "
        << num(info.box->max.y) << ", " << num(info.box->max.z) << ")\n";
  } else {
    out << "none (no vertices)\n";
  }
  out << "manifold:              " << (info.manifold ? "yes" : "no") << '\n'
      << "positively oriented:   " << (info.oriented ? "yes" : "no") << '\n';
  if (!info.violated.empty()) {
    out << "violated invariants:  ";
    for (const std::string& id : info.violated) out << ' ' << id;
    out << "   (see tetcut check)\n";
  }
  out << "hash:                  " << info.hash << '\n';
}

}  // namespace

int cmd_info(Args args, std::ostream& out, std::ostream& err) {
  static constexpr OptionSpec kOptions[] = {{"--json", false}};
  const ArgParseResult parsed = parse_args(args, kOptions);
  if (!parsed.ok()) return usage_error("info", parsed.error, err);
  if (parsed.args.positionals.size() != 1) {
    return usage_error("info", parsed.args.positionals.empty() ? "missing MESH" : "too many arguments",
                       err);
  }
  const std::string& path = parsed.args.positionals[0];
  const std::optional<RawMesh> mesh = load_mesh(path, err);
  if (!mesh) return kExitBadInput;
  const MeshInfo info = describe(*mesh);
  if (parsed.args.has("--json")) {
    write_json(path, info, out);
  } else {
    write_text(path, info, out);
  }
  return kExitOk;
}

}  // namespace tetcut::cli

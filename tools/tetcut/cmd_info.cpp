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

#include <charconv>

#include "command.hpp"
#include "command_parser.hpp"
#include "json_output.hpp"
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

Json info_json(const std::string& path, const MeshInfo& info) {
  // Without tets there is no quality to report: null, not a 0 that reads as "flat tets".
  const bool q = info.tets > 0;
  const auto xyz = [](const Vec3& p) { return Json::array({p.x, p.y, p.z}); };
  return Json{{"file", path},
              {"vertices", info.vertices},
              {"tets", info.tets},
              {"boundary_faces", info.boundary_faces},
              {"volume", info.volume},
              {"min_radius_ratio", number_or_null(info.quality.min_radius_ratio, q)},
              {"mean_radius_ratio", number_or_null(info.quality.mean_radius_ratio, q)},
              {"min_dihedral_deg", number_or_null(info.quality.min_dihedral_deg, q)},
              {"mean_min_dihedral_deg", number_or_null(info.quality.mean_min_dihedral_deg, q)},
              {"radius_ratio_histogram", info.quality.radius_ratio_histogram},
              {"bounding_box", info.box ? Json{{"min", xyz(info.box->min)}, {"max", xyz(info.box->max)}} : Json(nullptr)},
              {"manifold", info.manifold},
              {"oriented", info.oriented},
              {"violated", info.violated},
              {"hash", info.hash}};
}

// The shortest decimal form that reads back to the same double, as in the JSON.
std::string shortest(double d) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, d);
  return ec == std::errc{} ? std::string(buffer, end) : "?";
}

void write_text(const std::string& path, const MeshInfo& info, std::ostream& out) {
  const auto num = shortest;
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
  std::optional<std::string> path;
  bool json = false;
  CommandParser parser(
      "info", "tetcut info MESH [--json]",
      "Prints counts, boundary, volume, quality statistics (radius ratio min/mean/histogram,\n"
      "minimum dihedral angle), bounding box, manifold status and the canonical hash of a mesh.\n"
      "\n"
      "`manifold` is true when the full checker finds no violation of I1, I3, I5 or I6;\n"
      "`oriented` when it finds none of I4.\n",
      "exit: 0, 2 unreadable input or bad usage");
  opt::text(parser.app(), "MESH", path, "the mesh file", "")->required();
  opt::flag(parser.app(), "--json", json,
            "as JSON (quality values are null when there are no tets): keys vertices, tets, boundary_faces, "
            "volume, min_radius_ratio, mean_radius_ratio, min_dihedral_deg, mean_min_dihedral_deg, "
            "radius_ratio_histogram, bounding_box, manifold, oriented, violated, hash");
  if (const auto code = parser.parse(args, out, err)) return *code;
  const std::optional<RawMesh> mesh = load_mesh(*path, err);
  if (!mesh) return kExitBadInput;
  const MeshInfo info = describe(*mesh);
  if (json) {
    out << json_text(info_json(*path, info));
  } else {
    write_text(*path, info, out);
  }
  return kExitOk;
}

}  // namespace tetcut::cli

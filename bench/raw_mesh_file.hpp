// A mesh as raw arrays in a file of its own (native byte order, for one machine's runs): how the
// paired wall-time comparison hands both of its sides the same meshes without either reading a
// mesh format (paired_meshes.cpp writes them, paired_sweep.cpp reads them). Public API only: the
// reader builds against the engine of an older commit.
//
//   "tetcut-raw-1\n", then #V and #T (uint64), #V by 3 doubles, #T by 4 uint32 vertex ids.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "tetcut/raw_mesh.hpp"

namespace tetcut::bench {

inline constexpr char kRawMeshMagic[] = "tetcut-raw-1\n";

inline bool write_raw_mesh_file(const std::string& path, const RawMesh& mesh) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "wb"), std::fclose);
  if (!f) return false;
  const std::uint64_t counts[2] = {mesh.positions.size(), mesh.tets.size()};
  return std::fwrite(kRawMeshMagic, 1, sizeof kRawMeshMagic - 1, f.get()) == sizeof kRawMeshMagic - 1 &&
         std::fwrite(counts, sizeof counts, 1, f.get()) == 1 &&
         std::fwrite(mesh.positions.data(), sizeof(Vec3), mesh.positions.size(), f.get()) == mesh.positions.size() &&
         std::fwrite(mesh.tets.data(), sizeof mesh.tets[0], mesh.tets.size(), f.get()) == mesh.tets.size();
}

inline std::optional<RawMesh> read_raw_mesh_file(const std::string& path, std::string& error) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!f) {
    error = "cannot open " + path;
    return std::nullopt;
  }
  char magic[sizeof kRawMeshMagic - 1];
  std::uint64_t counts[2];
  if (std::fread(magic, 1, sizeof magic, f.get()) != sizeof magic || std::string(magic, sizeof magic) != kRawMeshMagic ||
      std::fread(counts, sizeof counts, 1, f.get()) != 1) {
    error = path + " is not a raw mesh file (" + std::string(kRawMeshMagic, sizeof kRawMeshMagic - 2) + ")";
    return std::nullopt;
  }
  RawMesh mesh;
  mesh.positions.resize(counts[0]);
  mesh.tets.resize(counts[1]);
  if (std::fread(mesh.positions.data(), sizeof(Vec3), counts[0], f.get()) != counts[0] ||
      std::fread(mesh.tets.data(), sizeof mesh.tets[0], counts[1], f.get()) != counts[1]) {
    error = path + " is truncated";
    return std::nullopt;
  }
  return mesh;
}

}  // namespace tetcut::bench

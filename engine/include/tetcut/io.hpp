// Reading and writing meshes in the formats users bring (design: formats). Formats are chosen by
// file extension. Readers never throw and never crash on bad bytes: a ParseError names the file,
// the line and the reason. Writers write a temporary file next to the target and rename it, so a
// failed write never leaves a partial file.
//
// Readers return tetrahedra only, with 0-based indices and the vertex order of the file (no
// reorientation: that is the builder's job, on request). Other element kinds are ignored with a
// notice. Second-order tetrahedra (Gmsh type 11, VTK type 24, TetGen 10-node .ele) are read as
// their 4 corner vertices, with a notice. A cell declared as a tetrahedron with another number of
// vertices is an error. Readers check the format only: a tet that repeats a vertex is returned as
// is, for the checker to name (I1).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tetcut/mesh.hpp"
#include "tetcut/raw_mesh.hpp"

namespace tetcut {

struct ParseError {
  std::string file;
  std::uint64_t line = 0;  // 1-based; 0 when the error is not tied to a line
  std::string reason;

  // "file:line: reason" ("file: reason" when line is 0)
  [[nodiscard]] std::string message() const;
};

struct ReadResult {
  std::optional<RawMesh> mesh;       // set iff error is empty
  std::optional<ParseError> error;
  std::vector<std::string> notices;  // e.g. "ignored 120 elements of type 2 (triangle)"
};

struct WriteResult {
  bool ok = true;
  std::string error;  // with the path
};

// Dispatch on extension (case-insensitive): .msh (Gmsh 1.0, 2.2 or 4.1, told apart by the file's
// header), .vtu, .vtk, .mesh (medit), .node or .ele (the TetGen pair: x.node with x.ele). Any
// other extension is an error ("unknown extension").
ReadResult read_mesh(const std::string& path);
// .msh is written as 2.2 (the most widely read); call write_mesh_as for 4.1.
WriteResult write_mesh(const std::string& path, const RawMesh& mesh);
WriteResult write_mesh(const std::string& path, const TetMesh& mesh);

enum class MeshFormat { kMsh22, kMsh41, kVtu, kVtk, kMedit, kTetgen };
WriteResult write_mesh_as(const std::string& path, const RawMesh& mesh, MeshFormat format);

// ---- per format, from memory (for fuzzing and tests); `name` is used in errors -----------------

// Gmsh: detects 1.0 ($NOD), 2.x or 4.1 from the header and calls the matching reader.
ReadResult read_msh(std::string_view text, std::string_view name);
// Gmsh MSH 2.2 ASCII.
ReadResult read_msh22(std::string_view text, std::string_view name);
std::string format_msh22(const RawMesh& mesh);
// Gmsh MSH 4.1 ASCII.
ReadResult read_msh41(std::string_view text, std::string_view name);
std::string format_msh41(const RawMesh& mesh);
// Gmsh MSH 1.0 ($NOD / $ELM), read only.
ReadResult read_msh10(std::string_view text, std::string_view name);
// VTK XML unstructured grid: ascii DataArrays; inline binary (base64, UInt32/UInt64 header) and
// appended data (raw or base64), uncompressed. Written as ascii.
ReadResult read_vtu(std::string_view text, std::string_view name);
std::string format_vtu(const RawMesh& mesh);
// Legacy VTK ASCII unstructured grid (file versions up to 5.1: CELLS with OFFSETS/CONNECTIVITY).
ReadResult read_vtk(std::string_view text, std::string_view name);
std::string format_vtk(const RawMesh& mesh);
// medit / Mmg .mesh ASCII (1-based).
ReadResult read_medit(std::string_view text, std::string_view name);
std::string format_medit(const RawMesh& mesh);
// TetGen .node + .ele (0- or 1-based, as the .node file numbers its points).
ReadResult read_tetgen(std::string_view node_text, std::string_view node_name,
                       std::string_view ele_text, std::string_view ele_name);
std::string format_tetgen_node(const RawMesh& mesh);
std::string format_tetgen_ele(const RawMesh& mesh);

// ---- closed triangle surfaces, input of mesh generation -----------------------------------------

struct SurfaceMesh {
  std::vector<Vec3> positions;                        // #V positions
  std::vector<std::array<std::uint32_t, 3>> triangles;  // #F by 3 vertex indices, 0-based
};

struct SurfaceReadResult {
  std::optional<SurfaceMesh> surface;  // set iff error is empty
  std::optional<ParseError> error;
  std::vector<std::string> notices;  // e.g. "split 6 polygons into triangles"
};

// Dispatch on extension: .off, .stl (ASCII or binary), .obj. Polygons are split into triangle
// fans with a notice; STL vertices with bit-identical positions are merged.
SurfaceReadResult read_surface(const std::string& path);
SurfaceReadResult read_off(std::string_view text, std::string_view name);
SurfaceReadResult read_stl(std::string_view bytes, std::string_view name);
SurfaceReadResult read_obj(std::string_view text, std::string_view name);

// ---- files ---------------------------------------------------------------------------------

// The whole file, or a ParseError (line 0) saying why it could not be read.
std::optional<ParseError> read_file(const std::string& path, std::string& contents);

// Writes `contents` to `path` through a temporary file in the same directory and an atomic
// rename. On failure the temporary is removed and `path` is untouched.
WriteResult write_file_atomically(const std::string& path, std::string_view contents);

}  // namespace tetcut

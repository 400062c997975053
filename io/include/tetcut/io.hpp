// Reading and writing meshes in the formats users bring (design: formats). A file's format is
// told by its content where the content says it (VTK XML, legacy VTK, Gmsh, medit), else by its
// extension. Readers never throw and never crash on bad bytes: a ParseError names the file, the
// line (inside binary data: the line of its section's header or tag) and the reason; no
// allocation is larger than what the file can hold (compressed data: than what it decompresses
// to). Writers write a temporary file next to the target and
// rename it, so a failed write never leaves a partial file.
//
// Read and written:
//   Gmsh .msh 2.2 and 4.1, ASCII and binary (either byte order, told by the file's own check
//     value); 1.0 read only;
//   VTK XML .vtu: ascii, inline binary (base64) and appended data (raw or base64), UInt32 or
//     UInt64 headers, either byte order, uncompressed or compressed (vtkZLibDataCompressor,
//     vtkLZMADataCompressor); written as ascii or as appended raw data, optionally compressed;
//   legacy VTK .vtk UNSTRUCTURED_GRID, ASCII and binary (big-endian, as the format says), file
//     versions up to 5.1;
//   medit .mesh (ASCII), TetGen .node/.ele.
// Surfaces, for mesh generation: .off, .stl (ASCII or binary), .obj, VTK POLYDATA (.vtk legacy
// ASCII or binary, .vtp XML).
//
// Readers return tetrahedra only, with 0-based indices and the vertex order of the file (no
// reorientation: that is the builder's job, on request). Other element kinds are ignored with a
// notice, and counted in ReadResult::ignored (a caller that needs tets says what a file without
// any held: no_tetrahedra_reason). Second-order tetrahedra (Gmsh type 11, VTK type 24, TetGen
// 10-node .ele) are read as their 4 corner vertices, with a notice. A cell declared as a
// tetrahedron with another number of vertices is an error. Readers check the format only: a tet
// that repeats a vertex is returned as is, for the checker to name (I1).
//
// Per-tet labels (RawMesh::labels: regions, materials) are read from Gmsh's physical tag (1.0,
// 2.2: each element's; 4.1: the first of its volume entity's, in $Entities; ASCII and binary),
// medit's tetrahedron reference, VTK cell data (legacy and XML: the first array named "label",
// "gmsh:physical", "medit:ref" or "CellEntityIds", in this order of preference, one integer
// component) and TetGen's region attribute (-A: the .ele's last attribute column, an integer or
// an integer-valued real), and written back by the 2.2, 4.1, medit, .vtk, .vtu and TetGen writers
// (VTK: as cell data "label", Int32; TetGen: as the .ele's one attribute, none when unlabelled).
// A label that is not an integer in [0, kMaxTetLabel], or a label array of the wrong length, is
// an error naming file and line.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
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

// How many elements of one kind a reader ignored; `noun` is singular ("hexahedron").
struct CellCount {
  std::string noun;
  std::uint64_t count = 0;
};

struct ReadResult {
  std::optional<RawMesh> mesh;       // set iff error is empty
  std::optional<ParseError> error;
  std::vector<std::string> notices;  // e.g. "ignored 120 elements of type 2 (triangle)"
  std::vector<CellCount> ignored;    // the elements that are not tets, by kind
};

// What a mesh read without tets held, for the error of a caller that needs tets:
// "27 hexahedra, no tetrahedra", "12 points and no cells, no tetrahedra".
std::string no_tetrahedra_reason(const ReadResult& result);

struct WriteResult {
  bool ok = true;
  std::string error;  // with the path
};

// The format is told by the content where its first bytes say it (an XML VTKFile, "# vtk
// DataFile", "$MeshFormat", "MeshVersionFormatted"), whatever the extension, with a notice when
// it differs from the extension's; otherwise by the extension (case-insensitive): .msh (Gmsh 1.0,
// 2.2 or 4.1, told apart by the header), .vtu, .vtk, .mesh (medit), .node or .ele (the TetGen
// pair: x.node with x.ele). An unknown extension whose content is not recognised is an error that
// says what the content looks like.
ReadResult read_mesh(const std::string& path);

enum class MeshFormat { kMsh22, kMsh41, kVtu, kVtk, kMedit, kTetgen };
// Compression of binary VTU arrays.
enum class Compression : std::uint8_t { kNone, kZlib, kLzma };

struct WriteOptions {
  // Gmsh: binary MSH (little-endian); legacy VTK: BINARY (big-endian); VTU: appended raw data.
  // medit and TetGen are written as text only: asking them for binary is an error.
  bool binary = false;
  // VTU only; implies binary.
  Compression compression = Compression::kNone;
};

// By extension; .msh is written as 2.2 (the most widely read): call write_mesh_as for 4.1.
WriteResult write_mesh(const std::string& path, const RawMesh& mesh, const WriteOptions& options = {});
WriteResult write_mesh(const std::string& path, const TetMesh& mesh);
// With `tet_labels` by TetId (one for every live tet's id): each live tet's label is written.
WriteResult write_mesh(const std::string& path, const TetMesh& mesh, std::span<const std::uint32_t> tet_labels);
WriteResult write_mesh_as(const std::string& path, const RawMesh& mesh, MeshFormat format,
                          const WriteOptions& options = {});

// ---- per format, from memory (for fuzzing and tests); `name` is used in errors -----------------

// Gmsh: detects 1.0 ($NOD), 2.x or 4.1 from the header and calls the matching reader.
ReadResult read_msh(std::string_view text, std::string_view name);
// Gmsh MSH 2.2, ASCII or binary.
ReadResult read_msh22(std::string_view text, std::string_view name);
std::string format_msh22(const RawMesh& mesh);
std::string format_msh22_binary(const RawMesh& mesh);
// Gmsh MSH 4.1, ASCII or binary.
ReadResult read_msh41(std::string_view text, std::string_view name);
std::string format_msh41(const RawMesh& mesh);
std::string format_msh41_binary(const RawMesh& mesh);
// Gmsh MSH 1.0 ($NOD / $ELM), read only.
ReadResult read_msh10(std::string_view text, std::string_view name);
// VTK XML unstructured grid (see the top of this file for the encodings read).
ReadResult read_vtu(std::string_view text, std::string_view name);
std::string format_vtu(const RawMesh& mesh);
// Appended raw data, UInt64 headers, little-endian, compressed as asked (32 KiB blocks).
std::string format_vtu_binary(const RawMesh& mesh, Compression compression);
// Legacy VTK unstructured grid, ASCII or BINARY (file versions up to 5.1: CELLS with
// OFFSETS/CONNECTIVITY). Written as version 3.0 (CELLS with point counts), read by every VTK.
ReadResult read_vtk(std::string_view text, std::string_view name);
std::string format_vtk(const RawMesh& mesh);
std::string format_vtk_binary(const RawMesh& mesh);
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

// Dispatch on extension: .off, .stl (ASCII or binary), .obj, .vtk and .vtp (VTK POLYDATA; a
// .vtk or .vtp is read as legacy or XML by its content). Polygons and triangle strips are split
// into triangles with a notice; STL vertices with bit-identical positions are merged.
SurfaceReadResult read_surface(const std::string& path);
SurfaceReadResult read_off(std::string_view text, std::string_view name);
SurfaceReadResult read_stl(std::string_view bytes, std::string_view name);
SurfaceReadResult read_obj(std::string_view text, std::string_view name);
// Legacy VTK DATASET POLYDATA (POLYGONS, TRIANGLE_STRIPS), ASCII or BINARY.
SurfaceReadResult read_vtk_polydata(std::string_view text, std::string_view name);
// VTK XML PolyData (.vtp): Polys and Strips, every encoding read_vtu reads.
SurfaceReadResult read_vtp(std::string_view text, std::string_view name);

// ---- files ---------------------------------------------------------------------------------

// The whole file, or a ParseError (line 0) saying why it could not be read.
std::optional<ParseError> read_file(const std::string& path, std::string& contents);

// Writes `contents` to `path` through a temporary file in the same directory and an atomic
// rename. On failure the temporary is removed and `path` is untouched.
WriteResult write_file_atomically(const std::string& path, std::string_view contents);

}  // namespace tetcut

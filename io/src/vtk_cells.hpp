// What legacy .vtk and XML .vtu share: VTK's cell-type table and the step from (offsets,
// connectivity, types) to tets, ignoring other cell types with a notice.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "text_reader.hpp"

namespace tetcut::io_detail {

inline constexpr std::int64_t kVtkTetra = 10;
inline constexpr std::int64_t kVtkQuadraticTetra = 24;

// Cells as VTK stores them: cell i has connectivity[offsets[i] .. offsets[i+1]).
struct VtkCells {
  std::vector<std::uint64_t> offsets{0};      // #cells + 1, non-decreasing, offsets[0] == 0
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> types;            // #cells
  std::vector<std::uint64_t> lines;           // line of each cell, or empty (then `line` below)
};

// "triangle", "hexahedron", ... or "" for a type we do not name.
std::string_view vtk_type_name(std::int64_t type);
// The noun a summary uses for cells of `type` ("hexahedron", "cell of VTK type 99").
std::string vtk_type_noun(std::int64_t type);
// Counts one ignored cell of `type` in `ignored` ("cells of VTK type 12 (hexahedron)").
void ignore_vtk_cell(IgnoredTally& ignored, std::int64_t type);

// VTK XML's offsets are where each cell ends: appends them to cells.offsets, checking that
// they increase within the connectivity (an error at `line` otherwise).
bool append_cell_ends(ErrorSink& sink, const std::vector<std::int64_t>& ends, std::uint64_t line, VtkCells& cells);

// Appends the tets of `cells` (point ids checked against num_points); the other cells go to
// `ignored`, a notice for quadratic tets to `notices`. `tet_cells`, when given, gets the cell
// index of every tet appended (to pick its label out of the cell data).
bool vtk_cells_to_tets(ErrorSink& sink, const VtkCells& cells, std::uint64_t num_points,
                       std::uint64_t line, std::vector<std::array<std::uint32_t, 4>>& tets,
                       IgnoredTally& ignored, std::vector<std::string>& notices,
                       std::vector<std::uint32_t>* tet_cells = nullptr);

// The cell data arrays a tet's label is read from, most preferred first: ours, then the names
// meshio gives Gmsh's physical tags and medit's references, then VTK's own (vtkGmshReader and
// ParaView's). A one-component integer array; a file with none of them is unlabelled.
inline constexpr std::string_view kLabelArrayNames[] = {"label", "gmsh:physical", "medit:ref", "CellEntityIds"};
// Its rank in kLabelArrayNames, or -1 when `name` is not a label array.
int label_array_rank(std::string_view name);
// labels[i] := values[tet_cells[i]], each checked by check_label (an error naming `array`).
bool labels_from_cell_data(ErrorSink& sink, std::uint64_t line, std::string_view array,
                           const std::vector<std::int64_t>& values, std::uint64_t cells,
                           const std::vector<std::uint32_t>& tet_cells, std::vector<std::uint32_t>& labels);

// Appends the triangles of polygons (`strips` false: each a fan) or of triangle strips (true:
// each consecutive triple, every other one turned so that all face the same way); point ids are
// checked against num_points. Counts the polygons with more than 3 corners and the strips.
bool vtk_faces_to_triangles(ErrorSink& sink, const VtkCells& cells, std::uint64_t num_points,
                            std::uint64_t line, bool strips, SurfaceMesh& surface,
                            std::uint64_t& polygons_split, std::uint64_t& strips_split);

}  // namespace tetcut::io_detail

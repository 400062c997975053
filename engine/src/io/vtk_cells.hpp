// What legacy .vtk and XML .vtu share: VTK's cell-type table and the step from (offsets,
// connectivity, types) to tets, ignoring other cell types with a notice.
#pragma once

#include <array>
#include <cstdint>
#include <string>
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

// Appends the tets of `cells` (point ids checked against num_points); notices for the rest.
bool vtk_cells_to_tets(ErrorSink& sink, const VtkCells& cells, std::uint64_t num_points,
                       std::uint64_t line, std::vector<std::array<std::uint32_t, 4>>& tets,
                       std::vector<std::string>& notices);

}  // namespace tetcut::io_detail

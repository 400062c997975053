#include "vtk_cells.hpp"

#include <string_view>

namespace tetcut::io_detail {

std::string_view vtk_type_name(std::int64_t type) {
  switch (type) {
    case 1: return "vertex";
    case 2: return "poly-vertex";
    case 3: return "line";
    case 4: return "poly-line";
    case 5: return "triangle";
    case 6: return "triangle strip";
    case 7: return "polygon";
    case 8: return "pixel";
    case 9: return "quad";
    case 10: return "tetrahedron";
    case 11: return "voxel";
    case 12: return "hexahedron";
    case 13: return "wedge";
    case 14: return "pyramid";
    case 21: return "quadratic edge";
    case 22: return "quadratic triangle";
    case 23: return "quadratic quad";
    case 24: return "quadratic tetrahedron";
    case 25: return "quadratic hexahedron";
    default: return "";
  }
}

std::string vtk_type_noun(std::int64_t type) {
  const std::string_view name = vtk_type_name(type);
  return name.empty() ? "cell of VTK type " + std::to_string(type) : std::string(name);
}

void ignore_vtk_cell(IgnoredTally& ignored, std::int64_t type) {
  std::string kind = "cells of VTK type " + std::to_string(type);
  const std::string_view name = vtk_type_name(type);
  if (!name.empty()) kind += " (" + std::string(name) + ")";
  ignored.add(std::move(kind), 1, vtk_type_noun(type));
}

bool append_cell_ends(ErrorSink& sink, const std::vector<std::int64_t>& ends, std::uint64_t line, VtkCells& cells) {
  for (std::size_t c = 0; c < ends.size(); ++c) {
    if (ends[c] < 0 || static_cast<std::uint64_t>(ends[c]) < cells.offsets.back() ||
        static_cast<std::uint64_t>(ends[c]) > cells.connectivity.size()) {
      return sink.fail(line, "offsets not increasing within the connectivity at cell " + std::to_string(c));
    }
    cells.offsets.push_back(static_cast<std::uint64_t>(ends[c]));
  }
  return true;
}

bool vtk_cells_to_tets(ErrorSink& sink, const VtkCells& cells, std::uint64_t num_points,
                       std::uint64_t line, std::vector<std::array<std::uint32_t, 4>>& tets,
                       IgnoredTally& ignored, std::vector<std::string>& notices,
                       std::vector<std::uint32_t>* tet_cells) {
  std::uint64_t second_order = 0;
  const std::size_t n = cells.types.size();
  if (cells.offsets.size() != n + 1) {
    return sink.fail(line, std::to_string(cells.offsets.size() - 1) + " cells but " +
                               std::to_string(n) + " cell types");
  }
  for (std::size_t c = 0; c < n; ++c) {
    const std::uint64_t at = cells.lines.empty() ? line : cells.lines[c];
    const std::int64_t type = cells.types[c];
    const std::uint64_t begin = cells.offsets[c];
    const std::uint64_t end = cells.offsets[c + 1];
    if (end < begin || end > cells.connectivity.size()) {
      return sink.fail(at, "cell " + std::to_string(c) + ": offsets out of range of the connectivity");
    }
    const std::uint64_t size = end - begin;
    if (type != kVtkTetra && type != kVtkQuadraticTetra) {
      ignore_vtk_cell(ignored, type);
      continue;
    }
    const std::uint64_t expected = type == kVtkTetra ? 4 : 10;
    if (size != expected) {
      return sink.fail(at, "expected " + std::to_string(expected) + " point ids for a " +
                               std::string(vtk_type_name(type)) + " (cell " + std::to_string(c) +
                               "), got " + std::to_string(size));
    }
    std::array<std::uint32_t, 4> tet{};
    // VTK lists a quadratic tet's 4 corners first.
    for (std::uint64_t k = 0; k < expected; ++k) {
      const std::int64_t id = cells.connectivity[begin + k];
      if (id < 0 || static_cast<std::uint64_t>(id) >= num_points) {
        return sink.fail(at, "point id " + std::to_string(id) + " not defined (" +
                                 std::to_string(num_points) + " points)");
      }
      if (k < 4) tet[k] = static_cast<std::uint32_t>(id);
    }
    if (type == kVtkQuadraticTetra) ++second_order;
    tets.push_back(tet);
    if (tet_cells != nullptr) tet_cells->push_back(static_cast<std::uint32_t>(c));
  }
  if (second_order > 0) {
    notices.push_back("read " + std::to_string(second_order) +
                      " quadratic tetrahedra (VTK type 24) as their 4 corner points");
  }
  return true;
}

bool vtk_faces_to_triangles(ErrorSink& sink, const VtkCells& cells, std::uint64_t num_points,
                            std::uint64_t line, bool strips, SurfaceMesh& surface,
                            std::uint64_t& polygons_split, std::uint64_t& strips_split) {
  std::vector<std::uint32_t> corners;
  for (std::size_t c = 0; c + 1 < cells.offsets.size(); ++c) {
    const std::uint64_t at = cells.lines.empty() ? line : cells.lines[c];
    const std::uint64_t begin = cells.offsets[c];
    const std::uint64_t end = cells.offsets[c + 1];
    if (end < begin || end > cells.connectivity.size()) {
      return sink.fail(at, "cell " + std::to_string(c) + ": offsets out of range of the connectivity");
    }
    if (end - begin < 3) {
      return sink.fail(at, std::string(strips ? "triangle strip " : "polygon ") + std::to_string(c) + " has " +
                               std::to_string(end - begin) + " points, fewer than 3");
    }
    corners.clear();
    for (std::uint64_t k = begin; k < end; ++k) {
      const std::int64_t id = cells.connectivity[k];
      if (id < 0 || static_cast<std::uint64_t>(id) >= num_points) {
        return sink.fail(at, "point id " + std::to_string(id) + " not defined (" + std::to_string(num_points) + " points)");
      }
      corners.push_back(static_cast<std::uint32_t>(id));
    }
    if (!strips) {
      add_polygon(surface, corners, polygons_split);
      continue;
    }
    for (std::size_t k = 0; k + 2 < corners.size(); ++k) {
      if (k % 2 == 0) surface.triangles.push_back({corners[k], corners[k + 1], corners[k + 2]});
      else surface.triangles.push_back({corners[k + 1], corners[k], corners[k + 2]});
    }
    ++strips_split;
  }
  return true;
}

int label_array_rank(std::string_view name) {
  for (std::size_t r = 0; r < std::size(kLabelArrayNames); ++r)
    if (name == kLabelArrayNames[r]) return static_cast<int>(r);
  return -1;
}

bool labels_from_cell_data(ErrorSink& sink, std::uint64_t line, std::string_view array,
                           const std::vector<std::int64_t>& values, std::uint64_t cells,
                           const std::vector<std::uint32_t>& tet_cells, std::vector<std::uint32_t>& labels) {
  if (values.size() != cells) {
    return sink.fail(line, "cell data " + quote(array) + " has " + std::to_string(values.size()) + " values for " +
                               std::to_string(cells) + " cells");
  }
  labels.clear();
  labels.reserve(tet_cells.size());
  for (std::uint32_t c : tet_cells) {
    std::uint32_t label = 0;
    if (!check_label(sink, line, values[c], "cell data " + quote(array) + " of cell " + std::to_string(c) + ":",
                     label)) {
      return false;
    }
    labels.push_back(label);
  }
  return true;
}

}  // namespace tetcut::io_detail

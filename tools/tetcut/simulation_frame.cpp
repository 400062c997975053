#include "simulation_frame.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

namespace tetcut::cli {

std::optional<std::string> write_simulation_frame(const std::string& path, const TetMesh& mesh,
                                                  const mechanics::TensorMassModel& model) {
  std::vector<std::uint32_t> index(mesh.vertex_capacity(), 0);
  std::uint32_t points = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.is_live(VertId{v})) index[v] = points++;
  const double to_mesh = 1.0 / model.params().length_unit;
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) return path + ": cannot write";
    char buffer[128];
    auto number = [&](double x) {
      std::snprintf(buffer, sizeof buffer, "%.17g ", x);
      out << buffer;
    };
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << mesh.num_tets() << "\">\n"
        << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
      if (!mesh.is_live(VertId{v})) continue;
      const Vec3& p = mesh.position(VertId{v});
      number(p.x), number(p.y), number(p.z);
      out << '\n';
    }
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
      if (!mesh.is_live(TetId{t})) continue;
      for (VertId v : mesh.tet(TetId{t})) out << index[v.value] << ' ';
      out << '\n';
    }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::uint32_t k = 1; k <= mesh.num_tets(); ++k) out << 4 * std::uint64_t{k} << (k % 16 == 0 ? '\n' : ' ');
    out << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::uint32_t k = 1; k <= mesh.num_tets(); ++k) out << "10" << (k % 32 == 0 ? '\n' : ' ');
    out << "\n</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\">\n"
        << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
      if (!mesh.is_live(VertId{v})) continue;
      const Vec3 u = to_mesh * model.displacement(VertId{v});
      number(u.x), number(u.y), number(u.z);
      out << '\n';
    }
    out << "</DataArray>\n</PointData>\n<CellData Scalars=\"label\">\n"
        << "<DataArray type=\"Int64\" Name=\"label\" format=\"ascii\">\n";
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
      if (!mesh.is_live(TetId{t})) continue;
      const std::uint32_t label = model.label(TetId{t});
      out << (label == mechanics::TensorMassModel::kNoLabel ? -1 : static_cast<std::int64_t>(label)) << '\n';
    }
    out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    if (!out.flush()) return path + ": cannot write";
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) return path + ": cannot write (" + ec.message() + ")";
  return std::nullopt;
}

}  // namespace tetcut::cli

// VTK XML UnstructuredGrid (.vtu): the tets of every Piece (vtk_xml.hpp finds the arrays,
// vtk_xml_arrays.hpp decodes them, vtk_cells.hpp keeps the tetrahedra) with their labels from
// the piece's CellData (the best ranked of kLabelArrayNames, vtk_cells.hpp; a piece without one:
// label 0, a file without any: unlabelled), and the two writers, which write the labels of a
// labelled mesh as the CellData array "label" (Int32):
// ascii, and binary appended raw data (UInt64 headers, little-endian), optionally compressed
// with zlib or xz in 32 KiB blocks as VTK itself writes them.
#include <algorithm>
#include <string>

#include "byte_order.hpp"
#include "compression.hpp"
#include "tetcut/io.hpp"
#include "text_reader.hpp"
#include "vtk_cells.hpp"
#include "vtk_xml.hpp"
#include "vtk_xml_arrays.hpp"

namespace tetcut {

namespace {

using namespace io_detail;

class VtuReader {
 public:
  VtuReader(std::string_view text, std::string_view name) : text_(text), sink_(name), arrays_(text, file_, sink_) {}

  ReadResult read() {
    std::vector<std::string> notices;
    if (scan_vtk_xml(text_, "UnstructuredGrid", sink_, file_)) {
      for (const VtkXmlPiece& piece : file_.pieces) {
        if (!read_piece(piece, notices)) break;
      }
    }
    if (!sink_.failed()) ignored_.emit(notices);
    if (!labelled_) mesh_.labels.clear();
    return make_result(sink_, std::move(mesh_), std::move(notices), &ignored_);
  }

 private:
  bool read_counts(const VtkXmlPiece& piece, std::uint64_t& points, std::uint64_t& cells) {
    if (!piece_count(sink_, piece, "NumberOfPoints", true, points) ||
        !piece_count(sink_, piece, "NumberOfCells", true, cells)) {
      return false;
    }
    // Each point and each cell takes a few bytes somewhere in an uncompressed file; compressed
    // data may hold more, and is then held to what its arrays decode to.
    const std::size_t room = file_.compressor ? static_cast<std::size_t>(-1) / 4 : text_.size();
    return check_count(sink_, piece.line, points, room) && check_count(sink_, piece.line, cells, room);
  }

  bool read_piece(const VtkXmlPiece& piece, std::vector<std::string>& notices) {
    std::uint64_t points = 0;
    std::uint64_t num_cells = 0;
    if (!read_counts(piece, points, num_cells)) return false;
    const VtkDataArray* coordinates = piece.find("Points", "");
    const VtkDataArray* connectivity = piece.find("Cells", "connectivity");
    const VtkDataArray* offsets = piece.find("Cells", "offsets");
    const VtkDataArray* types = piece.find("Cells", "types");
    const char* missing = coordinates == nullptr ? "Points" : connectivity == nullptr ? "connectivity"
                        : offsets == nullptr     ? "offsets" : types == nullptr       ? "types" : nullptr;
    if (points == 0 && num_cells == 0) return true;
    if (missing != nullptr) return sink_.fail(piece.line, std::string("Piece has no ") + missing + " DataArray");
    if (coordinates->components != 3) {
      return sink_.fail(coordinates->line, "Points must have 3 components, got " + std::to_string(coordinates->components));
    }
    std::vector<double> xyz;
    if (!arrays_.reals(*coordinates, points * 3, "coordinate", xyz)) return false;
    const std::uint64_t base = mesh_.positions.size();
    for (std::uint64_t i = 0; i < points; ++i) mesh_.positions.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
    VtkCells cells;
    std::vector<std::int64_t> ends;
    if (!arrays_.integers(*connectivity, VtkArrayDecoder::kAny, "connectivity", cells.connectivity) ||
        !arrays_.integers(*offsets, num_cells, "offsets", ends) ||
        !arrays_.integers(*types, num_cells, "types", cells.types)) {
      return false;
    }
    if (!append_cell_ends(sink_, ends, offsets->line, cells)) return false;
    std::vector<std::int64_t>().swap(ends);  // the session's peak is here (bench/session_memory.cpp)
    const std::size_t first_tet = mesh_.tets.size();
    // Room for every cell as a tet, grown geometrically over pieces: push_back's doubling held up
    // to half the tets again.
    if (mesh_.tets.capacity() < first_tet + num_cells)
      mesh_.tets.reserve(std::max<std::size_t>(first_tet + num_cells, 2 * mesh_.tets.capacity()));
    std::vector<std::uint32_t> tet_cells;
    if (!vtk_cells_to_tets(sink_, cells, points, types->line, mesh_.tets, ignored_, notices, &tet_cells)) return false;
    for (std::size_t t = first_tet; t < mesh_.tets.size(); ++t) {
      for (std::uint32_t& v : mesh_.tets[t]) v += static_cast<std::uint32_t>(base);
    }
    return read_labels(piece, num_cells, tet_cells);
  }

  // The piece's tets' labels after those of the pieces before (0 for an unlabelled piece).
  bool read_labels(const VtkXmlPiece& piece, std::uint64_t num_cells, const std::vector<std::uint32_t>& tet_cells) {
    const VtkDataArray* label = nullptr;
    for (const VtkDataArray& a : piece.arrays) {
      if (a.parent == "CellData" && (label == nullptr || label_array_rank(a.name) < label_array_rank(label->name))) {
        label = &a;
      }
    }
    mesh_.labels.resize(mesh_.tets.size() - tet_cells.size(), 0);
    if (label == nullptr) {
      mesh_.labels.resize(mesh_.tets.size(), 0);
      return true;
    }
    if (label->components != 1) {
      return sink_.fail(label->line, "cell data " + quote(label->name) + " has " + std::to_string(label->components) +
                                         " components, a label has 1");
    }
    std::vector<std::int64_t> values;
    std::vector<std::uint32_t> piece_labels;
    if (!arrays_.integers(*label, num_cells, "cell data " + quote(label->name), values) ||
        !labels_from_cell_data(sink_, label->line, label->name, values, num_cells, tet_cells, piece_labels)) {
      return false;
    }
    mesh_.labels.insert(mesh_.labels.end(), piece_labels.begin(), piece_labels.end());
    labelled_ = true;
    return true;
  }

  std::string_view text_;
  ErrorSink sink_;
  VtkXmlFile file_;
  VtkArrayDecoder arrays_;
  RawMesh mesh_;
  IgnoredTally ignored_;
  bool labelled_ = false;
};

// ---- writing ---------------------------------------------------------------------------------

constexpr std::size_t kBlockSize = 32768;  // VTK's default block size for compressed arrays

// One array's appended block: its header (UInt64, little-endian) and data, compressed or not.
void append_block(std::string& appended, std::string_view data, Compression compression) {
  constexpr auto kOrder = ByteOrder::kLittle;
  if (compression == Compression::kNone) {
    store_uint(appended, data.size(), 8, kOrder);
    appended += data;
    return;
  }
  const Compressor compressor = compression == Compression::kZlib ? Compressor::kZlib : Compressor::kLzma;
  const std::size_t blocks = (data.size() + kBlockSize - 1) / kBlockSize;
  std::vector<std::string> compressed;
  compressed.reserve(blocks);
  for (std::size_t b = 0; b < blocks; ++b) compressed.push_back(compress_block(compressor, data.substr(b * kBlockSize, kBlockSize)));
  store_uint(appended, blocks, 8, kOrder);
  store_uint(appended, kBlockSize, 8, kOrder);
  store_uint(appended, data.size() % kBlockSize, 8, kOrder);  // 0: the last block is full
  for (const std::string& c : compressed) store_uint(appended, c.size(), 8, kOrder);
  for (const std::string& c : compressed) appended += c;
}

void open_piece(std::string& out, const RawMesh& mesh, std::string_view compressor) {
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\"";
  if (!compressor.empty()) {
    out += " compressor=\"";
    out += compressor;
    out += '"';
  }
  out += ">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  append_uint(out, mesh.positions.size());
  out += "\" NumberOfCells=\"";
  append_uint(out, mesh.tets.size());
  out += "\">\n";
}

constexpr const char* kClosePiece = "    </Piece>\n  </UnstructuredGrid>\n";

}  // namespace

ReadResult read_vtu(std::string_view text, std::string_view name) {
  return VtuReader(text, name).read();
}

std::string format_vtu(const RawMesh& mesh) {
  std::string out;
  out.reserve(512 + mesh.positions.size() * 60 + mesh.tets.size() * 48);
  open_piece(out, mesh, "");
  out += "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  append_point_lines(out, mesh.positions, "          ");
  out += "        </DataArray>\n      </Points>\n      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& tet : mesh.tets) {
    out += "         ";
    for (std::uint32_t v : tet) {
      out += ' ';
      append_uint(out, v);
    }
    out += '\n';
  }
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    out += "          ";
    append_uint(out, 4 * (t + 1));
    out += '\n';
  }
  out += "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) out += "          10\n";
  out += "        </DataArray>\n      </Cells>\n";
  if (mesh.labelled()) {
    out += "      <CellData Scalars=\"label\">\n        <DataArray type=\"Int32\" Name=\"label\" format=\"ascii\">\n";
    for (std::uint32_t label : mesh.labels) {
      out += "          ";
      append_uint(out, label);
      out += '\n';
    }
    out += "        </DataArray>\n      </CellData>\n";
  }
  out += kClosePiece;
  out += "</VTKFile>\n";
  return out;
}

std::string format_vtu_binary(const RawMesh& mesh, Compression compression) {
  constexpr auto kOrder = ByteOrder::kLittle;
  std::string points;
  points.reserve(mesh.positions.size() * 24);
  for (const Vec3& p : mesh.positions) {
    for (double c : {p.x, p.y, p.z}) store_f64(points, c, kOrder);
  }
  std::string connectivity;
  std::string offsets;
  connectivity.reserve(mesh.tets.size() * 32);
  offsets.reserve(mesh.tets.size() * 8);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (std::uint32_t v : mesh.tets[t]) store_uint(connectivity, v, 8, kOrder);
    store_uint(offsets, 4 * (t + 1), 8, kOrder);
  }
  const std::string types(mesh.tets.size(), static_cast<char>(kVtkTetra));
  std::string labels;
  labels.reserve(mesh.labels.size() * 4);
  for (std::uint32_t label : mesh.labels) store_uint(labels, label, 4, kOrder);

  std::string appended;
  std::size_t array_offsets[5] = {};
  const std::string_view arrays[5] = {points, connectivity, offsets, types, labels};
  for (int i = 0; i < (mesh.labelled() ? 5 : 4); ++i) {
    array_offsets[i] = appended.size();
    append_block(appended, arrays[i], compression);
  }
  std::string out;
  out.reserve(1024 + appended.size());
  open_piece(out, mesh, compression == Compression::kZlib   ? "vtkZLibDataCompressor"
                        : compression == Compression::kLzma ? "vtkLZMADataCompressor"
                                                            : "");
  const auto array_tag = [&](const char* attributes, std::size_t offset) {
    out += "        <DataArray ";
    out += attributes;
    out += " format=\"appended\" offset=\"";
    append_uint(out, offset);
    out += "\"/>\n";
  };
  out += "      <Points>\n";
  array_tag("type=\"Float64\" NumberOfComponents=\"3\"", array_offsets[0]);
  out += "      </Points>\n      <Cells>\n";
  array_tag("type=\"Int64\" Name=\"connectivity\"", array_offsets[1]);
  array_tag("type=\"Int64\" Name=\"offsets\"", array_offsets[2]);
  array_tag("type=\"UInt8\" Name=\"types\"", array_offsets[3]);
  out += "      </Cells>\n";
  if (mesh.labelled()) {
    out += "      <CellData Scalars=\"label\">\n";
    array_tag("type=\"Int32\" Name=\"label\"", array_offsets[4]);
    out += "      </CellData>\n";
  }
  out += kClosePiece;
  out += "  <AppendedData encoding=\"raw\">\n   _";
  out += appended;
  out += "\n  </AppendedData>\n</VTKFile>\n";
  return out;
}

}  // namespace tetcut

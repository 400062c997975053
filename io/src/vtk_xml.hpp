// The structure of a VTK XML file (.vtu, .vtp): one pass of a small XML scanner over
//   VTKFile > UnstructuredGrid | PolyData > Piece > Points, Cells, Polys, ... > DataArray
// that records where each DataArray's content is, without decoding it (vtk_xml_arrays.hpp does),
// and stops at <AppendedData>. Internal to the engine (not installed).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "byte_order.hpp"
#include "compression.hpp"
#include "text_reader.hpp"

namespace tetcut::io_detail {

struct XmlAttribute {
  std::string_view name;
  std::string_view value;
};

struct VtkDataArray {
  std::string_view parent;  // the element that holds it: Points, Cells, Polys, Strips, PointData...
  std::string_view name;
  std::string_view type;    // Int8 ... Float64
  std::string_view format;  // ascii | binary | appended
  std::uint64_t components = 1;
  std::uint64_t offset = 0;  // appended only: where its data starts after the '_' mark
  std::size_t content_begin = 0;
  std::size_t content_end = 0;
  std::uint64_t line = 0;          // of the tag
  std::uint64_t content_line = 0;  // of the first character of the content
};

struct VtkXmlPiece {
  std::uint64_t line = 0;
  std::vector<XmlAttribute> attributes;  // NumberOfPoints, NumberOfCells, NumberOfPolys, ...
  std::vector<VtkDataArray> arrays;      // in file order

  // The first array under `parent` named `name` (any name when `name` is empty).
  [[nodiscard]] const VtkDataArray* find(std::string_view parent, std::string_view name) const;
};

struct VtkXmlFile {
  std::string_view type;  // the VTKFile's type: UnstructuredGrid, PolyData
  std::size_t header_size = 4;  // bytes of a binary block's header values (UInt32 or UInt64)
  ByteOrder order = ByteOrder::kLittle;
  std::optional<Compressor> compressor;
  std::vector<VtkXmlPiece> pieces;
  bool have_appended = false;
  bool appended_base64 = false;
  std::size_t appended_begin = 0;  // just after the '_' mark
};

// Size in bytes of a VTK scalar type, 0 for an unknown one.
std::size_t vtk_type_size(std::string_view type);

// Scans `text` as a VTK XML file whose VTKFile type is `expected_type`. False, with the error in
// `sink`, when the XML is malformed, the type differs, or an attribute is not one VTK writes.
bool scan_vtk_xml(std::string_view text, std::string_view expected_type, ErrorSink& sink, VtkXmlFile& file);

// The piece's count attribute `name` (e.g. NumberOfPoints); 0 when absent unless `required`.
// False with an error when it is not a non-negative integer, or required and absent.
bool piece_count(ErrorSink& sink, const VtkXmlPiece& piece, std::string_view name, bool required,
                 std::uint64_t& count);

}  // namespace tetcut::io_detail

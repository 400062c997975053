// Telling a file's format by its first bytes, as readers that go by content do: a `.vtk` that
// holds VTK XML is read as VTK XML, and a file whose extension says nothing is still read when
// its content does. Internal to the engine (not installed).
#pragma once

#include <string>
#include <string_view>

namespace tetcut::io_detail {

enum class ContentFormat {
  kUnknown,
  kVtkXml,     // <VTKFile ...>: `dataset` is its type (UnstructuredGrid, PolyData, ...)
  kLegacyVtk,  // "# vtk DataFile Version": `dataset` is its DATASET (UNSTRUCTURED_GRID, ...)
  kGmsh,       // $MeshFormat, $NOD or $Comments first
  kMedit,      // MeshVersionFormatted first (after comments)
  kSurface,    // STL (ASCII), OFF or OBJ text: a surface, not a volume mesh
};

struct DetectedContent {
  ContentFormat format = ContentFormat::kUnknown;
  std::string dataset;      // VTK only; may be empty when the header does not say
  std::string description;  // for messages: "VTK XML UnstructuredGrid", "binary data", ...
};

DetectedContent detect_content(std::string_view bytes);

}  // namespace tetcut::io_detail

// The file layout MSH 2.2 and 4.1 share: "$MeshFormat" first (only $Comments may come before),
// one "$Nodes", one "$Elements" after it, every other section ($PhysicalNames, $Entities,
// $NodeData, ...) skipped to its $End marker. Each version reads the three sections it knows; in
// a binary file their data is raw (gmsh_binary.hpp). Internal to the engine (not installed).
#pragma once

#include <string_view>

#include "gmsh_binary.hpp"
#include "gmsh_common.hpp"

namespace tetcut::io_detail {

class GmshSectionReader : public GmshReader {
 public:
  ReadResult read();

 protected:
  GmshSectionReader(std::string_view text, std::string_view name) : GmshReader(text, name, "$Nodes", "$Elements") {}

  // Called on the $MeshFormat line; reads up to $EndMeshFormat.
  virtual void read_format() = 0;

  GmshBinaryReader binary_reader_{lines_, sink_, mesh_, ids_, elements_};
  bool binary_ = false;  // the format line said file-type 1
};

}  // namespace tetcut::io_detail

// The file layout MSH 2.2 and 4.1 share: "$MeshFormat" first (only $Comments may come before),
// one "$Nodes", one "$Elements" after it, "$Entities" read by the version that knows it, every
// other section ($PhysicalNames, $NodeData, ...) skipped to its $End marker. Each version reads the three sections it knows; in
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
  // Called on an $Entities line; reads up to $EndEntities (MSH 4.1's physical tags live there).
  // 2.2 has none and skips it.
  virtual void read_entities() { skip_gmsh_section(lines_, sink_, "Entities"); }

  GmshBinaryReader binary_reader_{lines_, sink_, mesh_, ids_, elements_};
  bool binary_ = false;  // the format line said file-type 1
};

}  // namespace tetcut::io_detail

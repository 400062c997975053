#include "support/reader_contract.hpp"

#include <cmath>
#include <string>

#include "support/fuzz_failure.hpp"
#include "support/planted_bug.hpp"

namespace tetcut::fuzz {
namespace {

// A reader runs as operation 0 of its target: the input is one file.
constexpr std::size_t kReadOperation = 0;

std::string where(std::string_view what, std::size_t index) {
  std::string out(what);
  out += ' ';
  out += std::to_string(index);
  return out;
}

template <class Result>
void check_exactly_one(std::string_view reader, const Result& result, bool has_value) {
  if (has_value == result.error.has_value())
    fail("reader-contract", kReadOperation, reader,
         has_value ? "returned both a mesh and an error" : "returned neither a mesh nor an error");
}

void check_positions(std::string_view reader, const std::vector<Vec3>& positions) {
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!is_finite(positions[i])) fail("reader-contract", kReadOperation, reader, where("non-finite coordinate at vertex", i));
}

template <std::size_t N>
void check_indices(std::string_view reader, const std::vector<std::array<std::uint32_t, N>>& cells,
                   std::size_t vertex_count, std::string_view cell_name) {
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (std::uint32_t v : cells[c])
      if (v >= vertex_count)
        fail("reader-contract", kReadOperation, reader,
             where(cell_name, c) + " references vertex " + std::to_string(v) + " of " + std::to_string(vertex_count));
}

}  // namespace

const RawMesh* check_read_result(std::string_view reader, const ReadResult& result) {
  check_exactly_one(reader, result, result.mesh.has_value());
  if (!result.mesh) return nullptr;
  check_positions(reader, result.mesh->positions);
  check_indices(reader, result.mesh->tets, result.mesh->positions.size(), "tet");
  const RawMesh& m = *result.mesh;
  if (m.labelled() && m.labels.size() != m.tets.size())
    fail("reader-contract", kReadOperation, reader,
         std::to_string(m.labels.size()) + " labels for " + std::to_string(m.tets.size()) + " tets");
  for (std::size_t t = 0; t < m.labels.size(); ++t)
    if (m.labels[t] > kMaxTetLabel) fail("reader-contract", kReadOperation, reader, where("label out of range at tet", t));
  return &*result.mesh;
}

void check_surface_result(std::string_view reader, const SurfaceReadResult& result) {
  check_exactly_one(reader, result, result.surface.has_value());
  if (!result.surface) return;
  check_positions(reader, result.surface->positions);
  check_indices(reader, result.surface->triangles, result.surface->positions.size(), "triangle");
}

void check_round_trip(std::string_view writer, const RawMesh& mesh, TetFormatter format, TetReader read) {
  const std::string text = format(mesh);
  const ReadResult again = read(text, "round-trip");
  const std::string operation = std::string(writer) + " round trip";
  if (!again.mesh)
    fail("round-trip", 1, operation, "rereading our own output failed: " + (again.error ? again.error->message() : std::string()));
  const RawMesh& back = *again.mesh;
  if (back.positions.size() != mesh.positions.size() || back.tets.size() != mesh.tets.size())
    fail("round-trip", 1, operation,
         "counts changed: " + std::to_string(mesh.positions.size()) + " vertices, " + std::to_string(mesh.tets.size()) +
             " tets became " + std::to_string(back.positions.size()) + ", " + std::to_string(back.tets.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!(back.positions[i] == mesh.positions[i])) fail("round-trip", 1, operation, where("position changed at vertex", i));
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    if (back.tets[t] != mesh.tets[t]) fail("round-trip", 1, operation, where("vertices changed in tet", t));
  // Labels, where the writer carries them (every formatter a target round-trips through but
  // TetGen's, which writes none); an unlabelled mesh may come back with the writer's one region
  // (Gmsh 1.0 and 2.2, medit: 1).
  if (mesh.labelled() && back.labelled() && back.labels != mesh.labels)
    fail("round-trip", 1, operation, "labels changed");
}

void fuzz_tet_reader(std::string_view reader_name, TetReader read, std::string_view text, TetFormatter format,
                     TetReader reread, TetFormatter binary_format) {
  if (kPlantedReaderBug && text.find(kPlantedBugMarker) != std::string_view::npos)
    fail("planted-bug", kReadOperation, reader_name, "the input holds the planted marker (fuzz/support/planted_bug.hpp)");
  const ReadResult result = read(text, "input");
  const RawMesh* mesh = check_read_result(reader_name, result);
  if (mesh == nullptr || reread == nullptr) return;
  if (format != nullptr) check_round_trip(reader_name, *mesh, format, reread);
  if (binary_format != nullptr) check_round_trip(std::string(reader_name) + " (binary)", *mesh, binary_format, reread);
}

}  // namespace tetcut::fuzz

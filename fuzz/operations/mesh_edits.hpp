// Decoding fuzz bytes into edits of a mesh: which tet, which edges, which ball. Every value is
// clamped to what is valid (a live tet, an existing edge, a positive radius), so that no input is
// wasted on a refusal the API documents. Shared by the operation targets (mixed_ops,
// checker_differential, and the removal and cut targets to come).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "core/tool.hpp"
#include "refine/edge_split.hpp"
#include "refine/refine.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/raw_mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::fuzz {

// Every operation input starts with this byte; an input with another one is rejected (returns
// 0 at once), so that a future change of the encoding does not silently reinterpret old corpora.
// It is read by hand, not through FuzzedDataProvider (which takes integers from the end of the
// data), so that it is the first byte of every file in corpus/.
inline constexpr std::uint8_t kInputVersion = 1;

// True iff the input starts with kInputVersion; the provider then gets the bytes after it.
inline bool has_version(const std::uint8_t* data, std::size_t size) { return size > 0 && data[0] == kInputVersion; }

// What an operation target keeps between its edits so that they do not allocate afresh: the
// engine's workspaces, the log of the last edit, and scratch lists (mixed_ops,
// checker_differential).
struct EditWorkspace {
  EdgeSplitter splitter;
  Refiner refiner;
  ChangeLog log;
  std::vector<Edge> edges;
  std::vector<TetId> tets, region;
};

// A value in [0, 1] from 16 bits: coarse enough for libFuzzer to steer, fine enough to land
// anywhere that matters.
double consume_unit(FuzzedDataProvider& input);
// A value in [lo, hi].
double consume_in(FuzzedDataProvider& input, double lo, double hi);

// A small box mesh, 1..max_cells cells per axis, each side 0.25..4 long: the starting point of
// the operation targets.
RawMesh consume_box_mesh(FuzzedDataProvider& input, std::uint32_t max_cells);
// That box, built; a box the builder refuses is a finding (fuzz::fail), not a rejected input.
TetMesh consume_built_box_mesh(FuzzedDataProvider& input, std::uint32_t max_cells);

// A live tet: the first live one at or after a chosen id, wrapping around. kNoTet when none.
TetId consume_live_tet(const TetMesh& mesh, FuzzedDataProvider& input);
// The first live tet at or after a chosen id for which `accept` holds; kNoTet when none does.
template <class Predicate>
TetId consume_live_tet_where(const TetMesh& mesh, FuzzedDataProvider& input, Predicate accept) {
  const std::uint32_t capacity = mesh.tet_capacity();
  if (capacity == 0) return kNoTet;
  const std::uint32_t start = input.ConsumeIntegralInRange<std::uint32_t>(0, capacity - 1);
  for (std::uint32_t k = 0; k < capacity; ++k) {
    const TetId t{(start + k) % capacity};
    if (mesh.is_live(t) && accept(t)) return t;
  }
  return kNoTet;
}

// 1..max_edges edges of live tets (duplicates allowed: the splitter must cope).
void consume_edges(const TetMesh& mesh, FuzzedDataProvider& input, std::uint32_t max_edges, std::vector<Edge>& out);

// "(x, y, z)", for traces.
std::string to_string(const Vec3& p);

// Bounding box of the live vertices.
struct Box {
  Vec3 lo, hi;
  [[nodiscard]] double diagonal() const { return norm(hi - lo); }
};
Box bounding_box(const TetMesh& mesh);

// A ball whose centre lies in the bounding box grown by 10 % and whose radius is between
// min_fraction and max_fraction of the box diagonal.
Tool consume_ball(FuzzedDataProvider& input, const Box& box, double min_fraction, double max_fraction);


// Paper 3.3, written here from the paper independently of the engine's removability(), so that
// the two can be compared: removing t keeps the mesh manifold iff it has 3 or 4 boundary faces,
// or 2 with the edge joining the two vertices those faces omit interior (that edge is on neither
// face), or 1 with the vertex opposite it interior, or 0 with no vertex on the boundary.
bool removable_by_paper_rule(const TetMesh& mesh, TetId t);

}  // namespace tetcut::fuzz

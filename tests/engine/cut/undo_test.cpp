// Cutter::undo() (cut.hpp) and TetMesh::undo() (mesh.hpp): a cut taken back leaves the mesh's
// arrays, counts and attributes bit for bit as before it, and the Cutter as if the cut had never
// been made: the next cuts give the same arrays, reports and pieces as on a copy that never had
// it. Several cuts come back newest first, down to the history asked for; what empties the
// history (reset(), compact(), set_uncuttable(), a change made to the mesh behind the Cutter's
// back) is named in the refusal, and a refusal changes nothing. The undo's change log is the cut's
// turned around, and a consumer keeping per-id liveness from the two logs matches the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "checked.hpp"
#include "test_meshes.hpp"
#include "tetcut/box_mesh.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/io.hpp"

namespace tetcut::testing {
namespace {

TetMesh liver() {
  ReadResult read = read_mesh(std::string(TETCUT_CORPUS_DIR) + "/meshes/liver-coarse.msh");
  if (!read.mesh) {
    ADD_FAILURE() << "cannot read liver-coarse.msh";
    return {};
  }
  return build_or_fail(*read.mesh);
}

// Every array the mesh exposes, the tombstones (which thread the free list of tets) included,
// its counts and its attribute channels, as bytes: what "bit for bit" compares.
std::vector<unsigned char> bits(const TetMesh& mesh) {
  std::vector<unsigned char> out;
  auto add = [&](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    out.insert(out.end(), b, b + n);
  };
  const RawMeshView view = mesh.raw_view();
  add(view.positions.data(), view.positions.size_bytes());
  add(view.tets.data(), view.tets.size_bytes());
  add(view.engine->neighbours.data(), view.engine->neighbours.size_bytes());
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const std::uint32_t seed = mesh.vertex_tet(VertId{v}).value;
    add(&seed, sizeof seed);
  }
  add(view.engine->boundary_faces.data(), view.engine->boundary_faces.size_bytes());
  const std::uint64_t counts[] = {view.engine->live_tets, view.engine->live_vertices, view.engine->attribute_rows};
  add(counts, sizeof counts);
  for (std::uint32_t c = 0; c < mesh.attributes().channel_count(); ++c)
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
      const std::span<const double> x = mesh.attributes().value(c, VertId{v});
      add(x.data(), x.size_bytes());
    }
  return out;
}

// What two cuts' reports must share to be the same cut.
void expect_same_cut(const CutReport& a, const CutReport& b) {
  EXPECT_EQ(a.ok, b.ok);
  EXPECT_EQ(a.tets_hit, b.tets_hit);
  EXPECT_EQ(a.tets_removed, b.tets_removed);
  EXPECT_EQ(a.tets_created, b.tets_created);
  EXPECT_EQ(a.vertices_moved, b.vertices_moved);
  EXPECT_EQ(a.fragments, b.fragments);
  EXPECT_EQ(a.volume_removed, b.volume_removed);
}

CutParams liver_params(const TetMesh& mesh, std::uint32_t history) {
  CutParams p;
  p.tool_diameter = mesh.mean_edge_length();
  p.undo_history = history;
  return p;
}

// On the lancet sweep through a liver: before each cut of the sweep, a cut somewhere else that is
// taken back. The mesh is bit for bit as before that cut, the checker finds nothing, and the
// sweep's cut then gives what it gives on a copy that never had the stray one: same arrays (so
// the same ids from the same free lists), same report, same pieces, same removal statistics.
TEST(Undo, ACutTakenBackLeavesTheBitsAndTheNextCutAsIfItHadNeverBeenMade) {
  TetMesh mesh = liver();
  TetMesh twin = mesh;
  Cutter cutter(mesh, liver_params(mesh, 4));
  Cutter never(twin, liver_params(twin, 0));
  const BoundingBox box = bounding_box(mesh);
  const std::vector<Vec3> sweep = lancet_sweep(box, 12);
  int undone = 0;
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    const std::vector<unsigned char> before = bits(mesh);
    const RemovalReport statistics = cutter.removal_report();
    // A stray cut half a sweep away, off the lancet's line.
    Vec3 stray = sweep[(i + sweep.size() / 2) % sweep.size()];
    stray.z += 0.1 * (box.hi.z - box.lo.z);
    const std::uint32_t depth = cutter.undo_depth();
    cutter.cut(stray);
    if (bits(mesh) != before) {  // a cut that changed nothing is not kept: the last one kept is the sweep's
      // Kept with the sweep's cuts before it, the oldest dropped when the history is full.
      ASSERT_EQ(cutter.undo_depth(), std::min(depth + 1, 4u));
      const std::optional<std::string> refused = cutter.undo();
      ASSERT_FALSE(refused) << *refused;
      ++undone;
      EXPECT_EQ(cutter.undo_depth(), std::min(depth + 1, 4u) - 1);
    }
    ASSERT_TRUE(bits(mesh) == before) << "cut " << i << ": the mesh is not as before the stray cut";
    EXPECT_TRUE(mesh_is_valid(mesh));
    EXPECT_EQ(cutter.removal_report().requested, statistics.requested);
    EXPECT_EQ(cutter.removal_report().removed, statistics.removed);
    const CutReport a = cutter.cut(sweep[i]);
    const CutReport b = never.cut(sweep[i]);
    expect_same_cut(a, b);
    ASSERT_TRUE(bits(mesh) == bits(twin)) << "cut " << i << ": the sweep's cut differs after the undo";
    EXPECT_EQ(cutter.pieces(), never.pieces());
    EXPECT_EQ(canonical_hash(mesh), canonical_hash(twin));
  }
  EXPECT_GE(undone, 6) << "the stray cuts met too little of the liver to test anything";
}

// Six cuts along the lancet, each state kept: as many undos as cuts that changed the mesh bring
// back each state in turn, newest first; one more is refused with the reason and changes nothing.
// A history of 3 over the same cuts takes back three.
TEST(Undo, SeveralCutsComeBackNewestFirstDownToTheHistory) {
  for (std::uint32_t history : {8u, 3u}) {
    TetMesh mesh = liver();
    Cutter cutter(mesh, liver_params(mesh, history));
    std::vector<std::vector<unsigned char>> states{bits(mesh)};
    for (const Vec3& c : lancet_sweep(bounding_box(mesh), 6)) {
      const CutReport r = cutter.cut(c);
      ASSERT_TRUE(r.ok) << r.failure;
      if (bits(mesh) != states.back()) states.push_back(bits(mesh));  // a cut that changed nothing is not kept
    }
    ASSERT_GE(states.size(), 5u) << "the sweep changed the liver too little to test anything";
    const auto kept = std::min<std::uint32_t>(history, static_cast<std::uint32_t>(states.size() - 1));
    EXPECT_EQ(cutter.undo_depth(), kept);
    for (std::uint32_t k = 0; k < kept; ++k) {
      ASSERT_FALSE(cutter.undo()) << "undo " << k;
      states.pop_back();
      EXPECT_TRUE(bits(mesh) == states.back()) << "undo " << k << " of history " << history;
      EXPECT_TRUE(mesh_is_valid(mesh));
    }
    const std::vector<unsigned char> last = bits(mesh);
    const std::optional<std::string> refused = cutter.undo();
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->find("no cut to undo"), std::string::npos) << *refused;
    EXPECT_TRUE(bits(mesh) == last);
  }
}

TEST(Undo, IsRefusedWithItsReasonWhenNothingIsKept) {
  TetMesh mesh = liver();
  const Vec3 centre = lancet_sweep(bounding_box(mesh), 3)[1];
  {
    Cutter cutter(mesh, liver_params(mesh, 0));  // the default: no history
    ASSERT_TRUE(cutter.cut(centre).ok);
    const std::optional<std::string> refused = cutter.undo();
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->find("undo_history is 0"), std::string::npos) << *refused;
  }
  struct Emptier {
    const char* name;
    void (*empty)(Cutter&, TetMesh&);
  };
  const Emptier emptiers[] = {
      {"reset()", [](Cutter& c, TetMesh&) { c.reset(); }},
      {"compact()", [](Cutter& c, TetMesh&) { c.compact(); }},
      {"set_uncuttable()", [](Cutter& c, TetMesh&) { ASSERT_FALSE(c.set_uncuttable({})); }},
      {"undo_history", [](Cutter& c, TetMesh&) {
         CutParams p = c.params();
         p.undo_history = 2;
         ASSERT_FALSE(c.set_params(p));
       }},
      {"outside this Cutter", [](Cutter&, TetMesh& m) { m.add_vertex({1e3, 1e3, 1e3}); }},
  };
  for (const Emptier& e : emptiers) {
    TetMesh copy = liver();
    Cutter cutter(copy, liver_params(copy, 4));
    ASSERT_TRUE(cutter.cut(centre).ok);
    e.empty(cutter, copy);
    const std::vector<unsigned char> before = bits(copy);
    const std::optional<std::string> refused = cutter.undo();
    ASSERT_TRUE(refused) << e.name;
    EXPECT_NE(refused->find(e.name), std::string::npos) << *refused;
    EXPECT_TRUE(bits(copy) == before) << e.name;
  }
}

// A refused cut (its transaction rolled back) and a cut that changed nothing leave the kept cut
// the last change: it is still taken back.
TEST(Undo, ARefusedCutInBetweenLeavesTheKeptCutToUndo) {
  TetMesh mesh = liver();
  Cutter cutter(mesh, liver_params(mesh, 4));
  const std::vector<unsigned char> before = bits(mesh);
  const Vec3 centre = lancet_sweep(bounding_box(mesh), 3)[1];
  ASSERT_TRUE(cutter.cut(centre).ok);
  CutParams tight = cutter.params();
  tight.tool_diameter /= 4;    // a tool that needs refinement,
  tight.max_tets_created = 8;  // refused at the budget after its refinement began
  ASSERT_FALSE(cutter.set_params(tight));
  // Inside the liver, away from the first cut: the centroid of a live tet.
  Vec3 inside{};
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    const auto v = mesh.tet(TetId{t});
    const Vec3 c = 0.25 * (mesh.position(v[0]) + mesh.position(v[1]) + mesh.position(v[2]) + mesh.position(v[3]));
    if (norm(c - centre) > 4 * cutter.params().tool_diameter) {
      inside = c;
      break;
    }
  }
  const CutReport refused = cutter.cut(inside);
  ASSERT_FALSE(refused.ok);
  EXPECT_EQ(refused.refusal, CutRefusal::kTetBudget);
  EXPECT_TRUE(cutter.cut({1e6, 1e6, 1e6}).ok);  // meets nothing
  EXPECT_EQ(cutter.undo_depth(), 1u);
  ASSERT_FALSE(cutter.undo());
  EXPECT_TRUE(bits(mesh) == before);
}

// The undo's log is the cut's turned around: it removes what the cut made and restores what the
// cut removed, under the same ids; and a consumer that keeps which tets and vertices are live
// from the logs alone (the cut's, then the undo's) matches the mesh after each.
TEST(Undo, ItsChangeLogIsTheCutsTurnedAround) {
  TetMesh mesh = liver();
  Cutter cutter(mesh, liver_params(mesh, 4));
  // Room for every id the sweep makes: compared whole.
  const std::uint32_t room = 4 * mesh.tet_capacity();
  auto live_tets = [&] {
    std::vector<std::uint8_t> live(room, 0);
    for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) live[t] = mesh.is_live(TetId{t}) ? 1 : 0;
    return live;
  };
  auto live_vertices = [&] {
    std::vector<std::uint8_t> live(room, 0);
    for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) live[v] = mesh.is_live(VertId{v}) ? 1 : 0;
    return live;
  };
  std::vector<std::uint8_t> tets = live_tets(), vertices = live_vertices();
  auto apply = [&](const ChangeLog& log) {
    for (TetId t : log.removed) tets[t.value] = 0;
    for (const CreatedTet& c : log.created) tets[c.tet.value] = 1;
    for (VertId v : log.removed_vertices) vertices[v.value] = 0;
    for (const CreatedVertex& v : log.vertices) vertices[v.vertex.value] = 1;
  };
  int cuts = 0;
  for (const Vec3& c : lancet_sweep(bounding_box(mesh), 6)) {
    ChangeLog cut_log;
    ASSERT_TRUE(cutter.cut(c, &cut_log).ok);
    apply(cut_log);
    EXPECT_TRUE(tets == live_tets() && vertices == live_vertices());
    if (cut_log.removed.empty()) continue;  // changed nothing, so not kept: nothing of its own to undo
    ++cuts;
    ChangeLog undo_log;
    ASSERT_FALSE(cutter.undo(&undo_log));
    apply(undo_log);
    EXPECT_TRUE(tets == live_tets() && vertices == live_vertices()) << "after the undo";
    std::vector<TetId> made;
    for (const CreatedTet& t : cut_log.created) made.push_back(t.tet);
    std::vector<TetId> restored;
    for (const CreatedTet& t : undo_log.created) {
      restored.push_back(t.tet);
      EXPECT_EQ(t.parents_count, 0u);
    }
    EXPECT_EQ(undo_log.removed, made);
    EXPECT_EQ(restored, cut_log.removed);
    std::vector<VertId> made_vertices, restored_vertices;
    for (const CreatedVertex& v : cut_log.vertices) made_vertices.push_back(v.vertex);
    for (const CreatedVertex& v : undo_log.vertices) {
      restored_vertices.push_back(v.vertex);
      EXPECT_EQ(v.count, 0);
    }
    EXPECT_EQ(undo_log.removed_vertices, made_vertices);
    EXPECT_EQ(restored_vertices, cut_log.removed_vertices);
    std::vector<VertId> moved, moved_back;
    for (const MovedVertex& m : cut_log.moved) moved.push_back(m.vertex);
    for (const MovedVertex& m : undo_log.moved) {
      moved_back.push_back(m.vertex);
      EXPECT_EQ(m.count, 0);
      EXPECT_FALSE(m.before == mesh.position(m.vertex));
    }
    EXPECT_EQ(moved_back, moved);
    EXPECT_EQ(cutter.last_removed(), made);
    EXPECT_EQ(cutter.last_created(), cut_log.removed);
    // Cut again, for the next round to start from a mesh this sweep changed.
    ChangeLog again;
    ASSERT_TRUE(cutter.cut(c, &again).ok);
    apply(again);
  }
  EXPECT_GE(cuts, 3);
}

// Vertex attributes come back with the mesh: the values the cut interpolated into reused slots
// and the values it wrote over are as before.
TEST(Undo, AttributeChannelsComeBackBitForBit) {
  TetMesh mesh = liver();
  const std::uint32_t channel = *mesh.attributes().add_channel("temperature", 2);
  for (std::uint32_t v = 0; v < mesh.vertex_capacity(); ++v) {
    const Vec3 p = mesh.position(VertId{v});
    mesh.attributes().value(channel, VertId{v})[0] = p.x * p.y;
    mesh.attributes().value(channel, VertId{v})[1] = p.z;
  }
  Cutter cutter(mesh, liver_params(mesh, 8));
  std::vector<std::vector<unsigned char>> states{bits(mesh)};
  for (const Vec3& c : lancet_sweep(bounding_box(mesh), 6)) {
    ASSERT_TRUE(cutter.cut(c).ok);
    if (bits(mesh) != states.back()) states.push_back(bits(mesh));
  }
  ASSERT_GE(states.size(), 4u);
  while (cutter.undo_depth() > 0) {
    ASSERT_FALSE(cutter.undo());
    states.pop_back();
    EXPECT_TRUE(bits(mesh) == states.back());
  }
  EXPECT_EQ(states.size(), 1u);
}

// A slab cut detaches a piece of the plate and a second cut drops a small piece as debris: each
// undo puts back the piece count, and the same cuts made again report the same pieces.
TEST(Undo, DetachedPiecesAndDebrisComeBack) {
  TetMesh mesh = build_or_fail(make_box_mesh(40, 20, 4, {0, 0, -0.1}, {4, 2, 0.2}));
  Cutter cutter(mesh, {.tool_diameter = 0.5, .debris_volume = 0.1, .undo_history = 4});
  const std::vector<unsigned char> whole = bits(mesh);
  const CutReport slab = cutter.cut_segment({1.0, -0.3, 0.0}, {1.0, 2.3, 0.0});
  ASSERT_TRUE(slab.ok) << slab.failure;
  ASSERT_EQ(slab.fragments, 1u);
  ASSERT_EQ(cutter.pieces(), 2u);
  const std::vector<unsigned char> halves = bits(mesh);
  // A corner cut off the right side along x - y = 2.9: a wedge of legs about 0.75 (about 0.05 of
  // volume) beyond the tool, below the debris volume, dropped.
  const CutReport corner = cutter.cut_segment({2.9, -0.3, 0.0}, {4.3, 1.1, 0.0});
  ASSERT_TRUE(corner.ok) << corner.failure;
  ASSERT_EQ(corner.debris_pieces_removed, 1u);
  EXPECT_EQ(cutter.pieces(), 2u);
  ASSERT_FALSE(cutter.undo());
  EXPECT_TRUE(bits(mesh) == halves);
  EXPECT_EQ(cutter.pieces(), 2u);
  ASSERT_FALSE(cutter.undo());
  EXPECT_TRUE(bits(mesh) == whole);
  EXPECT_EQ(cutter.pieces(), 1u);
  EXPECT_TRUE(mesh_is_valid(mesh));
  const CutReport again = cutter.cut_segment({1.0, -0.3, 0.0}, {1.0, 2.3, 0.0});
  expect_same_cut(again, slab);
  EXPECT_EQ(cutter.pieces(), 2u);
  EXPECT_TRUE(bits(mesh) == halves);
}

}  // namespace
}  // namespace tetcut::testing

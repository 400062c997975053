// Fuzz target mixed_ops: a small box mesh, then a sequence of operations chosen by the input —
// edge splits (templates or bisection), refinement around a ball, removals the paper's rule says
// are safe, compaction, attribute channels — with the local checker after every operation and
// the full check every few (with the whole-mesh queries: boundary faces, vertex neighbours,
// boundary normals, to_raw). Any violated invariant aborts, naming it and the operation.
//
// Input: version byte, box (3 cell counts, 3 side lengths), then per operation an opcode and its
// arguments, decoded and clamped by mesh_edits.hpp. The sequence ends with the input.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "core/random.hpp"
#include "cut/spatial_index.hpp"
#include "operations/checked_mesh.hpp"
#include "operations/mesh_edits.hpp"
#include "refine/edge_split.hpp"
#include "refine/refine.hpp"
#include "remove/removability.hpp"
#include "support/fuzz_failure.hpp"
#include "tetcut/attributes.hpp"
#include "tetcut/canonical_hash.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/mesh_builder.hpp"

namespace {

using namespace tetcut;
using tetcut::fuzz::CheckedMesh;

constexpr std::uint32_t kMaxBoxCells = 2;
constexpr std::size_t kMaxOperations = 32;
constexpr std::size_t kFullCheckEvery = 16;
constexpr std::uint32_t kMaxEdgesPerSplit = 8;
// Operations that grow the mesh are skipped beyond these sizes: the target is about sequences of
// operations, each cheap on a small mesh, while the full check costs O(#T) (under ASan and
// coverage instrumentation about 20 us a tet) and executions per second are what finds bugs.
constexpr std::uint32_t kMaxTetsToRefine = 400;
constexpr std::uint32_t kMaxTetsToSplit = 1000;
constexpr std::uint32_t kMaxChannels = 3;
constexpr std::uint32_t kMaxChannelWidth = 3;
constexpr double kMaxAttributeValue = 1e3;

enum class Op : std::uint8_t { kSplit, kBisect, kRefine, kRemove, kCompact, kAddChannel, kFullCheck, kLast = kFullCheck };

const char* op_name(Op op) {
  switch (op) {
    case Op::kSplit: return "split";
    case Op::kBisect: return "bisect";
    case Op::kRefine: return "refine";
    case Op::kRemove: return "remove";
    case Op::kCompact: return "compact";
    case Op::kAddChannel: return "add channel";
    case Op::kFullCheck: return "full check";
  }
  return "?";
}

using Workspace = fuzz::EditWorkspace;

bool close(double got, double want, double scale) { return std::fabs(got - want) <= 1e-12 * scale; }

// Every vertex an operation made is the convex combination of old vertices its log names, in
// position and in every attribute channel (paper 3.2: texture and mechanical data follow the
// split); a single split puts it at the midpoint of an old edge.
void check_created_vertices(const CheckedMesh& checked, const ChangeLog& log, bool midpoints) {
  const TetMesh& mesh = checked.mesh();
  const VertexAttributes& attributes = mesh.attributes();
  for (const CreatedVertex& c : log.vertices) {
    std::string which = "vertex " + std::to_string(c.vertex.value) + " from";
    double sum = 0.0, scale = 1.0;
    Vec3 want{};
    for (int i = 0; i < c.count; ++i) {
      which.append(1, ' ').append(std::to_string(c.from[i].value)).append(1, ':').append(std::to_string(c.weight[i]));
      // Negative only for a vertex smoothing moved just outside the old region (change_log.hpp):
      // what must hold is that the weights reproduce its position, checked below.
      checked.require(c.weight[i] != 0.0 && c.from[i] != c.vertex && mesh.is_live(c.from[i]), "interpolation",
                      which + ": not a weight on another live vertex");
      sum += c.weight[i];
      want = want + c.weight[i] * mesh.position(c.from[i]);
      scale += norm(mesh.position(c.from[i]));
    }
    checked.require(c.count > 0 && close(sum, 1.0, 1.0), "interpolation", which + ": weights do not sum to 1");
    if (midpoints)
      checked.require(c.on_edge() && c.weight[0] == 0.5 && c.weight[1] == 0.5, "interpolation", which + ": not a midpoint");
    checked.require(mesh.is_live(c.vertex), "interpolation", which + ": not live after the operation");
    const Vec3 p = mesh.position(c.vertex);
    checked.require(close(p.x, want.x, scale) && close(p.y, want.y, scale) && close(p.z, want.z, scale),
                    "interpolation", which + ": position is not the combination");
    for (std::uint32_t ch = 0; ch < attributes.channel_count(); ++ch) {
      checked.require(c.vertex.value < attributes.size(), "I8", which + ": no attribute slot");
      const auto vp = attributes.value(ch, c.vertex);
      for (std::size_t k = 0; k < vp.size(); ++k) {
        double expected = 0.0, magnitude = 1.0;
        for (int i = 0; i < c.count; ++i) {
          const double x = attributes.value(ch, c.from[i])[k];
          expected += c.weight[i] * x;
          magnitude += std::fabs(x);
        }
        checked.require(close(vp[k], expected, magnitude), "interpolation",
                        which + ": channel " + attributes.channel(ch).name + "[" + std::to_string(k) + "] is " +
                            std::to_string(vp[k]) + ", not the combination " + std::to_string(expected));
      }
    }
  }
}

void split(CheckedMesh& checked, Workspace& ws, FuzzedDataProvider& input, SplitMethod method) {
  TetMesh& mesh = checked.mesh();
  fuzz::consume_edges(mesh, input, kMaxEdgesPerSplit, ws.edges);
  if (mesh.num_tets() > kMaxTetsToSplit) ws.edges.clear();
  if (checked.tracing())
    for (const Edge& e : ws.edges) checked.describe(std::to_string(e.a.value) + "-" + std::to_string(e.b.value));
  const std::uint32_t tets_before = mesh.num_tets();
  ws.log.clear();
  mesh.begin_transaction();
  const SplitResult result = ws.splitter.split(mesh, ws.edges, method);
  mesh.commit(&ws.log);
  // Every edge came from a live tet, so the only acceptable refusal is floating-point degeneracy,
  // and a refused split leaves the mesh untouched.
  checked.require(result.refusal != SplitRefusal::kNotAnEdge, "refused-split", "an edge of a live tet was not an edge");
  if (!result.ok())
    checked.require(mesh.num_tets() == tets_before && ws.log.created.empty(), "refused-split",
                    std::string("refused (") + to_string(result.refusal) + ") but changed the mesh");
  checked.end(ws.log, 0.0, invariants::QualityRule::kReportOnly);  // a raw split: no improvement pass
  check_created_vertices(checked, ws.log, true);
}

void refine(CheckedMesh& checked, Workspace& ws, FuzzedDataProvider& input) {
  TetMesh& mesh = checked.mesh();
  // Without a focus the loop spreads through the whole mesh (refine.hpp), so the tool is kept
  // larger then: the final size goes as (box diagonal / D_ref)^3.
  const bool focus = input.ConsumeBool();
  const Tool ball = fuzz::consume_ball(input, fuzz::bounding_box(mesh), focus ? 0.08 : 0.2, focus ? 0.3 : 0.5);
  RefineParams params;
  params.d_ref = 1.5 * (2.0 * ball.radius);  // paper 3.2: D_ref = 1.5 x tool diameter
  params.p = fuzz::consume_in(input, 1.1, 3.0);
  params.max_iterations = input.ConsumeIntegralInRange<std::uint32_t>(1, 8);
  params.method = input.ConsumeBool() ? SplitMethod::kBisection : SplitMethod::kTemplates;
  if (focus) params.focus = ball;
  checked.require(!validate(params).has_value(), "refine-params", "clamped parameters refused");
  if (checked.tracing())
    checked.describe("centre " + fuzz::to_string(ball.a) + " radius " + std::to_string(ball.radius) + " p " +
                     std::to_string(params.p) + " iterations " + std::to_string(params.max_iterations) +
                     (params.method == SplitMethod::kBisection ? " bisection" : " templates") +
                     (params.focus ? " focus" : ""));
  scan_tets_meeting(mesh, ball, ws.tets);  // O(#T): the targets' meshes are small
  ws.log.clear();
  mesh.begin_transaction();
  if (mesh.num_tets() <= kMaxTetsToRefine) ws.refiner.refine(mesh, ws.tets, params, ws.region);
  mesh.commit(&ws.log);
  checked.end(ws.log, 0.0, invariants::QualityRule::kReportOnly);  // a raw refinement loop
  check_created_vertices(checked, ws.log, false);
}

// Removes the first tet at or after a chosen id that the paper's rule (mesh_edits.hpp) says can
// go; on the way, the engine's removability() must agree with that rule on every tet it passes.
void remove(CheckedMesh& checked, FuzzedDataProvider& input) {
  TetMesh& mesh = checked.mesh();
  const TetId t = fuzz::consume_live_tet_where(mesh, input, [&](TetId c) {
    const bool ours = fuzz::removable_by_paper_rule(mesh, c);
    const Removability engine = removability(mesh, c);
    checked.require(ours == engine.removable(), "removability",
                    "tet " + std::to_string(c.value) + ": the paper's rule says " + (ours ? "removable" : "not removable") +
                        ", removability() says " + (engine.removable() ? "removable" : "not removable") + " (case " +
                        std::to_string(engine.paper_case) + ")");
    return ours;
  });
  if (!t.valid()) {
    checked.end({}, {}, 0.0);
    return;
  }
  if (checked.tracing())
    checked.describe("tet " + std::to_string(t.value) + " with " + std::to_string(mesh.boundary_face_count(t)) +
                     " boundary faces");
  const double volume = mesh.volume(t);
  const TetId removed[] = {t};
  mesh.remove_tets(removed);
  checked.end(removed, {}, -volume);
}

// compact() renumbers; every live vertex keeps its position and attributes under its new id.
void compact(CheckedMesh& checked) {
  TetMesh& mesh = checked.mesh();
  const std::uint32_t tets = mesh.num_tets(), vertices = mesh.num_vertices();
  const std::vector<Vec3> positions(mesh.positions().begin(), mesh.positions().end());
  const VertexAttributes attributes = mesh.attributes();
  const std::uint32_t old_capacity = mesh.vertex_capacity();
  std::vector<std::uint8_t> was_live(old_capacity);
  for (std::uint32_t v = 0; v < old_capacity; ++v) was_live[v] = mesh.is_live(VertId{v});
  const Renumbering renumbering = mesh.compact();
  checked.require(mesh.num_tets() == tets && mesh.num_vertices() == vertices && mesh.tet_capacity() == tets &&
                      mesh.vertex_capacity() == vertices,
                  "I8", "compact() changed the counts or left tombstones");
  checked.require(renumbering.vert_old_to_new.size() == old_capacity, "I8", "the renumbering misses vertices");
  for (std::uint32_t v = 0; v < old_capacity; ++v) {
    if (!was_live[v]) continue;
    const VertId to = renumbering.vert_old_to_new[v];
    checked.require(mesh.is_live(to) && mesh.position(to) == positions[v], "I8",
                    "vertex " + std::to_string(v) + " lost its position in compact()");
    for (std::uint32_t ch = 0; ch < attributes.channel_count(); ++ch) {
      const auto before = attributes.value(ch, VertId{v});
      const auto after = mesh.attributes().value(ch, to);
      for (std::size_t k = 0; k < before.size(); ++k)
        checked.require(before[k] == after[k], "I8", "vertex " + std::to_string(v) + " lost its attributes in compact()");
    }
  }
  checked.end_renumbered();
}

// A new channel with values on every vertex, so that later splits have something to interpolate.
void add_channel(CheckedMesh& checked, FuzzedDataProvider& input) {
  VertexAttributes& attributes = checked.mesh().attributes();
  if (attributes.channel_count() < kMaxChannels) {
    const std::uint32_t width = input.ConsumeIntegralInRange<std::uint32_t>(1, kMaxChannelWidth);
    const auto channel = attributes.add_channel("fuzz" + std::to_string(attributes.channel_count()), width);
    checked.require(channel.has_value(), "attributes", "a new channel name was refused");
    const std::uint64_t seed = input.ConsumeIntegral<std::uint64_t>();
    if (checked.tracing()) checked.describe("width " + std::to_string(width) + " seed " + std::to_string(seed));
    SplitMix64 rng(seed);
    for (std::uint32_t v = 0; v < attributes.size(); ++v)
      for (double& x : attributes.value(*channel, VertId{v})) x = (2.0 * rng.unit() - 1.0) * kMaxAttributeValue;
  }
  checked.end({}, {}, 0.0);
}

// The whole-mesh queries no operation above relies on, against the raw tets, with the full
// check: boundary_faces() lists exactly the faces the per-tet counts call boundary,
// vertex_neighbours() the vertices sharing an edge with v, boundary_normal() is zero exactly at
// interior vertices and finite, and to_raw() builds back into the same mesh (canonical hash).
void full_check(CheckedMesh& checked) {
  checked.full_check();
  const TetMesh& mesh = checked.mesh();
  std::vector<FaceRef> faces;
  mesh.boundary_faces(faces);
  std::uint64_t counted = 0;
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t)
    if (mesh.is_live(TetId{t})) counted += static_cast<std::uint64_t>(mesh.boundary_face_count(TetId{t}));
  checked.require(faces.size() == counted, "mesh-queries",
                  "boundary_faces() lists " + std::to_string(faces.size()) + " faces, the tets count " + std::to_string(counted));
  for (const FaceRef& f : faces)
    checked.require(mesh.is_live(f.tet) && mesh.is_boundary_face(f.tet, f.face), "mesh-queries",
                    "boundary_faces() lists face " + std::to_string(f.face) + " of tet " + std::to_string(f.tet.value) +
                        ", which is not a live boundary face");

  std::vector<std::vector<VertId>> expected(mesh.vertex_capacity());
  for (std::uint32_t t = 0; t < mesh.tet_capacity(); ++t) {
    if (!mesh.is_live(TetId{t})) continue;
    const auto v = mesh.tet(TetId{t});
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a != b) expected[v[a].value].push_back(v[b]);
  }
  std::vector<VertId> got;
  std::vector<TetId> scratch;
  for (std::uint32_t i = 0; i < mesh.vertex_capacity(); ++i) {
    const VertId v{i};
    if (!mesh.is_live(v)) continue;
    std::vector<VertId>& want = expected[i];
    std::sort(want.begin(), want.end());
    want.erase(std::unique(want.begin(), want.end()), want.end());
    mesh.vertex_neighbours(v, got, scratch);
    std::sort(got.begin(), got.end());
    checked.require(got == want, "mesh-queries",
                    "vertex_neighbours(" + std::to_string(i) + ") gives " + std::to_string(got.size()) +
                        " vertices, the tets around it have " + std::to_string(want.size()));
    const Vec3 n = mesh.boundary_normal(v, scratch);
    checked.require(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z), "mesh-queries",
                    "boundary_normal(" + std::to_string(i) + ") is not finite");
    if (!mesh.is_boundary_vertex(v))
      checked.require(n.x == 0.0 && n.y == 0.0 && n.z == 0.0, "mesh-queries",
                      "boundary_normal(" + std::to_string(i) + ") of an interior vertex is not zero");
  }

  BuildResult rebuilt = build_mesh(mesh.to_raw());
  checked.require(rebuilt.ok(), "mesh-queries",
                  "to_raw() does not build: " + (rebuilt.problems.empty() ? std::string("?") : rebuilt.problems.front().message));
  checked.require(canonical_hash(*rebuilt.mesh) == canonical_hash(mesh), "mesh-queries",
                  "to_raw() builds a different mesh (canonical hash)");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!fuzz::has_version(data, size)) return 0;
  FuzzedDataProvider input(data + 1, size - 1);
  CheckedMesh checked(fuzz::consume_built_box_mesh(input, kMaxBoxCells));
  Workspace ws;
  for (std::size_t i = 0; i < kMaxOperations && input.remaining_bytes() > 0 && checked.mesh().num_tets() > 0; ++i) {
    const Op op = static_cast<Op>(input.ConsumeIntegralInRange<std::uint8_t>(0, static_cast<std::uint8_t>(Op::kLast)));
    checked.begin(op_name(op));
    switch (op) {
      case Op::kSplit: split(checked, ws, input, SplitMethod::kTemplates); break;
      case Op::kBisect: split(checked, ws, input, SplitMethod::kBisection); break;
      case Op::kRefine: refine(checked, ws, input); break;
      case Op::kRemove: remove(checked, input); break;
      case Op::kCompact: compact(checked); break;
      case Op::kAddChannel: add_channel(checked, input); break;
      case Op::kFullCheck: checked.end({}, {}, 0.0); full_check(checked); break;
    }
    if (checked.operation_index() % kFullCheckEvery == 0) full_check(checked);
  }
  full_check(checked);
  return 0;
}

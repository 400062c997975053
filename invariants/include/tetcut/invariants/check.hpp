// The independent invariant checker (design: invariants I1-I10).
//
// It recomputes everything it verifies from the raw tet array with its own tables, its own
// quality measures and its own link analysis; it never trusts the engine's adjacency or
// classification, it only compares against them (I2, I8). It reads a mesh only through
// RawMeshView (tetcut/raw_mesh_view.hpp): no engine header is included anywhere in the checker,
// which shares nothing with the engine but tetcut::geometry (Vec3, the exact orientation
// predicate that decides I4, and that view). An engine mesh is passed as mesh.raw_view(), a
// RawMesh as itself.
//
// Levels and what they cost (#T tets, #V vertices, s = tets in a vertex shell, a few dozen):
//   local  LocalChecker::after_operation: O(sum of s over the vertices of the removed and
//          created tets), i.e. O(operation), plus O(1) count comparisons. Building the
//          LocalChecker is O(#T + #V) once. Cheap enough after every operation in tests and
//          fuzzers. On a whole mesh (check_raw / check_mesh) there is no operation, so `local`
//          means the same as `full`.
//   full   O(#T + #V) plus a small sort per vertex shell (O(s log s)): references, conformity,
//          orientation (exact), vertex links, edge shells, quality, volume; for an engine mesh
//          also the engine's adjacency and bookkeeping. About a second per million tets.
//   exact  full + the geometric half of I3: the boundary surface does not self-intersect (CGAL
//          box intersection with exact triangle-triangle predicates, O(#boundary log #boundary)
//          for reasonable surfaces). Only run when the boundary is a 2-manifold.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tetcut/raw_mesh_view.hpp"

namespace tetcut::invariants {

enum class Invariant : std::uint8_t {
  kI1References = 1,  // every live tet has 4 distinct live vertices; no duplicate tets
  kI2Adjacency,       // neighbours reciprocal and sharing exactly the face; boundary iff unshared
  kI3Conformity,      // a face belongs to at most 2 tets; (exact) boundary does not self-intersect
  kI4Orientation,     // every tet strictly positive (exact predicate)
  kI5VertexShell,     // vertex shell face-connected and link a disk or a sphere
  kI6EdgeShell,       // edge shell face-connected (boundary edge: exactly two boundary faces)
  kI7Quality,         // no operation makes tets worse than it found (and an optional absolute floor)
  kI8Bookkeeping,     // counts, vertex->tet references, boundary flags, attribute sizes
  kI9Volume,          // volume as expected after an operation (relative tolerance)
  kI10Tissue,         // after a cut: the tool's tissue taken, its neighbourhood refined, uncuttable kept
};
inline constexpr int kInvariantCount = 10;

// "I5" etc.
const char* id_string(Invariant id);
// A short human name: "manifold vertex shells".
const char* description(Invariant id);

enum class CheckLevel : std::uint8_t { kLocal, kFull, kExact };

inline constexpr std::size_t kMaxListed = 8;
inline constexpr std::size_t kHistogramBins = 10;
inline constexpr std::size_t kDihedralBins = 15;  // 5 degrees each

struct Violation {
  Invariant id;
  std::uint64_t count = 0;             // how many offending elements in all
  std::vector<std::uint32_t> tets;     // the first offending tets (at most kMaxListed)
  std::vector<std::uint32_t> vertices; // the first offending vertices (at most kMaxListed)
  std::string detail;                  // one line, for people: the first offence
};

struct QualityStats {
  std::uint64_t tets = 0;
  double min_radius_ratio = 0.0;
  double mean_radius_ratio = 0.0;
  double min_dihedral_deg = 0.0;
  double mean_min_dihedral_deg = 0.0;
  // Radius ratio histogram, bin i covers [i / 10, (i + 1) / 10); 1.0 goes in the last bin.
  std::array<std::uint64_t, kHistogramBins> radius_ratio_histogram{};
  // Smallest dihedral angle histogram, bin i covers [5 i, 5 (i + 1)) degrees; 70 and above (a
  // regular tet's 70.53) go in the last bin.
  std::array<std::uint64_t, kDihedralBins> min_dihedral_histogram{};
};

// How I7 judges the tets an operation created (LocalChecker::after_operation).
enum class QualityRule : std::uint8_t {
  // A Cutter transaction (a cut, a removal request: the units that end with the improvement
  // pass): every created tet has a radius ratio of at least min(quality_floor, its hosts') and a
  // smallest dihedral angle of at least min(min_dihedral_deg, its hosts'), each tet its own
  // floors. Its hosts are the removed tets that contain its centroid (the checker's own point
  // location: it does not take the engine's parents on trust); one that no removed tet holds is
  // held to the operation's worst host; tissue the operation removed whole hosts nothing and
  // lowers no floor. And the mesh rule: the volume of tets below min_dihedral_deg outside the
  // tool (the created tets whose centroid is outside CheckOptions::tool's ball; all of them
  // without a tool) is no more than the volume of that same region that removed tets below it
  // covered (their shared volumes, exactly, by clipping): splitting a bad tet keeps its bad
  // volume, spreading one over good volume does not, and removed tissue pays for nothing.
  kNoDegradation,
  // A raw operation (one split, a refinement loop, an edit under fuzzing): the quality of what it
  // made is reported, not judged. A midpoint split has no quality bound of its own to keep: the
  // templates' children of a parent of radius ratio 0.15 can be 100 times worse than it; I4 (every
  // child strictly positive) is what the templates guarantee.
  kReportOnly,
};

// I10's tool (the local level only: a cut is an operation): the cut's ball (or capsule: every
// point within `radius` of the segment centre-end), the length its neighbourhood was refined to,
// and the tets the cut reports it left in the tool (Cutter::last_left_in_tool()). After the
// operation no live cuttable tet meets the open tool with an edge longer than d_ref, and none with
// its centroid in the closed tool and its edges within d_ref remains unless `left` lists it; each
// listed tet is such a tet. Cuttable: not named by LocalChecker::set_uncuttable(), nor made from
// such a tet.
struct ToolRule {
  Vec3 centre;
  double radius = 0.0;
  double d_ref = 0.0;
  RawIds left;
  std::optional<Vec3> end;  // a capsule's other end (Cutter::cut_segment); none: a ball
};

struct CheckOptions {
  CheckLevel level = CheckLevel::kFull;
  // I7, absolute: a checked tet (full, exact: every live tet; local: the created ones) whose
  // radius ratio is below this floor is a violation. 0 disables: the default, since an input
  // mesh is what it is; for users who want every tet above a floor.
  double radius_ratio_floor = 0.0;
  // I7, no degradation, on by default wherever the local checker runs. F = 0.1: a radius ratio
  // below 0.1 is what mesh generators and improvers (TetGen's quality bound, Stellar) treat as a
  // sliver, and it is where an explicit FEM's stable time step starts to collapse; an input whose
  // tets are worse still sets its own floor through min(F, worst replaced).
  QualityRule quality_rule = QualityRule::kNoDegradation;
  double quality_floor = 0.1;
  // theta = 15 degrees: below it a tet's stiffness matrix conditioning and an explicit model's
  // stable step follow the angle, whatever its radius ratio (a tet at radius ratio 0.1 can have a
  // 2-degree dihedral). Lowered by an input whose tets are worse, through min(theta, its hosts').
  double min_dihedral_deg = 15.0;
  // I9: when set, the total volume must equal this to a relative tolerance.
  std::optional<double> expected_volume;
  // I10, the local level: when set, the operation was a cut with this tool.
  std::optional<ToolRule> tool;
  // I8, the local level only: the vertices that were there before the operation and moved, as
  // the operation reports them (the engine's change log). A vertex may move only when listed
  // here, within the tool's reach, to where its entry's weights put it, and when every tet
  // around it is one the operation created.
  std::span<const RawMovedVertex> moved;
  // I8, when `tool` is not set: the reach the moves must lie within for an operation that is
  // not a cut: an undo moves vertices back within the reach of the cut it takes back
  // (Cutter::last_undone_reach()). Its radius + d_ref is the reach; its `left` is not read.
  std::optional<ToolRule> reach;
  double volume_rel_tolerance = 1e-9;
  // Names the operation in the report ("remove tet 12", "cut 3"), for people triaging.
  std::string operation;
};

struct CheckReport {
  std::vector<Violation> violations;  // in invariant order, at most one per invariant
  QualityStats quality;               // over the checked tets (local: the created tets)
  // full/exact: live tets and used vertices; local: tets in the touched shells (a tet counted
  // once per touched vertex of it) and touched vertices.
  std::uint64_t tets_checked = 0;
  std::uint64_t vertices_checked = 0;
  // full/exact: the total signed volume; local: the operation's volume change (created volume
  // - removed volume).
  double volume = 0.0;
  std::string operation;              // copied from CheckOptions::operation
  std::vector<std::string> notes;     // what was not checked and why (e.g. skipped geometry)

  [[nodiscard]] bool ok() const { return violations.empty(); }
  [[nodiscard]] const Violation* find(Invariant id) const;
};

// The quality of the listed tets alone (say, the tets one cut created), measured as the checks
// measure every tet; nothing is judged. Dead or out-of-range ids are skipped: this is for
// statistics, and the checks above are what report a bad id.
QualityStats quality_of(const RawMeshView& mesh, RawIds tets);

// Pools `more` into `into`: minima of the minima, histograms added, means weighted by tets.
void pool(QualityStats& into, const QualityStats& more);

// Several lines for people: one per violation, "I5 manifold vertex shells: 3 ...: detail".
std::string to_string(const CheckReport& report);

// Full or exact check of a mesh as raw arrays (a file as read): I1, I3-I7, I9. Engine records
// in the view, if any, are ignored.
CheckReport check_raw(const RawMeshView& mesh, const CheckOptions& options = {});

// Full or exact check of an engine mesh (TetMesh::raw_view()): everything check_raw does on its
// live tets, plus I2 and I8 by comparing the engine's adjacency, boundary counts, vertex->tet
// references and counts with the checker's own recomputation.
CheckReport check_mesh(const RawMeshView& mesh, const CheckOptions& options = {});

// The local level. Holds its own vertex->tets index, built once from the raw tets and then
// updated from what each operation says it removed and created (read back from the raw tets),
// so it never consults the engine's adjacency. After an operation it checks, for every vertex of
// a removed or created tet, I1-I3, I5, I6 and I8 on that vertex's shell and on the edges and
// faces through it (I2: the engine's neighbours across those faces), I1, I4 and I7 on the
// created tets, the engine's counts (I8), I9 when an expected volume change is given, and I10
// when the options name the cut's tool: over the tets its own grid of bounding boxes finds near
// the tool (built on the first such check, O(#T) once, then kept up to date per operation), and,
// when uncuttable tets were named, that the operation kept their volume.
// An existing vertex moves only within the cut's reach, and as the change log says
// (CheckOptions::moved): the checker keeps its own copy of every vertex's position as it last
// saw it, so that the removed tets are judged as they were (their volume, their quality, the
// uncuttable tissue they held) and a move nobody reported is caught (I8) at the next operation
// that touches the vertex. That copy is one Vec3 per vertex more than the index; it is taken
// once by reset() and then updated for the touched and the reported vertices only.
// It assumes the mesh was valid before the operation: it reports what the operation broke.
// compact() renumbers everything: build a new LocalChecker after it.
class LocalChecker {
 public:
  explicit LocalChecker(const RawMeshView& mesh);
  ~LocalChecker();
  // Starts over on `mesh` as a new LocalChecker would, in the memory this one already holds (a
  // fuzz target checks thousands of inputs a second on the same few meshes).
  void reset(const RawMeshView& mesh);
  LocalChecker(LocalChecker&&) noexcept;
  LocalChecker& operator=(LocalChecker&&) noexcept;

  // `mesh`: the same engine mesh after the operation (its raw_view() again). `removed`: tet
  // ids the operation killed (their old vertices are remembered from the index, their old
  // positions from the checker's copy); `created`:
  // ids it made live (may reuse removed ids); both as the caller holds them (TetId spans or
  // vectors). I9 is checked when an expected volume change of the region (created volume -
  // removed volume) is given. options.level is ignored (the region is always checked
  // combinatorially and with exact orientation).
  CheckReport after_operation(const RawMeshView& mesh, RawIds removed, RawIds created,
                              const CheckOptions& options = {},
                              std::optional<double> expected_volume_change = std::nullopt);

  // The tets no cut may take (what the Cutter was told: Cutter::set_uncuttable()), live in the
  // mesh as the checker last saw it. From then on, a tet an operation makes is uncuttable when
  // its centroid lies in an uncuttable tet the operation replaced: the checker's own record,
  // which I10 judges by. Replaces the set; empty: none. reset() clears it.
  void set_uncuttable(RawIds tets);

 private:
  struct Scratch;  // per-operation scratch (vertex link workspace), reused: no steady allocation
  struct Operation;  // one after_operation() call, step by step (local_checker.cpp)

  std::vector<std::array<std::uint32_t, 4>> known_tets_;       // the checker's copy of each tet
  std::vector<double> known_volume_;                          // its signed volume when created
  std::vector<double> known_rounding_;                        // the rounding bound of that volume
  std::vector<std::vector<std::uint32_t>> vertex_to_tets_;     // its own incidence
  std::vector<Vec3> known_positions_;                          // each vertex where it last saw it
  std::vector<std::uint8_t> excluded_;                         // per tet, during one check
  std::vector<std::uint32_t> touched_stamp_;                   // per vertex
  std::uint32_t stamp_ = 0;
  std::uint64_t live_tets_ = 0;
  std::uint64_t live_vertices_ = 0;
  std::vector<std::uint8_t> uncuttable_;                       // per tet: the checker's own record
  bool any_uncuttable_ = false;
  std::unique_ptr<Scratch> scratch_;
};

// ---- pieces and fragments -------------------------------------------------------------------
// A cut can detach face-connected pieces of tissue from the rest of the mesh; the engine reports
// them ("fragments") and the largest remaining piece is "the organ". The checker finds the
// pieces itself, from the raw tets alone (invariants/src/components.hpp): two live tets are in
// one piece when they share a face (three vertex ids); a shared edge or vertex does not join them.

// No piece: the entry of a dead tet in Components::of_tet.
inline constexpr std::uint32_t kNoComponent = 0xFFFFFFFFu;

struct Components {
  std::uint32_t count = 0;            // the number of pieces
  // #T: the piece of each tet, kNoComponent for a tombstone. Pieces are numbered 0 .. count - 1
  // in order of their lowest tet id.
  std::vector<std::uint32_t> of_tet;
};

// The face-connected pieces of the live tets. Purely combinatorial: a tet with a bad reference
// (I1) is joined by its vertex ids as they are. O(#T log #T) (a sort of the 4 #T faces).
Components count_components(const RawMeshView& mesh);

// One piece a cut detached, as the engine reports it, in plain numbers (the engine fills it from
// its own records; the checker depends on nothing of the engine's).
struct RawFragment {
  RawIds tets;           // its tet ids, as the engine holds them (TetId or uint32 spans, vectors)
  double volume = 0.0;   // the sum of its tets' |signed volume|
  Vec3 centroid;         // the volume-weighted mean of its tets' centroids (vertex means)
};

// What the engine reports after one cut.
struct FragmentReport {
  std::span<const RawFragment> fragments;  // the detached pieces, the organ not among them
  // One live tet of the piece the engine takes for the organ; none when the cut detached nothing
  // or the engine did not resolve it (then the organ is not checked).
  std::optional<std::uint32_t> organ_tet;
  // The engine's running count of the mesh's pieces; none: not checked.
  std::optional<std::uint32_t> piece_count;
};

// What can be wrong with a FragmentReport. A fragment's piece is the checker's piece holding
// most of its live listed tets (the lowest such piece on a tie).
enum class FragmentFault : std::uint8_t {
  kDeadTet = 1,      // a listed id is out of range or a tombstone
  kRepeatedTet,      // a tet listed twice, in one fragment or in two
  kNoPiece,          // a fragment lists no live tet at all
  kForeignTet,       // a listed tet is in another piece than the fragment's
  kMissingTet,       // a tet of the fragment's piece is not listed
  kSamePiece,        // two fragments are the same piece
  kVolume,           // the reported volume is not the piece's
  kCentroid,         // the reported centroid is not the piece's
  kOrganTet,         // organ_tet is out of range or a tombstone
  kOrganListed,      // the organ's piece is reported as a fragment
  kLargerThanOrgan,  // a fragment's piece has more volume than the organ's
  kPieceCount,       // the engine's piece count is not the checker's
};

// A short human name: "a tet of the piece not listed".
const char* description(FragmentFault fault);

// One fault of one fragment (all its offending tets together).
struct FragmentViolation {
  FragmentFault fault;
  std::uint32_t fragment = kNoRawRef;  // index into FragmentReport::fragments; kNoRawRef: none
  std::uint64_t count = 0;             // how many offending tets (1 for a fault of the whole)
  std::vector<std::uint32_t> tets;     // the first offending tets (at most kMaxListed)
  std::string detail;                  // one line, for people: which fragment, which tet, numbers
};

struct FragmentCheckReport {
  std::vector<FragmentViolation> violations;  // by fragment, then in FragmentFault order
  Components components;                      // the checker's own pieces
  std::string operation;                      // copied from CheckOptions::operation
  std::vector<std::string> notes;             // what was not checked and why

  [[nodiscard]] bool ok() const { return violations.empty(); }
  // The first violation of that kind (of that fragment, when given).
  [[nodiscard]] const FragmentViolation* find(FragmentFault fault,
                                              std::optional<std::uint32_t> fragment = std::nullopt) const;
};

// One line per violation, "fragments: a tet of the piece not listed: detail", then the notes.
std::string to_string(const FragmentCheckReport& report);

// Checks what the engine reports after a cut against the checker's own pieces of `mesh` (the mesh
// after the cut): each fragment lists exactly the live tets of one piece, no two fragments the
// same; its volume is the piece's to options.volume_rel_tolerance of it plus the rounding bound of
// its tets' volumes; its centroid is the piece's to options.volume_rel_tolerance of the bounding
// box diagonal of the live tets; with an organ tet, the organ's piece is no fragment and has at
// least every fragment's volume (both as the checker measures them); with a piece count, it is
// the checker's. Uses options.volume_rel_tolerance and options.operation, nothing else.
// O(#T log #T) (count_components) plus O(#T + listed tets).
FragmentCheckReport check_fragments(const RawMeshView& mesh, const FragmentReport& report,
                                    const CheckOptions& options = {});

}  // namespace tetcut::invariants

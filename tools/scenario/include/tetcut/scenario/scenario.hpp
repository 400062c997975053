// Scenarios: readable, replayable sequences of operations on a mesh (design: scenario files).
//
// One operation a line, `#` starts a comment. Tets and tools are addressed geometrically, so a
// scenario survives any change of internal ids:
//
//   mesh PATH                     load a mesh (relative paths: to the scenario's folder)
//   diameter D                    tool diameter           (also: dref_factor F, p P, depth N,
//                                                          iterations N, split templates|bisection)
//   refinement R                  auto|paper|graded: the paper's refinement loop (3.2), longest-edge
//                                 bisection graded to the tool, or auto (CutParams::refinement)
//   strategy S                    basic|neighbours|combined|wide
//   order O                       direct-first|surface-first-by-id|revisit ("paper": the second's
//                                 old name): which selected tet a cut requests next
//                                 (CutParams::order, cut_strategies.hpp)
//   neighbour_set C               smallest|first: which removable set paper 3.5 keeps
//                                 (CutParams::neighbour_set)
//   improve on|off                the improvement pass that ends each cut (CutParams::improve)
//   quality_floor F               the radius ratio it lifts created tets to (CutParams, I7's F)
//   min_dihedral DEG              the smallest dihedral angle it lifts them to (I7's theta)
//   debris_volume V               detached pieces below this volume (mesh units cubed) are removed
//                                 by the cut that detached them (CutParams::debris_volume);
//                                 0, the default: detached pieces are only reported
//   undo_history N                the cuts `undo` can take back (CutParams::undo_history); 0, the
//                                 default: none kept
//   uncuttable LABEL...           tets with these labels (the mesh file's) are tissue no cut or
//                                 removal takes (Cutter::set_uncuttable(): the paper's Fig. 7);
//                                 `uncuttable none` lifts it. Needs a labelled mesh.
//   cut X,Y,Z                     one cut with the tool centred there (a ball: Cutter::cut)
//   cut X,Y,Z X,Y,Z               one cut by the capsule the tool sweeps from the first point to
//                                 the second: every point within its radius of the segment
//                                 (Cutter::cut_segment; `cut C C` is `cut C`)
//   sweep X,Y,Z X,Y,Z STEP        one cut every STEP along the segment, the end included when a
//                                 whole number of steps away (sweep.hpp: sweep_centres)
//   sweep X,Y,Z X,Y,Z STEP swept  the same centres joined by capsules: one cut from each to the
//                                 next (sweep.hpp: sweep_cuts), so no tissue is left between them
//   remove X,Y,Z                  remove the tet containing the point with the strategy
//   undo                          take back the last cut or removal that changed the mesh
//                                 (Cutter::undo()): the mesh bit for bit as before it, the labels
//                                 too; the run fails when nothing is kept to take back
//   compact                       renumber densely, the ids along a space-filling curve
//                                 (TetMesh::compact(): tets near each other in space get ids
//                                 near each other); the cuts after it may differ from those on
//                                 the old ids, where the engine breaks a tie by id
//   compact kept                  renumber densely, the ids in their relative order
//   check [local|full|exact]      the independent checker; the scenario fails when it objects
//   expect hash HEX               canonical hash of the current mesh
//   expect tets N                 live tets
//   expect unresolved N           tets left unresolved so far
//   expect components N           face-connected pieces of the mesh (a resection separates one):
//                                 the count the Cutter keeps (Cutter::pieces()), crossed with a
//                                 scan of the mesh (face_connected_pieces); the line fails when
//                                 the two disagree. After a bounded search for pieces
//                                 (CutReport::fragment_search_bounded) the kept count may be
//                                 short: the scan is then the count, and the kept one may not
//                                 exceed it
//   expect min_quality X          every tet the cuts so far created has radius ratio >= X, as the
//                                 checker measures the tets each cut left created
//
// Running one: every operation is followed by the local check (or the full check, or none, as
// asked), a cut's with the tissue rule (I10) at its tool (ball or capsule); the first failed check
// or expectation stops the run and names its line.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tetcut/cut.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/scenario/sweep.hpp"
#include "tetcut/scenario/values.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::scenario {

enum class OpKind : std::uint8_t {
  kMesh, kParam, kCut, kSweep, kRemove, kCompact, kCheck, kExpectHash, kExpectTets, kExpectUnresolved,
  kExpectComponents, kExpectMinQuality, kUncuttable, kUndo
};

struct Op {
  OpKind kind;
  std::uint32_t line = 0;  // 1-based, in the scenario text
  std::string text;        // mesh path, parameter name, check level, expected hash, "kept" (compact)
  std::string value;       // parameter value as written
  Vec3 a{}, b{};
  double step = 0.0;
  bool swept = false;      // cut: the capsule from a to b; sweep: its centres joined by capsules
  std::uint64_t count = 0;
  double bound = 0.0;      // expect min_quality
  std::vector<std::uint32_t> labels;  // uncuttable
};

struct Scenario {
  std::string name;        // the file, for messages
  std::string base_dir;    // relative mesh paths resolve against it
  std::vector<Op> ops;
};

struct ParseResult {
  std::optional<Scenario> scenario;
  std::string error;       // "FILE:LINE: reason"
};

ParseResult parse(const std::string& text, const std::string& name, const std::string& base_dir);
// `name` is what errors and reports call the scenario (default: `path`); its mesh lines are
// read relative to the folder of `path` all the same.
ParseResult parse_file(const std::string& path, const std::string& name = "");

// How a scenario written in folder `dir` names the mesh at absolute path `mesh`: relative when
// both lie in one tree (a checkout), so that the pair can move together; absolute otherwise.
std::string mesh_path_from(const std::string& mesh, const std::string& dir);

// A piece a cut detached (Cutter::last_fragments()) as a report gives it: its size and place,
// not its tets' ids (the engine's views die at the next cut).
struct DetachedPiece {
  std::uint32_t tets = 0;
  double volume = 0.0;
  Vec3 centroid{};
  bool removed = false;  // dropped as debris (CutParams::debris_volume)
};

// The pieces the Cutter's last cut or removal request detached, in the engine's order.
std::vector<DetachedPiece> detached_pieces(const Cutter& cutter);

struct CutRecord {
  std::uint32_t line = 0;  // the scenario line that made the cut
  Vec3 centre;             // the ball's centre, or the capsule's first end
  std::optional<Vec3> end; // the capsule's other end; none: a ball
  CutReport report;
  std::vector<DetachedPiece> pieces;  // report.fragments of them, copied when the cut returned
};

struct RunResult {
  bool ok = true;
  int exit_code = 0;       // 0 passed, 1 a check or expectation failed, 2 unusable input
  std::string error;       // "FILE:LINE: what failed"
  std::string reason;      // "what failed" alone, for callers that name the place themselves
  std::uint32_t failed_line = 0;
  std::vector<CutRecord> cuts;
  std::uint64_t removals = 0;
  std::uint64_t unresolved = 0;
  std::uint32_t undos = 0;  // `undo` lines that took a cut back
  double min_created_radius_ratio = 1.0;  // the worst tet any cut or removal created (1: none)
  // Of every tet a cut or a removal created and left live, measured by the checker's geometry.
  invariants::QualityStats created_quality;
  std::string hash;        // of the final mesh
  std::uint32_t tets = 0;
  RemovalReport removal;   // the paper's statistics over every removal request of the run
  // The labels of the final mesh's tets by TetId when the mesh file had labels (RawMesh::labels),
  // carried through every cut, removal and compaction by mechanics::TetLabels; else empty.
  std::vector<std::uint32_t> labels;
};

struct RunOptions {
  CheckMode check = CheckMode::kEvery;
  std::optional<CutParams> initial_params;  // before the scenario's own settings
  // Labels whose tets no cut or removal takes, before the scenario's own `uncuttable` lines
  // (`--keep-label`): the mesh must carry labels.
  std::vector<std::uint32_t> uncuttable_labels;
  // When non-zero, the run stops (exit 1) after a cut or removal that leaves more live tets:
  // a guard for comparisons that run a strategy known to refine without bound.
  std::uint64_t max_tets = 0;
  // Called after every cut that succeeded and passed its check, with the cut's index in the run
  // and the tets' labels by TetId as RunResult::labels would hold them then (empty: the mesh file
  // had none), so that `tetcut cut --frames` writes a snapshot with its labels. A message stops
  // the run with exit 2.
  std::function<std::optional<std::string>(const TetMesh&, std::size_t cut_index, std::span<const std::uint32_t> labels)>
      after_cut;
};

// What the local checker holds one Cutter transaction made with `params` to: I7's no-degradation
// rule at the transaction's own floors when the improvement pass runs: quality_floor, and the
// theta it held (min_dihedral_deg, or lower when the pass fell back: Cutter::
// last_min_dihedral_held(), CutReport::min_dihedral_held_deg). With the pass off the engine
// promises no floor (the paper's algorithm alone), so I7 reports quality and judges none.
invariants::CheckOptions transaction_check_options(const CutParams& params, double min_dihedral_held_deg);

// What the local checker holds the cut `cutter` just made at `centre` to: transaction_check_options()
// with its params and held theta, and I10, the tissue rule, with the cut's tool (the ball centred
// at `centre`, or with `end` the capsule from `centre` to `end`: ToolRule::end; the params'
// diameter and D_ref) and the tets the cut reports it left there (Cutter::last_left_in_tool(),
// which the options view: use them before the next cut).
invariants::CheckOptions cut_check_options(const Cutter& cutter, const Vec3& centre,
                                           const std::optional<Vec3>& end = std::nullopt);

// Runs the scenario; the final mesh is left in `mesh_out` when given (when the run stops early,
// the mesh as it was then: after a refused cut, as before that cut).
RunResult run(const Scenario& scenario, const RunOptions& options = {}, TetMesh* mesh_out = nullptr);

}  // namespace tetcut::scenario

// What the cuts of a run did, summed, and the per-cut spread of what a user gates on: the summary
// `tetcut cut` and `tetcut run` print and write (run_report.hpp) and the report page shows.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tetcut/cut.hpp"
#include "tetcut/scenario/scenario.hpp"

namespace tetcut::scenario {

struct CutTotals {
  std::uint64_t removed = 0, created = 0, unresolved = 0, refused = 0;  // removed: requests' and slivers
  std::array<std::uint64_t, kCutRefusals> refusals{};                   // by CutRefusal
  std::uint64_t left_in_tool = 0, cuts_leaving_tissue = 0;
  std::uint64_t removed_beyond_tool = 0, removed_beyond_reach = 0, removed_by_improvement = 0;
  std::uint64_t flips = 0, collapses = 0, moves = 0, insertions = 0;
  std::uint64_t vertices_moved = 0;  // vertices there before a cut that it moved
  std::uint64_t mesh_rule_retries = 0;  // passes made again under the mesh rule
  double volume_removed = 0.0, volume_removed_beyond_tool = 0.0;
  // Per ok cut that met tissue: the volume left in the tool, and removed beyond it.
  std::vector<double> volume_left, volume_beyond;
  double worst_created = 1.0;  // the worst radius ratio an ok cut created, as the engine measured it
  // The pieces the cuts detached (CutReport::fragments), the cuts that detached any, those removed
  // as debris (CutParams::debris_volume: not in `removed` or `volume_removed`, which are tissue),
  // and the cuts whose search for pieces was bounded.
  std::uint64_t fragments = 0, cuts_detaching = 0;
  std::uint64_t debris_pieces = 0, debris_tets = 0;
  double debris_volume = 0.0;
  std::uint64_t fragment_searches_bounded = 0;
};

CutTotals cut_totals(const std::vector<CutRecord>& cuts);

}  // namespace tetcut::scenario

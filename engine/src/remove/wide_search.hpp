// Our extension of the neighbour search (strategy "wide"; not the paper's 3.5). Where 3.5 tries
// one path and its two extensions, this search also offers the whole shell of the singular
// vertex, and repairs a failing candidate by the same moves at the vertex or edge it would leave
// singular, for a few rounds; candidates are tested smallest first, so the first removable one
// is the smallest found. It resolves more singularities than 3.5, with larger sets, which is
// why it is not the default (tetcut stats compares both).
//
// Cost: bounded by rounds x frontier width candidates and by the number of set tests.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "remove/set_removal.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

struct WideSearchLimits {
  int max_path_depth = 10;
  int max_rounds = 3;
  int max_evaluations = 32;
  std::uint32_t max_set_size = 64;
};

class WideSearch {
 public:
  // Working sizes, allocated and touched now (a larger request grows them once).
  void reserve();
  // A removable set containing `seed` into `out`, starting from the offence the seed alone has.
  bool find(const TetMesh& mesh, SetRemovalWorkspace& ws, std::span<const TetId> seed, const Removability& offence,
            const WideSearchLimits& limits, std::vector<TetId>& out);

 private:
  struct Candidate {
    std::uint32_t begin = 0, size = 0;  // in pool_
    TestedPrefix prefix;                // the candidate it extends, and what its test found
    Removability offence;
  };
  void expand(const TetMesh& mesh, SetRemovalWorkspace& ws, const Candidate& from, const WideSearchLimits& limits);
  void add_candidate(const Candidate& from, std::span<const TetId> extra, std::uint32_t max_set_size);

  std::vector<TetId> pool_;
  std::vector<Candidate> candidates_, frontier_, next_frontier_;
  std::vector<TetId> tmp_tets_, tmp_path_;
  std::vector<std::uint32_t> tmp_sizes_;
};

}  // namespace tetcut::detail

// The checker's own face-connected pieces (count_components in check.hpp), and the union-find
// they are found with.
//
// Why its own: after a cut the engine reports the pieces it detached from the organ, walking its
// own adjacency; a checker that walked the same adjacency would agree with any mistake in it.
// So the pieces are found from the raw tets alone: every face of every live tet is keyed by its
// three vertex ids, sorted; the keys are sorted, and the tets of every face met more than once
// are united. Sharing an edge or a vertex joins nothing: a piece is what stays together when
// only faces hold (two organs touching at a vertex are two pieces).
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace tetcut::invariants::detail {

// Union-find over 0 .. n - 1 with path halving; a union links the larger root under the smaller,
// so every root is the lowest element of its set. O(log n) amortised per operation, which is all
// a check needs (ranks would buy near-constant time for a second array).
class DisjointSets {
 public:
  explicit DisjointSets(std::uint32_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }

  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a < b) parent_[b] = a;
    else if (b < a) parent_[a] = b;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace tetcut::invariants::detail

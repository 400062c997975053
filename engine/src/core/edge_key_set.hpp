// A set of edges (unordered vertex pairs) for membership tests on the per-cut path: open
// addressing over a power-of-two table, cleared in O(1) by a generation stamp, so that a
// reused set never allocates once it has grown. Never iterated: results keep their own order.
#pragma once

#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "tetcut/ids.hpp"

namespace tetcut {

class EdgeKeySet {
 public:
  void clear() {
    if (++generation_ == 0) {  // wrapped: really clear once every 2^32 uses
      for (Slot& s : slots_) s.generation = 0;
      generation_ = 1;
    }
    size_ = 0;
  }

  // Room for this many edges without growing (the table is allocated and written now).
  void reserve(std::size_t edges) {
    while ((edges + 1) * 2 > slots_.size()) grow();
  }

  // Inserts the edge; returns false when it was already there.
  bool insert(VertId a, VertId b) {
    if ((size_ + 1) * 2 > slots_.size()) grow();
    return insert_key(key(a, b));
  }

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t generation = 0;
  };

  static std::uint64_t key(VertId a, VertId b) {
    const std::uint64_t lo = a.value < b.value ? a.value : b.value, hi = a.value < b.value ? b.value : a.value;
    return (hi << 32) | lo;
  }

  bool insert_key(std::uint64_t k) {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = mix64(k) & mask;; i = (i + 1) & mask) {
      Slot& s = slots_[i];
      if (s.generation != generation_) {
        s = {k, generation_};
        ++size_;
        return true;
      }
      if (s.key == k) return false;
    }
  }

  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(old.empty() ? 64 : old.size() * 2, Slot{});
    const std::uint32_t live = generation_;
    generation_ = 1;
    size_ = 0;
    for (const Slot& s : old)
      if (s.generation == live) insert_key(s.key);
  }

  std::vector<Slot> slots_;
  std::uint32_t generation_ = 1;
  std::size_t size_ = 0;
};

}  // namespace tetcut

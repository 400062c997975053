// A memo of a pure function of a 32-bit key (a tet id, a birth index) over one improvement run,
// direct-mapped into a fixed number of slots: its memory stays fixed, where a map by tet id
// would grow with the mesh (with the Cutter's room for half as many tets again), and a key
// whose slot another key took is only computed again. forget() is O(1) (a new generation);
// forget_from(k) drops the keys >= k, for the births a rollback undid.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace tetcut::detail {

template <class Value, std::uint32_t kSlots>
class DirectMappedMemo {
 public:
  // The value set for `key` since the last forget, or nullptr.
  [[nodiscard]] const Value* find(std::uint32_t key) const {
    const Slot& s = slots_[key % kSlots];
    return s.generation == generation_ && s.key == key ? &s.value : nullptr;
  }
  void set(std::uint32_t key, const Value& value) {
    slots_[key % kSlots] = {key, generation_, value};
    end_ = std::max(end_, key + 1);
  }
  void forget() {
    end_ = 0;
    if (++generation_ == 0) {  // wrapped: every slot is from an older generation
      slots_.fill({});
      generation_ = 1;
    }
  }
  void forget_from(std::uint32_t first) {
    if (end_ <= first) return;  // nothing set at or past it
    for (Slot& s : slots_)
      if (s.key >= first) s.generation = 0;
    end_ = first;
  }

 private:
  struct Slot {
    std::uint32_t key = 0, generation = 0;  // generation 0: empty
    Value value{};
  };
  std::array<Slot, kSlots> slots_{};
  std::uint32_t generation_ = 1;
  std::uint32_t end_ = 0;  // past the largest key set since the last forget
};

}  // namespace tetcut::detail

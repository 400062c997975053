// Per-entity state of one operation, the one mechanism every stage uses (style: OpenVolumeMesh
// properties, geogram attributes): typed by the id that indexes it (TetId, VertId), cleared in
// O(1) by a generation stamp instead of a fill, and sized by what an operation touches, not by
// the mesh.
//
//   StampedSet<TetId> selected;     selected.insert(t); selected.contains(t); selected.clear();
//   StampedMap<TetId, TetId> origin;   origin.set(t, p); origin.find(t) (nullptr when unset)
//
// Why a table of our own and not std::unordered_set: clear() must cost O(1) whatever the set
// held (every stage clears its sets once per cut or per walk), and nothing may allocate on a
// cut's path once a Cutter has reserved. Open addressing with linear probing, keys spread by
// Fibonacci hashing (consecutive ids land apart), at most half full; an entry is current when
// its stamp equals the table's generation, so clear() is one increment. Erasing shifts the
// entries after it back (Knuth's algorithm R), so there are no tombstones.
//
// What it replaced was an array indexed by id, sized by the mesh: fifteen-odd such arrays of a
// Cutter held about 120 bytes per tet of the mesh for the few hundred entries a cut writes.
// reserve() makes room up front for a cut's working size; a larger operation grows a table
// once and keeps the room (the allocation gate counts it).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace tetcut {

namespace detail {

// Entries reserve() makes room for at most, whatever it is asked (callers ask by the mesh's
// size): more than any one table holds in a cut of the gated sweeps, which allocate nothing. A
// table is then 32 KiB (a set) and the twenty-odd of a Cutter stay in the caches: at 16,384
// entries they took 5 MB, and the cut p50 of the 1M- and 8M-tet livers rose by a fifth.
inline constexpr std::uint32_t kStampedReserve = 2048;

struct NoValue {};

// The table both containers share; Value is NoValue for a set.
template <class Value>
class StampedTable {
 public:
  static constexpr std::uint32_t kNone = ~0u;

  // The slot holding key as a current entry, or kNone.
  [[nodiscard]] std::uint32_t find(std::uint32_t key) const {
    if (count_ == 0) return kNone;
    for (std::uint32_t i = home(key);; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (s.stamp != generation_) return kNone;
      if (s.key == key) return i;
    }
  }
  // The slot of key, made a current entry if it was not (`added` says which).
  std::uint32_t stamp(std::uint32_t key, bool& added) {
    if (2 * (count_ + 1) > static_cast<std::uint32_t>(slots_.size())) grow(2 * (count_ + 1));
    for (std::uint32_t i = home(key);; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.stamp != generation_) {
        s.key = key;
        s.stamp = generation_;
        s.value = Value{};
        ++count_;
        added = true;
        return i;
      }
      if (s.key == key) {
        added = false;
        return i;
      }
    }
  }
  void erase(std::uint32_t key) {
    std::uint32_t i = find(key);
    if (i == kNone) return;
    // Algorithm R: an entry after the hole moves into it unless its home lies cyclically in
    // (hole, entry], where a search for it would stop before reaching the hole.
    for (std::uint32_t j = (i + 1) & mask_; slots_[j].stamp == generation_; j = (j + 1) & mask_) {
      const std::uint32_t k = home(slots_[j].key);
      const bool stays = i <= j ? (i < k && k <= j) : (i < k || k <= j);
      if (stays) continue;
      slots_[i] = slots_[j];
      i = j;
    }
    slots_[i].stamp = 0;
    --count_;
  }
  // Every entry stale at once; the stamps are refilled only when the generation wraps around.
  void clear() {
    count_ = 0;
    if (++generation_ != 0) return;
    for (Slot& s : slots_) s.stamp = 0;
    generation_ = 1;
  }
  // Room for min(n, kStampedReserve) entries, allocated and written now (reserve_touched.hpp).
  void reserve(std::uint32_t n) { grow(2 * std::min(n, kStampedReserve)); }
  [[nodiscard]] const Value& value(std::uint32_t slot) const { return slots_[slot].value; }
  [[nodiscard]] Value& value(std::uint32_t slot) { return slots_[slot].value; }

 private:
  struct Slot {
    std::uint32_t key = 0;
    std::uint32_t stamp = 0;  // 0: never current (generations start at 1)
    [[no_unique_address]] Value value{};
  };
  [[nodiscard]] std::uint32_t home(std::uint32_t key) const { return (key * 0x9E3779B9u) >> shift_; }
  // At least `slots` slots (a power of two), the current entries moved over.
  void grow(std::uint32_t slots) {
    std::uint32_t size = 16, shift = 28;
    while (size < slots) size *= 2, --shift;
    if (size <= slots_.size()) return;
    std::vector<Slot> old(size);
    old.swap(slots_);
    mask_ = size - 1;
    shift_ = shift;
    const std::uint32_t generation = generation_;
    count_ = 0;
    for (const Slot& s : old) {
      if (s.stamp != generation) continue;
      bool added = false;
      slots_[stamp(s.key, added)].value = s.value;
    }
  }
  std::vector<Slot> slots_;
  std::uint32_t mask_ = 0;
  std::uint32_t shift_ = 32;
  std::uint32_t count_ = 0;
  std::uint32_t generation_ = 1;
};

}  // namespace detail

template <class Id>
class StampedSet {
 public:
  [[nodiscard]] bool contains(Id id) const { return table_.find(id.value) != table_.kNone; }
  // True when `id` was not in the set.
  bool insert(Id id) {
    bool added = false;
    table_.stamp(id.value, added);
    return added;
  }
  void erase(Id id) { table_.erase(id.value); }
  void clear() { table_.clear(); }
  // Room for n ids (at most detail::kStampedReserve), allocated and touched now.
  void reserve(std::uint32_t n) { table_.reserve(n); }

 private:
  detail::StampedTable<detail::NoValue> table_;
};

template <class Id, class T>
class StampedMap {
 public:
  [[nodiscard]] bool contains(Id id) const { return table_.find(id.value) != table_.kNone; }
  // The value set since the last clear(), or nullptr; valid until the next set() or erase().
  [[nodiscard]] const T* find(Id id) const {
    const std::uint32_t slot = table_.find(id.value);
    return slot == table_.kNone ? nullptr : &table_.value(slot);
  }
  [[nodiscard]] T* find(Id id) {
    const std::uint32_t slot = table_.find(id.value);
    return slot == table_.kNone ? nullptr : &table_.value(slot);
  }
  [[nodiscard]] T get(Id id, T otherwise) const {
    const T* v = find(id);
    return v ? *v : otherwise;
  }
  void set(Id id, const T& value) {
    bool added = false;
    table_.value(table_.stamp(id.value, added)) = value;
  }
  void erase(Id id) { table_.erase(id.value); }
  void clear() { table_.clear(); }
  // Room for n ids (at most detail::kStampedReserve), allocated and touched now.
  void reserve(std::uint32_t n) { table_.reserve(n); }

 private:
  detail::StampedTable<T> table_;
};

}  // namespace tetcut

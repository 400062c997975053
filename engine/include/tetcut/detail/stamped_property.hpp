// Per-entity state of one operation, the one mechanism every stage uses (style: OpenVolumeMesh
// properties, geogram attributes): typed by the id that indexes it (TetId, VertId), cleared in
// O(1) by a generation stamp instead of a fill, and grown on the first write past its size, so
// no caller sizes it by hand. reserve() makes room up front: a Cutter reserves for the mesh it
// prepares, so that growing on the per-cut path stays within capacity and allocates nothing.
//
//   StampedSet<TetId> selected;     selected.insert(t); selected.contains(t); selected.clear();
//   StampedMap<TetId, TetId> origin;   origin.set(t, p); origin.find(t) (nullptr when unset)
//
// A read past the size is "not in the set" / "unset": ids a mesh made after the last write are
// simply absent.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {

namespace detail {

// The stamps both containers share: entry i is current when stamp_[i] == generation_.
class Stamps {
 public:
  [[nodiscard]] bool current(std::uint32_t i) const { return i < stamp_.size() && stamp_[i] == generation_; }
  // Makes entry i current; true when it was not.
  bool stamp(std::uint32_t i) {
    if (i >= stamp_.size()) grow(i);
    if (stamp_[i] == generation_) return false;
    stamp_[i] = generation_;
    return true;
  }
  void unstamp(std::uint32_t i) {
    if (i < stamp_.size()) stamp_[i] = 0;
  }
  // Every entry stale at once; the stamps are refilled only when the generation wraps around.
  void clear() {
    if (++generation_ != 0) return;
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    generation_ = 1;
  }
  void reserve(std::uint32_t n) {
    detail::reserve_touched(stamp_, n);
    stamp_.resize(std::max<std::size_t>(stamp_.size(), n), 0u);
  }
  [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(stamp_.size()); }

 private:
  // A quarter more than asked, so that a mesh growing one id at a time grows the array rarely.
  void grow(std::uint32_t i) { stamp_.resize(static_cast<std::size_t>(i) + i / 4 + 16, 0u); }
  std::vector<std::uint32_t> stamp_;
  std::uint32_t generation_ = 1;
};

}  // namespace detail

template <class Id>
class StampedSet {
 public:
  [[nodiscard]] bool contains(Id id) const { return stamps_.current(id.value); }
  // True when `id` was not in the set.
  bool insert(Id id) { return stamps_.stamp(id.value); }
  void erase(Id id) { stamps_.unstamp(id.value); }
  void clear() { stamps_.clear(); }
  // Room for ids below n, allocated and touched now.
  void reserve(std::uint32_t n) { stamps_.reserve(n); }

 private:
  detail::Stamps stamps_;
};

template <class Id, class T>
class StampedMap {
 public:
  [[nodiscard]] bool contains(Id id) const { return stamps_.current(id.value); }
  // The value set since the last clear(), or nullptr.
  [[nodiscard]] const T* find(Id id) const { return contains(id) ? &values_[id.value] : nullptr; }
  [[nodiscard]] T* find(Id id) { return contains(id) ? &values_[id.value] : nullptr; }
  [[nodiscard]] T get(Id id, T otherwise) const { return contains(id) ? values_[id.value] : otherwise; }
  void set(Id id, const T& value) {
    stamps_.stamp(id.value);
    if (values_.size() < stamps_.size()) values_.resize(stamps_.size());
    values_[id.value] = value;
  }
  void erase(Id id) { stamps_.unstamp(id.value); }
  void clear() { stamps_.clear(); }
  void reserve(std::uint32_t n) {
    stamps_.reserve(n);
    detail::reserve_touched(values_, n);
    values_.resize(std::max<std::size_t>(values_.size(), n));
  }

 private:
  detail::Stamps stamps_;
  std::vector<T> values_;
};

}  // namespace tetcut

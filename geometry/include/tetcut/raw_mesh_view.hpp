// A tet mesh as read-only flat arrays: how the independent checker (invariants/) reads a mesh
// without including a single engine header. The engine makes one with TetMesh::raw_view(), a
// file as read converts from RawMesh; the checker recomputes everything from `positions` and
// `tets`, and only compares its results with the engine's own records.
//
// This header fixes the data conventions both sides must agree on to talk at all (the
// tombstone marker, how a neighbour reference is packed); it holds no table and no logic.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <ranges>
#include <span>
#include <type_traits>

#include "tetcut/vec3.hpp"

namespace tetcut {

// Marks a dead tet in a raw tet array (TetMesh keeps tombstones): its first entry.
inline constexpr std::uint32_t kDeadTetMarker = 0xFFFFFFFFu;
// No such element: the neighbour across a boundary face, the tet of an unused vertex.
inline constexpr std::uint32_t kNoRawRef = 0xFFFFFFFFu;

// A 32-bit id as a plain number, or wrapped in a typed id whose only member is
// `std::uint32_t value` (the engine's TetId).
template <class T>
concept RawIdElement = std::is_trivially_copyable_v<T> && sizeof(T) == sizeof(std::uint32_t) &&
                       (std::same_as<T, std::uint32_t> || std::same_as<decltype(T::value), std::uint32_t>);

// A read-only array of 32-bit ids, whatever wraps them. The ids are read from their bytes
// (std::as_bytes, then std::bit_cast): defined for any trivially copyable element, whereas
// reading an array of TetId as an array of uint32_t would not be. Converts implicitly from a
// span or vector of ids, so that callers pass what they have.
class RawIds {
 public:
  RawIds() = default;
  template <std::ranges::contiguous_range R>
    requires RawIdElement<std::ranges::range_value_t<R>>
  RawIds(const R& ids)  // NOLINT(google-explicit-constructor): a view, like std::span
      : bytes_(std::as_bytes(std::span(std::ranges::data(ids), std::ranges::size(ids)))) {}

  [[nodiscard]] std::size_t size() const { return bytes_.size() / sizeof(std::uint32_t); }
  [[nodiscard]] bool empty() const { return bytes_.empty(); }
  [[nodiscard]] std::uint32_t operator[](std::size_t i) const {
    std::array<std::byte, sizeof(std::uint32_t)> word;
    std::copy_n(bytes_.data() + i * sizeof(std::uint32_t), word.size(), word.begin());
    return std::bit_cast<std::uint32_t>(word);
  }

  // So that `for (std::uint32_t id : ids)` reads.
  class Iterator {
   public:
    using value_type = std::uint32_t;
    using difference_type = std::ptrdiff_t;
    Iterator() = default;
    Iterator(const RawIds* ids, std::size_t i) : ids_(ids), i_(i) {}
    std::uint32_t operator*() const { return (*ids_)[i_]; }
    Iterator& operator++() {
      ++i_;
      return *this;
    }
    Iterator operator++(int) {
      Iterator old = *this;
      ++i_;
      return old;
    }
    bool operator==(const Iterator&) const = default;

   private:
    const RawIds* ids_ = nullptr;
    std::size_t i_ = 0;
  };
  [[nodiscard]] Iterator begin() const { return {this, 0}; }
  [[nodiscard]] Iterator end() const { return {this, size()}; }

 private:
  std::span<const std::byte> bytes_;
};

// What the engine keeps besides the tets, to be compared with the checker's recomputation
// (invariants I2 and I8), never used to compute it.
struct EngineRecordsView {
  // #T by 4: across face f of tet t (the face opposite its vertex f), (neighbour << 2) | the
  // neighbour's face we enter by, or kNoRawRef on the boundary.
  std::span<const std::array<std::uint32_t, 4>> neighbours;
  // #V: one live tet containing each vertex, kNoRawRef for an unused vertex.
  RawIds vertex_tet;
  // #V: the number of boundary faces through each vertex.
  std::span<const std::uint32_t> boundary_faces;
  std::uint64_t live_tets = 0;
  std::uint64_t live_vertices = 0;
  std::uint64_t attribute_rows = 0;  // rows of per-vertex attributes (one per vertex id)
};

// A vertex that was there before an operation and moved during it (the improvement pass smooths
// vertices within a cut's reach): its new position as a combination of the positions of `count`
// vertices as they were before the operation, sum of weight[i] * old position of from[i] (the
// engine's ChangeLog::moved, as plain numbers). What the checker's I8 holds a move to.
struct RawMovedVertex {
  std::uint32_t vertex = kNoRawRef;
  std::array<std::uint32_t, 4> from{};
  std::array<double, 4> weight{};
  std::uint8_t count = 0;
};

struct RawMeshView {
  std::span<const Vec3> positions;                     // #V positions
  std::span<const std::array<std::uint32_t, 4>> tets;  // #T by 4 vertex ids, 0-based
  // A tet whose first entry is kDeadTetMarker is a tombstone to skip, not a bad reference.
  bool has_tombstones = false;
  // Present for an engine mesh, absent for a file as read.
  std::optional<EngineRecordsView> engine;
};

}  // namespace tetcut

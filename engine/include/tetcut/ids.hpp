// Typed 32-bit ids for the mesh's entities (style: OpenVolumeMesh handles, geogram sentinels).
//
// A TetId and a VertId cannot be mixed up by accident: both wrap a uint32_t and convert only
// explicitly. The all-ones value is the invalid id (`kNoTet`, `kNoVert`).
#pragma once

#include <compare>
#include <cstdint>

namespace tetcut {

template <class Tag>
struct Id {
  static constexpr std::uint32_t kInvalidValue = 0xFFFFFFFFu;

  std::uint32_t value = kInvalidValue;

  constexpr Id() = default;
  constexpr explicit Id(std::uint32_t v) : value(v) {}

  [[nodiscard]] constexpr bool valid() const { return value != kInvalidValue; }
  constexpr auto operator<=>(const Id&) const = default;
};

using TetId = Id<struct TetTag>;
using VertId = Id<struct VertTag>;

inline constexpr TetId kNoTet{};
inline constexpr VertId kNoVert{};

// A face is not an object: it is a (tet, local face) pair, local face i being opposite the
// tet's local vertex i (style: CGAL's TDS facets).
struct FaceRef {
  TetId tet;
  std::uint8_t face = 0;

  [[nodiscard]] constexpr bool valid() const { return tet.valid(); }
  constexpr bool operator==(const FaceRef&) const = default;
};

// Likewise an edge is (tet, local edge), local edges numbered as in kEdgeVerts.
struct EdgeRef {
  TetId tet;
  std::uint8_t edge = 0;

  [[nodiscard]] constexpr bool valid() const { return tet.valid(); }
  constexpr bool operator==(const EdgeRef&) const = default;
};

}  // namespace tetcut

// Per-vertex attribute channels carried by the mesh (rest position, texture coordinates, user
// data), so that edge splits can interpolate them as the paper does for texture and mechanical
// data (paper 3.2), and compaction can move them with their vertex (style: OpenVolumeMesh
// properties).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tetcut/ids.hpp"

namespace tetcut {

// Conventional channel names.
inline constexpr std::string_view kRestPositionChannel = "rest_position";  // width 3
inline constexpr std::string_view kTexCoordChannel = "texcoord";           // width 2

// Channels are addressed by their index (0, 1, ... in the order added), vertices by VertId; the
// values of vertex v in channel c are value(c, v), `width` doubles.
class VertexAttributes {
 public:
  struct Channel {
    std::string name;
    std::uint32_t width = 1;
    std::vector<double> values;  // #V by width
  };

  // Adds a channel of `width` doubles per vertex, zero-filled; returns its index. Adding an
  // existing name returns the existing channel if the width matches, nullopt otherwise.
  std::optional<std::uint32_t> add_channel(std::string_view name, std::uint32_t width);
  [[nodiscard]] std::optional<std::uint32_t> find(std::string_view name) const;

  [[nodiscard]] std::size_t channel_count() const { return channels_.size(); }
  [[nodiscard]] const Channel& channel(std::uint32_t c) const { return channels_[c]; }

  std::span<double> value(std::uint32_t c, VertId vertex);
  [[nodiscard]] std::span<const double> value(std::uint32_t c, VertId vertex) const;

  // Number of vertices every channel is sized for.
  [[nodiscard]] std::uint32_t size() const { return size_; }
  void resize(std::uint32_t vertex_count);
  void reserve(std::uint32_t vertex_count);

  // dst := (1 - t) * a + t * b on every channel.
  void interpolate(VertId dst, VertId a, VertId b, double t);
  // dst := sum of weight[i] * from[i] on every channel (a vertex moved inside an old tet).
  void combine(VertId dst, std::span<const VertId> from, std::span<const double> weight);

  // Renumbers the vertices: vertex n takes the values vertex new_to_old[n] had (compaction).
  void permute(std::span<const VertId> new_to_old);

 private:
  std::vector<Channel> channels_;
  std::uint32_t size_ = 0;
};

}  // namespace tetcut
